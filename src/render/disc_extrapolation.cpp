#include "render/disc_extrapolation.hpp"

#include <algorithm>
#include <cmath>

namespace creaturelab::render {
namespace {

using Triangles = std::vector<std::array<std::int32_t, 3>>;

// Closes a sequence of `count` rings of `segments` vertices each, stored one after the other from
// `first_pole` + 1, with a pole before the first ring (`first_pole`) and one after the last. With
// the ring index i advancing along the surface and the longitude j around it, the outward
// normal is ∂z/∂j × ∂z/∂i, so each quad is split as (i, j) (i, j+1) (i+1, j+1) and (i, j) (i+1, j+1)
// (i+1, j): counter-clockwise seen from outside. (For the umbrella: at σ = 0 on the exumbrella,
// ∂z/∂σ = r ẑ and ∂z/∂i = (dr, dy, 0) with dy < 0 going down from the apex, so the cross product
// is (−r dy, r dr, 0): outward and up.)
void stitch(int first_pole, int count, int segments, Triangles& out) {
  const int last_pole = first_pole + 1 + count * segments;
  const auto ring = [&](int i) { return first_pole + 1 + i * segments; };
  for (int j = 0; j < segments; ++j) {
    const int j1 = (j + 1) % segments;
    out.push_back({first_pole, ring(0) + j1, ring(0) + j});
    for (int i = 0; i + 1 < count; ++i) {
      const int a = ring(i), b = ring(i + 1);
      out.push_back({a + j, a + j1, b + j1});
      out.push_back({a + j, b + j1, b + j});
    }
    out.push_back({ring(count - 1) + j, ring(count - 1) + j1, last_pole});
  }
}

Vec3 unit(Vec3 v, Vec3 fallback) {
  const double n = norm(v);
  return n > 0 ? (1.0 / n) * v : fallback;
}

}  // namespace

DiscExtrapolation::DiscExtrapolation(const RenderParams& params, bool tentacles) {
  layout_.rings = params.rings;
  layout_.segments = params.segments;
  layout_.tentacles = tentacles ? params.tentacles : 0;
  layout_.tentacle_rings = params.tentacle_rings;
  layout_.tentacle_segments = params.tentacle_segments;
  for (int j = 0; j < layout_.segments; ++j) {
    cos_.push_back(std::cos(longitude(j)));
    sin_.push_back(std::sin(longitude(j)));
  }
  for (int j = 0; j < layout_.tentacle_segments; ++j) {
    const double phi = 2.0 * M_PI * j / layout_.tentacle_segments;
    tube_cos_.push_back(std::cos(phi));
    tube_sin_.push_back(std::sin(phi));
  }
  // The tentacle's own thickness profile, tapering linearly from the root to the tip.
  for (int l = 0; l < layout_.tentacle_rings; ++l) {
    const double v = double(l) / double(layout_.tentacle_rings - 1);
    tube_radius_m_.push_back(0.5 * params.tentacle_thickness_m * (1.0 - (1.0 - params.tentacle_tip_ratio) * v));
  }
}

void DiscExtrapolation::initialise(TriangleMesh& mesh) const {
  const MeshLayout& m = layout_;
  mesh.positions.assign(m.vertices(), Vec3{});
  mesh.normals.assign(m.vertices(), Vec3{});
  mesh.parts.assign(m.vertices(), Part::tentacle);
  for (int v = 0; v < m.umbrellaVertices(); ++v)
    mesh.parts[v] = v < m.subumbrellaRing(0) ? Part::exumbrella : Part::subumbrella;
  mesh.triangles.clear();
  mesh.triangles.reserve(m.triangles());
  stitch(m.exumbrellaPole(), 2 * (m.rings - 1), m.segments, mesh.triangles);
  for (int k = 0; k < m.tentacles; ++k) stitch(m.tentacleRoot(k), m.tentacle_rings, m.tentacle_segments, mesh.triangles);
}

void DiscExtrapolation::umbrella(const Slice2& slice, TriangleMesh& mesh) const {
  const MeshLayout& m = layout_;
  const int apex = m.rings - 1, s = m.segments;
  Vec3* p = mesh.positions.data();
  p[m.exumbrellaPole()] = discPoint(slice.exum_left[apex], slice.exum_right[apex], 1.0, 0.0);
  p[m.subumbrellaPole()] = discPoint(slice.sub_left[apex], slice.sub_right[apex], 1.0, 0.0);
  for (int i = 0; i < apex; ++i) {
    Vec3* exum = p + m.exumbrellaRing(i);
    Vec3* sub = p + m.subumbrellaRing(i);
    for (int j = 0; j < s; ++j) {
      exum[j] = discPoint(slice.exum_left[i], slice.exum_right[i], cos_[j], sin_[j]);
      sub[j] = discPoint(slice.sub_left[i], slice.sub_right[i], cos_[j], sin_[j]);
    }
  }
}

void DiscExtrapolation::centreline(const Slice2& slice, int k, Centreline& out) const {
  const int n = int(slice.tentacle_left.size());
  const double c = std::cos(tentacleLongitude(k)), s = std::sin(tentacleLongitude(k));
  out.points.resize(n);
  out.normals.resize(n);
  for (int l = 0; l < n; ++l) out.points[l] = discPoint(slice.tentacle_left[l], slice.tentacle_right[l], c, s);
  for (int l = 0; l < n; ++l) {
    const Vec3 tangent = unit(out.points[std::min(l + 1, n - 1)] - out.points[std::max(l - 1, 0)], Vec3{0, -1, 0});
    // The radial direction at the tentacle's longitude on this pair's disc, made normal to the
    // tentacle: the 2-D slice's tentacle normal carried to longitude σ_k.
    const Eigen::Vector2d h = slice.tentacle_right[l] - slice.tentacle_left[l];
    const double hn = h.norm();
    const Vec3 across = hn > 0 ? Vec3{c * h.x() / hn, c * h.y() / hn, s} : Vec3{c, 0, s};
    out.normals[l] = unit(across - dot(across, tangent) * tangent, unit(cross(tangent, Vec3{0, 0, 1}), Vec3{1, 0, 0}));
  }
}

void DiscExtrapolation::tube(const Centreline& line, int k, TriangleMesh& mesh) const {
  const int n = int(line.points.size()), segments = layout_.tentacle_segments;
  Vec3* p = mesh.positions.data();
  Vec3 first_tangent{0, -1, 0}, last_tangent{0, -1, 0};
  for (int l = 0; l < n; ++l) {
    const Vec3 tangent = unit(line.points[std::min(l + 1, n - 1)] - line.points[std::max(l - 1, 0)], Vec3{0, -1, 0});
    // Each ring is the disc of the opposite points c ± ρ N of the tentacle's thick outline,
    // revolved about the tangent: c + ρ (cos φ N + sin φ B), B = T × N (outward with the stitch).
    const Vec3 normal = unit(line.normals[l] - dot(line.normals[l], tangent) * tangent, line.normals[l]);
    const Vec3 binormal = cross(tangent, normal);
    const double radius = tube_radius_m_[l];
    Vec3* ring = p + layout_.tentacleRing(k, l);
    for (int j = 0; j < segments; ++j)
      ring[j] = line.points[l] + radius * (tube_cos_[j] * normal + tube_sin_[j] * binormal);
    if (l == 0) first_tangent = tangent;
    if (l == n - 1) last_tangent = tangent;
  }
  // The caps: a pole a ring's radius beyond each end.
  p[layout_.tentacleRoot(k)] = line.points.front() - tube_radius_m_.front() * first_tangent;
  p[layout_.tentacleTip(k)] = line.points.back() + tube_radius_m_.back() * last_tangent;
}

}  // namespace creaturelab::render
