#include "control/controller.hpp"

#include "control/central_difference.hpp"
#include "control/prescription.hpp"

#include <stdexcept>

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
  if (std::string err = validate(p, model); !err.empty()) throw std::invalid_argument(err);
  return p;
}
}  // namespace

Controller::Controller(const rigid::RigidModel& model, ControllerParams p, const ForceModel& force)
    : model_(model), p_(checked(p, model)), force_(force), layout_(makeLayout(p_, model)), main_(model) {
  const int n = int(p_.controlled.size());
  Prescription base = prescription(p_, model);
  prescribed_ = std::move(base.prescribed);
  holds_ = std::move(base.holds);
  direction_.assign(n, 0.0);
  derivative_.assign(n, 0.0);
  pool_ = std::make_unique<fluid::WorkerPool>(p_.threads);
  for (int k = 0; k < fluid::piece_count(pool_.get()); ++k) workers_.push_back(std::make_unique<Worker>(model));
  kinematic_rad_.clear();
  for (std::size_t k = n; k < prescribed_.qpos.size(); ++k) kinematic_rad_.push_back(main_.qpos()[prescribed_.qpos[k]]);
}

Controller::~Controller() = default;

void Controller::setAngle(const std::string& joint, double rad) {
  const int id = model_.findJoint(joint);
  if (id < 0) throw std::invalid_argument("joint '" + joint + "' is not in the model " + model_.path());
  const auto j = model_.joint(id);
  main_.qpos()[j.qpos] = rad;
  const int n = int(p_.controlled.size());
  for (std::size_t k = n; k < prescribed_.qpos.size(); ++k)
    if (prescribed_.qpos[k] == j.qpos) kinematic_rad_[k - n] = rad;
  main_.kinematics();
}

// (d, e): joint i moved by offset over one frame; everything else prescribed is held, the
// passive joints outboard of i are held too (rigidified with it); then J_i.
double Controller::evaluate(Worker& w, const rigid::RigidState& start, int joint, double offset) {
  w.data.restore(start);
  Prescribed& pr = w.prescribed;
  perturbation(prescribed_, holds_[joint], model_, start.qpos.data(), joint, offset, pr);
  advanceFrame(w.data, pr, force_, p_.substeps, p_.servo_iterations, p_.servo_tolerance_rad, w.servo);
  measure(w.data, layout_, force_, w.scratch, w.measures);
  return combined(p_.weights, w.measures.objective, joint);
}

double Controller::evaluate(int joint, double offset_rad) {
  return evaluate(*workers_[0], main_.save(), joint, offset_rad);
}

std::vector<double> Controller::derivatives() {
  const rigid::RigidState start = main_.save();
  return centralDifferences(
      pool_.get(), int(p_.controlled.size()), p_.delta_rad, p_.one_sided,
      [&](int part, int joint, double offset) { return evaluate(*workers_[part], start, joint, offset); },
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
  FrameRecord r;
  // (b): the search, every search_every_frames frames (§2.1).
  if (frame_ % p_.search_every_frames == 0) {
    derivative_ = derivatives();
    for (int i = 0; i < n; ++i) {
      const double sign = derivative_[i] > 0 ? 1.0 : derivative_[i] < 0 ? -1.0 : 0.0;
      direction_[i] = p_.senses[i] == Sense::minimize ? -sign : sign;
    }
    r.searched = true;
  }
  // (g) -> targets: the strength-limited step (§2.1), kinematic joints held.
  const double step_rad = p_.strength_rad_per_s * p_.frame_s;
  for (int i = 0; i < n; ++i) prescribed_.target[i] = main_.qpos()[prescribed_.qpos[i]] + step_rad * direction_[i];
  for (std::size_t k = n; k < prescribed_.qpos.size(); ++k) prescribed_.target[k] = kinematic_rad_[k - n];
  // (a, c): one frame of the creature.
  const ServoReport servo = advanceFrame(main_, prescribed_, force_, p_.substeps, p_.servo_iterations,
                                         p_.servo_tolerance_rad, main_servo_);
  r.time_s = main_.time_s();
  r.servo_residual_rad = servo.residual_rad;
  r.target_rad.assign(prescribed_.target.begin(), prescribed_.target.begin() + n);
  for (int i = 0; i < n; ++i) r.angle_rad.push_back(main_.qpos()[prescribed_.qpos[i]]);
  r.derivative = derivative_;
  r.measures = measureNow();
  for (int i = 0; i < n; ++i) r.objective.push_back(combined(p_.weights, r.measures.objective, i));
  ++frame_;
  return r;
}

}  // namespace creaturelab::control
