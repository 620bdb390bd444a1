// The Arnold–Beltrami–Childress flow decays exactly as exp(−ν k² t) in a periodic box
// (fluid3d/initial_conditions3.hpp): the full 3-D step against it over three resolutions, the
// step's order in time, and the two pressure solvers against each other.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>

#include "fluid3d/fluid_solver3.hpp"
#include "fluid3d/initial_conditions3.hpp"

namespace creaturelab::fluid3d {
namespace {

constexpr double kSide_m = 2.0 * std::numbers::pi;  // wavenumber k = 1 per metre
constexpr double kViscosity_m2_per_s = 0.1;
constexpr double kEnd_s = 0.5;  // ν k² t = 0.05

// Amplitudes (m/s) scaled by `speed`: Reynolds number U L / ν ≈ 63 · speed.
AbcFlow flow(double speed) {
  AbcFlow f;
  f.a_m_per_s = 1.0 * speed, f.b_m_per_s = 0.8 * speed, f.c_m_per_s = 0.6 * speed;
  f.viscosity_m2_per_s = kViscosity_m2_per_s;
  return f;
}

// From the exact field at t = 0 to kEnd_s in `steps` equal steps.
std::unique_ptr<FluidSolver3> run(int n, int steps, double speed, PressureSolverType3 pressure,
                                  AdvectionScheme3 advection = AdvectionScheme3::maccormack) {
  FluidParams3 p;
  p.cells_x = p.cells_y = p.cells_z = n;
  p.domain_x_m = p.domain_y_m = p.domain_z_m = kSide_m;
  p.boundaries = Boundaries3::allPeriodic();
  p.kinematic_viscosity_m2_per_s = kViscosity_m2_per_s;
  p.viscosity_scheme = ViscosityScheme3::crank_nicolson;
  p.advection = advection;
  p.pressure_solver = pressure;
  p.pressure_tolerance = 1e-12;
  auto solver = std::make_unique<FluidSolver3>(p);
  setAbcFlow(solver->grid(), flow(speed), 0.0);
  for (int s = 0; s < steps; ++s) solver->step(kEnd_s / steps);
  return solver;
}

double maxDifference(const MacGrid3& x, const MacGrid3& y) {
  double m = 0.0;
  for (int a = 0; a < 3; ++a)
    for (std::size_t t = 0; t < x.velocity_m_per_s[a].size(); ++t)
      m = std::max(m, std::fabs(x.velocity_m_per_s[a].data()[t] - y.velocity_m_per_s[a].data()[t]));
  return m;
}

// Three grids (8³, 16³, 32³) at Re ≈ 6, where the split's first-order time error is small: the error
// falls at second order in space with the two second-order schemes. `steps(r)` gives the steps on
// grid r; the 8³ grid (8 cells per wavelength) is not yet asymptotic, hence its own bound.
template <class Steps>
void expectSecondOrderInSpace(AdvectionScheme3 scheme, Steps steps, double min_first_order) {
  const double speed = 0.1;
  double error[3];
  for (int r = 0; r < 3; ++r) {
    const int n = 8 << r;
    error[r] = maxAbcError_m_per_s(run(n, steps(r), speed, PressureSolverType3::spectral, scheme)->grid(),
                                   flow(speed), kEnd_s);
  }
  const double order1 = std::log2(error[0] / error[1]), order2 = std::log2(error[1] / error[2]);
  std::printf("ABC max error / U (%s): %.3e %.3e %.3e at 8^3 16^3 32^3 with %d, %d, %d steps, orders %.2f %.2f\n",
              std::string(toString(scheme)).c_str(), error[0] / speed, error[1] / speed, error[2] / speed, steps(0),
              steps(1), steps(2), order1, order2);
  EXPECT_GT(order1, min_first_order);
  EXPECT_GT(order2, 1.85);
  EXPECT_LT(error[2], 5e-4 * speed);
}

// Grid and step refined together (4, 8, 16 steps: CFL ≈ 0.03).
TEST(Fluid3dAbc, MacCormackStepConvergesAtSecondOrderInSpace) {
  expectSecondOrderInSpace(AdvectionScheme3::maccormack, [](int r) { return 4 << r; }, 1.8);
}

// 16 steps on every grid (CFL ≤ 0.03): with the step refined with the grid, the upwind scheme's
// smaller spatial error lets the split's O(dt) error show in the orders.
TEST(Fluid3dAbc, UpwindStepConvergesAtSecondOrderInSpace) {
  expectSecondOrderInSpace(AdvectionScheme3::upwind2_rk2, [](int) { return 16; }, 1.7);
}

// At Re ≈ 63 and a fixed 16³ grid, halving the step three times: the differences between
// successive solutions halve, i.e. the split step is first order in time (as the 2-D solver's).
TEST(Fluid3dAbc, SplitStepIsFirstOrderInTime) {
  std::unique_ptr<FluidSolver3> s[3];
  for (int r = 0; r < 3; ++r) s[r] = run(16, 8 << r, 1.0, PressureSolverType3::spectral);
  const double d01 = maxDifference(s[0]->grid(), s[1]->grid()), d12 = maxDifference(s[1]->grid(), s[2]->grid());
  const double order = std::log2(d01 / d12);
  std::printf("ABC differences between 8, 16 and 32 steps at 16^3: %.3e %.3e, order %.2f\n", d01, d12, order);
  EXPECT_GT(order, 0.7);
  EXPECT_LT(order, 1.3);
}

// MG-PCG (to 1e-12) and the exact spectral solve give the same flow after 8 steps.
TEST(Fluid3dAbc, MultigridPcgAndSpectralSolversAgree) {
  const auto spectral = run(16, 8, 1.0, PressureSolverType3::spectral);
  const auto pcg = run(16, 8, 1.0, PressureSolverType3::mg_pcg);
  const double difference = maxDifference(spectral->grid(), pcg->grid());
  std::printf("ABC MG-PCG vs spectral after 8 steps at 16^3: max velocity difference %.3e m/s\n", difference);
  EXPECT_LT(difference, 1e-9);
  EXPECT_LT(pcg->maxDivergence_per_s(), 1e-9);
}

}  // namespace
}  // namespace creaturelab::fluid3d
