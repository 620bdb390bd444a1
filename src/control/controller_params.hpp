#pragma once
// Parameters of the creature controller (Lentine et al. 2010 §2-3, §5;
// "Creature Control in a Fluid Environment"). Plain data with defaults; validate() against the
// model says what is wrong in words a user understands.
#include <string>
#include <vector>

#include "control/pattern.hpp"
#include "rigid/rigid_model.hpp"

namespace creaturelab::control {

using rigid::Vec3;

// What a controlled joint's objective measures (§2.3, §3.2):
//   effort      F_e: the angular impulse |tau| dt the actuator of the joint applies to keep the
//               current velocities (inverse dynamics at zero acceleration, Eq. 1), N m s;
//   drag        |F_d|, F_d = sum_i F_di over the triangles of the bodies the joint moves (Eq. 3), N;
//   drag_along  w . F_d over the same bodies (Eq. 4) with w = drag_direction; "lift" is this
//               with w pointing up, N.
enum class Objective { effort, drag, drag_along };
enum class Sense { minimize, maximize };

struct ControllerParams {
  // Joints the controller drives: hinges (one DOF) and ball joints (three DOFs, each perturbed
  // and stepped on its own axis of the body frame).
  std::vector<std::string> controlled;
  // Joints that follow a prescribed motion exactly whatever the load (the paper's kinematic legs):
  // hinges with a pattern each (empty = all hold their initial angle), ball joints held.
  std::vector<std::string> kinematic;
  std::vector<Pattern> kinematic_patterns;
  // Hinges PD-driven to a pattern (§2.2: "PD targets ... can be pre-specified"): they yield to loads.
  std::vector<std::string> pd_driven;
  std::vector<Pattern> pd_patterns;  // one per pd_driven joint
  double pd_kp_n_m_per_rad = 200;
  double pd_kd_n_m_s_per_rad = 10;
  // Per controlled joint j: its objective F_j and sense.
  std::vector<Objective> objectives;
  std::vector<Sense> senses;
  // weights[i][j]: joint i descends sum_j weights[i][j] F_j (§5's weighted average; the weights
  // carry the unit conversion between N m s and N). Empty = identity (each joint its own). One
  // row and column per controlled joint: a ball joint counts once (its three axes share its objective).
  std::vector<std::vector<double>> weights;
  Vec3 drag_direction{1, 0, 0};

  double frame_s = 1.0 / 60;        // one controller step (a frame); the paper's Fig. 2 counts frames
  int substeps = 1;                 // MuJoCo steps per frame; targets are reached at every substep
  double strength_rad_per_s = 1.0;  // largest joint angle change per second (§2.1: fixed step = strength)
  double delta_rad = 0.01;          // perturbation of each central difference (§2.1, Fig. 3)
  bool one_sided = false;           // forward difference; off by default (§2.1: biased)
  int search_every_frames = 1;      // re-determine the direction only every k frames (§2.1)
  bool steady_state = false;        // §3.3: shape frozen (RigidData::freezeShape) before evaluating
  bool rigidify_outboard = true;    // §5: bodies outboard of a perturbed joint held with it
  int threads = 1;                  // per-DOF evaluations in parallel (§5, Fig. 10)
  int servo_iterations = 8;         // Newton iterations of the target servo per substep
  double servo_tolerance_rad = 1e-10;
  // Test only: false skips the servo's projection of its last residual (post-stabilisation, §2.2), so
  // that a test sees the kinematic joints leave their patterns (tests/cli/control_checks_fail.sh).
  bool servo_projection = true;

  // "" when these fit the model, else what is wrong (joint names, lengths, ranges).
  std::string validate(const rigid::RigidModel& model) const;
};

std::string toString(Objective o);
std::string toString(Sense s);

}  // namespace creaturelab::control
