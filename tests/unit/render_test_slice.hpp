#pragma once
// A synthetic jellyfish slice for the render tests: the subumbrella a half-ellipse sampled at equal
// angles (left aperture → apex → right aperture, exactly mirror-symmetric about x = 0), a straight
// tentacle hanging from each aperture marker, and muscle elements at every marker of the lower
// 7/8 of each half (as the jellyfish kind lays them out).
#include <cmath>
#include <vector>

#include "render/jellyfish_renderer.hpp"

namespace creaturelab::render::test {

struct TestSlice {
  SliceTopology topology;
  std::vector<double> xy;          // markers × 2
  std::vector<double> activation;  // one per muscle
  int markers() const { return int(xy.size() / 2); }
  SliceFrame frame(double t = 0) const { return {t, xy, activation}; }
};

// segments: bell segments (even); semi-axes a (half width), b (height); `squeeze` scales x by
// (1 - squeeze * (1 - y / b)), narrowing the aperture like a contraction.
inline TestSlice testSlice(int segments = 32, int tentacle_segments = 8, double a = 0.016, double b = 0.024,
                           double squeeze = 0.0) {
  TestSlice s;
  const int n = segments + 1;
  s.xy.resize(2 * n);
  for (int k = 0; k <= segments / 2; ++k) {
    const double angle = M_PI * k / segments;  // 0 at the left aperture, pi/2 at the apex
    const double y = b * std::sin(angle), x = -a * std::cos(angle) * (1 - squeeze * (1 - y / b));
    s.xy[2 * k] = x;
    s.xy[2 * k + 1] = y;
    s.xy[2 * (segments - k)] = -x;
    s.xy[2 * (segments - k) + 1] = y;
  }
  s.xy[segments] = 0.0;  // the apex exactly on the axis
  s.topology.bell_markers = n;
  for (int side = 0; side < 2 && tentacle_segments > 0; ++side) {
    const int root = side == 0 ? 0 : segments;
    auto& chain = side == 0 ? s.topology.left_tentacle : s.topology.right_tentacle;
    chain.push_back(root);
    for (int m = 1; m <= tentacle_segments; ++m) {
      s.xy.push_back(s.xy[2 * root]);
      s.xy.push_back(s.xy[2 * root + 1] - 0.02 * m / tentacle_segments);
      chain.push_back(int(s.xy.size() / 2) - 1);
    }
  }
  for (int m = 0; m < segments / 2 * 7 / 8; ++m) s.topology.muscle_markers.push_back(m);
  s.activation.assign(s.topology.muscle_markers.size(), 0.0);
  return s;
}

inline RenderParams noVariation(RenderParams p = {}) {
  p.structural = p.ridges = p.noise = false;
  return p;
}

}  // namespace creaturelab::render::test
