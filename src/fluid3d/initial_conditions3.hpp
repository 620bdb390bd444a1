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

/// Samples the flow at time t_s onto the grid's faces.
void setAbcFlow(MacGrid3& grid, const AbcFlow& flow, double t_s);
/// max over faces of |u_grid − u_exact(t_s)|.
double maxAbcError_m_per_s(const MacGrid3& grid, const AbcFlow& flow, double t_s);

}  // namespace creaturelab::fluid3d
