#include "control/fluid_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "control/central_difference.hpp"
#include "control/prescription.hpp"

namespace creaturelab::control {
namespace {

// The fluid's reaction of the last coupled step as the servo's external-force stage (nothing with the 3-D
// coupled solve, whose step applied it), or, `measuring`, the fluid's force of the last step whatever the
// forcing (the measurements' inverse dynamics).
class CouplingReaction final : public ForceModel {
 public:
  CouplingReaction(const CoupledFluid* c, std::vector<double> armature, bool measuring = false)
      : c_(c), armature_(std::move(armature)), measuring_(measuring) {}
  void apply(rigid::RigidData& data, std::vector<Vec3>& body_force_n) const override {
    body_force_n = c_->bodyForce_n();
    if (measuring_)
      c_->applyFluidForce(data);
    else
      c_->applyReaction(data);
    addArmatureForce(data);
  }

 private:
  // FluidControlParams::armature_added_mass: A a^n on the stabilised DOFs. a^n is MuJoCo's last
  // acceleration (qacc_warmstart, which RigidState saves, so evaluations from a snapshot see it).
  void addArmatureForce(rigid::RigidData& data) const {
    if (armature_.empty()) return;
    const std::vector<double> a = data.save().warmstart;
    for (std::size_t d = 0; d < armature_.size(); ++d) data.appliedForces()[d] += armature_[d] * a[d];
  }
  const CoupledFluid* c_;
  std::vector<double> armature_;  // per DOF; empty: off
  bool measuring_;
};

// The DOFs the servo prescribes in pr (scalars, then the balls' three each): the coupled solve's held ones.
void prescribedDofs(const Prescribed& pr, std::vector<int>& out) {
  out.assign(pr.dof.begin(), pr.dof.end());
  for (const PrescribedBall& b : pr.balls)
    for (int a = 0; a < 3; ++a) out.push_back(b.dof + a);
}

// Armature per DOF of the joints not prescribed (the stabilised ones), or empty when off.
std::vector<double> stabilisedArmature(const rigid::RigidModel& m, const ControllerParams& p, bool on) {
  if (!on) return {};
  std::vector<double> a(m.dofs(), 0.0);
  for (int j = 0; j < m.joints(); ++j) {
    const rigid::JointInfo info = m.joint(j);
    bool prescribed = false;
    for (const auto* names : {&p.controlled, &p.kinematic, &p.pd_driven})
      for (const auto& name : *names) prescribed = prescribed || m.findJoint(name) == j;
    if (!prescribed && info.type != rigid::JointType::ball && info.type != rigid::JointType::free)
      a[info.dof] = m.dofArmature(info.dof);
  }
  return a;
}

const ControllerParams& checked(const ControllerParams& p, const FluidControlParams& f, const rigid::RigidModel& m) {
  if (std::string err = f.validate(p, m); !err.empty()) throw std::invalid_argument(err);
  return p;
}

}  // namespace

std::string FluidControlParams::validate(const ControllerParams& p, const rigid::RigidModel& model) const {
  const FluidControlParams& f = *this;
  if (auto e = p.validate(model); !e.empty()) return e;
  for (const auto* names : {&p.controlled, &p.kinematic, &p.pd_driven})
    for (const auto& name : *names)
      if (f.planar_fluid && model.joint(model.findJoint(name)).type == rigid::JointType::ball)
        return "joint '" + name + "' is a ball joint: the fluid is planar (x-z), give hinges";
  if (p.steady_state)
    return "steady_state: with the fluid use perturbation = placed (§3.3's steady-state calculation on the fluid's "
           "state) and settle_steps (§4.3's validation mode) instead";
  if (f.limit_rad < 0) return "the joint limit must be >= 0 (0: none)";
  if (f.settle_steps < 0) return "settle_steps must be >= 0";
  if (auto e = control::validate(f.stroke, p); !e.empty()) return e;
  if (f.average_steps < 1 || f.average_steps > p.substeps + f.settle_steps)
    return "average_steps must be 1..substeps + settle_steps (the steps of one evaluation)";
  return "";
}

struct FluidController::World {
  World(const rigid::RigidModel& m, const std::vector<std::pair<std::string, double>>& initial,
        const CoupledFluidFactory& make, bool single_threaded, std::vector<double> armature)
      : data(m), force(nullptr, {}), measured(nullptr, {}) {
    for (const auto& [name, rad] : initial) data.qpos()[m.joint(m.findJoint(name)).qpos] = rad;
    data.kinematics();
    coupling = make(data, single_threaded);
    measured = CouplingReaction(coupling.get(), armature, true);
    force = CouplingReaction(coupling.get(), std::move(armature));
  }
  rigid::RigidData data;
  std::unique_ptr<CoupledFluid> coupling;
  CouplingReaction force, measured;
  std::vector<int> held_dofs;
  ServoScratch servo;
  Prescribed pr, step;
  std::vector<Vec3> forces;     // per step of an evaluation: the joint's force
  std::vector<double> torques;  // per step of an evaluation: the joint's actuator torque
  MeasureScratch measure_scratch;
  JointMeasures measures;
  double residual_rad = 0;
  int forcing_iterations = 0;
  Vec3 bodies_force_sum{};  // sum over coupled steps of the force on all moving bodies
};

FluidController::FluidController(const rigid::RigidModel& model, ControllerParams p, FluidControlParams f,
                                 const std::vector<std::pair<std::string, double>>& initial,
                                 const fluid::FluidParams& fluid, const coupling::RigidFluidParams& cp)
    : FluidController(model, std::move(p), std::move(f), initial, planarFluid(fluid, cp)) {}

FluidController::FluidController(const rigid::RigidModel& model, ControllerParams p, FluidControlParams f,
                                 const std::vector<std::pair<std::string, double>>& initial,
                                 const CoupledFluidFactory& make)
    : model_(model), p_(checked(p, f, model)), f_(f), layout_(makeLayout(p_, model)) {
  for (const auto& [name, rad] : initial)
    if (model.findJoint(name) < 0) throw std::invalid_argument("joint '" + name + "' is not in the model " + model.path());
  pres_ = prescription(p_, model);
  const auto armature = stabilisedArmature(model, p_, f_.armature_added_mass);
  // The frame's own coupled steps are serial between the evaluations, so its fluid takes the
  // fluid's threads (fluid_threads; bitwise the same for any count). The evaluations' fluids take
  // them only when the evaluations themselves run one at a time: nested, the two kinds of thread
  // would compete for the same cores (§5's parallelism is across evaluations).
  // A fluid whose snapshot is not exact gets one copy per evaluation (joint, side) instead of one per
  // thread, so that what it keeps of its last evaluation does not depend on the thread count.
  main_ = std::make_unique<World>(model, initial, make, false, armature);
  captureHolds(pres_, main_->data.qpos());
  pool_ = std::make_unique<fluid::WorkerPool>(p_.threads);
  const int n = int(p_.controlled.size());
  const int copies = main_->coupling->exactSnapshot() ? fluid::threadPieceCount(pool_.get()) : 2 * n;
  for (int k = 0; k < copies; ++k)
    workers_.push_back(std::make_unique<World>(model, initial, make, p_.threads > 1, armature));
  direction_.assign(n, 0.0);
  derivative_.assign(n, 0.0);
  frame_force_.assign(n, Vec3{});
  senses_ = p_.senses;
}

FluidController::~FluidController() = default;

rigid::RigidData& FluidController::data() { return main_->data; }
const CoupledFluid& FluidController::coupledFluid() const { return *main_->coupling; }
const coupling::RigidFluidCoupling& FluidController::coupling() const {
  const auto* planar = dynamic_cast<const CoupledFluid2*>(main_->coupling.get());
  if (!planar) throw std::logic_error("FluidController::coupling(): the fluid is not the planar one");
  return planar->coupling();
}

FluidController::World& FluidController::evaluationWorld(int part, int joint, double offset_rad) {
  if (main_->coupling->exactSnapshot()) return *workers_[part];
  return *workers_[2 * joint + (offset_rad > 0 ? 1 : 0)];
}

// One coupled step (rigid_fluid_coupling.hpp): fluid to u~, the solid to x^{n+1} with the servo
// reaching pr's targets under the fluid's last reaction, forcing at x^{n+1}, projection. With the 3-D
// coupled solve (Eq. 9) the servo steps without the fluid's force and the forcing gives the DOFs the
// servo does not prescribe this step's fluid impulse.
void FluidController::coupledStep(World& w, const Prescribed& pr) {
  const double dt = model_.timestep_s();
  w.coupling->advanceFluid(dt);
  const ServoReport s = advanceFrame(w.data, pr, w.force, 1, p_.servo_iterations, p_.servo_tolerance_rad, w.servo);
  w.residual_rad = std::max(w.residual_rad, s.residual_rad);
  w.data.kinematics();
  if (w.coupling->coupledSolve()) {
    prescribedDofs(pr, w.held_dofs);
    w.coupling->forceAndCorrect(w.data, dt, w.held_dofs);
  } else {
    w.coupling->forceAndProject(w.data, dt);
  }
  w.forcing_iterations = std::max(w.forcing_iterations, w.coupling->forcingIterations());
  const auto& body = w.coupling->bodyForce_n();
  for (std::size_t b = 1; b < body.size(); ++b)
    for (int k = 0; k < 3; ++k) w.bodies_force_sum[k] += body[b][k];
}

Vec3 FluidController::jointForce(const World& w, int joint) const {
  Vec3 f{};
  const auto& body =
      f_.objective_force == ObjectiveForce::flesh_on_bone ? w.coupling->boneForce_n() : w.coupling->bodyForce_n();
  for (int b = 0; b < int(body.size()); ++b)
    if (f_.creature_force ? b > 0 : layout_.moves[joint][b])
      for (int k = 0; k < 3; ++k) f[k] += body[b][k];
  return f;
}

// Eq. 1's actuator torque of each controlled joint after a coupled step: inverse dynamics at
// qacc = 0 under the fluid's reaction of that step (objectives.hpp, measure), appended to `out`.
void FluidController::jointTorques(World& w, std::vector<double>& out) const {
  measure(w.data, layout_, w.measured, w.measure_scratch, w.measures);
  out.insert(out.end(), w.measures.torque_n_m.begin(), w.measures.torque_n_m.end());
}

// `steps` coupled steps with the prescribed angles moving linearly from `start` to pr's targets;
// the joints' forces and actuator torques of each step appended to w.forces and w.torques
// (joint-major: step s, joint j at s n + j) when `record`.
void FluidController::moveOver(World& w, Prescribed& pr, const std::vector<double>& start, int steps, bool record) {
  const int n = int(p_.controlled.size());
  w.step = pr;
  for (int s = 0; s < steps; ++s) {
    const double a = double(s + 1) / steps;
    for (std::size_t k = 0; k < start.size(); ++k) w.step.target[k] = start[k] + a * (pr.target[k] - start[k]);
    coupledStep(w, w.step);
    if (!record) continue;
    for (int j = 0; j < n; ++j) w.forces.push_back(jointForce(w, j));
    jointTorques(w, w.torques);
  }
}

void FluidController::save(World& w, CoupledState& s) const {
  s.rigid = w.data.save();
  w.coupling->save(s.fluid);
}

void FluidController::restore(World& w, const CoupledState& s) const {
  w.data.restore(s.rigid);
  w.data.kinematics();
  w.coupling->restore(*s.fluid, w.data);
}

// Perturbation::placed: pr's held joints (those without a pattern) set to their targets at rest
// relative to their parents, the markers placed at the new pose without a step.
void FluidController::place(World& w, const Prescribed& pr) const {
  for (std::size_t k = 0; k < pr.qpos.size(); ++k) {
    if (pr.pattern[k]) continue;
    w.data.qpos()[pr.qpos[k]] = pr.target[k];
    w.data.qvel()[pr.dof[k]] = 0.0;
  }
  w.data.kinematics();
  w.coupling->placeMarkers(w.data);
}

namespace {
// Joint j's objective from its mean force f and mean actuator torque (Eq. 1: effort is the
// angular impulse |torque| x frame).
double objectiveOf(const ObjectiveLayout& l, int j, const Vec3& f, double torque_n_m) {
  switch (l.kinds[j]) {
    case Objective::effort: return std::abs(torque_n_m) * l.frame_s;
    case Objective::drag: return std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    case Objective::drag_along: break;
  }
  return f[0] * l.direction[0] + f[1] * l.direction[1] + f[2] * l.direction[2];
}
}  // namespace

// (d, e) in the fluid: joint i moved by offset over one frame of coupled steps from its own copy
// of the state, held for settle_steps; the force along w averaged over the last average_steps.
double FluidController::evaluate(World& w, const CoupledState& start, int joint, double offset) {
  restore(w, start);
  perturbation(pres_, model_, start.rigid.qpos.data(), joint, offset, w.pr);
  std::vector<double> from(w.pr.qpos.size());
  for (std::size_t k = 0; k < from.size(); ++k) from[k] = start.rigid.qpos[w.pr.qpos[k]];
  const int n = int(p_.controlled.size());
  w.forces.clear();
  w.torques.clear();
  if (f_.perturbation == Perturbation::placed) {
    place(w, w.pr);
    std::vector<double> held(w.pr.target.begin(), w.pr.target.end());
    moveOver(w, w.pr, held, p_.substeps + f_.settle_steps, true);
  } else {
    moveOver(w, w.pr, from, p_.substeps, true);
    if (f_.settle_steps > 0) {
      std::vector<double> held(w.pr.target.begin(), w.pr.target.end());
      moveOver(w, w.pr, held, f_.settle_steps, true);
    }
  }
  const int steps = int(w.forces.size()) / n;
  std::vector<double> objective(n);
  for (int j = 0; j < n; ++j) {
    Vec3 f{};
    double torque = 0;
    for (int s = steps - f_.average_steps; s < steps; ++s) {
      for (int k = 0; k < 3; ++k) f[k] += w.forces[s * n + j][k] / f_.average_steps;
      torque += w.torques[s * n + j] / f_.average_steps;
    }
    objective[j] = objectiveOf(layout_, j, f, torque);
  }
  return combined(p_.weights, objective, joint);
}

double FluidController::evaluate(int joint, double offset_rad) {
  CoupledState s;
  save(*main_, s);
  return evaluate(evaluationWorld(0, joint, offset_rad), s, joint, offset_rad);
}

std::vector<double> FluidController::derivatives() {
  CoupledState start;
  save(*main_, start);
  auto g = centralDifferences(
      pool_.get(), int(p_.controlled.size()), p_.delta_rad, p_.one_sided,
      [&](int part, int joint, double offset) {
        return evaluate(evaluationWorld(part, joint, offset), start, joint, offset);
      },
      "while perturbing a joint in the fluid");
  for (const auto& w : workers_) max_forcing_iterations_ = std::max(max_forcing_iterations_, w->forcing_iterations);
  return g;
}

void FluidController::hold(int steps) {
  World& w = *main_;
  w.pr = pres_.prescribed;
  for (std::size_t k = 0; k < w.pr.qpos.size(); ++k)
    if (!w.pr.pattern[k]) w.pr.target[k] = w.data.qpos()[w.pr.qpos[k]];
  for (int s = 0; s < steps; ++s) coupledStep(w, w.pr);
}

FrameRecord FluidController::frame() {
  const int n = int(p_.controlled.size());
  World& w = *main_;
  FrameRecord r;
  // §7.1: the sense of the stroke at the frame's middle.
  const double mid_s = w.data.time_s() + 0.5 * p_.frame_s;
  // Without a stroke, the given senses (setSenses: the swimmer's phases, §7.2).
  for (int i = 0; i < n; ++i)
    senses_[i] = f_.stroke.empty() ? p_.senses[i]
                                   : senseAt(p_.senses[i], strokePattern(f_.stroke[i], p_), f_.stroke[i].sign, mid_s);
  // Strength 0 holds the controlled joints (the "controller off" case of §7.1's comparison): no search.
  if (frame_ % p_.search_every_frames == 0 && p_.strength_rad_per_s > 0) {
    derivative_ = derivatives();
    r.searched = true;
  }
  for (int i = 0; i < n; ++i) {
    const double sign = derivative_[i] > 0 ? 1.0 : derivative_[i] < 0 ? -1.0 : 0.0;
    direction_[i] = senses_[i] == Sense::minimize ? -sign : sign;
  }
  const double step_rad = p_.strength_rad_per_s * p_.frame_s;
  std::vector<double> from(pres_.prescribed.qpos.size());
  for (std::size_t k = 0; k < from.size(); ++k) from[k] = w.data.qpos()[pres_.prescribed.qpos[k]];
  for (int i = 0; i < n; ++i) {
    const double t = clampToRange(pres_.controlled[i], from[i] + step_rad * direction_[i]);
    pres_.prescribed.target[i] = f_.limit_rad > 0 ? std::clamp(t, -f_.limit_rad, f_.limit_rad) : t;
  }
  w.residual_rad = 0;
  w.bodies_force_sum = Vec3{};
  w.forces.clear();
  w.torques.clear();
  moveOver(w, pres_.prescribed, from, p_.substeps, true);
  for (int k = 0; k < 3; ++k) frame_bodies_force_[k] = w.bodies_force_sum[k] / p_.substeps;
  r.time_s = w.data.time_s();
  r.servo_residual_rad = w.residual_rad;
  r.target_rad.assign(pres_.prescribed.target.begin(), pres_.prescribed.target.begin() + n);
  for (int i = 0; i < n; ++i) r.angle_rad.push_back(w.data.qpos()[pres_.prescribed.qpos[i]]);
  r.derivative = derivative_;
  // The frame's mean force on each joint's bodies (the coupled steps' exchange) and mean actuator torque.
  JointMeasures& m = r.measures;
  m.torque_n_m.assign(n, 0.0);
  m.effort_n_m_s.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    Vec3 f{};
    for (int s = 0; s < p_.substeps; ++s) {
      for (int k = 0; k < 3; ++k) f[k] += w.forces[s * n + i][k] / p_.substeps;
      m.torque_n_m[i] += w.torques[s * n + i] / p_.substeps;
    }
    m.effort_n_m_s[i] = std::abs(m.torque_n_m[i]) * p_.frame_s;
    frame_force_[i] = f;
    m.drag_vector_n.push_back(f);
    m.drag_n.push_back(std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
    m.drag_along_n.push_back(f[0] * layout_.direction[0] + f[1] * layout_.direction[1] + f[2] * layout_.direction[2]);
    m.objective.push_back(objectiveOf(layout_, i, f, m.torque_n_m[i]));
  }
  for (int i = 0; i < n; ++i) r.objective.push_back(combined(p_.weights, m.objective, i));
  max_forcing_iterations_ = std::max(max_forcing_iterations_, w.forcing_iterations);
  ++frame_;
  return r;
}

void FluidController::setSenses(const std::vector<Sense>& senses) {
  if (senses.size() != p_.controlled.size())
    throw std::invalid_argument("senses: one per controlled joint (" + std::to_string(p_.controlled.size()) + ")");
  p_.senses = senses;
}

}  // namespace creaturelab::control
