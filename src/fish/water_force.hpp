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
  double mu = 600.0;  // the fish kind's default (see describe); 0 = fish in air (spec §2)
  WaterLaw law = WaterLaw::quadratic;
  Eigen::Vector3d current_m_per_s = Eigen::Vector3d::Zero();  // uniform water velocity (still by default)

  template <class V>
  void describe(V& v) {
    v.real("water_mu", mu, "", 0, 1e9,
           "water force coefficient mu (linear: N*s/m^3; quadratic: N*s^2/m^4); ours: the pressure drag of a plate "
           "broadside to the flow, rho C_D / 2 with rho = 1000 kg/m^3 and C_D = 1.2; 0 = in air");
    v.choice("water_law", law, {{"linear", WaterLaw::linear}, {"quadratic", WaterLaw::quadratic}},
             "f = min(0, -mu A (n.v)) n (linear) or min(0, -mu A |v| (n.v)) n (quadratic, [reimpl]; ours by default: "
             "the drag of water at a fish's Reynolds numbers grows as the square of the speed); spec §2");
    v.real("current_x_m_per_s", current_m_per_s.x(), "m/s", -1e3, 1e3, "uniform water current, x (still water by default)");
    v.real("current_y_m_per_s", current_m_per_s.y(), "m/s", -1e3, 1e3, "uniform water current, y");
    v.real("current_z_m_per_s", current_m_per_s.z(), "m/s", -1e3, 1e3, "uniform water current, z");
  }
};

// Adds the water force on every face into force_n (one row per node). Returns nothing: a force
// that is not finite is caught by the solver's blow-up check.
void addWaterForce(const FishModel& fish, const WaterParams& water, const NodeMatrix& x, const NodeMatrix& v,
                   NodeMatrix& force_n);

}  // namespace creaturelab::fish
