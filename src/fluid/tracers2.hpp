#pragma once
// Passive tracer particles (the markers of the jellyfish paper's Fig. 6).

#include <vector>

#include "fluid/staggered_sampler2.hpp"

namespace creaturelab::fluid {

/// Moves each tracer with the sampled velocity for dt_s by the midpoint rule (RK2):
///   x_mid = x + ½ dt u(x),   x_new = x + dt u(x_mid),
/// with bilinear interpolation of the staggered velocity. Tracers stay in the closed domain
/// [0, width] × [0, height] (clamped), also at open walls.
void advectTracersRk2(std::vector<Vec2>& positions_m, const VelocitySampler2& velocity, double dt_s, double width_m,
                        double height_m);

}  // namespace creaturelab::fluid
