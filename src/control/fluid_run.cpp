#include "control/fluid_run.hpp"

#include <algorithm>
#include <limits>
#include <numbers>

#include "fluid/diagnostics2.hpp"

namespace creaturelab::control {
namespace {

constexpr double kFluidRunDeg = 180.0 / std::numbers::pi;
const Vec3 kStream = {1, 0, 0};  // the flow angle's reference line

}  // namespace

FluidRunRecorder::FluidRunRecorder(const rigid::RigidModel& model, const ControllerParams& p,
                                   FluidController& controller, double origin_x_m, double origin_z_m,
                                   long field_every_frames)
    : field_every_(field_every_frames), common_(series_, p.controlled) {
  flow_ = &series_.add("flow_angle_deg", "deg");
  for (const auto& j : p.controlled) {
    angle_.push_back(&series_.add("angle_deg_" + j, "deg"));
    target_.push_back(&series_.add("target_deg_" + j, "deg"));
    derivative_.push_back(&series_.add("derivative_per_rad_" + j, "1/rad"));
    fx_.push_back(&series_.add("force_x_n_" + j, "N"));
    fz_.push_back(&series_.add("force_z_n_" + j, "N"));
  }
  // §7.1: the force on all bodies, the senses followed, the PD-driven angles (the flap).
  body_fx_ = &series_.add("force_x_n_bodies", "N");
  body_fz_ = &series_.add("force_z_n_bodies", "N");
  for (const auto& j : p.controlled) sense_.push_back(&series_.add("sense_" + j, ""));
  for (const auto& j : p.pd_driven) {
    pd_angle_.push_back(&series_.add("pd_angle_deg_" + j, "deg"));
    pd_qpos_.push_back(model.joint(model.findJoint(j)).qpos);
  }
  // Bodies for drawing: the outline markers (world x, z) and which body each belongs to.
  const auto& markers = controller.coupling().markers();
  for (const auto& m : markers) markers_.body.push_back(m.body);
  markers_.points = int(markers.size());
  const auto& grid = controller.coupling().fluid().grid();
  vorticity_.nx = grid.nx;
  vorticity_.ny = grid.ny;
  vorticity_.dx_m = grid.dx_m;
  vorticity_.origin_x_m = origin_x_m;
  vorticity_.origin_z_m = origin_z_m;
  j0_id_ = model.findJoint(p.controlled[0]);
  j0_body_ = model.joint(j0_id_).body;
}

void FluidRunRecorder::start(FluidController& controller) {
  if (field_every_ > 0) recordField(controller);
}

void FluidRunRecorder::recordField(FluidController& controller) {
  markers_.time_s.push_back(controller.data().time_s());
  for (const auto& x : controller.coupling().markerPosition_m())
    markers_.data.insert(markers_.data.end(), {x.x + vorticity_.origin_x_m, x.y + vorticity_.origin_z_m});
  const auto& c = controller.coupling().fluid();
  fluid::Array2 w;
  fluid::vorticityAtCentres(c.grid(), c.walls(), w);
  vorticity_.time_s.push_back(controller.data().time_s());
  vorticity_.data.insert(vorticity_.data.end(), w.data(), w.data() + w.size());
}

void FluidRunRecorder::record(const FrameRecord& fr, FluidController& controller) {
  max_cells_ = std::max(max_cells_, controller.coupling().markerCellsPerStep());
  common_.record(fr);
  for (std::size_t i = 0; i < angle_.size(); ++i) {
    angle_[i]->push_back(fr.angle_rad[i] * kFluidRunDeg);
    target_[i]->push_back(fr.target_rad[i] * kFluidRunDeg);
    derivative_[i]->push_back(fr.derivative[i]);
    fx_[i]->push_back(fr.measures.drag_vector_n[i][0]);
    fz_[i]->push_back(fr.measures.drag_vector_n[i][2]);
  }
  body_fx_->push_back(controller.frameBodiesForce_n()[0]);
  body_fz_->push_back(controller.frameBodiesForce_n()[2]);
  for (std::size_t i = 0; i < sense_.size(); ++i)
    sense_[i]->push_back(controller.frameSenses()[i] == Sense::maximize ? 1.0 : -1.0);
  for (std::size_t k = 0; k < pd_angle_.size(); ++k)
    pd_angle_[k]->push_back(controller.data().qpos()[pd_qpos_[k]] * kFluidRunDeg);
  auto& d = controller.data();
  const double* anchor = d.jointAnchor(j0_id_);
  const double* com = d.subtreeCom(j0_body_);
  lines_.push_back({com[0] - anchor[0], com[1] - anchor[1], com[2] - anchor[2]});
  flow_->push_back(lineAngleDeg(lines_.back(), kStream));
  ++frame_;
  if (field_every_ > 0 && frame_ % field_every_ == 0) recordField(controller);
}

std::vector<NamedValue> FluidRunRecorder::measure(int average_frames, double tolerance_deg, int frames_per_cycle,
                                                  int force_cycles, int forcing_iterations_most) const {
  const int tail = std::min(average_frames, common_.frames());
  std::vector<std::vector<double>> angles;
  for (const auto* a : angle_) angles.push_back(*a);
  return {
      {"final_angle_deg", "deg", tailMean(*angle_[0], tail)},
      {"flow_angle_deg", "deg", meanLineAngleDeg({lines_.end() - tail, lines_.end()}, kStream)},
      {"converged_frame", "", convergedFrame(angles, tolerance_deg, tail)},
      {"final_drag_n", "N", tailMean(common_.drag(0), tail)},
      {"final_drag_along_n", "N", tailMean(common_.dragAlong(0), tail)},
      {"final_effort_n_m_s", "N m s", tailMean(common_.effort(0), tail)},
      {"final_derivative_per_rad", "1/rad", tailMean(*derivative_[0], tail)},
      {"max_servo_residual_rad", "rad", common_.maxResidualRad()},
      {"forcing_iterations_most", "", double(forcing_iterations_most)},
      {"markers", "", double(markers_.points)},
      {"marker_cells_per_step_most", "", max_cells_},
      {"mean_up_force_n", "N",
       frames_per_cycle > 0 ? lastCyclesMean(*body_fz_, frames_per_cycle, force_cycles) : tailMean(*body_fz_, tail)},
      {"mean_up_force_n_stderr", "N",
       frames_per_cycle > 0 ? lastCyclesStandardError(*body_fz_, frames_per_cycle, force_cycles)
                            : std::numeric_limits<double>::quiet_NaN()},
  };
}

}  // namespace creaturelab::control
