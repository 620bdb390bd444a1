#include "coupling/mouth.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace creaturelab::coupling {

double cyclesAt(const PhaseSchedule& s, double t_s) { return t_s / s.cycle_s; }

int phaseAt(const PhaseSchedule& s, double t_s) {
  if (s.fractions.empty()) return 0;
  const double c = cyclesAt(s, t_s);
  const double within = c - std::floor(c);
  double end = 0;
  for (int k = 0; k < int(s.fractions.size()); ++k) {
    end += s.fractions[k];
    if (within < end) return k;
  }
  return int(s.fractions.size()) - 1;  // round-off at the cycle's end
}

std::string MouthParams::validate() const {
  const MouthParams& m = *this;
  const auto& f = m.schedule.fractions;
  if (!(m.schedule.cycle_s > 0)) return "cycle_s must be positive";
  for (double x : f)
    if (!(x > 0)) return "phase_fractions: every phase needs a positive share of the cycle";
  if (!f.empty() && std::abs(std::accumulate(f.begin(), f.end(), 0.0) - 1.0) > 1e-9)
    return "phase_fractions must sum to 1 (shares of cycle_s)";
  if (m.body.empty()) return "";
  if (m.flux_m_per_s.size() != f.size())
    return "phase_flux_m_per_s needs one flux per phase (" + std::to_string(f.size()) + " phases, got " +
           std::to_string(m.flux_m_per_s.size()) + ")";
  if (!(m.width_m > 0)) return "mouth_width_m must be positive when mouth_body is given";
  if (!(std::hypot(m.normal_x, m.normal_z) > 0)) return "mouth_normal_x, mouth_normal_z: the normal is zero";
  return "";
}

double mouthFlux_m_per_s(const MouthParams& m, double t_s) {
  if (m.body.empty() || m.flux_m_per_s.empty()) return 0.0;
  return m.flux_m_per_s[phaseAt(m.schedule, t_s)];
}

std::vector<OutlineMarker> mouthMarkers(const rigid::RigidModel& model, const MouthParams& m, double spacing_m) {
  std::vector<OutlineMarker> out;
  if (m.body.empty()) return out;
  int body = -1;
  for (int b = 1; b < model.bodies(); ++b)
    if (model.bodyName(b) == m.body) body = b;
  if (body < 0) throw std::invalid_argument("mouth_body: the model " + model.path() + " has no body '" + m.body + "'");
  int geom = -1;
  for (int g = model.geoms() - 1; g >= 0; --g)
    if (model.geomBody(g) == body) geom = g;
  if (geom < 0) throw std::invalid_argument("mouth_body: body '" + m.body + "' has no geom to carry the mouth");
  // The segment across the normal, centred on the mouth's centre.
  const double norm = std::hypot(m.normal_x, m.normal_z);
  const double tx = -m.normal_z / norm, tz = m.normal_x / norm;
  const int n = std::max(1, int(std::ceil(m.width_m / spacing_m - 1e-12)));
  for (int k = 0; k < n; ++k) {
    const double s = ((k + 0.5) / n - 0.5) * m.width_m;
    OutlineMarker mk;
    mk.geom = geom;
    mk.body = body;
    mk.local_m = {m.centre_x_m + s * tx, 0.0, m.centre_z_m + s * tz};
    mk.length_m = m.width_m / n;
    out.push_back(mk);
  }
  return out;
}

}  // namespace creaturelab::coupling
