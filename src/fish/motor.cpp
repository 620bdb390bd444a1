#include "fish/motor.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace creaturelab::fish {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\n"), e = s.find_last_not_of(" \t\n");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// A triangle wave that starts at 0 at t = 0, rises at `slope` to `peak`, falls back, and repeats;
// 0 before t = 0.
double triangle(double t, double peak, double slope) {
  if (t <= 0 || peak <= 0) return 0;
  const double half = peak / slope, phase = std::fmod(t, 2 * half);
  return phase < half ? slope * phase : peak - slope * (phase - half);
}

}  // namespace

std::string actionName(Action a) {
  switch (a) {
    case Action::swim: return "swim";
    case Action::left: return "left";
    case Action::right: return "right";
    case Action::glide: return "glide";
  }
  return "?";
}

std::vector<ScheduleItem> parseSchedule(const std::string& text) {
  std::vector<ScheduleItem> out;
  std::stringstream all(text);
  std::string part;
  double start = 0;
  while (std::getline(all, part, ';')) {
    part = trim(part);
    if (part.empty()) continue;
    std::istringstream in(part);
    std::string name, extra;
    double duration = 0;
    in >> name;
    if (!(in >> duration) || (in >> extra))
      throw std::invalid_argument("schedule item \"" + part + "\": expected a controller name and a duration in seconds");
    Action a;
    if (name == "swim") a = Action::swim;
    else if (name == "left") a = Action::left;
    else if (name == "right") a = Action::right;
    else if (name == "glide") a = Action::glide;
    else throw std::invalid_argument("schedule item \"" + part + "\": unknown controller \"" + name +
                                     "\" (expected swim, left, right or glide)");
    if (!(duration > 0) || !std::isfinite(duration))
      throw std::invalid_argument("schedule item \"" + part + "\": the duration must be positive");
    out.push_back({a, duration, start});
    start += duration;
  }
  if (out.empty()) throw std::invalid_argument("schedule is empty (expected e.g. \"swim 10; left 3\")");
  return out;
}

double scheduleDurationS(const std::vector<ScheduleItem>& s) { return s.back().start_s + s.back().duration_s; }

double swimPeriodS(const MotorParams& p) {
  // Rest lengths cancel: height alpha (1 - f) l0 (twice that when antagonistic), slope r l0 / dt_ref
  // (alpha r l0 / dt_ref when the rate is the full stroke's).
  const double stroke = p.rate_reading == RateReading::full_stroke ? 1.0 : p.swim.amplitude_anterior;
  const double height = stroke * (1.0 - p.contracted_fraction) * (p.stroke == Stroke::antagonistic ? 2 : 1);
  return 2.0 * height / p.swim.rate_anterior * p.reference_step_s;
}

std::string MotorParams::validate() const {
  const MotorParams& p = *this;
  auto amp = [](const char* name, double a) {
    return a > 0 && a <= 1 ? std::string() : std::string(name) + " must be in (0, 1] (got " + std::to_string(a) + ")";
  };
  auto rate = [&](const char* name, double r) {
    return r > 0 && r <= p.r_max ? std::string()
                                 : std::string(name) + " must be in (0, r_max = " + std::to_string(p.r_max) +
                                       "] (got " + std::to_string(r) + ")";
  };
  for (const auto& m : {amp("swim_amplitude", p.swim.amplitude_anterior), amp("swim_amplitude", p.swim.amplitude_posterior),
                        amp("turn_amplitude", p.turn_amplitude), rate("swim_rate", p.swim.rate_anterior),
                        rate("swim_rate", p.swim.rate_posterior), rate("turn_rate", p.turn_rate)})
    if (!m.empty()) return m;
  if (!(p.contracted_fraction > 0 && p.contracted_fraction < 1))
    return "contracted_fraction must be in (0, 1) (got " + std::to_string(p.contracted_fraction) + ")";
  if (!(p.reference_step_s > 0)) return "reference_step_s must be positive";
  if (!std::isfinite(p.posterior_lag_rad)) return "posterior_lag_rad must be finite";
  if (!(p.turn_relax_fraction > 0 && p.turn_relax_fraction <= 1))
    return "turn_relax_fraction must be in (0, 1] (got " + std::to_string(p.turn_relax_fraction) + ")";
  return "";
}

MotorController::MotorController(const FishModel& fish, MotorParams params, std::vector<ScheduleItem> schedule)
    : fish_(fish), params_(params), schedule_(std::move(schedule)) {
  if (auto m = params_.validate(); !m.empty()) throw std::invalid_argument(m);
  if (schedule_.empty()) throw std::invalid_argument("schedule is empty");
  for (int k = 0; k < kMuscles; ++k) rest_m_[k] = fish.network.rest_length_m[fish.muscles[k].unit];
}

const ScheduleItem& MotorController::itemAt(double t) const {
  for (const auto& item : schedule_)
    if (t < item.start_s + item.duration_s) return item;
  return schedule_.back();
}

// The start of the run of swim and turn items that contains t's item: the swim wave runs on
// through a turn (the middle segment swims and turns) and across swim items, restarting only after
// a glide.
double MotorController::swimClockStart(const ScheduleItem& item) const {
  double start = 0;
  for (const auto& it : schedule_) {
    if (it.start_s >= item.start_s) break;
    if (it.action == Action::glide) start = it.start_s + it.duration_s;
  }
  return start;
}

std::array<double, kMuscles> MotorController::targetContraction(double t) const {
  std::array<double, kMuscles> c{};
  if (t >= scheduleDurationS(schedule_)) return c;  // after the schedule: relax
  const ScheduleItem& item = itemAt(t);
  const bool turning = item.action == Action::left || item.action == Action::right;
  const bool swimming = item.action == Action::swim || (turning && params_.swim_during_turn);
  const double since_swim = t - swimClockStart(item), per_s = 1.0 / params_.reference_step_s;
  const bool anta = params_.stroke == Stroke::antagonistic;
  for (int k = 0; k < kMuscles; ++k) {
    const Muscle& m = fish_.muscles[k];
    const int side = params_.mirror ? 1 - m.side : m.side;
    const double full = rest_m_[k] * (1.0 - params_.contracted_fraction);
    if (swimming && m.segment >= 1) {
      const bool posterior = m.segment == 2;
      const double alpha = posterior ? params_.swim.amplitude_posterior : params_.swim.amplitude_anterior;
      const double r = posterior ? params_.swim.rate_posterior : params_.swim.rate_anterior;
      const double ramp = params_.rate_reading == RateReading::full_stroke ? alpha : 1.0;
      const double peak = alpha * full, slope = ramp * r * rest_m_[k] * per_s;
      // contract: 0 -> peak -> 0; antagonistic: 0 -> peak -> -peak -> 0 (a triangle of twice the
      // height, entered a quarter period in so that it starts at 0 rising).
      const double height = anta ? 2 * peak : peak, period = 2 * height / slope;
      double delay = posterior ? params_.posterior_lag_rad / (2 * M_PI) * period : 0.0;
      if (side == 1) delay += 0.5 * period;  // right side: exactly out of phase
      const double since = since_swim - delay;
      c[k] = !anta ? triangle(since, peak, slope) : since <= 0 ? 0.0 : triangle(since + 0.25 * period, height, slope) - peak;
    }
    if (m.segment <= 1) c[k] += turnContraction(k, side, t);
    c[k] = std::clamp(c[k], anta || params_.turn_stroke == Stroke::antagonistic ? -full : 0.0, full);
  }
  return c;
}

// A turn item on this muscle's side: contract at turn_rate up to turn_amplitude, hold while the item
// lasts, then relax at turn_rate x turn_relax_fraction (also into the next item); on the other side,
// when the turn stroke is antagonistic, the opposite (a lengthening).
double MotorController::turnContraction(int k, int side, double t) const {
  const double full = rest_m_[k] * (1.0 - params_.contracted_fraction);
  const double ramp = params_.rate_reading == RateReading::full_stroke ? params_.turn_amplitude : 1.0;
  const double peak = params_.turn_amplitude * full;
  const double slope = ramp * params_.turn_rate * rest_m_[k] / params_.reference_step_s;
  double c = 0;
  for (const auto& it : schedule_) {
    if (it.start_s > t) break;
    if (it.action != Action::left && it.action != Action::right) continue;
    const bool inner = (it.action == Action::left) == (side == 0);
    if (!inner && params_.turn_stroke != Stroke::antagonistic) {
      c = 0;
      continue;
    }
    const double end = it.start_s + it.duration_s;
    const double reached = std::min(peak, slope * (std::min(t, end) - it.start_s));
    c = t < end ? reached : std::max(0.0, reached - slope * params_.turn_relax_fraction * (t - end));
    if (!inner) c = -c;  // antagonistic: the outer side lengthens as much as the inner side shortens
  }
  return c;
}

void MotorController::apply(double t, double dt, std::array<double, kUnits>& rest_m) {
  const auto target = targetContraction(t + dt);
  for (int k = 0; k < kMuscles; ++k) {
    const double limit = params_.r_max * rest_m_[k] / params_.reference_step_s * dt;
    contraction_m_[k] += std::clamp(target[k] - contraction_m_[k], -limit, limit);
    rest_m[fish_.muscles[k].unit] = rest_m_[k] - contraction_m_[k];
  }
}

}  // namespace creaturelab::fish
