#pragma once
// The undeformed fish's small vibrations in air: the eigenmodes of K v = w^2 M v, K the units'
// tangent stiffness at rest (sum over units of c r^ r^T on the 3 x 3 blocks; damping and water left
// out). Two numbers explain the fish's measured behaviour (docs/fish-spec-audit.md):
// - the lowest lateral bending mode: a swim gait much faster than it is filtered by the body's
//   inertia, so the spec's c = 28-38 N/m against 1.1-11 kg masses (a 0.15 Hz mode) caps the useful
//   tail-beat frequency and hence the speed in body lengths per second;
// - the highest mode w_max: 2 / w_max is the symplectic-Euler limit of the undamped body, and the
//   spec's semi-implicit step (whose matrix holds the units' secant coefficients n_ij = (c e +
//   gamma e') / |r|, zero at rest length) gets no stiffness from it for vibrations about rest, so it
//   shares that limit.
#include "fish/fish_model.hpp"

namespace creaturelab::fish {

struct RestModes {
  double lowest_lateral_hz = 0;  // lowest mode whose displacement is > 90% sideways (y)
  double highest_rad_per_s = 0;  // w_max
};

RestModes restModes(const FishModel& fish);

}  // namespace creaturelab::fish
