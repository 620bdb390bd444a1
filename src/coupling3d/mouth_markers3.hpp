#pragma once
// The mouths' markers (rigid_fluid_coupling3.hpp's Mouth3: Lentine et al. 2010 §7.2, the swimmer's flux
// through its mouth), shared by RigidFluidCoupling3 and FleshFluidCoupling3. Header-only, no I/O.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "coupling3d/surface_markers3.hpp"

namespace creaturelab::coupling3d {

// A disc of markers (mouth m) in its geom's frame: a centre marker and rings about it, no two neighbours
// farther apart than spacing_m, their areas summing to the disc's.
inline std::vector<SurfaceMarker3> mouthMarkers(const rigid::RigidModel& model, const Mouth3& m, double spacing_m) {
  if (m.geom >= model.geoms())
    throw std::invalid_argument("coupling3d: a mouth's geom " + std::to_string(m.geom) + " is not in the model " + model.path());
  const double len = std::hypot(m.normal_geom[0], m.normal_geom[1], m.normal_geom[2]);
  const Vec3 n{m.normal_geom[0] / len, m.normal_geom[1] / len, m.normal_geom[2] / len};
  // Two tangents: n × (the axis least along n), and n × t1.
  Vec3 e{0.0, 0.0, 0.0};
  e[std::abs(n[0]) <= std::abs(n[1]) && std::abs(n[0]) <= std::abs(n[2]) ? 0 : std::abs(n[1]) <= std::abs(n[2]) ? 1 : 2] = 1;
  Vec3 t1{n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2], n[0] * e[1] - n[1] * e[0]};
  const double l1 = std::hypot(t1[0], t1[1], t1[2]);
  for (double& x : t1) x /= l1;
  const Vec3 t2{n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
  // Ring i (1..rings) at radius i w stands for the annulus (i − ½) w..(i + ½) w, the centre marker for
  // the disc of radius w/2; w = radius / (rings + ½), so the last annulus ends at the rim.
  const int rings = std::max(1, static_cast<int>(std::ceil(m.radius_m / spacing_m - 0.5 - 1e-12)));
  const double w = m.radius_m / (rings + 0.5);
  std::vector<SurfaceMarker3> out;
  SurfaceMarker3 mk;
  mk.geom = m.geom;
  mk.body = model.geomBody(m.geom);
  for (int i = 0; i <= rings; ++i) {
    const double r = i * w;
    const int count = i == 0 ? 1 : static_cast<int>(std::ceil(2.0 * std::numbers::pi * r / spacing_m - 1e-12));
    const double outer = (i + 0.5) * w, inner = i == 0 ? 0.0 : (i - 0.5) * w;
    for (int c = 0; c < count; ++c) {
      const double a = 2.0 * std::numbers::pi * c / count;
      for (int d = 0; d < 3; ++d)
        mk.local_m[d] = m.centre_geom_m[d] + r * (std::cos(a) * t1[d] + std::sin(a) * t2[d]);
      mk.area_m2 = std::numbers::pi * (outer * outer - inner * inner) / count;
      out.push_back(mk);
    }
  }
  return out;
}

/// velocity += flux_m_per_s times the mouth's outward normal in the world at data's pose (its geom's rotation).
inline void addMouthFlux(const rigid::RigidData& data, const Mouth3& mouth, double flux_m_per_s, Vec3& velocity) {
  const double* R = data.geomRotation(mouth.geom);  // row-major, columns the geom's axes
  const double len = std::hypot(mouth.normal_geom[0], mouth.normal_geom[1], mouth.normal_geom[2]);
  for (int a = 0; a < 3; ++a) {
    const double nw = R[3 * a] * mouth.normal_geom[0] + R[3 * a + 1] * mouth.normal_geom[1] + R[3 * a + 2] * mouth.normal_geom[2];
    velocity[a] += flux_m_per_s * nw / len;
  }
}

}  // namespace creaturelab::coupling3d
