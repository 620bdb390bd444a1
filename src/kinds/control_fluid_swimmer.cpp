#include "kinds/control_fluid_swimmer.hpp"

#include <cmath>
#include <stdexcept>

#include "kinds/control_params.hpp"

namespace creaturelab::kinds {
namespace {

std::vector<double> reals(const ParamReader& r, const std::string& key) {
  std::vector<double> out;
  for (const auto& s : splitList(r.text(key), ',')) {
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

std::vector<ParamSpec> swimmerParams() {
  return {
      text("mouth_body", "", "", "§7.2: body carrying the mouth (coupling/mouth.hpp); empty: no mouth"),
      real("mouth_centre_x_m", 0.0, "m", -1e3, 1e3, "mouth centre, x in the frame of the body's first geom"),
      real("mouth_centre_z_m", 0.0, "m", -1e3, 1e3, "mouth centre, z in that frame"),
      real("mouth_width_m", 0.1, "m", 1e-6, 1e3, "width of the mouth's segment of markers"),
      real("mouth_normal_x", 0.0, "", -1, 1, "outward (expelling) normal of the mouth, x in that frame"),
      real("mouth_normal_z", -1.0, "", -1, 1, "outward normal, z"),
      real("cycle_s", 1.0, "s", 1e-6, 1e6, "period of the phases (§7.2's three; ours: the paper gives none)"),
      text("phase_fractions", "", "", "share of cycle_s of each phase, comma-separated, summing to 1; empty: none"),
      text("phase_senses", "", "", "sense of every controlled joint per phase: min | max, comma-separated"),
      text("phase_flux_m_per_s", "", "m/s", "mouth flux per phase (+ expels along the normal, - draws in)"),
      text("phase_strength_rad_per_s", "", "rad/s",
           "strength of the controlled joints per phase (§2.1's step per frame; the paper gives one); empty: "
           "strength_rad_per_s throughout"),
      text("rise_body", "", "", "body whose subtree's centre of mass is tracked for the rise; empty: none"),
      integer("rise_cycles", 2, 1, 100000, "rise per cycle: mean over the last this many cycles"),
      boolean("armature_added_mass", false,
              "free joints' MJCF armature as the fluid's added mass, its lagged force given back (stabilises the "
              "staggered coupling of light free bodies; fluid_controller.hpp)"),
  };
}

std::vector<MetricSpec> swimmerMetrics() {
  return {
      {"rise_per_cycle_m", "m", "rise of rise_body's subtree centre of mass per cycle, mean over the last rise_cycles"},
      {"rise_total_m", "m", "rise of that centre of mass over the run"},
      {"creature_density_ratio", "", "creature mass over the fluid mass its outlines displace"},
  };
}

coupling::MouthParams mouthParams(const ParamReader& r) {
  coupling::MouthParams m;
  m.body = r.text("mouth_body");
  m.centre_x_m = r.real("mouth_centre_x_m");
  m.centre_z_m = r.real("mouth_centre_z_m");
  m.width_m = r.real("mouth_width_m");
  m.normal_x = r.real("mouth_normal_x");
  m.normal_z = r.real("mouth_normal_z");
  m.schedule.cycle_s = r.real("cycle_s");
  m.schedule.fractions = reals(r, "phase_fractions");
  m.flux_m_per_s = reals(r, "phase_flux_m_per_s");
  return m;
}

std::vector<std::vector<control::Sense>> phaseSenses(const ParamReader& r, int joints) {
  std::vector<std::vector<control::Sense>> out;
  for (const auto& s : splitList(r.text("phase_senses"), ',')) {
    if (s != "min" && s != "max") throw std::invalid_argument("phase_senses: '" + s + "' is not min or max");
    out.emplace_back(joints, s == "min" ? control::Sense::minimize : control::Sense::maximize);
  }
  return out;
}

std::vector<double> phaseStrengths(const ParamReader& r) { return reals(r, "phase_strength_rad_per_s"); }

std::string validateSwimmer(const ParamReader& r, const rigid::RigidModel& model) {
  const auto m = mouthParams(r);
  if (auto e = coupling::validate(m); !e.empty()) return e;
  const auto strengths = phaseStrengths(r);
  if (!strengths.empty() && strengths.size() != m.schedule.fractions.size())
    return "phase_strength_rad_per_s needs one strength per phase (" + std::to_string(m.schedule.fractions.size()) +
           " phases)";
  for (double s : strengths)
    if (!(s >= 0)) return "phase_strength_rad_per_s: strengths must be >= 0";
  const auto senses = phaseSenses(r, 1);
  if (!senses.empty() && senses.size() != m.schedule.fractions.size())
    return "phase_senses needs one sense per phase (" + std::to_string(m.schedule.fractions.size()) + " phases)";
  if (!m.body.empty()) bodyId(model, m.body, "mouth_body");
  if (!r.text("rise_body").empty()) {
    bodyId(model, r.text("rise_body"), "rise_body");
    const double per_cycle = r.real("cycle_s") / r.real("frame_s");
    if (std::abs(per_cycle - std::round(per_cycle)) > 1e-6)
      return "cycle_s must be a whole number of frames (frame_s) for the rise per cycle";
    if (double(r.integer("frames")) < r.integer("rise_cycles") * std::round(per_cycle))
      return "frames must cover rise_cycles cycles of cycle_s";
  }
  return "";
}

control::SwimmerPhases swimmerPhases(const ParamReader& r, int joints) {
  return {mouthParams(r).schedule, phaseSenses(r, joints), phaseStrengths(r)};
}

control::RiseSettings riseSettings(const ParamReader& r, const rigid::RigidModel& model) {
  control::RiseSettings s;
  s.mouth = mouthParams(r);
  if (r.text("rise_body").empty()) return s;
  s.body = bodyId(model, r.text("rise_body"), "rise_body");
  s.frames_per_cycle = int(std::lround(r.real("cycle_s") / r.real("frame_s")));
  s.cycles = int(r.integer("rise_cycles"));
  return s;
}

}  // namespace creaturelab::kinds
