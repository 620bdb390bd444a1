#pragma once
// Simple wind forces, Lentine et al. 2010 §3.1 Eq. 2:
// for each surface triangle i with area A, inward unit normal n and relative wind velocity
// u_rel = u(centre) - v_triangle(centre),
//     F_di = sign(u_rel . n) A rho (u_rel . n)^2 n,
// "equally distributed to each of the triangle's nodes". The three equal node forces on a rigid
// body are one force at the centroid (sum r_k x F/3 = centroid x F), so each F_di is applied at
// its triangle's centre. Note what Eq. 2 says for a closed body: the upstream face (u.n > 0) is
// pushed along n, with the flow, and the downstream face (u.n < 0) is pushed along -n, also with
// the flow; a plate across a wind u feels 2 rho A u^2 (front pressure plus back suction).
#include <functional>
#include <vector>

#include "control/force_model.hpp"
#include "rigid/geom_surface.hpp"

namespace creaturelab::control {

// Wind velocity (m/s) at a world point (m) and time (s).
using WindField = std::function<Vec3(const Vec3& point_m, double time_s)>;

WindField constantWind(const Vec3& u_m_per_s);

class SimpleWind final : public ForceModel {
 public:
  // Surfaces from rigid::geomSurfaces(); those on the world body (static scenery) feel no force
  // that matters and are dropped.
  SimpleWind(std::vector<rigid::GeomSurface> surfaces, double density_kg_per_m3, WindField wind);
  void apply(rigid::RigidData& data, std::vector<Vec3>& body_force_n) const override;
  int triangles() const;

 private:
  std::vector<rigid::GeomSurface> surfaces_;
  double density_kg_per_m3_;
  WindField wind_;
};

// Eq. 2 for one triangle (world coordinates): the force (N) on it.
Vec3 triangleWindForce(const rigid::Triangle& t, const Vec3& u_rel_m_per_s, double density_kg_per_m3);

}  // namespace creaturelab::control
