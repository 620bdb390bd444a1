// Taylor–Green vortex on [0, π]² with free-slip walls (an exact solution of Eq. 1 of Rudolf &
// Mould 2009, §3.2): u = sin x cos y e^{−2νt}, v = −cos x sin y e^{−2νt}, kinetic energy
// ∝ e^{−4νt}. Measures, per advection scheme and grid, the velocity error at t = T, the
// observed order of convergence, and the effective viscosity ν_eff fitted to the kinetic-energy
// decay (KE ∝ e^{−4 ν_eff t}: physical plus numerical viscosity).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::fluid {
namespace {

constexpr double kViscosity = 0.01;  // m²/s; Re = U L / ν ≈ 314 with U = 1 m/s, L = π m
constexpr double kEndTime = 2.0;     // s
constexpr double kCourant = 0.5;     // dt = kCourant dx / U

struct TaylorGreenRun {
  int cells = 0;
  double relative_l2_error = 0.0;
  double effective_viscosity = 0.0;
  double max_divergence = 0.0;
};

TaylorGreenRun run_taylor_green(AdvectionScheme scheme, int cells, double courant = kCourant) {
  FluidParams params;
  params.domain_width_m = params.domain_height_m = std::numbers::pi;
  params.cells_x = params.cells_y = cells;
  params.density_kg_per_m3 = 1.0;
  params.kinematic_viscosity_m2_per_s = kViscosity;
  params.advection = scheme;
  params.time_step_policy = TimeStepPolicy::fixed;
  const double dx = std::numbers::pi / cells;
  const int steps = static_cast<int>(std::ceil(kEndTime / (courant * dx)));
  params.fixed_step_s = kEndTime / steps;
  FluidSolver2 solver(params);
  setTaylorGreen(solver.grid(), TaylorGreenVortex{1.0});
  solver.makeDivergenceFree();

  // Least-squares fit of ln KE = a − 4 ν_eff t over every step.
  double st = 0, sy = 0, stt = 0, sty = 0;
  int samples = 0;
  auto sample = [&](double t, double ke) {
    const double y = std::log(ke);
    st += t, sy += y, stt += t * t, sty += t * y;
    ++samples;
  };
  sample(0.0, solver.kineticEnergy_joule_per_m());
  TaylorGreenRun run;
  run.cells = cells;
  for (int s = 0; s < steps; ++s) {
    const FluidStepReport report = solver.step();
    sample(report.time_s, report.kinetic_energy_joule_per_m);
    run.max_divergence = std::max(run.max_divergence, report.max_divergence_per_s);
  }
  const double slope = (samples * sty - st * sy) / (samples * stt - st * st);
  run.effective_viscosity = -slope / 4.0;

  const MacGrid2& g = solver.grid();
  const double w = g.width_m(), h = g.height_m(), t = solver.time_s();
  double err2 = 0.0, ref2 = 0.0;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i <= g.nx; ++i) {
      const double exact = taylorGreenVelocity_m_per_s(g.uPosition_m(i, j), t, w, h, 1.0, kViscosity).x;
      err2 += (g.u_m_per_s(i, j) - exact) * (g.u_m_per_s(i, j) - exact);
      ref2 += exact * exact;
    }
  }
  for (int j = 0; j <= g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double exact = taylorGreenVelocity_m_per_s(g.vPosition_m(i, j), t, w, h, 1.0, kViscosity).y;
      err2 += (g.v_m_per_s(i, j) - exact) * (g.v_m_per_s(i, j) - exact);
      ref2 += exact * exact;
    }
  }
  run.relative_l2_error = std::sqrt(err2 / ref2);
  return run;
}

std::vector<TaylorGreenRun> convergence_study(AdvectionScheme scheme) {
  std::vector<TaylorGreenRun> runs;
  for (int cells : {32, 64, 128}) runs.push_back(run_taylor_green(scheme, cells));
  std::printf("Taylor-Green, %s, nu = %g m^2/s, T = %g s, CFL %g\n", std::string(to_string(scheme)).c_str(), kViscosity,
              kEndTime, kCourant);
  std::printf("  cells  rel. L2 error  order  nu_eff (m^2/s)  nu_eff/nu  max div (1/s)\n");
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const double order = k == 0 ? NAN : std::log2(runs[k - 1].relative_l2_error / runs[k].relative_l2_error);
    std::printf("  %5d  %13.4e  %5.2f  %14.5e  %9.3f  %12.3e\n", runs[k].cells, runs[k].relative_l2_error, order,
                runs[k].effective_viscosity, runs[k].effective_viscosity / kViscosity, runs[k].max_divergence);
    const std::string key = std::string(to_string(scheme)) + "_" + std::to_string(runs[k].cells);
    ::testing::Test::RecordProperty(key + "_error", std::to_string(runs[k].relative_l2_error));
    ::testing::Test::RecordProperty(key + "_nu_eff", std::to_string(runs[k].effective_viscosity));
    // max |∇·u| ≤ 1e-10 max|u| / dx after every step (max|u| ≤ 1 here).
    EXPECT_LE(runs[k].max_divergence, 1e-10 / (std::numbers::pi / runs[k].cells));
    // The fitted viscosity is the physical one plus a positive numerical part.
    EXPECT_GT(runs[k].effective_viscosity, kViscosity);
    if (k > 0) {
      EXPECT_LT(runs[k].relative_l2_error, runs[k - 1].relative_l2_error);
      // Stam's splitting (advect without pressure, then project) is first order in time and
      // dt ∝ dx here, so both schemes converge at first order.
      EXPECT_GE(order, 0.85) << to_string(scheme) << " at " << runs[k].cells << " cells";
      // The numerical viscosity halves with each refinement.
      const double excess = runs[k].effective_viscosity - kViscosity;
      const double previous_excess = runs[k - 1].effective_viscosity - kViscosity;
      EXPECT_LT(excess, 0.6 * previous_excess);
    }
  }
  return runs;
}

TEST(TaylorGreen, BothSchemesConvergeAndMacCormackIsMoreAccurate) {
  const std::vector<TaylorGreenRun> sl = convergence_study(AdvectionScheme::semi_lagrangian);
  const std::vector<TaylorGreenRun> mc = convergence_study(AdvectionScheme::maccormack);
  for (std::size_t k = 0; k < sl.size(); ++k) {
    EXPECT_LT(mc[k].relative_l2_error, 0.5 * sl[k].relative_l2_error) << sl[k].cells << " cells";
    EXPECT_LT(mc[k].effective_viscosity, sl[k].effective_viscosity) << sl[k].cells << " cells";
  }
  // At 128 cells the semi-Lagrangian scheme's numerical viscosity is about half of ν, MacCormack's less.
  EXPECT_LT(sl.back().effective_viscosity, 1.7 * kViscosity);
  EXPECT_LT(mc.back().effective_viscosity, 1.25 * kViscosity);
}

// MacCormack's remaining error is the splitting's, proportional to dt: at a fixed grid a
// five times smaller step makes it about five times smaller (semi-Lagrangian's is dominated by
// interpolation and barely moves).
TEST(TaylorGreen, MacCormackErrorIsTemporal) {
  const TaylorGreenRun coarse_step = run_taylor_green(AdvectionScheme::maccormack, 64, 0.5);
  const TaylorGreenRun fine_step = run_taylor_green(AdvectionScheme::maccormack, 64, 0.1);
  std::printf("MacCormack, 64 cells: error %.3e at CFL 0.5, %.3e at CFL 0.1 (ratio %.2f)\n",
              coarse_step.relative_l2_error, fine_step.relative_l2_error,
              coarse_step.relative_l2_error / fine_step.relative_l2_error);
  EXPECT_GT(coarse_step.relative_l2_error / fine_step.relative_l2_error, 3.5);
}

// The Eulerian flux-form scheme (upwind2_rk2) on the whole step at the same CFL (0.5, its
// stability bound): first order like the others (the splitting), and at 64 cells and CFL 0.1
// its error compared with the semi-Lagrangian schemes' at small steps: on this smooth,
// well-resolved field MacCormack stays ahead.
TEST(TaylorGreen, Upwind2Rk2ConvergesAndBeatsSemiLagrangianAtSmallSteps) {
  const std::vector<TaylorGreenRun> up = convergence_study(AdvectionScheme::upwind2_rk2);
  const TaylorGreenRun up_small = run_taylor_green(AdvectionScheme::upwind2_rk2, 64, 0.1);
  const TaylorGreenRun mc_small = run_taylor_green(AdvectionScheme::maccormack, 64, 0.1);
  const TaylorGreenRun sl_small = run_taylor_green(AdvectionScheme::semi_lagrangian, 64, 0.1);
  std::printf("64 cells, CFL 0.1: error semi-Lagrangian %.3e, MacCormack %.3e, upwind2_rk2 %.3e; "
              "nu_eff/nu %.3f, %.3f, %.3f\n",
              sl_small.relative_l2_error, mc_small.relative_l2_error, up_small.relative_l2_error,
              sl_small.effective_viscosity / kViscosity, mc_small.effective_viscosity / kViscosity,
              up_small.effective_viscosity / kViscosity);
  EXPECT_LT(up_small.relative_l2_error, 0.25 * sl_small.relative_l2_error);
  EXPECT_LT(up_small.effective_viscosity - kViscosity, 0.25 * (sl_small.effective_viscosity - kViscosity));
  EXPECT_LT(up.back().effective_viscosity, 1.25 * kViscosity);
}

}  // namespace
}  // namespace creaturelab::fluid
