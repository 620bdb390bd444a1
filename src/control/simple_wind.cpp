#include "control/simple_wind.hpp"

#include <cmath>

namespace creaturelab::control {

WindField constantWind(const Vec3& u) {
  return [u](const Vec3&, double) { return u; };
}

Vec3 triangleWindForce(const rigid::Triangle& t, const Vec3& u, double rho) {
  const double e1[3] = {t.b[0] - t.a[0], t.b[1] - t.a[1], t.b[2] - t.a[2]};
  const double e2[3] = {t.c[0] - t.a[0], t.c[1] - t.a[1], t.c[2] - t.a[2]};
  // Outward normal times twice the area (geom_surface.hpp orders triangles counter-clockwise).
  const double m[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const double twice_area = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (twice_area == 0) return {};
  const double area = 0.5 * twice_area;
  const Vec3 n = {-m[0] / twice_area, -m[1] / twice_area, -m[2] / twice_area};  // inward
  const double un = u[0] * n[0] + u[1] * n[1] + u[2] * n[2];
  const double magnitude = (un > 0 ? 1.0 : un < 0 ? -1.0 : 0.0) * area * rho * un * un;
  return {magnitude * n[0], magnitude * n[1], magnitude * n[2]};
}

SimpleWind::SimpleWind(std::vector<rigid::GeomSurface> surfaces, double density, WindField wind)
    : density_kg_per_m3_(density), wind_(std::move(wind)) {
  for (auto& s : surfaces)
    if (s.body != 0) surfaces_.push_back(std::move(s));
}

int SimpleWind::triangles() const {
  int n = 0;
  for (const auto& s : surfaces_) n += int(s.triangles.size());
  return n;
}

void SimpleWind::apply(rigid::RigidData& data, std::vector<Vec3>& body_force_n) const {
  body_force_n.assign(data.model().bodies(), Vec3{});
  const double t_s = data.time_s();
  for (const auto& s : surfaces_) {
    const double* p = data.geomPosition(s.geom);
    const double* R = data.geomRotation(s.geom);  // row-major: world = R local + p
    auto world = [&](const Vec3& x) {
      return Vec3{R[0] * x[0] + R[1] * x[1] + R[2] * x[2] + p[0], R[3] * x[0] + R[4] * x[1] + R[5] * x[2] + p[1],
                  R[6] * x[0] + R[7] * x[1] + R[8] * x[2] + p[2]};
    };
    // One wrench per geom about its centre: the sum of the triangles' forces and their moments.
    Vec3 total{}, moment{};
    for (const auto& local : s.triangles) {
      const rigid::Triangle t{world(local.a), world(local.b), world(local.c)};
      const Vec3 centre = {(t.a[0] + t.b[0] + t.c[0]) / 3, (t.a[1] + t.b[1] + t.c[1]) / 3, (t.a[2] + t.b[2] + t.c[2]) / 3};
      const Vec3 u = wind_(centre, t_s);
      const Vec3 v = data.pointVelocity(s.body, centre);
      const Vec3 f = triangleWindForce(t, {u[0] - v[0], u[1] - v[1], u[2] - v[2]}, density_kg_per_m3_);
      if (f[0] == 0 && f[1] == 0 && f[2] == 0) continue;
      const double r[3] = {centre[0] - p[0], centre[1] - p[1], centre[2] - p[2]};
      moment[0] += r[1] * f[2] - r[2] * f[1];
      moment[1] += r[2] * f[0] - r[0] * f[2];
      moment[2] += r[0] * f[1] - r[1] * f[0];
      for (int k = 0; k < 3; ++k) total[k] += f[k];
    }
    data.applyWrenchAt(s.body, total, moment, {p[0], p[1], p[2]});
    for (int k = 0; k < 3; ++k) body_force_n[s.body][k] += total[k];
  }
}

}  // namespace creaturelab::control
