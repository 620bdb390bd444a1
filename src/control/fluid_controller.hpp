#pragma once
// The creature controller of Lentine et al. 2010 in the full fluid (§4.3, §5, §6;
// "Creature Control in a Fluid Environment"): Controller's frame (controller.hpp) with the
// simple wind replaced by a two-way coupled fluid (coupled_fluid.hpp: the planar fluid of src/coupling/
// or the 3-D one of src/coupling3d/):
//   - a derivative evaluation restores its own copy of the whole state (bodies and fluid, §4.3:
//     "each perturbation needs its own copy of the fluid state"), moves the joint by +-delta over
//     one frame of stable coupled steps (the servo reaches the target at each step, the bodies
//     outboard held with it, §5), the markers moving with the pseudo-velocity
//     (delta position / delta time) of each step;
//   - optional validation mode (§4.3): settle_steps further coupled steps with the pose held, so
//     that the disturbance of the move is swept downstream;
//   - or (Perturbation::placed) §3.3's steady-state calculation: the pose set by +-delta without a
//     move (the markers placed there, the relative joint velocities zero), then the frame's
//     coupled steps and settle_steps with it held: the objective sees the pose, not the
//     pseudo-velocity of reaching it;
//   - the objective is the force the fluid exerts on the bodies the joint moves (creature_force:
//     on every body), from the coupling (its exchanged momentum; with flesh, objective_force may take
//     the force on the bones instead), resolved along w (Eq. 10, drag_along) or its magnitude (drag),
//     averaged over the evaluation's last average_steps coupled steps;
//   - the DOFs' evaluations run in parallel, each on its own worker's copy: results are bitwise
//     the same for any thread count (§5, Fig. 10).
//   - effort (Eq. 1): the actuator torque that holds the joint under the fluid's reaction
//     (inverse dynamics at qacc = 0, as in the wind), averaged like the force, times the frame.
#include <memory>
#include <vector>

#include "control/controller.hpp"
#include "control/coupled_fluid.hpp"
#include "control/prescription.hpp"
#include "control/stroke_sense.hpp"
#include "coupling/rigid_fluid_coupling.hpp"

namespace creaturelab::control {

// How a derivative evaluation reaches the perturbed pose. moved: over one frame of coupled steps,
// the markers carrying the pseudo-velocity (§4.3); placed: set at once, the markers placed there
// without a velocity (§3.3's "relative joint velocities" projected out, on the fluid's state).
enum class Perturbation { moved, placed };

// Which force on a body the objective reads. fluid_on_flesh: the fluid's on the body's surface (with flesh its
// flesh, §4.3 Eq. 10's integral over "the surface of the creature") and interior; flesh_on_bone: the force its
// bone takes, the flesh's binding reaction plus the fluid's on its interior (CoupledFluid::boneForce_n), which
// differs by the flesh's rate of change of momentum. Without flesh the two are the same.
enum class ObjectiveForce { fluid_on_flesh, flesh_on_bone };

struct FluidControlParams {
  Perturbation perturbation = Perturbation::moved;
  // The objective's force: false, on the bodies the joint moves; true, on the whole creature
  // (every body but the world; §7.1: "maximize drag (F_d) on the body").
  bool creature_force = false;
  ObjectiveForce objective_force = ObjectiveForce::fluid_on_flesh;
  int settle_steps = 0;   // §4.3 validation mode: coupled steps with the pose held after the move
  int average_steps = 1;  // the objective: mean force over an evaluation's last this many steps
  // §7.1: per controlled joint, the inboard pattern whose stroke flips its sense (empty: fixed senses).
  std::vector<StrokeFollow> stroke;
  // Controlled angles kept within +-this (0: no limit). The paper gives no joint range; without one
  // the flyer's outer wings fold back over the body (flyer.toml).
  double limit_rad = 0;
  // Added-mass stabilisation of free bodies (the swimmer, §7.2): the armature A of a DOF that no
  // joint prescribes is taken as an estimate of the fluid's added mass on it, and the fluid's lagged
  // force gets A a^n (a^n: the DOF's last acceleration) added, so the solid integrates
  // (M + A) a^{n+1} = F^n + A a^n. The explicit (staggered) step with the fluid force of the last
  // step, F^n ~ F - m_a a^n, has the amplification -m_a / M per step and blows up for M < m_a
  // (added-mass instability, Causin, Gerbeau & Nobile 2005, CMAME 194; Förster, Wall & Ramm 2007,
  // CMAME 196); with A it is (A - m_a) / (M + A), stable for m_a < M + 2A. The change to the
  // dynamics, A (a^{n+1} - a^n), is first order in the step (swimmer.toml's convergence runs).
  bool armature_added_mass = false;
  // The fluid is planar (x-z, src/coupling/): prescribed joints must be hinges. False for the 3-D fluid.
  bool planar_fluid = true;

  // "" when usable with the controller's parameters p (p.validate(model) first) and the model,
  // else what is wrong.
  std::string validate(const ControllerParams& p, const rigid::RigidModel& model) const;
};

// The state of a coupled creature: bodies and fluid.
struct CoupledState {
  rigid::RigidState rigid;
  std::unique_ptr<FluidSnapshot> fluid;
};

class FluidController {
 public:
  // `model` (time step = frame_s / substeps, the coupled step) must outlive the controller.
  // Initial angles are set before the fluid sees the bodies (the markers start there).
  FluidController(const rigid::RigidModel& model, ControllerParams p, FluidControlParams f,
                  const std::vector<std::pair<std::string, double>>& initial_rad, const fluid::FluidParams& fluid,
                  const coupling::RigidFluidParams& coupling);
  // The same over any coupled fluid: `make` builds the main copy and each evaluation's.
  FluidController(const rigid::RigidModel& model, ControllerParams p, FluidControlParams f,
                  const std::vector<std::pair<std::string, double>>& initial_rad, const CoupledFluidFactory& make);
  ~FluidController();

  FrameRecord frame();
  // Coupled steps with every prescribed joint held (e.g. to let the flow develop before control).
  void hold(int steps);

  std::vector<double> derivatives();
  // Joint i's objective after a perturbation by offset_rad (as the derivative sees it).
  double evaluate(int joint, double offset_rad);

  rigid::RigidData& data();
  // The planar coupling (throws std::logic_error over another fluid).
  const coupling::RigidFluidCoupling& coupling() const;
  const CoupledFluid& coupledFluid() const;
  const ControllerParams& params() const { return p_; }
  // Mean force of the last frame on the bodies each controlled joint moves (N, world).
  const std::vector<Vec3>& frameForce_n() const { return frame_force_; }
  int maxForcingIterations() const { return max_forcing_iterations_; }
  // Mean force of the last frame on all the creature's bodies (world body excluded; N, world).
  const Vec3& frameBodiesForce_n() const { return frame_bodies_force_; }
  // The senses the last frame descended with (§7.1: they follow the stroke when f.stroke is set).
  const std::vector<Sense>& frameSenses() const { return senses_; }
  // Replaces the controlled joints' senses from the next search on (the swimmer's phases, §7.2).
  void setSenses(const std::vector<Sense>& senses);
  // Replaces the strength (rad/s) from the next frame on (the swimmer's power and recovery strokes).
  void setStrength(double rad_per_s) { p_.strength_rad_per_s = rad_per_s; }

 private:
  struct World;
  void coupledStep(World& w, const Prescribed& pr);
  void moveOver(World& w, Prescribed& pr, const std::vector<double>& start, int steps, bool record);
  void place(World& w, const Prescribed& pr) const;
  void jointTorques(World& w, std::vector<double>& out) const;
  double evaluate(World& w, const CoupledState& start, int joint, double offset_rad);
  void save(World& w, CoupledState& s) const;
  void restore(World& w, const CoupledState& s) const;
  Vec3 jointForce(const World& w, int joint) const;
  // The copy an evaluation of joint at offset runs in, on thread piece `part`.
  World& evaluationWorld(int part, int joint, double offset_rad);

  const rigid::RigidModel& model_;
  ControllerParams p_;
  FluidControlParams f_;
  ObjectiveLayout layout_;
  Prescription pres_;  // the frame's targets live in pres_.prescribed
  std::vector<double> direction_, derivative_;
  std::unique_ptr<World> main_;
  std::vector<std::unique_ptr<World>> workers_;
  std::unique_ptr<fluid::WorkerPool> pool_;
  std::vector<Vec3> frame_force_;
  Vec3 frame_bodies_force_{};
  std::vector<Sense> senses_;
  long frame_ = 0;
  int max_forcing_iterations_ = 0;
};

}  // namespace creaturelab::control
