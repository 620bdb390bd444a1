#include "render/geom_mesh.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace creaturelab::render {
namespace {

// A surface of revolution about z through the profile (radius, z) from the top pole to the bottom
// one (both radius 0): a pole vertex each, a ring of `slices` vertices per inner profile point.
TriangleMesh revolve(const std::vector<std::pair<double, double>>& profile, int slices) {
  TriangleMesh m;
  const int rings = int(profile.size()) - 2;
  m.positions.push_back({0, 0, profile.front().second});
  for (int r = 1; r <= rings; ++r)
    for (int s = 0; s < slices; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / slices;
      m.positions.push_back({profile[r].first * std::cos(phi), profile[r].first * std::sin(phi), profile[r].second});
    }
  m.positions.push_back({0, 0, profile.back().second});
  const auto at = [slices](int ring, int s) { return std::int32_t(1 + (ring - 1) * slices + (s % slices)); };
  const std::int32_t bottom = std::int32_t(m.positions.size()) - 1;
  for (int s = 0; s < slices; ++s) {
    m.triangles.push_back({0, at(1, s), at(1, s + 1)});
    for (int r = 1; r < rings; ++r) {
      m.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
    m.triangles.push_back({at(rings, s), bottom, at(rings, s + 1)});
  }
  return m;
}

TriangleMesh box(const std::array<double, 3>& h) {
  Vec3 corner[8];
  for (int k = 0; k < 8; ++k) corner[k] = {(k & 1 ? 1 : -1) * h[0], (k & 2 ? 1 : -1) * h[1], (k & 4 ? 1 : -1) * h[2]};
  // Faces counter-clockwise seen from outside: -z, +z, -y, +y, -x, +x; four vertices each (flat normals).
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  TriangleMesh m;
  for (const auto& f : faces) {
    const std::int32_t first = std::int32_t(m.positions.size());
    for (int c : f) m.positions.push_back(corner[c]);
    m.triangles.push_back({first, first + 1, first + 2});
    m.triangles.push_back({first, first + 2, first + 3});
  }
  return m;
}

}  // namespace

bool isPrimitiveGeom(int t) { return t >= int(GeomShape::sphere) && t <= int(GeomShape::box); }

TriangleMesh geomMesh(int type, const std::array<double, 3>& size_m, int slices) {
  if (!isPrimitiveGeom(type))
    throw std::invalid_argument("geom type " + std::to_string(type) + " is not a primitive (sphere, capsule, "
                                "ellipsoid, cylinder or box): its surface is not in its type and size");
  const int needed = type == int(GeomShape::box) || type == int(GeomShape::ellipsoid) ? 3
                     : type == int(GeomShape::sphere)                                 ? 1
                                                                                      : 2;
  for (int a = 0; a < needed; ++a)
    if (!(size_m[a] > 0)) throw std::invalid_argument("geom size " + std::to_string(size_m[a]) + " m is not positive");
  if (slices < 3) throw std::invalid_argument("a round geom needs at least 3 slices");
  const int half = std::max(1, slices / 4);  // rings over a quarter turn of latitude
  std::vector<std::pair<double, double>> profile;
  const double r = size_m[0];
  switch (GeomShape(type)) {
    case GeomShape::box: {
      TriangleMesh m = box(size_m);
      computeNormals(m);
      return m;
    }
    case GeomShape::cylinder:
      profile = {{0, size_m[1]}, {r, size_m[1]}, {r, -size_m[1]}, {0, -size_m[1]}};
      break;
    case GeomShape::capsule:
      for (int k = 0; k <= half; ++k) {
        const double t = 0.5 * std::numbers::pi * k / half;
        profile.push_back({r * std::sin(t), size_m[1] + r * std::cos(t)});
      }
      for (int k = half; k <= 2 * half; ++k) {
        const double t = 0.5 * std::numbers::pi * k / half;
        profile.push_back({r * std::sin(t), -size_m[1] + r * std::cos(t)});
      }
      profile.front().first = profile.back().first = 0;
      break;
    default:  // sphere, ellipsoid: the unit sphere, scaled below
      for (int k = 0; k <= 2 * half; ++k) {
        const double t = std::numbers::pi * k / (2 * half);
        profile.push_back({std::sin(t), std::cos(t)});
      }
      profile.front().first = profile.back().first = 0;
  }
  TriangleMesh m = revolve(profile, slices);
  if (type == int(GeomShape::sphere) || type == int(GeomShape::ellipsoid)) {
    const std::array<double, 3> s = type == int(GeomShape::sphere) ? std::array<double, 3>{r, r, r} : size_m;
    for (Vec3& p : m.positions) p = {s[0] * p.x, s[1] * p.y, s[2] * p.z};
  }
  computeNormals(m);
  return m;
}

}  // namespace creaturelab::render
