#pragma once
// What the controller kinds (control: simple wind, issue 15; control_fluid: the full fluid, issue
// 16) read the same way: the controller's text parameters, initial angles, and the converged
// frame of Lentine et al. 2010 Fig. 2 (seeds/creature-control-lentine-2010.txt).
#include <string>
#include <utility>
#include <vector>

#include "control/controller_params.hpp"
#include "kinds/params.hpp"

namespace creaturelab::kinds::control_text {

std::string trim(const std::string& s);
std::vector<std::string> split(const std::string& s, char sep);
// Throws std::invalid_argument "what: 'text' is not a number".
double number(const std::string& text, const std::string& what);

// model_file with gravity_m_per_s2 (along -z) and the step frame_s / substeps.
rigid::RigidModel loadModel(const ParamReader& r);

// controlled, kinematic, objectives, senses, weights, drag_direction_*, frame_s, substeps,
// strength_rad_per_s, delta_rad, one_sided, search_every_frames, rigidify_outboard, threads.
// Throws std::invalid_argument naming the parameter.
control::ControllerParams controllerParams(const ParamReader& r);

// "joint=deg, joint=deg" -> (joint, degrees).
std::vector<std::pair<std::string, double>> initialAngles(const ParamReader& r);

// Angle (deg) between two lines (not directions): in [0, 90].
double lineAngleDeg(const control::Vec3& a, const control::Vec3& b);

// The frame from which every controlled angle stays within tol of its mean over the last `tail`
// frames; frames + 1 if the last frame is not yet settled.
double convergedFrame(const std::vector<std::vector<double>>& angles_deg, double tol_deg, int tail);

}  // namespace creaturelab::kinds::control_text
