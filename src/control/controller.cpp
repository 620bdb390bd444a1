#include "control/controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "control/central_difference.hpp"

namespace creaturelab::control {

struct Controller::Worker {
  explicit Worker(const rigid::RigidModel& m) : data(m) {}
  rigid::RigidData data;
  ServoScratch servo;
  MeasureScratch scratch;
  JointMeasures measures;
  Prescribed prescribed;
};

namespace {
// Validated before anything reads the model by the parameters' joint names.
const ControllerParams& checked(const ControllerParams& p, const rigid::RigidModel& model) {
  if (std::string err = p.validate(model); !err.empty()) throw std::invalid_argument(err);
  return p;
}

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
}  // namespace

Controller::Controller(const rigid::RigidModel& model, ControllerParams p, const ForceModel& force)
    : model_(model), p_(checked(p, model)), force_(force), layout_(makeLayout(p_, model)), main_(model),
      pres_(prescription(p_, model)) {
  direction_.assign(controlledDofs(), 0.0);
  derivative_.assign(controlledDofs(), 0.0);
  pool_ = std::make_unique<fluid::WorkerPool>(p_.threads);
  for (int k = 0; k < fluid::threadPieceCount(pool_.get()); ++k) workers_.push_back(std::make_unique<Worker>(model));
  captureHolds(pres_, main_.qpos());
}

Controller::~Controller() = default;

void Controller::setAngle(const std::string& joint, double rad) {
  const int id = model_.findJoint(joint);
  if (id < 0) throw std::invalid_argument("joint '" + joint + "' is not in the model " + model_.path());
  const auto j = model_.joint(id);
  if (j.type == rigid::JointType::ball || j.type == rigid::JointType::free)
    throw std::invalid_argument("joint '" + joint + "' has no single angle (a ball or free joint): give a rotation");
  main_.qpos()[j.qpos] = rad;
  main_.kinematics();
  captureHolds(pres_, main_.qpos());
}

void Controller::setRotation(const std::string& joint, const Vec3& r) {
  const int id = model_.findJoint(joint);
  if (id < 0) throw std::invalid_argument("joint '" + joint + "' is not in the model " + model_.path());
  const auto j = model_.joint(id);
  if (j.type != rigid::JointType::ball) throw std::invalid_argument("joint '" + joint + "' is not a ball joint");
  const rigid::Quat q = rigid::quatExp(r);
  std::copy(q.begin(), q.end(), main_.qpos() + j.qpos);
  main_.kinematics();
  captureHolds(pres_, main_.qpos());
}

// (d, e): DOF t moved by offset over one frame; the other controlled joints and the kinematic
// ones without a pattern are held, kinematic patterns go on; the passive joints outboard of t's
// joint are held too (rigidified with it); then J of t's joint.
double Controller::evaluate(Worker& w, const rigid::RigidState& start, int t, double offset) {
  w.data.restore(start);
  Prescribed& pr = w.prescribed;
  perturbation(pres_, model_, start.qpos.data(), t, offset, pr);
  advanceFrame(w.data, pr, force_, p_.substeps, p_.servo_iterations, p_.servo_tolerance_rad, w.servo,
               p_.servo_projection);
  measure(w.data, layout_, force_, w.scratch, w.measures);
  return combined(p_.weights, w.measures.objective, pres_.dof_joint[t]);
}

double Controller::evaluate(int dof, double offset_rad) { return evaluate(*workers_[0], main_.save(), dof, offset_rad); }

std::vector<double> Controller::derivatives() {
  const rigid::RigidState start = main_.save();
  return centralDifferences(
      pool_.get(), controlledDofs(), p_.delta_rad, p_.one_sided,
      [&](int part, int dof, double offset) { return evaluate(*workers_[part], start, dof, offset); },
      "while perturbing a joint");
}

JointMeasures Controller::measureNow() {
  Worker& w = *workers_[0];
  w.data.restore(main_.save());
  measure(w.data, layout_, force_, w.scratch, w.measures);
  return w.measures;
}

FrameRecord Controller::frame() {
  const int n = int(p_.controlled.size());
  const int nd = controlledDofs();
  FrameRecord r;
  // (b): the search, every search_every_frames frames (§2.1).
  if (frame_ % p_.search_every_frames == 0) {
    derivative_ = derivatives();
    for (int t = 0; t < nd; ++t) {
      const double sign = derivative_[t] > 0 ? 1.0 : derivative_[t] < 0 ? -1.0 : 0.0;
      direction_[t] = p_.senses[pres_.dof_joint[t]] == Sense::minimize ? -sign : sign;
    }
    r.searched = true;
  }
  // (g) -> targets: the strength-limited step (§2.1) on every DOF, within the joint's range;
  // kinematic joints follow their patterns or hold (their targets set by captureHolds).
  const double step_rad = p_.strength_rad_per_s * p_.frame_s;
  for (int t = 0; t < nd;) {
    const Slot& s = pres_.controlled[pres_.dof_joint[t]];
    if (s.ball) {
      const Vec3 r3 = {step_rad * direction_[t], step_rad * direction_[t + 1], step_rad * direction_[t + 2]};
      pres_.prescribed.balls[s.index].target = clampToRange(s, rigid::quatRotate(quatAt(main_.qpos(), s.qpos), r3));
      t += 3;
    } else {
      pres_.prescribed.target[s.index] = clampToRange(s, main_.qpos()[s.qpos] + step_rad * direction_[t]);
      t += 1;
    }
  }
  // (a, c): one frame of the creature.
  const ServoReport servo = advanceFrame(main_, pres_.prescribed, force_, p_.substeps, p_.servo_iterations,
                                         p_.servo_tolerance_rad, main_servo_, p_.servo_projection);
  r.time_s = main_.time_s();
  r.servo_residual_rad = servo.residual_rad;
  for (int i = 0; i < n; ++i) {
    const Slot& s = pres_.controlled[i];
    if (s.ball) {
      const Vec3 now = rigid::quatLog(quatAt(main_.qpos(), s.qpos));
      const Vec3 goal = rigid::quatLog(pres_.prescribed.balls[s.index].target);
      r.angle_rad.insert(r.angle_rad.end(), now.begin(), now.end());
      r.target_rad.insert(r.target_rad.end(), goal.begin(), goal.end());
    } else {
      r.angle_rad.push_back(main_.qpos()[s.qpos]);
      r.target_rad.push_back(pres_.prescribed.target[s.index]);
    }
  }
  for (const Slot& s : pres_.kinematic) {
    double miss = 0;
    if (s.ball) {
      miss = norm(rigid::quatDifference(quatAt(main_.qpos(), s.qpos), pres_.prescribed.balls[s.index].target));
    } else {
      const Pattern* pat = pres_.prescribed.pattern[s.index];
      const double goal = pat ? pat->angle(r.time_s, 0.0) : pres_.prescribed.target[s.index];
      miss = std::abs(main_.qpos()[s.qpos] - goal);
    }
    r.kinematic_error_rad = std::max(r.kinematic_error_rad, miss);
  }
  for (const PdDrive& d : pres_.prescribed.pd) {
    const double goal = d.pattern ? d.pattern->angle(r.time_s, d.hold_rad) : d.hold_rad;
    r.pd_error_rad = std::max(r.pd_error_rad, std::abs(main_.qpos()[d.qpos] - goal));
  }
  r.derivative = derivative_;
  r.measures = measureNow();
  for (int i = 0; i < n; ++i) r.objective.push_back(combined(p_.weights, r.measures.objective, i));
  ++frame_;
  return r;
}

}  // namespace creaturelab::control
