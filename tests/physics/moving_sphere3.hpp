#pragma once
// The scene of the leak tests of the 3-D coupling (coupling3d_sphere_test.cpp: a rigid sphere;
// flesh_fluid_leak_test.cpp: a bone in flesh): a sphere of radius 0.15 m on a free joint at (0.25, 0.3,
// 0.3) m of a closed no-slip box of side 0.6 m (n³ cells, ν = 1e-3 m²/s: Re = 15), moved along x at
// 0.05 m/s by steps of 0.05 s; and the measure both take, the fluid's mean velocity inside the sphere.
#include <cmath>
#include <filesystem>
#include <string>

#include "../unit/coupling3d_scenes.hpp"
#include "coupling3d/transfer3.hpp"
#include "fluid3d/mac_grid3.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::coupling3d::testing {

struct MovingSphere {
  static constexpr double dt_s = 0.05, speed_m_per_s = 0.05, radius_m = 0.15;
};

// The sphere's model, written to `dir` as NAME.xml.
inline rigid::RigidModel movingSphereModel(const std::filesystem::path& dir, const std::string& name) {
  return loadScene(dir, name, "<body pos=\"0.25 0.3 0.3\"><freejoint/><geom type=\"sphere\" size=\"0.15\"/></body>",
                   MovingSphere::dt_s);
}

// The closed box of n³ cells (water-like: the test sets another density).
inline fluid3d::FluidParams3 movingSphereBox(int n) {
  return cube(n, 0.6, fluid3d::Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip), 1e-3);
}

// `steps` coupled steps: the fluid advanced, the sphere moved kinematically along x (its reaction not
// applied), the fluid forced.
template <class Coupling>
void moveSphere(Coupling& c, rigid::RigidData& data, int steps) {
  const double dt = MovingSphere::dt_s;
  for (int s = 0; s < steps; ++s) {
    c.advanceFluid(dt);
    data.qpos()[0] += MovingSphere::speed_m_per_s * dt;
    data.kinematics();
    c.forceFluid(data, dt);
  }
}

// |mean u − V| / |V| inside the sphere at `centre` (V its velocity along x): with no flux through its
// surface the interior's mean velocity is the body's (∫ u dV = ∫ x (u·n) dA = V vol), whatever the flow
// inside; averaged over the faces more than the kernel's reach (2 cells) inside.
inline double interiorDeficit(const fluid3d::MacGrid3& g, const double* centre) {
  const double U = MovingSphere::speed_m_per_s;
  const double inner = MovingSphere::radius_m - 2 * g.dx_m;
  Vec3 mean{};
  for (int a = 0; a < 3; ++a) {
    const auto e = g.faceExtents(a);
    int count = 0;
    for (int k = 0; k < e[2]; ++k)
      for (int j = 0; j < e[1]; ++j)
        for (int i = 0; i < e[0]; ++i) {
          const auto x = g.facePosition_m(a, i, j, k);
          if (std::hypot(x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]) < inner) {
            mean[a] += g.velocity_m_per_s[a](i, j, k);
            ++count;
          }
        }
    mean[a] /= count;
  }
  return std::hypot(mean[0] - U, mean[1], mean[2]) / U;
}

}  // namespace creaturelab::coupling3d::testing
