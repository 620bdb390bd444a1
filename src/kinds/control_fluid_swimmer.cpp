#include "kinds/control_fluid_swimmer.hpp"

#include <cmath>
#include <stdexcept>

#include "kinds/control_params.hpp"

namespace creaturelab::kinds {
namespace {

std::vector<double> reals(const std::string& text, const std::string& key) {
  std::vector<double> out;
  for (const auto& s : splitList(text, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(s, &used));
      if (used != s.size()) throw std::invalid_argument(s);
    } catch (const std::exception&) {
      throw std::invalid_argument(key + ": '" + s + "' is not a number");
    }
  }
  return out;
}

int bodyId(const rigid::RigidModel& model, const std::string& name, const std::string& key) {
  for (int b = 1; b < model.bodies(); ++b)
    if (model.bodyName(b) == name) return b;
  throw std::invalid_argument(key + ": the model " + model.path() + " has no body '" + name + "'");
}

}  // namespace

std::vector<MetricSpec> swimmerMetrics() {
  return {
      {"rise_per_cycle_m", "m", "rise of rise_body's subtree centre of mass per cycle, mean over the last rise_cycles"},
      {"rise_total_m", "m", "rise of that centre of mass over the run"},
      {"creature_density_ratio", "", "creature mass over the fluid mass its outlines displace"},
  };
}

coupling::MouthParams SwimmerSettings::mouthParams() const {
  coupling::MouthParams m;
  m.body = mouth_body;
  m.centre_x_m = mouth_centre_x_m;
  m.centre_z_m = mouth_centre_z_m;
  m.width_m = mouth_width_m;
  m.normal_x = mouth_normal_x;
  m.normal_z = mouth_normal_z;
  m.schedule.cycle_s = cycle_s;
  m.schedule.fractions = reals(phase_fractions, "phase_fractions");
  m.flux_m_per_s = reals(phase_flux_m_per_s, "phase_flux_m_per_s");
  return m;
}

std::vector<std::vector<control::Sense>> SwimmerSettings::phaseSenses(int joints) const {
  std::vector<std::vector<control::Sense>> out;
  for (const auto& s : splitList(phase_senses, ',')) {
    if (s != "min" && s != "max") throw std::invalid_argument("phase_senses: '" + s + "' is not min or max");
    out.emplace_back(joints, s == "min" ? control::Sense::minimize : control::Sense::maximize);
  }
  return out;
}

std::vector<double> SwimmerSettings::phaseStrengths() const {
  return reals(phase_strength_rad_per_s, "phase_strength_rad_per_s");
}

std::string SwimmerSettings::validate(const rigid::RigidModel& model, double frame_s, std::int64_t frames) const {
  const auto m = mouthParams();
  if (auto e = m.validate(); !e.empty()) return e;
  const auto strengths = phaseStrengths();
  if (!strengths.empty() && strengths.size() != m.schedule.fractions.size())
    return "phase_strength_rad_per_s needs one strength per phase (" + std::to_string(m.schedule.fractions.size()) +
           " phases)";
  for (double s : strengths)
    if (!(s >= 0)) return "phase_strength_rad_per_s: strengths must be >= 0";
  const auto senses = phaseSenses(1);
  if (!senses.empty() && senses.size() != m.schedule.fractions.size())
    return "phase_senses needs one sense per phase (" + std::to_string(m.schedule.fractions.size()) + " phases)";
  if (!m.body.empty()) bodyId(model, m.body, "mouth_body");
  if (!rise_body.empty()) {
    bodyId(model, rise_body, "rise_body");
    const double per_cycle = cycle_s / frame_s;
    if (std::abs(per_cycle - std::round(per_cycle)) > 1e-6)
      return "cycle_s must be a whole number of frames (frame_s) for the rise per cycle";
    if (double(frames) < rise_cycles * std::round(per_cycle)) return "frames must cover rise_cycles cycles of cycle_s";
  }
  return "";
}

control::SwimmerPhases SwimmerSettings::swimmerPhases(int joints) const {
  return {mouthParams().schedule, phaseSenses(joints), phaseStrengths()};
}

control::RiseSettings SwimmerSettings::riseSettings(const rigid::RigidModel& model, double frame_s) const {
  control::RiseSettings s;
  s.mouth = mouthParams();
  if (rise_body.empty()) return s;
  s.body = bodyId(model, rise_body, "rise_body");
  s.frames_per_cycle = int(std::lround(cycle_s / frame_s));
  s.cycles = int(rise_cycles);
  return s;
}

}  // namespace creaturelab::kinds
