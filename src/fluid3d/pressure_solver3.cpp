#include "fluid3d/pressure_solver3.hpp"

#include "fluid3d/pcg_pressure_solver3.hpp"
#include "fluid3d/pressure_operator3.hpp"
#include "fluid3d/spectral_pressure_solver3.hpp"
#include "fluid3d/stencil3.hpp"

namespace creaturelab::fluid3d {

SolveReport3 PressureSolver3::project(MacGrid3& grid, double density_kg_per_m3, double dt_s, bool increment) {
  projectionRhs(grid, rhs_, workers_);
  if (grid.boundaries.closed()) {
    std::vector<double> per_slab;
    subtractConstant3(sum3(rhs_, workers_, per_slab) / static_cast<double>(rhs_.size()), rhs_, workers_);
  }
  // Warm start from the previous pressure, q = p dt / ρ; an increment starts from zero.
  q_ = grid.pressure_pa;
  const double to_q = increment ? 0.0 : dt_s / density_kg_per_m3;
  for (std::size_t t = 0; t < q_.size(); ++t) q_.data()[t] *= to_q;
  const SolveReport3 report = solve(grid.n, grid.boundaries, rhs_, q_);
  subtractGradient(grid, q_, 1.0 / grid.dx_m, workers_);
  const double to_p = density_kg_per_m3 / dt_s;
  if (increment) {
    for (std::size_t t = 0; t < q_.size(); ++t) grid.pressure_pa.data()[t] += q_.data()[t] * to_p;
  } else {
    for (std::size_t t = 0; t < q_.size(); ++t) grid.pressure_pa.data()[t] = q_.data()[t] * to_p;
  }
  return report;
}

std::unique_ptr<PressureSolver3> makePressureSolver(const FluidParams3& params) {
  if (params.pressure_solver == PressureSolverType3::spectral) return std::make_unique<SpectralPressureSolver3>();
  return std::make_unique<MgPcgPressureSolver3>(params.pressure_tolerance, params.pressure_max_iterations);
}

}  // namespace creaturelab::fluid3d
