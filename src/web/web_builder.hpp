#pragma once
// The web under construction: particles in the plane and strands laid between them. Internal to the
// web module; each construction stage (frame_stage, spoke_stage, spiral_stage) adds to one builder.
#include <cstdint>
#include <vector>

#include "web/geometry2.hpp"
#include "web/strand_type.hpp"
#include "web/web_model.hpp"
#include "web/web_params.hpp"

namespace creaturelab::web {

// Spacing and spring of one strand type (see web_params.hpp, "How a strand is laid").
struct StrandSpec {
  double placement_m;       // nominal distance between neighbouring masses as laid
  double rest_over_laid;    // rest length / laid length of every spring of the type
  double k_n_per_m;
};

StrandSpec strandSpec(const WebParams& p, StrandType type);

class WebBuilder {
 public:
  explicit WebBuilder(const WebParams& params);

  const WebParams& params() const { return params_; }
  int addParticle(const Point2& x_m, bool pinned);
  const Point2& position(int particle) const { return x_m_[particle]; }
  int particleCount() const { return static_cast<int>(x_m_.size()); }

  // Lays a strand of the given type from existing particle a to existing particle b (thesis Fig. 5.5
  // step 7: "create strands by laying spring-mass pairs"): n = max(1, round(d / placement)) springs,
  // n - 1 new particles evenly spaced on the segment, each spring's rest length rest_over_laid * d / n.
  // Returns the strand's particles from a to b (a and b included). a and b must be distinct points.
  std::vector<int> layStrand(int a, int b, StrandType type);

  // Moves everything into a model (network, state at rest, spring types); the caller fills the rest.
  WebModel finish();

 private:
  WebParams params_;
  std::vector<Point2> x_m_;
  std::vector<std::uint8_t> pinned_;
  std::vector<int> spring_a_, spring_b_;
  std::vector<double> rest_m_, k_n_per_m_;
  std::vector<StrandType> type_;
};

}  // namespace creaturelab::web
