#pragma once
// The swim motor controller's speed map (thesis ch. 5: the swim-MC turns a desired speed into
// contraction amplitudes and rates). One knob s in (0, 1] sets both, alpha = s and r = s r_max, as
// the public reimplementation's SwimMC scales its amplitude and frequency by one speed factor. The
// map from s to speed is the fish's own: calibrateSwimMC swims the fish from rest at levels of s
// spaced evenly in log s from the slowest to 1 and measures each settled speed; knobForSpeed interpolates log s linearly in log speed
// between those levels. The controller claims the speeds between its slowest and fastest level.
#include <string>
#include <vector>

#include "fish/fish_model.hpp"
#include "fish/fish_solver.hpp"
#include "fish/motor.hpp"

namespace creaturelab::fish {

struct SpeedMap {
  std::vector<double> knob;                      // s, increasing
  std::vector<double> speed_body_lengths_per_s;  // the measured speed at each s
};

// alpha = s, r = s r_max on both swim segments.
SwimCommand swimCommandForKnob(double s, double r_max);

// Swims the fish for swim_s from rest at each of `levels` (>= 2) knobs s = slowest_knob^(k / (levels - 1)),
// k = levels - 1 ... 0, and measures the speed from warmup_s to the end (measureSwim). A level that
// blows up throws std::runtime_error naming it.
SpeedMap calibrateSwimMC(const FishModel& fish, const SolverParams& solver, const MotorParams& motor, double swim_s,
                         double warmup_s, double slowest_knob, int levels);

// The knob whose interpolated speed is `speed`; "" or, in `error`, why not (outside the claimed
// range, or a map whose speed does not rise with s).
double knobForSpeed(const SpeedMap& map, double speed_body_lengths_per_s, std::string& error);

}  // namespace creaturelab::fish
