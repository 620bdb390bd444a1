#include "fish/swim_mc.hpp"

#include <cmath>
#include <stdexcept>

#include "fish/fish_measure.hpp"
#include "fish/fish_run.hpp"

namespace creaturelab::fish {

SwimCommand swimCommandForKnob(double s, double r_max) { return {s, s * r_max, s, s * r_max}; }

SpeedMap calibrateSwimMC(const FishModel& fish, const SolverParams& solver, const MotorParams& motor, double swim_s,
                         double warmup_s, double slowest_knob, int levels) {
  SpeedMap map;
  RunOptions quiet;
  quiet.frame_every_steps = 10;
  const std::vector<ScheduleItem> schedule = {{Action::swim, swim_s, 0.0}};
  for (int k = levels - 1; k >= 0; --k) {
    const double s = std::pow(slowest_knob, double(k) / double(levels - 1));
    MotorParams m = motor;
    m.swim = swimCommandForKnob(s, motor.r_max);
    const FishRecord rec = runSchedule(fish, solver, m, schedule, quiet);
    if (rec.blew_up) throw std::runtime_error("swim-MC calibration at s = " + std::to_string(s) + ": " + rec.blowup_cause);
    map.knob.push_back(s);
    map.speed_body_lengths_per_s.push_back(measureSwim(rec, fish.body_length_m, warmup_s).speed_body_lengths_per_s);
  }
  return map;
}

double knobForSpeed(const SpeedMap& map, double speed, std::string& error) {
  const auto& u = map.speed_body_lengths_per_s;
  for (size_t i = 1; i < u.size(); ++i)
    if (!(u[i] > u[i - 1])) {
      error = "the swim-MC's calibrated speed does not rise with its knob (s = " + std::to_string(map.knob[i]) + ")";
      return std::nan("");
    }
  if (u.empty() || !(speed >= u.front() && speed <= u.back())) {
    error = "requested speed " + std::to_string(speed) + " body lengths/s is outside the swim-MC's calibrated range [" +
            (u.empty() ? std::string("none") : std::to_string(u.front()) + ", " + std::to_string(u.back())) + "]";
    return std::nan("");
  }
  size_t i = 1;
  while (i + 1 < u.size() && speed > u[i]) ++i;
  const double w = (std::log(speed) - std::log(u[i - 1])) / (std::log(u[i]) - std::log(u[i - 1]));
  return std::exp(std::log(map.knob[i - 1]) + w * (std::log(map.knob[i]) - std::log(map.knob[i - 1])));
}

}  // namespace creaturelab::fish
