#pragma once
// A controlled joint's sense that follows the flap (Lentine et al. 2010 §7.1: "As the kinematically
// controlled inner wing joints push
// down, the outer joints governed by the controller maximize drag (F_d) on the body, and when the
// inner kinematic wing joints are moving upwards the controller works to minimize drag"). The
// stroke is read from the prescribed pattern of an inboard joint (PD-driven or kinematic): its
// rate's sign, times a sign that says which way of the angle is the down-stroke for that wing.
#include <string>
#include <vector>

#include "control/controller_params.hpp"

namespace creaturelab::control {

// Per controlled joint: the joint whose pattern gives the stroke ("" = the sense is fixed), and
// sign = +1 when that joint's angle increasing is the stroke of the given sense, -1 when its
// angle decreasing is.
struct StrokeFollow {
  std::string joint;
  double sign = 1.0;
};

// "" when every named joint is PD-driven or kinematic with a moving pattern (sine | table), else
// what is wrong. `follow` is empty (no joint follows a stroke) or one entry per controlled joint.
std::string validate(const std::vector<StrokeFollow>& follow, const ControllerParams& p);

// The pattern a follow entry reads (pd_driven first, then kinematic); nullptr when none.
const Pattern* strokePattern(const StrokeFollow& follow, const ControllerParams& p);

// The sense at time t_s: `given` while sign x rate > 0, the other while sign x rate < 0; `given`
// at the turning points (rate exactly 0) and when no pattern is followed.
Sense senseAt(Sense given, const Pattern* pattern, double sign, double t_s);

}  // namespace creaturelab::control
