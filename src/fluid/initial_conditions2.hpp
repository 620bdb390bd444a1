#pragma once
// Initial velocity fields. These functions only write face velocities; call
// FluidSolver2::makeDivergenceFree() afterwards so that the walls hold and ∇·u = 0 exactly.
// Fields built from a stream function ψ at cell corners, u = ∂ψ/∂y, v = −∂ψ/∂x by differences,
// are discretely divergence-free by construction.

#include <numbers>

#include "fluid/mac_grid2.hpp"

namespace creaturelab::fluid {

/// Taylor–Green vortex on [0, W] × [0, H] with k_x = π/W, k_y = π/H:
///   u =  A sin(k_x x) cos(k_y y) e^{−ν (k_x² + k_y²) t},
///   v = −A (k_x/k_y) cos(k_x x) sin(k_y y) e^{−ν (k_x² + k_y²) t}.
/// On [0, π]² this is u = sin x cos y e^{−2νt}, v = −cos x sin y e^{−2νt}: an exact solution of
/// Eq. 1 with free-slip walls (its advection term is a pressure gradient), whose kinetic energy
/// decays as e^{−4νt} (twice the velocity rate).
struct TaylorGreenVortex {
  double amplitude_m_per_s = 1.0;
};
Vec2 taylorGreenVelocity_m_per_s(Vec2 position_m, double time_s, double width_m, double height_m,
                                   double amplitude_m_per_s, double kinematic_viscosity_m2_per_s);
/// Velocity decay rate ν (k_x² + k_y²), 1/s.
double taylorGreenDecayRate_per_s(double width_m, double height_m, double kinematic_viscosity_m2_per_s);
void setTaylorGreen(MacGrid2& grid, const TaylorGreenVortex& vortex);

/// Two counter-rotating smooth vortices (Kaufmann–Scully profile, u_θ = Γ r / (2π (r² + r_c²)),
/// stream function ψ = −Γ/(4π) ln(r² + r_c²)) that propel each other along heading_rad.
/// Positions are fractions of the domain width/height; no image vortices (the walls are
/// imposed by the projection that follows).
struct VortexPair {
  double centre_x_fraction = 0.5;                ///< midpoint of the pair, fraction of the width
  double centre_y_fraction = 0.6;                ///< fraction of the height
  double separation_fraction = 0.2;              ///< distance between the cores, fraction of the width
  double core_radius_fraction = 0.04;            ///< r_c, fraction of the width
  double circulation_m2_per_s = 1e-3;            ///< |Γ| of each vortex
  double heading_rad = -0.5 * std::numbers::pi;  ///< direction of travel (default: downwards)
};
void setVortexPair(MacGrid2& grid, const VortexPair& pair);

/// A shear layer u = U tanh((y − y0)/δ), perturbed by a stream function
/// ψ' = ε U (W / 2πk) cos(2πk x / W) exp(−((y − y0)/2δ)²) that seeds k Kelvin–Helmholtz waves.
struct ShearLayer {
  double speed_m_per_s = 0.01;          ///< U
  double thickness_fraction = 0.025;    ///< δ, fraction of the height
  double centre_y_fraction = 0.5;       ///< y0, fraction of the height
  double perturbation_fraction = 0.05;  ///< ε
  int perturbation_waves = 2;           ///< k
};
void setShearLayer(MacGrid2& grid, const ShearLayer& layer);

/// Fluid at rest.
void setRest(MacGrid2& grid);

}  // namespace creaturelab::fluid
