#pragma once
#include <string>

#include "control/simple_wind.hpp"
#include "kinds/control_params.hpp"
#include "kinds/describe_kind.hpp"

namespace creaturelab::kinds {

// The control kind's parameters: the controller's (ControllerSettings) and the wind's.
struct ControlParams {
  ControllerSettings controller;
  double wind_x_m_per_s = 10;
  double wind_y_m_per_s = 0;
  double wind_z_m_per_s = 0;
  double density_kg_per_m3 = 1.2;
  bool steady_state = false;
  bool servo_projection = true;
  std::int64_t surface_slices = 12;

  template <class V>
  void describe(V& v) {
    controller.describeCreature(v);
    v.real("wind_x_m_per_s", wind_x_m_per_s, "m/s", -1e4, 1e4, "constant wind (§3.1); the paper gives no speed: 10 m/s");
    v.real("wind_y_m_per_s", wind_y_m_per_s, "m/s", -1e4, 1e4, "constant wind");
    v.real("wind_z_m_per_s", wind_z_m_per_s, "m/s", -1e4, 1e4, "constant wind");
    v.real("density_kg_per_m3", density_kg_per_m3, "kg/m^3", 0, 1e5,
           "rho of Eq. 2; the paper's fluid was 'similar to water' (§7) at an unstated speed: air here, with model "
           "masses chosen so that the leans are visible");
    controller.describeRun(v);
    controller.describeDescent(v);
    v.boolean("steady_state", steady_state,
              "§3.3: freeze the shape before evaluating objectives (joint velocities zeroed, a free creature keeps its "
              "rigid velocity); else §3.2, dynamic");
    v.boolean("servo_projection", servo_projection,
              "test only: false skips the servo's projection of its last residual (§2.2 post-stabilisation), so the "
              "kinematic joints end where the servo's Newton iteration left them");
    v.integer("surface_slices", surface_slices, 3, 256, "segments around round geoms in the wind's surface triangles");
    controller.describeMeasures(v);
  }

  control::Vec3 windVelocity() const { return {wind_x_m_per_s, wind_y_m_per_s, wind_z_m_per_s}; }
  // The controller's parameters with the wind kind's own (steady_state, servo_projection).
  control::ControllerParams controllerParams() const;
  // Ranges, then against the model: the controller, the initial poses, average_frames within frames.
  std::string validate() const;
};

// A creature driven by the gradient-descent controller of Lentine et al. 2010 under gravity and
// simple wind (Lentine et al. 2010 §2-3, §5, §7): an MJCF model,
// controlled joints with their objectives, kinematic joints held.
class ControlKind : public DescribedKind<ControlParams> {
 public:
  ControlKind();
  std::string name() const override { return "control"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
