#pragma once
// The markers' forcing solve shared by rigid_fluid_coupling3.hpp and flesh_fluid_coupling3.hpp: vector
// helpers on marker vectors and face fields, and the preconditioned conjugate gradients on the marker
// forces F (Taira & Colonius 2007, J. Comput. Phys. 225, the immersed-boundary projection; each coupling's
// comment derives its operator). Header-only; deterministic (fixed summation order), no I/O.
#include <algorithm>
#include <cmath>
#include <vector>

#include "coupling3d/transfer3.hpp"
#include "fluid3d/mac_grid3.hpp"

namespace creaturelab::coupling3d::forcing {

inline void zero(fluid3d::FaceField3& field) {
  for (fluid3d::Array3& a : field) a.fill(0.0);
}

/// a += s b, component by component.
inline void addScaled(fluid3d::FaceField3& a, double s, const fluid3d::FaceField3& b) {
  for (int c = 0; c < 3; ++c) {
    double* p = a[c].data();
    const double* q = b[c].data();
    for (std::size_t t = 0; t < a[c].size(); ++t) p[t] += s * q[t];
  }
}

inline double dot(const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  double s = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) s += x[k][0] * y[k][0] + x[k][1] * y[k][1] + x[k][2] * y[k][2];
  return s;
}

inline double maxAbs(const std::vector<Vec3>& x) {
  double m = 0.0;
  for (const Vec3& v : x) m = std::max({m, std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  return m;
}

/// The solve's work vectors (kept by the caller between steps to reuse their storage).
struct ForcingWork3 {
  std::vector<Vec3> z, direction, applied;
};

/// Preconditioned conjugate gradients on A F = b for the marker forces F (N), A symmetric positive
/// definite, from `force` (the warm start) and `residual` = b − A force (m/s, given). Each iteration:
///   apply(p, Ap)            Ap = A p; the fluid's response to p left where `advance` finds it;
///   advance(α)              the fluid's velocity += α times that response (u^{n+1} built with F);
///   precondition(r, z)      z = M⁻¹ r.
/// Stops when max |r| <= tolerance (m/s), after max_iterations, or when pᵀAp or rᵀz is not positive
/// (round-off at convergence). Returns the iterations done; force and residual hold the result.
template <class Apply, class Advance, class Precondition>
int conjugateGradients(std::vector<Vec3>& force, std::vector<Vec3>& residual, ForcingWork3& w, double tolerance,
                       int max_iterations, Apply&& apply, Advance&& advance, Precondition&& precondition) {
  const std::size_t n = force.size();
  w.z.resize(n);
  w.direction.resize(n);
  w.applied.resize(n);
  precondition(residual, w.z);
  double rz = dot(w.z, residual);
  w.direction = w.z;
  int iterations = 0;
  while (maxAbs(residual) > tolerance && iterations < max_iterations && rz > 0) {
    ++iterations;
    apply(w.direction, w.applied);
    const double pap = dot(w.direction, w.applied);
    if (!(pap > 0)) break;
    const double alpha = rz / pap;
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) {
        force[k][a] += alpha * w.direction[k][a];
        residual[k][a] -= alpha * w.applied[k][a];
      }
    advance(alpha);
    const double rz_old = rz;
    precondition(residual, w.z);
    rz = dot(w.z, residual);
    const double beta = rz / rz_old;
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) w.direction[k][a] = w.z[k][a] + beta * w.direction[k][a];
  }
  return iterations;
}

}  // namespace creaturelab::coupling3d::forcing
