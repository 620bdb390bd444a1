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

std::string validate(const BellParams& p) {
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
  if (!(p.angular_stiffness_nm_per_rad >= 0)) e.add("angular stiffness must be >= 0");
  if (!positive(p.muscle_modulus_pa)) e.add("muscle modulus must be > 0");
  if (!positive(p.muscle_thickness_m)) e.add("muscle thickness must be > 0");
  if (p.muscle_pairs < 1) e.add("at least one muscle pair is needed");
  if (p.muscle_stride < 1) e.add("muscle stride must be >= 1");
  if (p.segments >= 8 && p.muscle_pairs >= 1 && p.muscle_stride >= 1 &&
      (p.muscle_pairs - 1) * p.muscle_stride >= p.segments / 2)
    e.add("muscle pairs x stride reach the apex: " + std::to_string(p.muscle_pairs) + " pairs every " +
          std::to_string(p.muscle_stride) + " markers need more than " + std::to_string(p.segments / 2) +
          " markers per side");
  if (p.tentacles && !positive(p.tentacle_length_m)) e.add("tentacle length must be > 0");
  if (!positive(p.tentacle_area_factor)) e.add("tentacle area factor must be > 0");
  return e.str();
}

std::string validate(const ActivationParams& a) {
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
  if (!(a.synaptic_delay_s >= 0)) e.add("synaptic delay must be >= 0");
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

}  // namespace creaturelab::jellyfish
