#pragma once
// Spiral segments of a built web and the surgery on them (thesis §6: "The orb web spiral is composed
// of short line segments which run from a mass in a particular radial spoke to another mass in the
// next radial spoke", Fig. 6.2). In our webs (src/web, §5.2) such a segment is one spiral strand: a
// chain of springs from a spoke mass to a mass on the neighbouring spoke, through masses of its own.
#include <cstdint>
#include <vector>

#include "springs/network.hpp"
#include "web/strand_type.hpp"
#include "web/web_builder.hpp"

namespace creaturelab::charlotte {

// Where a segment comes from: the web's own spiral, or an emphasis variant (§6, Figs. 6.12-6.13).
enum class SegmentOrigin : std::uint8_t {
  spiral = 0,       // laid by the web construction (Figs. 5.15-5.16)
  cross_hatch = 1,  // extra strand from a spiral mass to a neighbour of its partner (Fig. 6.12)
  attachment = 2,   // random strand between masses inside the letters (Fig. 6.13)
};

struct Segment {
  int a = -1, b = -1;         // end masses (each on a spoke), a as laid
  std::vector<int> springs;   // the chain from a to b, in order
  std::vector<int> interior;  // its own masses strictly between a and b (nothing else touches them)
  SegmentOrigin origin = SegmentOrigin::spiral;
};

// The web's spiral segments: every maximal chain of spiral springs whose inner masses belong to that
// chain alone (two springs each, both spiral, not pinned). Ordered by their first spring; a is the
// end at which the first spring starts (the direction the spiral was laid, Fig. 5.16).
std::vector<Segment> spiralSegments(const springs::Network<3>& network, const std::vector<web::StrandType>& type);

// Lays a strand from a to b at their current positions in s, the way the web construction lays one
// (web_builder.hpp, "How a strand is laid"): n = max(1, round(d / placement)) springs, n - 1 new free
// masses of mass_kg evenly spaced on the straight line, velocity zero, each spring's rest length
// rest_over_laid * d / n. Appends to network, s and type (as `strand_type`); returns the segment.
Segment layStrand(springs::Network<3>& network, springs::State<3>& s, std::vector<web::StrandType>& type, int a, int b,
                  const web::StrandSpec& spec, web::StrandType strand_type, double mass_kg, SegmentOrigin origin);

// A network with some springs taken out (§6: segments "are removed from the final image"), and every
// free mass left without a spring dropped with them (it would fall forever and leave the static
// problem singular). The particles and springs that stay keep their order.
struct Pruned {
  springs::Network<3> network;
  springs::State<3> state;
  std::vector<web::StrandType> type;
  std::vector<int> particle_of;      // new particle -> old
  std::vector<int> new_particle;     // old particle -> new, -1 if dropped
  std::vector<int> spring_of;        // new spring -> old
  int dropped_particles = 0;
};
Pruned removeSprings(const springs::Network<3>& network, const springs::State<3>& s,
                     const std::vector<web::StrandType>& type, const std::vector<int>& springs_to_remove);

}  // namespace creaturelab::charlotte
