#include "control/fluid_run3.hpp"

#include <numbers>

#include "control/coupled_flesh_fluid3.hpp"
#include "control/coupled_fluid3.hpp"

namespace creaturelab::control {
namespace {
constexpr double kRun3Deg = 180.0 / std::numbers::pi;

// The 3-D fluid's grid under the controller's coupled fluid, bare bodies or flesh.
const fluid3d::MacGrid3& recordedGrid(const CoupledFluid& fluid) {
  if (const auto* flesh = dynamic_cast<const CoupledFleshFluid3*>(&fluid)) return flesh->coupling().fluid().grid();
  return dynamic_cast<const CoupledFluid3&>(fluid).coupling().fluid().grid();
}
}  // namespace

FluidRunRecorder3::FluidRunRecorder3(const rigid::RigidModel& model, const ControllerParams& p,
                                     FluidRecording3 recording)
    : common_(series_, p.controlled), recording_(recording) {
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
  for (int g = 0; g < model.geoms(); ++g) {
    geoms_.type.push_back(model.geomType(g));
    geoms_.body.push_back(model.geomBody(g));
    const Vec3 size = model.geomSize(g);
    geoms_.size_m.insert(geoms_.size_m.end(), size.begin(), size.end());
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
  const long frame = long(geoms_.time_s.size());
  recordGeoms(fr.time_s, controller.data());
  if (recording_.stored != StoredFields3::none && frame % recording_.field_every == 0) recordFluid(fr.time_s, controller);
}

void FluidRunRecorder3::recordGeoms(double time_s, const rigid::RigidData& data) {
  geoms_.time_s.push_back(time_s);
  for (int g = 0; g < geoms_.geoms(); ++g) {
    const double* x = data.geomPosition(g);
    const double* r = data.geomRotation(g);
    geoms_.position_m.insert(geoms_.position_m.end(), x, x + 3);
    geoms_.rotation.insert(geoms_.rotation.end(), r, r + 9);
  }
}

void FluidRunRecorder3::recordFluid(double time_s, const FluidController& controller) {
  const fluid3d::MacGrid3& grid = recordedGrid(controller.coupledFluid());
  observables_.update(grid);
  const fluid3d::Array3* arrays[] = {&observables_.cellVelocity_m_per_s(0), &observables_.cellVelocity_m_per_s(1),
                                     &observables_.cellVelocity_m_per_s(2), &grid.pressure_pa,
                                     &observables_.vorticityMagnitude_per_s(), &observables_.q_per_s2()};
  if (fluid_.fields.empty()) {
    fluid_.n = {grid.n[0], grid.n[1], grid.n[2]};
    fluid_.dx_m = grid.dx_m;
    if (recording_.stored == StoredFields3::plane) fluid_.plane_layer = grid.n[1] / 2;
    fluid_.fields = {{"u_m_per_s", "m/s", {}},      {"v_m_per_s", "m/s", {}},
                     {"w_m_per_s", "m/s", {}},      {"pressure_pa", "Pa", {}},
                     {"vorticity_magnitude_per_s", "1/s", {}}, {"q_per_s2", "1/s^2", {}}};
  }
  fluid_.time_s.push_back(time_s);
  for (std::size_t f = 0; f < fluid_.fields.size(); ++f) {
    std::vector<double>& out = fluid_.fields[f].values;
    const fluid3d::Array3& a = *arrays[f];
    if (fluid_.plane_layer < 0) {
      out.insert(out.end(), a.data(), a.data() + a.size());
      continue;
    }
    for (int k = 0; k < fluid_.n[2]; ++k)
      for (int i = 0; i < fluid_.n[0]; ++i) out.push_back(a(i, fluid_.plane_layer, k));
  }
}

std::vector<NamedValue> FluidRunRecorder3::measure(int frames_per_cycle, int force_cycles, int markers,
                                                   int forcing_iterations_most) const {
  const PhaseMean maximising = lastCyclesPhaseMean(common_.objective(0), *sense_[0], +1, frames_per_cycle, force_cycles);
  const PhaseMean minimising = lastCyclesPhaseMean(common_.objective(0), *sense_[0], -1, frames_per_cycle, force_cycles);
  return {
      {"mean_up_force_n", "N", lastCyclesMean(*body_fz_, frames_per_cycle, force_cycles)},
      {"mean_up_force_n_stderr", "N", lastCyclesStandardError(*body_fz_, frames_per_cycle, force_cycles)},
      {"mean_derivative_per_rad", "1/rad", lastCyclesMean(*derivative_[0], frames_per_cycle, force_cycles)},
      {"mean_objective_maximising", "", maximising.mean},
      {"mean_objective_maximising_stderr", "", maximising.standard_error},
      {"mean_objective_minimising", "", minimising.mean},
      {"mean_objective_minimising_stderr", "", minimising.standard_error},
      {"max_servo_residual_rad", "rad", common_.maxResidualRad()},
      {"forcing_iterations_most", "", double(forcing_iterations_most)},
      {"markers", "", double(markers)},
  };
}

}  // namespace creaturelab::control
