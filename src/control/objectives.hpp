#pragma once
// The objectives of Lentine et al. 2010 evaluated at a
// state: effort F_e (§2.3, Eq. 1), drag F_d (§3.2, Eq. 3) and directional drag (Eq. 4) per
// controlled joint, then each joint's weighted average (§5).
#include <vector>

#include "control/controller_params.hpp"
#include "control/force_model.hpp"

namespace creaturelab::control {

// Per controlled joint: the quantities its objective may use, at one state.
struct JointMeasures {
  std::vector<double> torque_n_m;   // actuator torque that keeps the current velocities (qacc = 0);
                                    // a ball joint: the magnitude of its three
  std::vector<double> effort_n_m_s; // |torque| x frame: the angular impulse of Eq. 1
  std::vector<double> drag_n;       // |F_d| over the bodies the joint moves (Eq. 3)
  std::vector<double> drag_along_n; // w . F_d over the same bodies (Eq. 4)
  std::vector<Vec3> drag_vector_n;  // F_d itself
  std::vector<double> objective;    // F_j of the joint's own objective kind
};

// What the objectives need from the model, fixed once: each controlled joint's dof and which
// bodies it moves.
struct ObjectiveLayout {
  std::vector<int> dof;                   // per controlled joint: its first dof
  std::vector<int> ndof;                  // 1 (hinge) or 3 (ball)
  std::vector<std::vector<char>> moves;   // [joint][body]: body outboard of the joint
  std::vector<Objective> kinds;
  Vec3 direction{1, 0, 0};                // unit drag_direction
  double frame_s = 0;
  bool steady_state = false;
};

ObjectiveLayout makeLayout(const ControllerParams& p, const rigid::RigidModel& model);

// Scratch per thread.
struct MeasureScratch {
  std::vector<Vec3> body_force_n;
  std::vector<double> zero, torque;
};

// Evaluates every joint's measures at data's state. With steady_state the shape is frozen first
// (§3.3, RigidData::freezeShape: "setting the object velocities to zero before calculating F_d"
// for a creature rooted in a stationary object; for a free creature the relative joint
// velocities zeroed with its momentum kept), which changes data. The force stage is applied to data as it would be in a step.
void measure(rigid::RigidData& data, const ObjectiveLayout& layout, const ForceModel& force, MeasureScratch& s,
             JointMeasures& out);

// Joint i's objective value: sum_j w_ij F_j (identity weights when `weights` is empty).
double combined(const std::vector<std::vector<double>>& weights, const std::vector<double>& objective, int i);

}  // namespace creaturelab::control
