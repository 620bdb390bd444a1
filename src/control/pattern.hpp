#pragma once
// A prescribed motion pattern for a joint that is not controlled (Lentine et al. 2010 §2.2, §7:
// "other joints may be kinematic ... or PD-driven to a given pattern"; the paper's legs follow
// motion capture). Angles in rad of absolute simulation time in s.
#include <string>
#include <vector>

namespace creaturelab::control {

struct Pattern {
  // hold: the joint's angle when the run starts; sine: mean + amplitude sin(2 pi f t + phase);
  // table: piecewise linear through (time_s, angle_rad), held before the first and after the last
  // point (a cyclic motion is a sine, or a table as long as the run).
  enum class Kind { hold, sine, table };
  Kind kind = Kind::hold;
  double mean_rad = 0, amplitude_rad = 0, frequency_hz = 0, phase_rad = 0;
  std::vector<double> time_s, angle_rad;

  double angle(double t_s, double hold_rad) const;
  double rate(double t_s) const;  // d angle / dt, rad/s (0 for hold)
  // "" when the pattern is usable, else what is wrong (for a message that names the key).
  std::string validate() const;
};

}  // namespace creaturelab::control
