#include "coupling3d/surface_markers3.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace creaturelab::coupling3d {
namespace {

double distance(const Vec3& p, const Vec3& q) {
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

double area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

}  // namespace

std::vector<SurfaceMarker3> surfaceMarkers(const std::vector<rigid::GeomSurface>& surfaces, double spacing_m,
                                           double retraction_m) {
  if (!(spacing_m > 0) || !std::isfinite(spacing_m))
    throw std::invalid_argument("marker spacing must be a positive length");
  if (!(retraction_m >= 0) || !std::isfinite(retraction_m))
    throw std::invalid_argument("marker retraction must be a length of at least 0");
  std::vector<SurfaceMarker3> out;
  for (const rigid::GeomSurface& s : surfaces)
    for (const rigid::Triangle& t : s.triangles) {
      const double edge = std::max({distance(t.a, t.b), distance(t.b, t.c), distance(t.c, t.a)});
      const int m = std::max(1, static_cast<int>(std::ceil(edge / spacing_m - 1e-12)));
      const double whole = area(t.a, t.b, t.c), piece = whole / (static_cast<double>(m) * m);
      // The inward shift: −retraction times the unit outward normal (b − a) × (c − a) / (2 area).
      Vec3 shift{};
      if (retraction_m > 0 && whole > 0) {
        const double u[3] = {t.b[0] - t.a[0], t.b[1] - t.a[1], t.b[2] - t.a[2]};
        const double v[3] = {t.c[0] - t.a[0], t.c[1] - t.a[1], t.c[2] - t.a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        for (int d = 0; d < 3; ++d) shift[d] = -retraction_m * n[d] / (2 * whole);
      }
      // Barycentric lattice: point (i, j) = a + (i/m)(b − a) + (j/m)(c − a). Upward pieces (i, j),
      // (i+1, j), (i, j+1) have centroid (i + 1/3, j + 1/3); downward ones (i+1, j), (i+1, j+1),
      // (i, j+1) for i + j ≤ m − 2 have centroid (i + 2/3, j + 2/3).
      auto at = [&](double i, double j) {
        Vec3 p;
        for (int d = 0; d < 3; ++d) p[d] = t.a[d] + (i / m) * (t.b[d] - t.a[d]) + (j / m) * (t.c[d] - t.a[d]);
        if (retraction_m > 0)
          for (int d = 0; d < 3; ++d) p[d] += shift[d];
        return p;
      };
      for (int i = 0; i < m; ++i)
        for (int j = 0; i + j < m; ++j) {
          out.push_back({s.geom, s.body, at(i + 1.0 / 3, j + 1.0 / 3), piece});
          if (i + j <= m - 2) out.push_back({s.geom, s.body, at(i + 2.0 / 3, j + 2.0 / 3), piece});
        }
    }
  return out;
}

std::vector<SurfaceMarker3> modelSurfaceMarkers(const rigid::RigidModel& model, double spacing_m, double retraction_m) {
  if (!(spacing_m > 0) || !std::isfinite(spacing_m))
    throw std::invalid_argument("marker spacing must be a positive length");
  double radius = 0.0;  // the largest radius of a round geom (sphere, capsule, cylinder, ellipsoid)
  for (int g = 0; g < model.geoms(); ++g) {
    const int type = model.geomType(g);
    const Vec3 s = model.geomSize(g);
    if (type == 2 || type == 3 || type == 5) radius = std::max(radius, s[0]);
    if (type == 4) radius = std::max({radius, s[0], s[1], s[2]});
  }
  // A chord of 2π r / slices at most the spacing; slices a multiple of 4 (whole rings per hemisphere).
  const int needed = static_cast<int>(std::ceil(2 * std::numbers::pi * radius / spacing_m));
  const int slices = std::min(4096, std::max(16, (needed + 3) / 4 * 4));
  return surfaceMarkers(rigid::geomSurfaces(model, slices), spacing_m, retraction_m);
}

std::vector<SurfaceMarker3> interiorMarkers(const rigid::RigidModel& model, double spacing_m, double margin_m) {
  if (!(spacing_m > 0) || !std::isfinite(spacing_m) || !(margin_m >= 0))
    throw std::invalid_argument("interior markers need a positive spacing and a margin of at least 0");
  std::vector<SurfaceMarker3> out;
  for (int g = 0; g < model.geoms(); ++g) {
    const int type = model.geomType(g);
    const Vec3 s = model.geomSize(g);
    // Depth of a point below the surface (positive inside; for the ellipsoid a lower bound), geom frame.
    auto depth = [&](const Vec3& x) {
      switch (type) {
        case 2: return s[0] - std::hypot(x[0], x[1], x[2]);                                        // sphere
        case 3: return s[0] - std::hypot(x[0], x[1], std::max(0.0, std::abs(x[2]) - s[1]));        // capsule
        case 4: {                                                                                  // ellipsoid
          const double r = std::hypot(x[0] / s[0], x[1] / s[1], x[2] / s[2]);
          return (1.0 - r) * std::min({s[0], s[1], s[2]});
        }
        case 5: return std::min(s[0] - std::hypot(x[0], x[1]), s[1] - std::abs(x[2]));             // cylinder
        case 6: return std::min({s[0] - std::abs(x[0]), s[1] - std::abs(x[1]), s[2] - std::abs(x[2])});  // box
        default: return -1.0;
      }
    };
    if (type < 2 || type > 6) continue;
    Vec3 half{s[0], s[0], s[0]};  // half extents of the geom's bounding box
    if (type == 3) half[2] = s[0] + s[1];
    if (type == 4 || type == 6) half = s;
    if (type == 5) half[2] = s[1];
    int m[3];
    for (int a = 0; a < 3; ++a) m[a] = static_cast<int>(std::floor(half[a] / spacing_m));
    // Lattice points (i + ½ or i) spacing about the centre: symmetric, so a symmetric geom gets a symmetric set.
    for (int k = -m[2]; k <= m[2]; ++k)
      for (int j = -m[1]; j <= m[1]; ++j)
        for (int i = -m[0]; i <= m[0]; ++i) {
          const Vec3 x{i * spacing_m, j * spacing_m, k * spacing_m};
          if (depth(x) >= margin_m) out.push_back({g, model.geomBody(g), x, 0.0, spacing_m * spacing_m * spacing_m});
        }
  }
  return out;
}

Vec3 markerWorld(const rigid::RigidData& data, const SurfaceMarker3& m) {
  const double* p = data.geomPosition(m.geom);
  const double* R = data.geomRotation(m.geom);
  const Vec3& x = m.local_m;
  return {R[0] * x[0] + R[1] * x[1] + R[2] * x[2] + p[0], R[3] * x[0] + R[4] * x[1] + R[5] * x[2] + p[1],
          R[6] * x[0] + R[7] * x[1] + R[8] * x[2] + p[2]};
}

}  // namespace creaturelab::coupling3d
