#pragma once
// Analytic initial fields for the 3-D solver.
//
// The Arnold–Beltrami–Childress (ABC) flow in a periodic box of side 2π/k:
//   u = A sin(k z) + C cos(k y),   v = B sin(k x) + A cos(k z),   w = C sin(k y) + B cos(k x),
// a Beltrami field (∇ × u = k u), so u × ω = 0 and u·∇u = ∇(|u|²/2) is a gradient that the
// pressure absorbs: u(t) = u(0) exp(−ν k² t) solves the Navier–Stokes equations exactly
// (Dombre et al. 1986, J. Fluid Mech. 167, §1; Ethier & Steinman 1994 use the same property).

#include <array>

#include "fluid3d/mac_grid3.hpp"

namespace creaturelab::fluid3d {

struct AbcFlow {
  double a_m_per_s = 1.0, b_m_per_s = 1.0, c_m_per_s = 1.0;
  double wavenumber_per_m = 1.0;
  double viscosity_m2_per_s = 0.0;
  /// Exact velocity at position x (m) and time t (s).
  std::array<double, 3> velocity_m_per_s(const std::array<double, 3>& x_m, double t_s) const;
};

/// The 3-D Taylor–Green vortex (Taylor & Green 1937, Proc. R. Soc. A 158, §2) in a box of side 2π/k:
///   u = A sin(k x) cos(k y) cos(k z),   v = −A cos(k x) sin(k y) cos(k z),   w = 0,
/// divergence-free, periodic, and free-slip on the planes x, y, z = 0 and π/k. It is not a steady
/// shape of the Navier–Stokes equations (u·∇u is not a gradient: energy cascades to smaller scales),
/// but in the Stokes limit (Reynolds number A / (ν k) → 0) it decays as exp(−3 ν k² t), its kinetic
/// energy as exp(−6 ν k² t); at Reynolds number Re the relative departure is of order Re².
struct TaylorGreen3 {
  double amplitude_m_per_s = 1.0;
  double wavenumber_per_m = 1.0;
  double viscosity_m2_per_s = 0.0;
  /// Velocity at x (m) and t (s) in the Stokes limit.
  std::array<double, 3> velocity_m_per_s(const std::array<double, 3>& x_m, double t_s) const;
};

/// Samples a flow (anything with velocity_m_per_s(x, t)) at time t_s onto the grid's faces.
template <class Flow>
void setFlow(MacGrid3& grid, const Flow& flow, double t_s) {
  for (int a = 0; a < 3; ++a) {
    Array3& u = grid.velocity_m_per_s[a];
    for (int k = 0; k < u.nz(); ++k)
      for (int j = 0; j < u.ny(); ++j)
        for (int i = 0; i < u.nx(); ++i) u(i, j, k) = flow.velocity_m_per_s(grid.facePosition_m(a, i, j, k), t_s)[a];
  }
}

/// Samples the flow at time t_s onto the grid's faces.
void setAbcFlow(MacGrid3& grid, const AbcFlow& flow, double t_s);
/// max over faces of |u_grid − u_exact(t_s)|.
double maxAbcError_m_per_s(const MacGrid3& grid, const AbcFlow& flow, double t_s);

}  // namespace creaturelab::fluid3d
