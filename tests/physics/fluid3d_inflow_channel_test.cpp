// Flow from an inflow floor between two no-slip walls (periodic along y) develops into plane
// Poiseuille flow, w(x) = 6 U x (h − x) / h², before the open top: the inflow side, the no-slip ghosts
// and the open side together against an analytic profile. The steady state keeps an error beside the
// walls that falls with the step as well as the cell: the projection follows the viscous stage
// without the previous pressure (the non-incremental scheme of Guermond, Minev & Shen 2006, Comput.
// Methods Appl. Mech. Engrg. 195, §3.1, whose numerical boundary layer is of width √(ν dt)), so the
// grid is refined with ν dt / dx² fixed.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid3d/fluid_solver3.hpp"

namespace creaturelab::fluid3d {
namespace {

constexpr double kWidth_m = 0.08;
constexpr double kSpeed_m_per_s = 0.01;  // mean speed; Reynolds number U h / ν = 0.8

// Largest |w − w_Poiseuille| / max w_Poiseuille across the channel, three quarters of the way up,
// after 12 s (eighteen times the slowest viscous mode's time h² / (π² ν) = 0.65 s) with `n` cells
// across and the step dt (ν dt / dx² = 1 by default).
double profileError(int n, ProjectionScheme3 projection = ProjectionScheme3::non_incremental, double dt = 0.0) {
  FluidParams3 p;
  const double dx = kWidth_m / n;
  p.cells_x = n, p.cells_y = 2, p.cells_z = 4 * n;
  p.domain_x_m = kWidth_m, p.domain_y_m = 2 * dx, p.domain_z_m = 4 * kWidth_m;
  p.boundaries.axis[0] = {BoundaryType3::no_slip, BoundaryType3::no_slip};
  p.boundaries.axis[1] = {BoundaryType3::periodic, BoundaryType3::periodic};
  p.boundaries.axis[2] = {BoundaryType3::inflow, BoundaryType3::open, kSpeed_m_per_s, 0.0};
  p.kinematic_viscosity_m2_per_s = 1e-3;
  p.projection = projection;
  p.viscosity_scheme = projection == ProjectionScheme3::incremental ? ViscosityScheme3::backward_euler
                                                                    : ViscosityScheme3::crank_nicolson;
  p.pressure_tolerance = 1e-12;
  FluidSolver3 solver(p);
  solver.makeDivergenceFree();
  if (dt == 0.0) dt = dx * dx / p.kinematic_viscosity_m2_per_s;
  const int steps = int(std::lround(12.0 / dt));
  for (int s = 0; s < steps; ++s) solver.step(dt);
  const Array3& w = solver.grid().velocity_m_per_s[2];
  const double peak = 1.5 * kSpeed_m_per_s;
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * dx;
    const double exact = 6.0 * kSpeed_m_per_s * x * (kWidth_m - x) / (kWidth_m * kWidth_m);
    worst = std::max(worst, std::fabs(w(i, 0, 3 * n) - exact) / peak);
  }
  return worst;
}

// Measured: 0.043 with 8 cells across, 0.015 with 16 (order 1.5); the windows leave 15% and 0.2.
TEST(Fluid3dInflowChannel, DevelopsIntoPoiseuilleFlow) {
  const double coarse = profileError(8), fine = profileError(16);
  EXPECT_LT(coarse, 0.05) << coarse;
  EXPECT_LT(fine, 0.018) << fine;
  EXPECT_GT(std::log2(coarse / fine), 1.3) << coarse << " " << fine;
}

// The incremental projection (backward Euler viscosity) has a steady state that does not depend on the
// step: measured 0.0147 (8 cells) and 0.0040 (16 cells) at any dt from 0.00625 to 0.4 s (ν dt / dx² from
// 0.25 to 16), against 0.19 for the non-incremental scheme on 8 cells at 0.4 s.
TEST(Fluid3dInflowChannel, IncrementalProjectionSteadyStateDoesNotDependOnTheStep) {
  const ProjectionScheme3 incremental = ProjectionScheme3::incremental;
  const double coarse = profileError(8, incremental, 0.4), fine = profileError(16, incremental, 0.1);
  EXPECT_NEAR(profileError(16, incremental, 0.2), fine, 1e-4) << fine;
  EXPECT_LT(fine, 0.005) << fine;
  EXPECT_GT(std::log2(coarse / fine), 1.7) << coarse << " " << fine;
  EXPECT_GT(profileError(8, ProjectionScheme3::non_incremental, 0.4), 0.1);
}

}  // namespace
}  // namespace creaturelab::fluid3d
