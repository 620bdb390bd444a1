#pragma once
// The servo that moves prescribed joints to their targets "irrespective of all external forces"
// (Lentine et al. 2010 §2.2; the paper uses the
// post-stabilisation projections of Weinstein et al. 2008). Here: over each MuJoCo step the
// prescribed angles must land exactly on their targets while every other degree of freedom
// moves under the full dynamics (gravity, wind, contacts, the reaction of the prescribed
// torques). The generalized forces tau_P on the prescribed DOFs that do this solve
//     q_P(t + h; tau_P) = target_P,
// by Newton's method: q_P(t+h) = q_P + h qdot_P + h^2 qacc_P with qacc = M^-1 (... + tau), so the
// Jacobian is h^2 (M^-1)_PP, exact without contacts and damping (one iteration, then a check);
// contacts and implicit joint damping only make it approximate, and the iteration goes on until
// the residual is below a tolerance. The remaining residual (reported) is then projected away,
// which is the post-stabilisation of the paper. The torques tau_P are the PD impulses of §2.2
// over the step (tau_P h), recorded as the servo's work.
#include <vector>

#include "control/force_model.hpp"
#include "control/pattern.hpp"
#include "rigid/rotation.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::control {

// Prescribed joints and where they go over a frame. Hinges and slides (one qpos, one dof): the
// angle at the end of the frame, reached linearly over the substeps, or, when a pattern is given,
// the pattern's angle at the end of every substep. Ball joints (four qpos, three dofs): the
// quaternion at the end of the frame, reached along the shortest rotation (slerp).
struct PrescribedBall {
  int qpos = 0, dof = 0;
  rigid::Quat target{1, 0, 0, 0};
};

// A joint driven towards a pattern by PD torques (§2.2), not prescribed: it yields to loads.
// tau = kp (pattern(t + h) - q) + kd (pattern'(t + h) - qdot), explicit at each substep's start.
struct PdDrive {
  int qpos = 0, dof = 0;
  const Pattern* pattern = nullptr;
  double hold_rad = 0;  // the angle a hold pattern keeps
  double kp_n_m_per_rad = 0, kd_n_m_s_per_rad = 0;
};

struct Prescribed {
  std::vector<int> qpos, dof;
  std::vector<double> target;             // angle at the end of the frame, rad
  std::vector<const Pattern*> pattern;    // empty, or per scalar joint: nullptr or its pattern
  std::vector<PrescribedBall> balls;
  std::vector<PdDrive> pd;
};

struct ServoReport {
  double residual_rad = 0;  // largest |q - target| (ball: rotation angle) before the final projection
  int iterations = 0;       // most Newton iterations any substep needed
};

// Scratch of one servo (per thread): reused between frames so that a frame does not allocate.
struct ServoScratch {
  std::vector<Vec3> body_force_n;
  std::vector<double> base_force, start, goal, tau, residual, jacobian;
  std::vector<rigid::Quat> ball_start, ball_goal;
  std::vector<int> unknown_dof;
};

// Advances `data` one frame of `substeps` MuJoCo steps: the prescribed angles move linearly from
// where they are to their targets (or follow their patterns), reaching each substep's goal exactly;
// PD-driven joints get their torques; `force` is evaluated at
// the start of every substep (explicit). `project` false skips stage 3, the projection of the residual
// (test only: the prescribed joints then end where the Newton iteration left them). Throws std::runtime_error when the state stops being
// finite (a diverging model) or MuJoCo warns of a bad acceleration.
ServoReport advanceFrame(rigid::RigidData& data, const Prescribed& p, const ForceModel& force, int substeps,
                         int max_iterations, double tolerance_rad, ServoScratch& scratch, bool project = true);

}  // namespace creaturelab::control
