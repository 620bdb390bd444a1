#pragma once
// The `control` kind's text parameters parsed into controller parameters (issue 15): joint lists,
// objectives, weights, initial poses, and the motion patterns of kinematic and PD-driven joints
// (Lentine et al. 2010 §2.2). Every parse error throws std::invalid_argument naming the key.
#include <string>
#include <utility>
#include <vector>

#include "control/controller_params.hpp"
#include "kinds/params.hpp"

namespace creaturelab::kinds {

std::vector<std::string> splitList(const std::string& s, char sep);

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

}  // namespace creaturelab::kinds
