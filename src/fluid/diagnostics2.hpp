#pragma once
// Observables of a MAC velocity field: divergence, kinetic energy, CFL number, vorticity.
// Stateless functions of the grid (and walls where ghost values matter).

#include <vector>

#include "fluid/fluid_params.hpp"
#include "fluid/mac_grid2.hpp"
#include "fluid/worker_pool.hpp"

namespace creaturelab::fluid {

/// max over cells of |∇·u| = |u_E − u_W + v_N − v_S| / dx, 1/s.
double maxDivergence_per_s(const MacGrid2& grid);

/// max over cells of |u_E − u_W + v_N − v_S| (= dx |∇·u|), m/s; +infinity if not finite.
double maxAbsFluxSum_m_per_s(const MacGrid2& grid, WorkerPool* workers = nullptr);

/// Kinetic energy per metre of depth, ½ ρ ∫ |u|² dA, J/m: each component summed over its faces
/// with trapezoidal weights (½ on faces lying on a wall).
double kineticEnergy_joule_per_m(const MacGrid2& grid, double density_kg_per_m3);

/// max(|u|, |v|) over all faces, m/s; +infinity if any value is NaN or infinite.
double maxVelocityComponent_m_per_s(const MacGrid2& grid, WorkerPool* workers = nullptr);

/// CFL number max(|u|, |v|) dt / dx (Griebel et al. 1998, ch. 3 time-step control).
double cflNumber(const MacGrid2& grid, double dt_s);

/// The per-step observables in one pass over the faces.
struct FlowSummary {
  double max_velocity_component_m_per_s = 0.0;  ///< as maxVelocityComponent_m_per_s()
  double max_divergence_per_s = 0.0;            ///< as maxDivergence_per_s() (+inf if not finite)
  double kinetic_energy_joule_per_m = 0.0;      ///< as kineticEnergy_joule_per_m()
};
/// With workers, threads share the rows; the result is bitwise the same for any thread count.
FlowSummary summarizeFlow(const MacGrid2& grid, double density_kg_per_m3, WorkerPool* workers = nullptr);
/// The same, with scratch for the per-row energies kept by the caller (no allocation per call).
FlowSummary summarizeFlow(const MacGrid2& grid, double density_kg_per_m3, WorkerPool* workers,
                           std::vector<double>& row_energies);

/// Vorticity ω = ∂v/∂x − ∂u/∂y at the (nx + 1) × (ny + 1) cell corners, 1/s, with wall ghost
/// values from the walls (so ω = 0 on free-slip walls).
void vorticityAtCorners(const MacGrid2& grid, const Walls& walls, Array2& omega_per_s);

/// Vorticity at cell centres (mean of the four corners), nx × ny, 1/s.
void vorticityAtCentres(const MacGrid2& grid, const Walls& walls, Array2& omega_per_s);

/// Velocity interpolated to cell centres (mean of the two faces), nx × ny each, m/s.
void velocityAtCentres(const MacGrid2& grid, Array2& u_m_per_s, Array2& v_m_per_s);

}  // namespace creaturelab::fluid
