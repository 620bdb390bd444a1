#pragma once
// What the controller kinds (control: simple wind, issue 15; control_fluid: the full fluid, issue
// 16) read and measure the same way: the text parameters parsed into controller parameters (joint
// lists, objectives, weights, initial poses, the motion patterns of kinematic and PD-driven joints,
// Lentine et al. 2010 §2.2; the flyer's stroke senses and flap period, §7.1), the model, and the copy of a
// run's measures (control/run_measures.hpp) into the Result
// (M. Lentine et al., "Creature Control in a Fluid Environment"). Every parse error throws std::invalid_argument naming
// the key.
#include <string>
#include <utility>
#include <vector>

#include "control/controller_params.hpp"
#include "control/run_measures.hpp"
#include "control/stroke_sense.hpp"
#include "kinds/params.hpp"
#include "kinds/result.hpp"

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

// "outer=inner, outer2=-inner2" (the driven flyer, Lentine et al. 2010 §7.1): per controlled joint (in
// `controlled` order) the inboard joint whose pattern's stroke flips its sense; "+" (default) = the
// given sense while that joint's angle increases, "-" = while it decreases. Joints not named keep their
// sense; "" = none. Throws std::invalid_argument naming stroke_sense for a malformed entry or a joint
// not controlled.
std::vector<control::StrokeFollow> parseStrokeSense(const std::string& text, const std::vector<std::string>& controlled);

// Frames in one flap period: period_s / frame_s rounded; throws std::invalid_argument naming
// flap_period_s when that is not within 1e-6 of a whole number of frames (cycles would drift).
int framesPerCycle(double period_s, double frame_s);

// Copies a controller run's series (each the length of time_s) and measures into the Result.
void addSeries(Result& result, const control::SeriesSet& series);
void addMetrics(Result& result, const std::vector<control::NamedValue>& values);

}  // namespace creaturelab::kinds
