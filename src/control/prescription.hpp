#pragma once
// The prescribed joints of a controller (Lentine et al. 2010 §2.2, §5), shared by the wind and the
// fluid controllers: the
// controlled joints first, in order, then the kinematic ones (each a slot in Prescribed: scalar
// for hinges and slides, a quaternion for ball joints), the PD drives, the controlled DOFs (a ball
// joint has three, about its body's axes), and per controlled joint the passive joints outboard of
// it (PD-driven ones too), held rigid with it while it is perturbed (§5).
#include <vector>

#include "control/controller_params.hpp"
#include "control/target_servo.hpp"

namespace creaturelab::control {

struct Slot {
  int qpos = 0, dof = 0, index = 0;  // index: into Prescribed's scalars or balls
  bool ball = false;
  // The joint's MJCF range (rigid::JointInfo): hinge [lo, hi] rad; ball: rotation angle up to hi.
  bool limited = false;
  double lo = 0, hi = 0;
};

// A controlled joint's target kept within its range, so that the servo, which reaches any target
// "irrespective of all external forces" (§2.2), never drives a joint past its anatomical limit: a
// hinge's angle clamped to [lo, hi]; a ball's rotation vector log(q) shortened to the angle hi,
// its axis kept. Unlimited joints' targets pass unchanged.
double clampToRange(const Slot& s, double target_rad);
rigid::Quat clampToRange(const Slot& s, const rigid::Quat& target);

struct Prescription {
  Prescribed prescribed;
  std::vector<Slot> controlled, kinematic;
  std::vector<int> dof_joint, dof_axis;  // per controlled DOF: its joint, its axis (ball: 0-2)
  std::vector<std::vector<int>> holds;   // per controlled joint: joint ids held with it
};

// p must pass p.validate(model) and outlive the result (the patterns are pointed at).
Prescription prescription(const ControllerParams& p, const rigid::RigidModel& model);

// The poses the kinematic and PD joints without a moving pattern hold: those in qpos.
void captureHolds(Prescription& pr, const double* qpos);

// pr = base's prescription for evaluating controlled DOF `dof` moved by offset_rad from qpos, within
// its joint's range (at a limit the probe past it stays on it, so the difference sees only poses the
// joint can take): the other controlled joints and the kinematic ones without a pattern held where
// they are in qpos, kinematic patterns going on, the DOF's joint's outboard joints held (and their PD
// drives off).
void perturbation(const Prescription& base, const rigid::RigidModel& model, const double* qpos, int dof,
                  double offset_rad, Prescribed& pr);

rigid::Quat quatAt(const double* qpos, int address);

}  // namespace creaturelab::control
