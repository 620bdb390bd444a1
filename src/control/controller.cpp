#include "control/controller.hpp"

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
  for (const auto& name : p_.controlled) {
    const auto j = model.joint(model.findJoint(name));
    prescribed_.qpos.push_back(j.qpos);
    prescribed_.dof.push_back(j.dof);
  }
  for (const auto& name : p_.kinematic) {
    const auto j = model.joint(model.findJoint(name));
    prescribed_.qpos.push_back(j.qpos);
    prescribed_.dof.push_back(j.dof);
  }
  prescribed_.target.assign(prescribed_.qpos.size(), 0.0);
  // §5: the passive joints outboard of each controlled joint, held while it is perturbed.
  holds_.resize(n);
  for (int i = 0; i < n; ++i) {
    if (!p_.rigidify_outboard) break;
    const int body = model.joint(model.findJoint(p_.controlled[i])).body;
    for (int id = 0; id < model.joints(); ++id) {
      const auto j = model.joint(id);
      if (j.type != rigid::JointType::hinge && j.type != rigid::JointType::slide) continue;
      bool prescribed = false;
      for (int q : prescribed_.qpos) prescribed = prescribed || q == j.qpos;
      if (!prescribed && model.inSubtree(j.body, body)) holds_[i].push_back(id);
    }
  }
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
  pr = prescribed_;
  for (std::size_t k = 0; k < pr.qpos.size(); ++k) pr.target[k] = start.qpos[pr.qpos[k]];
  pr.target[joint] += offset;
  for (int id : holds_[joint]) {
    const auto j = model_.joint(id);
    pr.qpos.push_back(j.qpos);
    pr.dof.push_back(j.dof);
    pr.target.push_back(start.qpos[j.qpos]);
  }
  advanceFrame(w.data, pr, force_, p_.substeps, p_.servo_iterations, p_.servo_tolerance_rad, w.servo);
  measure(w.data, layout_, force_, w.scratch, w.measures);
  return combined(p_.weights, w.measures.objective, joint);
}

double Controller::evaluate(int joint, double offset_rad) {
  return evaluate(*workers_[0], main_.save(), joint, offset_rad);
}

std::vector<double> Controller::derivatives() {
  const int n = int(p_.controlled.size());
  const rigid::RigidState start = main_.save();
  // Two evaluations per DOF; each writes only its own slot and starts from the same snapshot, so
  // the values do not depend on which worker runs them (bitwise, any thread count).
  std::vector<double> value(2 * n, 0.0);
  std::vector<std::string> error(workers_.size());
  const double d = p_.delta_rad;
  fluid::for_pieces(pool_.get(), 0, 2 * n, [&](int lo, int hi, int part) {
    try {
      for (int t = lo; t < hi; ++t) {
        const int i = t / 2;
        const double offset = t % 2 == 0 ? d : (p_.one_sided ? 0.0 : -d);
        value[t] = evaluate(*workers_[part], start, i, offset);
      }
    } catch (const std::exception& e) {
      error[part] = e.what();
    }
  });
  for (const auto& e : error)
    if (!e.empty()) throw std::runtime_error("while perturbing a joint: " + e);
  std::vector<double> g(n);
  for (int i = 0; i < n; ++i) g[i] = (value[2 * i] - value[2 * i + 1]) / (p_.one_sided ? d : 2 * d);
  return g;
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
