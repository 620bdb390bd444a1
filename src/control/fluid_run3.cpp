#include "control/fluid_run3.hpp"

#include <numbers>

namespace creaturelab::control {
namespace {
constexpr double kRun3Deg = 180.0 / std::numbers::pi;
}  // namespace

FluidRunRecorder3::FluidRunRecorder3(const rigid::RigidModel& model, const ControllerParams& p)
    : common_(series_, p.controlled) {
  for (const auto& j : p.controlled) {
    angle_.push_back(&series_.add("angle_deg_" + j, "deg"));
    target_.push_back(&series_.add("target_deg_" + j, "deg"));
    derivative_.push_back(&series_.add("derivative_per_rad_" + j, "1/rad"));
    sense_.push_back(&series_.add("sense_" + j, ""));
  }
  // §7.1: the fluid's force on all bodies (z up: the lift), the PD-driven angles (the flap).
  body_fx_ = &series_.add("force_x_n_bodies", "N");
  body_fy_ = &series_.add("force_y_n_bodies", "N");
  body_fz_ = &series_.add("force_z_n_bodies", "N");
  for (const auto& j : p.pd_driven) {
    pd_angle_.push_back(&series_.add("pd_angle_deg_" + j, "deg"));
    pd_qpos_.push_back(model.joint(model.findJoint(j)).qpos);
  }
}

void FluidRunRecorder3::record(const FrameRecord& fr, FluidController& controller) {
  common_.record(fr);
  for (std::size_t i = 0; i < angle_.size(); ++i) {
    angle_[i]->push_back(fr.angle_rad[i] * kRun3Deg);
    target_[i]->push_back(fr.target_rad[i] * kRun3Deg);
    derivative_[i]->push_back(fr.derivative[i]);
    sense_[i]->push_back(controller.frameSenses()[i] == Sense::maximize ? 1.0 : -1.0);
  }
  const Vec3& f = controller.frameBodiesForce_n();
  body_fx_->push_back(f[0]);
  body_fy_->push_back(f[1]);
  body_fz_->push_back(f[2]);
  for (std::size_t k = 0; k < pd_angle_.size(); ++k)
    pd_angle_[k]->push_back(controller.data().qpos()[pd_qpos_[k]] * kRun3Deg);
}

std::vector<NamedValue> FluidRunRecorder3::measure(int frames_per_cycle, int force_cycles, int markers,
                                                   int forcing_iterations_most) const {
  return {
      {"mean_up_force_n", "N", lastCyclesMean(*body_fz_, frames_per_cycle, force_cycles)},
      {"mean_up_force_n_stderr", "N", lastCyclesStandardError(*body_fz_, frames_per_cycle, force_cycles)},
      {"max_servo_residual_rad", "rad", common_.maxResidualRad()},
      {"forcing_iterations_most", "", double(forcing_iterations_most)},
      {"markers", "", double(markers)},
  };
}

}  // namespace creaturelab::control
