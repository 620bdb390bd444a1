#include "jellyfish/jellyfish_params.hpp"

#include <cmath>
#include <sstream>

namespace creaturelab::jellyfish {
namespace {

struct Problems {
  std::ostringstream out;
  void add(const std::string& s) { out << (out.tellp() > 0 ? "; " : "") << s; }
  std::string str() const { return out.str(); }
};

bool positive(double v) { return std::isfinite(v) && v > 0; }

}  // namespace

std::string BellParams::validate() const {
  const BellParams& p = *this;
  Problems e;
  if (!positive(p.diameter_m)) e.add("bell diameter must be > 0");
  if (!positive(p.height_m)) e.add("bell height must be > 0");
  if (!positive(p.thickness_m)) e.add("bell thickness must be > 0");
  if (positive(p.diameter_m) && positive(p.thickness_m) && 2 * p.thickness_m >= p.diameter_m)
    e.add("bell thickness must be less than half its diameter (the subumbrella has semi-axis diameter/2 - thickness)");
  if (positive(p.height_m) && positive(p.thickness_m) && p.thickness_m >= p.height_m)
    e.add("bell thickness must be less than its height");
  if (p.segments < 8 || p.segments % 2 != 0) e.add("bell segments must be even and at least 8, got " + std::to_string(p.segments));
  if (!positive(p.bell_modulus_pa)) e.add("bell modulus must be > 0");
  if (!(p.bending_rigidity_n_m >= 0)) e.add("bending rigidity must be >= 0");
  if (!positive(p.muscle_modulus_pa)) e.add("muscle modulus must be > 0");
  if (!positive(p.muscle_section_per_arc)) e.add("muscle section per arc must be > 0");
  if (!(p.muscle_tension_n_per_m2 >= 0) || !std::isfinite(p.muscle_tension_n_per_m2))
    e.add("muscle tension must be >= 0");
  if (!(p.muscle_band_fraction > 0 && p.muscle_band_fraction < 1))
    e.add("muscle band fraction must be in (0, 1): the band cannot reach the apex, where a muscle element would join a marker to itself");
  if (p.tentacles && !positive(p.tentacle_length_m)) e.add("tentacle length must be > 0");
  if (!positive(p.tentacle_area_factor)) e.add("tentacle area factor must be > 0");
  if (p.tentacles && p.tentacles_per_side < 1) e.add("tentacles per side must be at least 1");
  if (p.tentacles && p.tentacles_per_side > 1 && !positive(p.tentacle_root_spacing_m))
    e.add("tentacle root spacing must be > 0");
  if (!(p.tentacle_permeability_m >= 0) || !std::isfinite(p.tentacle_permeability_m))
    e.add("tentacle permeability must be >= 0");
  if (!(p.tentacle_axial_permeability_m >= 0) || !std::isfinite(p.tentacle_axial_permeability_m))
    e.add("tentacle axial permeability must be >= 0");
  return e.str();
}

std::string ActivationParams::validate() const {
  const ActivationParams& a = *this;
  Problems e;
  if (!positive(a.contraction_hz)) e.add("contraction frequency must be > 0");
  if (a.knots.empty() || a.knots.size() > 16) e.add("the contraction curve needs 1 to 16 knots");
  for (std::size_t i = 0; i < a.knots.size(); ++i) {
    const Knot& k = a.knots[i];
    if (!(k.phase >= 0 && k.phase < 1)) e.add("knot " + std::to_string(i) + " phase must be in [0, 1)");
    if (i > 0 && !(k.phase > a.knots[i - 1].phase))
      e.add("knot phases must increase: knot " + std::to_string(i) + " is not after knot " + std::to_string(i - 1));
    if (!std::isfinite(k.value) || !std::isfinite(k.tangent)) e.add("knot " + std::to_string(i) + " is not finite");
  }
  if (!(a.stagger >= 0 && a.stagger < 1)) e.add("stagger must be in [0, 1)");
  if (!(a.pulse_stagger >= 0 && a.pulse_stagger < 1)) e.add("pulse stagger must be in [0, 1)");
  if (!(a.synaptic_delay_s >= 0)) e.add("synaptic delay must be >= 0");
  if (a.shape == ActivationShape::pulse && !(positive(a.pulse_duration_s) && a.pulse_duration_s * a.contraction_hz <= 1))
    e.add("pulse duration must be > 0 and no longer than the period (1 / contraction_hz)");
  if (a.active_cycles < 0) e.add("active cycles must be >= 0 (0 = every cycle)");
  if (e.str().empty()) {
    // A rest length must stay positive all through the cycle (Hermite segments can overshoot).
    const ExpansionWindow window = expansionWindow(a.knots);
    double low = 1e300, high = -1e300;
    for (int s = 0; s <= 2000; ++s) {
      const double f = muscleFactor(a.knots, s / 2000.0, window, 0.0, 1.0);
      low = std::min(low, f);
      high = std::max(high, f);
    }
    if (!(low > 0.05))
      e.add("the contraction curve falls to " + std::to_string(low) +
            " of the relaxed length; its knots or tangents overshoot (keep it within (0.05, 1.5])");
    if (!(high <= 1.5))
      e.add("the contraction curve rises to " + std::to_string(high) +
            " of the relaxed length; its knots or tangents overshoot (keep it within (0.05, 1.5])");
  }
  return e.str();
}

std::string KnotTable::validate() const {
  const KnotTable defaults;
  for (int k = int(std::clamp<std::int64_t>(used, 0, kMax)); k < kMax; ++k) {
    const Knot &given = knots[k], &d = defaults.knots[k];
    if (given.phase != d.phase || given.value != d.value || given.tangent != d.tangent)
      return "knot" + std::to_string(k) + "_* is set but contraction_knots = " + std::to_string(used) +
             ": raise contraction_knots or remove the knot";
  }
  return "";
}

ModelPreset modelPreset(Model model) {
  if (model == Model::paper) return {MuscleModel::rest_length, ActivationShape::hermite, 2.352e-3, std::nullopt, 0.0, 0.0};
  return {BellParams{}.muscle_model, ActivationParams{}.shape, BellParams{}.bending_rigidity_n_m,
          kFilamentKernelRadius_m, kFilamentPermeability_m, kFilamentAxialPermeability_m};
}

BellParams paperBell() {
  BellParams p;
  p.segments = 32;
  p.bending_rigidity_n_m = 1.186 * 1.98319e-3;
  p.muscle_model = MuscleModel::rest_length;
  p.muscle_tension_n_per_m2 = 1.0;
  p.tentacle_root_spacing_m = 0.004;
  p.tentacle_permeability_m = 0.0;
  p.tentacle_axial_permeability_m = 0.0;
  return p;
}

ActivationParams paperActivation() {
  ActivationParams a;
  a.shape = ActivationShape::hermite;
  return a;
}

}  // namespace creaturelab::jellyfish
