#pragma once
// The hydrodynamic force on the fish's faces (spec §2; thesis ch. 4, whose formula is an image).
// A face pushes on the water only while it moves into it (n . v > 0, v relative to the water); the
// water pushes back along -n. Two readings of the formula, a switch (spec §2 [choose]):
//   linear:    f = min(0, -mu A (n . v)) n        mu in N s / m^3
//   quadratic: f = min(0, -mu A |v| (n . v)) n    mu in N s^2 / m^4  [reimpl]
// v is the mean of the face's four corner velocities (a triangle counts its repeated vertex twice)
// minus the water velocity, and f is split equally among the four corners, so sum f is the face force.
#include <Eigen/Core>

#include "fish/fish_model.hpp"

namespace creaturelab::fish {

enum class WaterLaw { linear, quadratic };

struct WaterParams {
  double mu = 100.0;  // the kind's default (kinds/fish.cpp); 0 = fish in air (spec §2)
  WaterLaw law = WaterLaw::linear;
  Eigen::Vector3d current_m_per_s = Eigen::Vector3d::Zero();  // uniform water velocity (still by default)
};

// Adds the water force on every face into force_n (one row per node). Returns nothing: a force
// that is not finite is caught by the solver's blow-up check.
void addWaterForce(const FishModel& fish, const WaterParams& water, const NodeMatrix& x, const NodeMatrix& v,
                   NodeMatrix& force_n);

}  // namespace creaturelab::fish
