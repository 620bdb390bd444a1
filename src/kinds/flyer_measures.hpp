#pragma once
// What the driven flyer (Lentine et al. 2010 §7.1, Figs. 11-13; experiments/control/flyer.toml) adds to
// the control_fluid kind: the stroke each controlled joint's sense follows, read from a parameter, and
// the mean of a per-frame series over whole flap cycles (a mean over a part of a cycle would weigh up-
// and down-stroke unequally) and its standard error from the cycles' scatter.
#include <string>
#include <vector>

#include "control/stroke_sense.hpp"

namespace creaturelab::kinds {

// "outer=inner, outer2=-inner2": per controlled joint (in `controlled` order) the inboard joint
// whose pattern's stroke flips its sense; "+" (default) = the given sense while that joint's angle
// increases, "-" = while it decreases. Joints not named keep their sense; "" = none. Throws
// std::invalid_argument naming stroke_sense for a malformed entry or a joint not controlled.
std::vector<control::StrokeFollow> parseStrokeSense(const std::string& text, const std::vector<std::string>& controlled);

// Frames in one flap period: period_s / frame_s rounded; throws std::invalid_argument naming
// flap_period_s when that is not within 1e-6 of a whole number of frames (cycles would drift).
int framesPerCycle(double period_s, double frame_s);

// Mean of the last `cycles` x `frames_per_cycle` values of v; NaN when v is shorter.
double lastCyclesMean(const std::vector<double>& v, int frames_per_cycle, int cycles);

// Standard error of lastCyclesMean from its cycles' means m_k: sqrt(sum (m_k - mean)^2 / (cycles - 1)) /
// sqrt(cycles), cycles taken as independent samples; NaN with fewer than two cycles or v shorter.
double lastCyclesStandardError(const std::vector<double>& v, int frames_per_cycle, int cycles);

}  // namespace creaturelab::kinds
