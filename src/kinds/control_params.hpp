#pragma once
// What the controller kinds (control: simple wind, issue 15; control_fluid: the full fluid, issue
// 16) read and measure the same way: the text parameters parsed into controller parameters (joint
// lists, objectives, weights, initial poses, the motion patterns of kinematic and PD-driven joints,
// Lentine et al. 2010 §2.2), the model, and the converged frame of Fig. 2
// (M. Lentine et al., "Creature Control in a Fluid Environment"). Every parse error throws std::invalid_argument naming
// the key.
#include <string>
#include <utility>
#include <vector>

#include "control/controller_params.hpp"
#include "kinds/params.hpp"

namespace creaturelab::kinds {

std::vector<std::string> splitList(const std::string& s, char sep);

// model_file with gravity_m_per_s2 (along -z) and the step frame_s / substeps.
rigid::RigidModel loadModel(const ParamReader& r);

// Inserts the motion patterns' parameters that controllerParams reads (§2.2) right after the
// kind's `kinematic` parameter: kinematic_pattern, pd_driven, pd_pattern, pd_kp_n_m_per_rad,
// pd_kd_n_m_s_per_rad.
void addMotionPatternSpecs(std::vector<ParamSpec>& params);

// Every controller parameter but steady_state (the wind kind's own; the fluid has settle_steps).
control::ControllerParams controllerParams(const ParamReader& r);

// One initial pose: a hinge's angle (one value) or a ball joint's rotation vector (three), deg.
struct InitialPose {
  std::string joint;
  std::vector<double> deg;
};
// "joint=deg, ball=x y z"
std::vector<InitialPose> initialPoses(const ParamReader& r);

// "hold" | "sine(mean_deg, amplitude_deg, frequency_hz, phase_deg)" |
// "table(t_s angle_deg, t_s angle_deg, ...)"; `key` names the parameter in errors.
control::Pattern parsePattern(const std::string& text, const std::string& key);

// Angle (deg) between two lines (not directions): in [0, 90].
double lineAngleDeg(const control::Vec3& a, const control::Vec3& b);

// The mean of lines (not directions) as axial data: the principal axis of the orientation tensor
// sum u u^T of their unit vectors (Mardia & Jupp 2000 §9.2.3), returned as its angle (deg, in
// [0, 90]) to the line `reference`. Unlike the mean of folded angles it is not biased when the lines
// wander across the perpendicular or across the reference (a flat optimum at 90 or 0 degrees).
double meanLineAngleDeg(const std::vector<control::Vec3>& lines, const control::Vec3& reference);

// The frame from which every controlled angle stays within tol of its mean over the last `tail`
// frames; frames + 1 if the last frame is not yet settled (frames count from 1).
double convergedFrame(const std::vector<std::vector<double>>& angles_deg, double tol_deg, int tail);

}  // namespace creaturelab::kinds
