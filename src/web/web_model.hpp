#pragma once
// What build() returns: a spring network ready for springs::System, its laid state, and what the
// experiments need to read it (strand types, hub, spokes, counts, the frame's inward forces).
#include <vector>

#include "springs/network.hpp"
#include "web/geometry2.hpp"
#include "web/strand_type.hpp"

namespace creaturelab::web {

struct WebCounts {
  int particles = 0;        // all particles, the pinned attachment masses included
  int springs = 0;
  int spokes = 0;           // radii: each primary spoke counts as its two arms, plus the secondary spokes
  int primary_spokes = 0;   // primary spoke strands laid (each gives two radii)
  int spiral_segments = 0;  // spiral strands, each joining masses on two neighbouring spokes
  int spiral_springs = 0;   // springs in those strands
  // Total silk, metres: the sum of the springs' REST lengths, i.e. the unstretched silk the spider
  // would have spun (thesis ch. 3: "the combined length of silk in a spider's web is about 20-60m").
  // The laid length is larger by the over-extension (1.33-2.5 times): see silk_laid_length_m.
  double silk_length_m = 0;
  double silk_laid_length_m = 0;  // sum of the springs' lengths as laid
  double web_mass_kg = 0;         // sum of all particle masses, pinned ones included
};

struct WebModel {
  // Particles, springs (Eq. 4.14, no spring damping), gravity (0, -g, 0) and air drag. Pinned: the
  // attachment particles only.
  springs::Network<3> network;
  // The web as laid (Figs. 5.14/5.17): z = 0 everywhere, at rest. Far from equilibrium: the strands
  // are over-extended and gravity has not acted yet.
  springs::State<3> state;
  // strand type of spring s, for every s: spring_type.size() == network.springCount().
  std::vector<StrandType> spring_type;
  // The constant inward radial force on the inner frame (Fig. 5.8), newtons, 3 x particles; zero on
  // every other particle. Give it to springs::System::setConstantForce, so that the static solve sees it too.
  springs::Points<3> external_force_n;

  Point2 centre_m{0, 0};      // middle of the attachment points' bounding box (Fig. 5.3)
  Point2 hub_centre_m{0, 0};  // least-squares intersection of the primary spokes (Fig. 5.10 step 4)
  std::vector<int> attachment_particles;   // one per attachment point, in order; pinned
  std::vector<int> inner_frame_particles;  // the closed inner-frame chain, corner 0 first, each mass once
  std::vector<int> hub_particles;          // the hub ring's masses on the primary spokes, then the hub strands' own
  // The radii in order of angle about the hub centre, each from its inner-frame mass to its hub mass.
  // A primary spoke gives two radii (its arms, each ending at the arm's hub-ring mass).
  std::vector<std::vector<int>> spokes;
  WebCounts counts;
};

}  // namespace creaturelab::web
