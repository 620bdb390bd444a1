#include "jellyfish/bell_model.hpp"

#include <cmath>
#include <stdexcept>

namespace creaturelab::jellyfish {
namespace {

using springs::Vec;

// Points along the half-ellipse x = -a cos s, y = b sin s, s in [0, pi], equally spaced in arc
// length (a fine polyline, then linear interpolation at equal arc steps), so every chain spring
// has the same length and stiffness.
std::vector<fluid::Vec2> halfEllipse(double a, double b, int segments) {
  const int fine = 4096;
  std::vector<fluid::Vec2> poly(fine + 1);
  std::vector<double> arc(fine + 1, 0.0);
  for (int i = 0; i <= fine; ++i) {
    const double s = M_PI * i / fine;
    poly[i] = {-a * std::cos(s), b * std::sin(s)};
    if (i > 0) arc[i] = arc[i - 1] + std::hypot(poly[i].x - poly[i - 1].x, poly[i].y - poly[i - 1].y);
  }
  std::vector<fluid::Vec2> out(segments + 1);
  int k = 0;
  for (int m = 0; m <= segments; ++m) {
    const double target = arc[fine] * m / segments;
    while (k < fine - 1 && arc[k + 1] < target) ++k;
    const double t = (target - arc[k]) / (arc[k + 1] - arc[k]);
    out[m] = {poly[k].x + t * (poly[k + 1].x - poly[k].x), poly[k].y + t * (poly[k + 1].y - poly[k].y)};
  }
  // Exact ends and apex, and exact mirror symmetry (x ↔ -x) so that the model stays symmetric.
  for (int m = 0; m <= segments / 2; ++m) {
    const fluid::Vec2 left = out[m];
    out[segments - m] = {-left.x, left.y};
  }
  out[segments / 2].x = 0.0;
  return out;
}

Vec<2> toVec(fluid::Vec2 p) { return Vec<2>(p.x, p.y); }

// A chain of springs and bends through `markers` (indices into positions): k = E t / L per
// spring, and at each joint an angular spring kb = B / L_joint with L_joint the mean of the two
// segments' lengths (the discrete elastica: ½ B κ² ds with κ = θ / L_joint).
void addChain(springs::Network<2>& net, const std::vector<fluid::Vec2>& x, const std::vector<int>& markers,
              double modulus_pa, double thickness_m, double bending_rigidity_n_m) {
  for (std::size_t m = 0; m + 1 < markers.size(); ++m) {
    const int a = markers[m], b = markers[m + 1];
    const double length = std::hypot(x[b].x - x[a].x, x[b].y - x[a].y);
    net.addSpring(a, b, length, modulus_pa * thickness_m / length);
  }
  for (std::size_t m = 1; m + 1 < markers.size(); ++m) {
    const int i = markers[m - 1], j = markers[m], k = markers[m + 1];
    const double joint_m = 0.5 * (std::hypot(x[j].x - x[i].x, x[j].y - x[i].y) + std::hypot(x[k].x - x[j].x, x[k].y - x[j].y));
    net.addBend(i, j, k, springs::turningAngleRad<2>(toVec(x[i]), toVec(x[j]), toVec(x[k])),
                bending_rigidity_n_m / joint_m);
  }
}

}  // namespace

BellModel buildBell(const BellParams& p) {
  if (const std::string err = p.validate(); !err.empty()) throw std::invalid_argument(err);
  BellModel model;
  const double a = 0.5 * p.diameter_m - p.thickness_m;
  const double b = p.height_m - p.thickness_m;
  model.rest_positions_m = halfEllipse(a, b, p.segments);
  model.bell_markers = p.segments + 1;
  model.apex = p.segments / 2;
  const double segment_m = std::hypot(model.rest_positions_m[1].x - model.rest_positions_m[0].x,
                                      model.rest_positions_m[1].y - model.rest_positions_m[0].y);
  model.bell_area_m2 = segment_m * p.segments * p.thickness_m;
  model.segment_m = segment_m;
  model.muscle_model = p.muscle_model;
  model.aperture_width_m = model.rest_positions_m.back().x - model.rest_positions_m.front().x;

  // Tentacles: straight down from their roots, segments as long as the bell's; the left chains, then
  // their mirror images, so that marker k of the left half and k of the right are mirror pairs.
  const int tentacle_segments = p.tentacles ? std::max(1, int(std::lround(p.tentacle_length_m / segment_m))) : 0;
  const int per_side = p.tentacles ? p.tentacles_per_side : 0;
  const int root_step = std::max(1, int(std::lround(p.tentacle_root_spacing_m / segment_m)));
  if (per_side > 1 && (per_side - 1) * root_step >= model.apex)
    throw std::invalid_argument("the tentacles' roots (" + std::to_string(per_side) + " per side, " +
                                std::to_string(p.tentacle_root_spacing_m) + " m apart) do not fit on the half bell");
  std::vector<std::vector<int>> tentacle_chains;
  std::vector<int> chain_side;
  for (int side = 0; side < 2; ++side)
    for (int t = 0; t < per_side; ++t) {
      const int root = side == 0 ? t * root_step : p.segments - t * root_step;
      chain_side.push_back(side);
      std::vector<int> chain{root};
      for (int m = 1; m <= tentacle_segments; ++m) {
        const fluid::Vec2 top = model.rest_positions_m[root];
        model.rest_positions_m.push_back({top.x, top.y - p.tentacle_length_m * m / tentacle_segments});
        const int index = static_cast<int>(model.rest_positions_m.size()) - 1;
        model.tentacle_markers.push_back(index);
        chain.push_back(index);
      }
      tentacle_chains.push_back(chain);
    }
  model.tentacle_chains = tentacle_chains;
  model.tentacle_permeability_m = p.tentacle_permeability_m;
  model.tentacle_axial_permeability_m = p.tentacle_axial_permeability_m;

  auto& net = model.network;
  for (std::size_t i = 0; i < model.rest_positions_m.size(); ++i) net.addParticle(1.0, false);
  std::vector<int> bell(model.bell_markers);
  for (int i = 0; i < model.bell_markers; ++i) bell[i] = i;
  addChain(net, model.rest_positions_m, bell, p.bell_modulus_pa, p.thickness_m, p.bending_rigidity_n_m);
  const double factor = p.tentacle_area_factor;
  for (std::size_t c = 0; c < tentacle_chains.size(); ++c) {
    addChain(net, model.rest_positions_m, tentacle_chains[c], p.bell_modulus_pa, p.thickness_m * factor,
             p.bending_rigidity_n_m * factor);
    const int root = tentacle_chains[c][0];
    // Joint at the root: the bend continues the bell's tangent into the tentacle, with the bell
    // marker bec the root on the apex's c as its first point.
    const int inner = chain_side[c] == 0 ? root + 1 : root - 1;
    const int first = tentacle_chains[c][1];
    const auto& x = model.rest_positions_m;
    const double joint_m = 0.5 * (std::hypot(x[root].x - x[inner].x, x[root].y - x[inner].y) +
                                  std::hypot(x[first].x - x[root].x, x[first].y - x[root].y));
    net.addBend(inner, root, first, springs::turningAngleRad<2>(toVec(x[inner]), toVec(x[root]), toVec(x[first])),
                p.bending_rigidity_n_m * factor / joint_m);
  }

  // The muscle band: arc [0, band] from each aperture end. The element at marker m (arc m L from
  // the aperture) carries the band's arc within half a segment of it.
  const double band_m = p.muscle_band_fraction * model.apex * segment_m;
  for (int m_index = 0; m_index < model.apex; ++m_index) {
    const double s0 = std::max(0.0, (m_index - 0.5) * segment_m), s1 = std::min(band_m, (m_index + 0.5) * segment_m);
    if (s1 <= s0) break;
    MuscleSpring m;
    m.a = m_index;
    m.b = p.segments - m_index;
    const auto& x = model.rest_positions_m;
    m.relaxed_length_m = std::hypot(x[m.b].x - x[m.a].x, x[m.b].y - x[m.a].y);
    m.arc_weight_m = s1 - s0;
    m.stiffness_n_per_m = p.muscle_modulus_pa * p.muscle_section_per_arc * m.arc_weight_m / m.relaxed_length_m;
    m.tension_max_n_per_m = p.muscle_tension_n_per_m2 * m.arc_weight_m;
    m.aperture_position = 1.0 - double(m.a) / model.apex;
    m.order_from_aperture = m_index;
    model.muscles.push_back(m);
  }
  if (const std::string err = net.validate(); !err.empty())
    throw std::logic_error("jellyfish bell network is inconsistent: " + err);
  return model;
}

}  // namespace creaturelab::jellyfish
