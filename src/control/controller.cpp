#include "control/controller.hpp"

#include <algorithm>
#include <cmath>
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

rigid::Quat quatAt(const double* qpos, int address) {
  return {qpos[address], qpos[address + 1], qpos[address + 2], qpos[address + 3]};
}

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
}  // namespace

Controller::Slot Controller::slotOf(const std::string& name, bool kinematic) {
  const auto j = model_.joint(model_.findJoint(name));
  Slot s{j.qpos, j.dof, 0, j.type == rigid::JointType::ball};
  if (s.ball) {
    s.index = int(prescribed_.balls.size());
    prescribed_.balls.push_back({j.qpos, j.dof, {1, 0, 0, 0}});
  } else {
    s.index = int(prescribed_.qpos.size());
    prescribed_.qpos.push_back(j.qpos);
    prescribed_.dof.push_back(j.dof);
    prescribed_.target.push_back(0.0);
    const std::size_t k = kinematic_.size();
    const bool moves = kinematic && !p_.kinematic_patterns.empty() && p_.kinematic_patterns[k].kind != Pattern::Kind::hold;
    prescribed_.pattern.push_back(moves ? &p_.kinematic_patterns[k] : nullptr);
  }
  return s;
}

Controller::Controller(const rigid::RigidModel& model, ControllerParams p, const ForceModel& force)
    : model_(model), p_(checked(p, model)), force_(force), layout_(makeLayout(p_, model)), main_(model) {
  const int n = int(p_.controlled.size());
  for (int i = 0; i < n; ++i) {
    controlled_.push_back(slotOf(p_.controlled[i], false));
    for (int a = 0; a < (controlled_.back().ball ? 3 : 1); ++a) {
      dof_joint_.push_back(i);
      dof_axis_.push_back(a);
    }
  }
  for (const auto& name : p_.kinematic) kinematic_.push_back(slotOf(name, true));
  for (std::size_t k = 0; k < p_.pd_driven.size(); ++k) {
    const auto j = model.joint(model.findJoint(p_.pd_driven[k]));
    const Pattern* pat = p_.pd_patterns[k].kind == Pattern::Kind::hold ? nullptr : &p_.pd_patterns[k];
    prescribed_.pd.push_back({j.qpos, j.dof, pat, 0.0, p_.pd_kp_n_m_per_rad, p_.pd_kd_n_m_s_per_rad});
  }
  // §5: the passive joints outboard of each controlled joint (PD-driven ones too), held while it
  // is perturbed.
  holds_.resize(n);
  for (int i = 0; i < n; ++i) {
    if (!p_.rigidify_outboard) break;
    const int body = model.joint(model.findJoint(p_.controlled[i])).body;
    for (int id = 0; id < model.joints(); ++id) {
      const auto j = model.joint(id);
      if (j.type == rigid::JointType::free) continue;
      bool prescribed = false;
      for (const Slot& s : controlled_) prescribed = prescribed || s.qpos == j.qpos;
      for (const Slot& s : kinematic_) prescribed = prescribed || s.qpos == j.qpos;
      if (!prescribed && model.inSubtree(j.body, body)) holds_[i].push_back(id);
    }
  }
  direction_.assign(dof_joint_.size(), 0.0);
  derivative_.assign(dof_joint_.size(), 0.0);
  pool_ = std::make_unique<fluid::WorkerPool>(p_.threads);
  for (int k = 0; k < fluid::piece_count(pool_.get()); ++k) workers_.push_back(std::make_unique<Worker>(model));
  captureHolds();
}

Controller::~Controller() = default;

// The poses the kinematic and PD joints without a moving pattern hold: the current ones.
void Controller::captureHolds() {
  for (const Slot& s : kinematic_) {
    if (s.ball) prescribed_.balls[s.index].target = quatAt(main_.qpos(), s.qpos);
    else prescribed_.target[s.index] = main_.qpos()[s.qpos];
  }
  for (PdDrive& d : prescribed_.pd) d.hold_rad = main_.qpos()[d.qpos];
}

void Controller::setAngle(const std::string& joint, double rad) {
  const int id = model_.findJoint(joint);
  if (id < 0) throw std::invalid_argument("joint '" + joint + "' is not in the model " + model_.path());
  const auto j = model_.joint(id);
  if (j.type == rigid::JointType::ball || j.type == rigid::JointType::free)
    throw std::invalid_argument("joint '" + joint + "' has no single angle (a ball or free joint): give a rotation");
  main_.qpos()[j.qpos] = rad;
  main_.kinematics();
  captureHolds();
}

void Controller::setRotation(const std::string& joint, const Vec3& r) {
  const int id = model_.findJoint(joint);
  if (id < 0) throw std::invalid_argument("joint '" + joint + "' is not in the model " + model_.path());
  const auto j = model_.joint(id);
  if (j.type != rigid::JointType::ball) throw std::invalid_argument("joint '" + joint + "' is not a ball joint");
  const rigid::Quat q = rigid::quatExp(r);
  std::copy(q.begin(), q.end(), main_.qpos() + j.qpos);
  main_.kinematics();
  captureHolds();
}

// (d, e): DOF t moved by offset over one frame; the other controlled joints and the kinematic
// ones without a pattern are held, kinematic patterns go on; the passive joints outboard of t's
// joint are held too (rigidified with it); then J of t's joint.
double Controller::evaluate(Worker& w, const rigid::RigidState& start, int t, double offset) {
  w.data.restore(start);
  Prescribed& pr = w.prescribed;
  pr = prescribed_;
  for (std::size_t k = 0; k < pr.qpos.size(); ++k)
    if (!pr.pattern[k]) pr.target[k] = start.qpos[pr.qpos[k]];
  for (auto& b : pr.balls) b.target = quatAt(start.qpos.data(), b.qpos);
  const int i = dof_joint_[t];
  const Slot& s = controlled_[i];
  if (s.ball) {
    Vec3 r{};
    r[dof_axis_[t]] = offset;
    pr.balls[s.index].target = rigid::quatRotate(pr.balls[s.index].target, r);
  } else {
    pr.target[s.index] += offset;
  }
  for (int id : holds_[i]) {
    const auto j = model_.joint(id);
    if (j.type == rigid::JointType::ball) {
      pr.balls.push_back({j.qpos, j.dof, quatAt(start.qpos.data(), j.qpos)});
    } else {
      pr.qpos.push_back(j.qpos);
      pr.dof.push_back(j.dof);
      pr.target.push_back(start.qpos[j.qpos]);
      pr.pattern.push_back(nullptr);
    }
    std::erase_if(pr.pd, [&](const PdDrive& d) { return d.qpos == j.qpos; });
  }
  advanceFrame(w.data, pr, force_, p_.substeps, p_.servo_iterations, p_.servo_tolerance_rad, w.servo);
  measure(w.data, layout_, force_, w.scratch, w.measures);
  return combined(p_.weights, w.measures.objective, i);
}

double Controller::evaluate(int dof, double offset_rad) { return evaluate(*workers_[0], main_.save(), dof, offset_rad); }

std::vector<double> Controller::derivatives() {
  const int n = controlledDofs();
  const rigid::RigidState start = main_.save();
  // Two evaluations per DOF; each writes only its own slot and starts from the same snapshot, so
  // the values do not depend on which worker runs them (bitwise, any thread count).
  std::vector<double> value(2 * n, 0.0);
  std::vector<std::string> error(workers_.size());
  const double d = p_.delta_rad;
  fluid::for_pieces(pool_.get(), 0, 2 * n, [&](int lo, int hi, int part) {
    try {
      for (int t = lo; t < hi; ++t) {
        const double offset = t % 2 == 0 ? d : (p_.one_sided ? 0.0 : -d);
        value[t] = evaluate(*workers_[part], start, t / 2, offset);
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
  const int nd = controlledDofs();
  FrameRecord r;
  // (b): the search, every search_every_frames frames (§2.1).
  if (frame_ % p_.search_every_frames == 0) {
    derivative_ = derivatives();
    for (int t = 0; t < nd; ++t) {
      const double sign = derivative_[t] > 0 ? 1.0 : derivative_[t] < 0 ? -1.0 : 0.0;
      direction_[t] = p_.senses[dof_joint_[t]] == Sense::minimize ? -sign : sign;
    }
    r.searched = true;
  }
  // (g) -> targets: the strength-limited step (§2.1) on every DOF; kinematic joints follow their
  // patterns or hold (their targets set by captureHolds).
  const double step_rad = p_.strength_rad_per_s * p_.frame_s;
  for (int t = 0; t < nd;) {
    const Slot& s = controlled_[dof_joint_[t]];
    if (s.ball) {
      const Vec3 r3 = {step_rad * direction_[t], step_rad * direction_[t + 1], step_rad * direction_[t + 2]};
      prescribed_.balls[s.index].target = rigid::quatRotate(quatAt(main_.qpos(), s.qpos), r3);
      t += 3;
    } else {
      prescribed_.target[s.index] = main_.qpos()[s.qpos] + step_rad * direction_[t];
      t += 1;
    }
  }
  // (a, c): one frame of the creature.
  const ServoReport servo = advanceFrame(main_, prescribed_, force_, p_.substeps, p_.servo_iterations,
                                         p_.servo_tolerance_rad, main_servo_);
  r.time_s = main_.time_s();
  r.servo_residual_rad = servo.residual_rad;
  for (int i = 0; i < n; ++i) {
    const Slot& s = controlled_[i];
    if (s.ball) {
      const Vec3 now = rigid::quatLog(quatAt(main_.qpos(), s.qpos));
      const Vec3 goal = rigid::quatLog(prescribed_.balls[s.index].target);
      r.angle_rad.insert(r.angle_rad.end(), now.begin(), now.end());
      r.target_rad.insert(r.target_rad.end(), goal.begin(), goal.end());
    } else {
      r.angle_rad.push_back(main_.qpos()[s.qpos]);
      r.target_rad.push_back(prescribed_.target[s.index]);
    }
  }
  for (const Slot& s : kinematic_) {
    double miss = 0;
    if (s.ball) {
      miss = norm(rigid::quatDifference(quatAt(main_.qpos(), s.qpos), prescribed_.balls[s.index].target));
    } else {
      const Pattern* pat = prescribed_.pattern[s.index];
      const double goal = pat ? pat->angle(r.time_s, 0.0) : prescribed_.target[s.index];
      miss = std::abs(main_.qpos()[s.qpos] - goal);
    }
    r.kinematic_error_rad = std::max(r.kinematic_error_rad, miss);
  }
  for (const PdDrive& d : prescribed_.pd) {
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
