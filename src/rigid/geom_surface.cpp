#include "rigid/geom_surface.hpp"

#include <mujoco/mujoco.h>

#include <cmath>
#include <numbers>

namespace creaturelab::rigid {
namespace {

double area2(const Triangle& t) {
  const double u[3] = {t.b[0] - t.a[0], t.b[1] - t.a[1], t.b[2] - t.a[2]};
  const double v[3] = {t.c[0] - t.a[0], t.c[1] - t.a[1], t.c[2] - t.a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

void push(std::vector<Triangle>& out, const Triangle& t) {
  if (area2(t) > 1e-14) out.push_back(t);  // poles of a profile give empty triangles
}

// A solid of revolution about z: rings (radius, z) from the bottom pole to the top, `slices`
// points each; quads between rings split in two, counter-clockwise seen from outside. The diagonal
// alternates between the quadrants of the angle and between z < 0 and z > 0, so that with slices a
// multiple of 4 the triangles are mirror images across x = 0, y = 0 and (for a profile symmetric in
// z) z = 0, as the solid is.
std::vector<Triangle> revolve(const std::vector<std::pair<double, double>>& profile, int slices, const Vec3& scale) {
  std::vector<Triangle> out;
  auto point = [&](int k, int j) {
    const double phi = 2 * std::numbers::pi * j / slices;
    return Vec3{scale[0] * profile[k].first * std::cos(phi), scale[1] * profile[k].first * std::sin(phi),
                scale[2] * profile[k].second};
  };
  for (int k = 0; k + 1 < int(profile.size()); ++k)
    for (int j = 0; j < slices; ++j) {
      const Vec3 a = point(k, j), b = point(k, j + 1), c = point(k + 1, j + 1), d = point(k + 1, j);
      const int quadrant = (4 * j + 2) / slices;  // of the quad's middle angle
      const int upper = profile[k].second + profile[k + 1].second > 0 ? 1 : 0;
      if ((quadrant + upper) % 2 == 0) {
        push(out, {a, b, c});
        push(out, {a, c, d});
      } else {
        push(out, {a, b, d});
        push(out, {b, c, d});
      }
    }
  return out;
}

// Profile of a capsule of radius r and half-length h (h = 0: a sphere): two hemispheres of
// `rings` rings each.
std::vector<std::pair<double, double>> capsuleProfile(double r, double h, int rings) {
  std::vector<std::pair<double, double>> p;
  for (int k = 0; k <= rings; ++k) {
    const double theta = -std::numbers::pi / 2 + (std::numbers::pi / 2) * k / rings;
    p.push_back({r * std::cos(theta), -h + r * std::sin(theta)});
  }
  for (int k = 0; k <= rings; ++k) {
    const double theta = (std::numbers::pi / 2) * k / rings;
    if (k == 0 && h == 0) continue;  // the sphere's equator once
    p.push_back({r * std::cos(theta), h + r * std::sin(theta)});
  }
  return p;
}

std::vector<Triangle> box(const double* s) {
  std::vector<Triangle> out;
  // Each face: centre along axis a at sign, spanned by the other two axes in right-handed order.
  for (int a = 0; a < 3; ++a)
    for (int sign : {-1, 1}) {
      const int u = (a + 1) % 3, v = (a + 2) % 3;
      auto corner = [&](double su, double sv) {
        Vec3 p{};
        p[a] = sign * s[a];
        p[u] = su * s[u];
        p[v] = sv * s[v];
        return p;
      };
      // e_u x e_v = e_a: counter-clockwise in (u, v) faces +a; reversed on the -a face. Four
      // triangles about the face's centre, so that the face is its own mirror image across u = 0 and v = 0.
      Vec3 p00 = corner(-1, -1), p10 = corner(1, -1), p11 = corner(1, 1), p01 = corner(-1, 1);
      if (sign < 0) std::swap(p10, p01);
      const Vec3 centre = corner(0, 0);
      out.push_back({centre, p00, p10});
      out.push_back({centre, p10, p11});
      out.push_back({centre, p11, p01});
      out.push_back({centre, p01, p00});
    }
  return out;
}

std::vector<Triangle> mesh(const mjModel* m, int id) {
  std::vector<Triangle> out;
  const float* v = m->mesh_vert + 3 * m->mesh_vertadr[id];
  const int* f = m->mesh_face + 3 * m->mesh_faceadr[id];
  for (int k = 0; k < m->mesh_facenum[id]; ++k) {
    auto p = [&](int i) { return Vec3{v[3 * f[3 * k + i]], v[3 * f[3 * k + i] + 1], v[3 * f[3 * k + i] + 2]}; };
    push(out, {p(0), p(1), p(2)});
  }
  return out;
}

}  // namespace

std::vector<GeomSurface> geomSurfaces(const RigidModel& model, int slices) {
  const mjModel* m = model.raw();
  const int rings = std::max(1, slices / 4);
  std::vector<GeomSurface> out;
  for (int g = 0; g < m->ngeom; ++g) {
    const double* s = m->geom_size + 3 * g;
    GeomSurface surface{g, m->geom_bodyid[g], {}};
    switch (m->geom_type[g]) {
      case mjGEOM_BOX: surface.triangles = box(s); break;
      case mjGEOM_SPHERE: surface.triangles = revolve(capsuleProfile(s[0], 0, rings), slices, {1, 1, 1}); break;
      case mjGEOM_CAPSULE: surface.triangles = revolve(capsuleProfile(s[0], s[1], rings), slices, {1, 1, 1}); break;
      case mjGEOM_ELLIPSOID:
        surface.triangles = revolve(capsuleProfile(1, 0, rings), slices, {s[0], s[1], s[2]});
        break;
      case mjGEOM_CYLINDER:
        surface.triangles = revolve({{0, -s[1]}, {s[0], -s[1]}, {s[0], s[1]}, {0, s[1]}}, slices, {1, 1, 1});
        break;
      case mjGEOM_MESH: surface.triangles = mesh(m, m->geom_dataid[g]); break;
      default: continue;  // planes, height fields: the ground, not part of a creature
    }
    out.push_back(std::move(surface));
  }
  return out;
}

}  // namespace creaturelab::rigid
