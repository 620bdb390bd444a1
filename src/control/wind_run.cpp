#include "control/wind_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace creaturelab::control {
namespace {

constexpr double kWindDeg = 180.0 / std::numbers::pi;

double windNorm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

}  // namespace

WindRunRecorder::WindRunRecorder(const rigid::RigidModel& model, const ControllerParams& p, const ForceModel& force,
                                 const Vec3& wind_m_per_s, double gravity_m_per_s2, Controller& controller)
    : model_(model), p_(p), wind_(wind_m_per_s), gravity_(gravity_m_per_s2), common_(series_, p.controlled) {
  // Per controlled DOF a name: the hinge's, or the ball's with _x, _y, _z (its rotation vector).
  std::vector<std::string> dof_names;
  for (const auto& j : p.controlled) {
    if (model.joint(model.findJoint(j)).type != rigid::JointType::ball) dof_names.push_back(j);
    else
      for (const char* axis : {"_x", "_y", "_z"}) dof_names.push_back(j + axis);
  }
  for (const auto& d : dof_names) {
    angle_.push_back(&series_.add("angle_deg_" + d, "deg"));
    target_.push_back(&series_.add("target_deg_" + d, "deg"));
    derivative_.push_back(&series_.add("derivative_per_rad_" + d, "1/rad"));
  }
  geoms_.points = 4 * model.geoms();
  for (int g = 0; g < model.geoms(); ++g) {
    geoms_.type.push_back(model.geomType(g));
    geoms_.body.push_back(model.geomBody(g));
  }
  recordGeoms(controller.data(), controller.data().time_s());

  // The first controlled joint's load: the line from its anchor to the centre of mass it carries,
  // and the net external force on those bodies at zero velocity (gravity + Eq. 3), every frame.
  j0_id_ = model.findJoint(p.controlled[0]);
  j0_body_ = model.joint(j0_id_).body;
  mass_ = model.subtreeMass_kg(j0_body_);
  ControllerParams steady = p;
  steady.steady_state = true;
  steady.threads = 1;
  probe_ = std::make_unique<Controller>(model, steady, force);
  flow_ = &series_.add("flow_angle_deg", "deg");
  load_ = &series_.add("load_line_angle_deg", "deg");
  lean_ = &series_.add("lean_deg", "deg");
  force_lean_ = &series_.add("net_force_lean_deg", "deg");
  offset_ = &series_.add("com_offset_m", "m");
  arm_length_ = &series_.add("com_arm_m", "m");
}

WindRunRecorder::~WindRunRecorder() = default;

void WindRunRecorder::record(const FrameRecord& fr, Controller& controller) {
  common_.record(fr);
  max_contacts_ = std::max(max_contacts_, controller.data().contacts());
  max_kinematic_ = std::max(max_kinematic_, fr.kinematic_error_rad);
  max_pd_ = std::max(max_pd_, fr.pd_error_rad);
  for (std::size_t t = 0; t < angle_.size(); ++t) {
    angle_[t]->push_back(fr.angle_rad[t] * kWindDeg);
    target_[t]->push_back(fr.target_rad[t] * kWindDeg);
    derivative_[t]->push_back(fr.derivative[t]);
  }
  recordGeoms(controller.data(), fr.time_s);
  recordLoad(controller.data());
}

void WindRunRecorder::recordGeoms(const rigid::RigidData& d, double time_s) {
  geoms_.time_s.push_back(time_s);
  for (int g = 0; g < model_.geoms(); ++g) {
    const double* c = d.geomPosition(g);
    const double* R = d.geomRotation(g);
    // Half-extents along the geom's axes: MuJoCo's sizes are (radius, half-length) for
    // capsules and cylinders (along z), (radius) for spheres.
    Vec3 s = model_.geomSize(g);
    if (geoms_.type[g] == 3 || geoms_.type[g] == 5) s = {s[0], s[0], s[1]};
    if (geoms_.type[g] == 2) s = {s[0], s[0], s[0]};
    geoms_.data.insert(geoms_.data.end(), c, c + 3);
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 3; ++k) geoms_.data.push_back(c[k] + s[a] * R[3 * k + a]);
  }
}

void WindRunRecorder::recordLoad(rigid::RigidData& d) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  d.kinematics();
  const double* anchor = d.jointAnchor(j0_id_);
  const double* com = d.subtreeCom(j0_body_);
  const Vec3 arm = {com[0] - anchor[0], com[1] - anchor[1], com[2] - anchor[2]};
  probe_->data().restore(d.save());
  const JointMeasures still = probe_->measureNow();
  const Vec3 net = {still.drag_vector_n[0][0], still.drag_vector_n[0][1], still.drag_vector_n[0][2] - mass_ * gravity_};
  const double nn = windNorm(net);
  double off = 0;
  if (nn > 0) {
    const double along = (arm[0] * net[0] + arm[1] * net[1] + arm[2] * net[2]) / nn;
    off = std::sqrt(std::max(0.0, windNorm(arm) * windNorm(arm) - along * along));
  }
  flow_->push_back(windNorm(wind_) > 0 ? lineAngleDeg(arm, wind_) : nan);
  load_->push_back(nn > 0 ? lineAngleDeg(arm, net) : nan);
  // Leans from the vertical line through the anchor, positive towards +x: the carried centre of
  // mass, and the point of the load line on the same side (below the anchor for a hanging
  // block, above it for an upright trunk).
  lean_->push_back(std::atan2(arm[0], std::abs(arm[2])) * kWindDeg);
  const double side = arm[0] * net[0] + arm[1] * net[1] + arm[2] * net[2] >= 0 ? 1.0 : -1.0;
  force_lean_->push_back(nn > 0 ? std::atan2(side * net[0], std::abs(net[2])) * kWindDeg : nan);
  offset_->push_back(off);
  arm_length_->push_back(windNorm(arm));
  arm_x_.push_back(arm[0]);
  arm_y_.push_back(arm[1]);
  arm_z_.push_back(arm[2]);
  net_x_.push_back(net[0]);
  net_y_.push_back(net[1]);
  net_z_.push_back(net[2]);
}

std::vector<NamedValue> WindRunRecorder::measure(int average_frames, double tolerance_deg, int triangles) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int frames = common_.frames();
  const int tail = std::min(average_frames, frames);
  auto mean = [&](const std::vector<double>& v) { return tailMean(v, tail); };
  const int nd = int(angle_.size());
  std::vector<std::vector<double>> angles;
  for (int t = 0; t < nd; ++t) angles.push_back(*angle_[t]);
  const double g = gravity_;
  const double final_effort = mean(common_.effort(0));
  const double gravity_effort = mass_ * g * mean(*arm_length_) * p_.frame_s;
  std::vector<double> last(common_.torque(0).end() - tail, common_.torque(0).end());
  for (double& x : last) x = std::abs(x);
  std::sort(last.begin(), last.end());
  const double median = tail % 2 ? last[tail / 2] : 0.5 * (last[tail / 2 - 1] + last[tail / 2]);
  const auto& a0 = *angle_[0];
  return {
      {"final_angle_deg", "deg", mean(*angle_[0])},
      {"final_angle_deg_2", "deg", nd > 1 ? mean(*angle_[1]) : nan},
      {"final_angle_deg_3", "deg", nd > 2 ? mean(*angle_[2]) : nan},
      {"max_contacts", "", double(max_contacts_)},
      {"converged_frame", "", convergedFrame(angles, tolerance_deg, tail)},
      {"flow_angle_deg", "deg", mean(*flow_)},
      // Signed means: the strength-limited step chatters about the optimum, and the steady state is
      // the mean pose of that chatter.
      {"load_line_angle_deg", "deg", std::abs(mean(*lean_) - mean(*force_lean_))},
      {"com_offset_m", "m", mean(*offset_)},
      {"com_arm_m", "m", mean(*arm_length_)},
      {"lean_deg", "deg", mean(*lean_)},
      {"net_force_lean_deg", "deg", mean(*force_lean_)},
      {"final_effort_n_m_s", "N m s", final_effort},
      {"gravity_effort_n_m_s", "N m s", gravity_effort},
      {"effort_ratio", "", final_effort / gravity_effort},
      {"mean_torque_ratio", "", std::abs(mean(common_.torque(0))) / (mass_ * g * mean(*arm_length_))},
      {"median_torque_ratio", "", median / (mass_ * g * mean(*arm_length_))},
      {"final_drag_n", "N", mean(common_.drag(0))},
      {"mean_speed_deg_per_s", "deg/s", tail > 1 ? (a0.back() - a0[a0.size() - tail]) / ((tail - 1) * p_.frame_s) : 0.0},
      {"max_servo_residual_rad", "rad", common_.maxResidualRad()},
      {"max_kinematic_error_rad", "rad", max_kinematic_},
      {"max_pd_error_rad", "rad", max_pd_},
      // The 3-D angle between the mean carried arm and the mean net force (a ball joint's Fig. 4).
      {"load_line_angle_3d_deg", "deg", lineAngleDeg({mean(arm_x_), mean(arm_y_), mean(arm_z_)},
                                                     {mean(net_x_), mean(net_y_), mean(net_z_)})},
      {"triangles", "", double(triangles)},
  };
}

}  // namespace creaturelab::control
