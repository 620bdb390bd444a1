#include "render/variation.hpp"

#include <cmath>
#include <stdexcept>

namespace creaturelab::render {
namespace {

double smoothstep(double edge, double x) {
  if (edge <= 0 || x >= edge) return 1.0;
  const double t = x / edge;
  return t * t * (3 - 2 * t);
}

}  // namespace

Variation::Variation(const RenderParams& params, const MeshLayout& layout)
    : layout_(layout), noise_field_(core::ImprovedNoise::seeded(params.noise_seed)) {
  if (!noise_field_.setPeriods(256, params.noise_longitude_cells, 256))
    throw std::invalid_argument("noise_longitude_cells must be a power of two up to 256");
  const double theta = params.thickness.apex_m;
  structural_ = params.structural;
  ridges_ = params.ridges;
  noise_ = params.noise;
  structural_m_ = params.structural_scale * theta;
  ridge_m_ = params.ridge_scale * theta;
  noise_m_ = params.noise_scale * theta;
  taper_ = params.structural_apex_taper;
  longitude_cells_ = params.noise_longitude_cells;
  latitude_frequency_ = params.noise_latitude_frequency;
  time_frequency_ = params.noise_time_frequency_hz;
  for (int j = 0; j < layout.segments; ++j) {
    const double sigma = 2.0 * M_PI * j / layout.segments;
    const double wave = std::sin(params.structural_frequency * sigma);
    structural_pattern_.push_back(params.structural_shape == StructuralShape::abs_sin ? std::abs(wave) : wave);
    ridge_pattern_.push_back(0.5 * (1.0 + std::sin(params.ridge_frequency * sigma)));  // sin normalised to [0, 1]
  }
  for (int k = 0; k < layout.tentacles; ++k) tentacle_longitude_.push_back((k + 0.5) / layout.tentacles);
}

double Variation::unstructured(double d_i, double d_j, double time_s) const {
  return noise_m_ * d_i * noise_field_(latitude_frequency_ * d_i, longitude_cells_ * d_j, time_frequency_ * time_s);
}

void Variation::umbrella(const Slice2& slice, double time_s, TriangleMesh& mesh) {
  const int rings = layout_.rings, s = layout_.segments;
  // Eq. 2 is the same on both surfaces at one (d_i, d_j): evaluated once per ring and longitude.
  ring_noise_.assign(std::size_t(rings - 1) * s, 0.0);
  if (noise_)
    for (int i = 0; i < rings - 1; ++i)
      for (int j = 0; j < s; ++j)
        ring_noise_[std::size_t(i) * s + j] = unstructured(slice.latitude[i], double(j) / s, time_s);
  Vec3* p = mesh.positions.data();
  const Vec3* n = mesh.normals.data();
  for (int i = 0; i < rings - 1; ++i) {
    const double structural = structural_ ? structural_m_ * smoothstep(taper_, slice.latitude[i]) : 0.0;
    const double ridge = ridges_ ? ridge_m_ * slice.contraction[i] : 0.0;
    const double* noise = ring_noise_.data() + std::size_t(i) * s;
    const int exum = layout_.exumbrellaRing(i), sub = layout_.subumbrellaRing(i);
    for (int j = 0; j < s; ++j) {
      // The wall normal at (i, j): the exumbrella's outward normal and the opposite of the
      // subumbrella's (which points into the cavity), averaged, so that both surfaces of the wall
      // move by one vector and its thickness stays (at the margin, the rim's own faces in the two
      // vertex normals cancel).
      const Vec3 sum = n[exum + j] - n[sub + j];
      const double length = norm(sum);
      const Vec3 wall_normal = length > 0 ? (1.0 / length) * sum : n[exum + j];
      const double wall = structural * structural_pattern_[j] + noise[j];
      p[exum + j] = p[exum + j] + (wall + ridge * ridge_pattern_[j]) * wall_normal;
      p[sub + j] = p[sub + j] + wall * wall_normal;
    }
  }
}

void Variation::tentacle(int k, double time_s, Centreline& line) const {
  if (!noise_) return;
  const int n = int(line.points.size());
  for (int l = 0; l < n; ++l) {
    const double d = 1.0 + double(l) / double(n - 1);
    line.points[l] = line.points[l] + unstructured(d, tentacle_longitude_[k], time_s) * line.normals[l];
  }
}

}  // namespace creaturelab::render
