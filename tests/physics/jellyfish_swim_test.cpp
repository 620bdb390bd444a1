// The swimming jellyfish of Rudolf & Mould 2009 (§3.1-3.3):
// bell, muscles and fluid coupled by the immersed boundary (jellyfish/swimmer.hpp), on short runs
// (one to three cycles) on the paper's 100² grid (and 50²) at a 0.01 s step: determinism, mirror
// symmetry, the depth of the contraction against the body's static equilibrium, the sign of the
// work, the stability of the semi-implicit step against the explicit one (and of the force at the
// step's middle over a whole 10 s window), and time-step convergence. The whole file takes a few
// seconds in Release.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>
#include <vector>

#include "jellyfish/swimmer.hpp"
#include "support/dense_linalg.hpp"

namespace creaturelab::jellyfish {
namespace {

// The paper's set-up (paperSwimmer()): a 0.4 m free-slip box, sea water, the paper's bilinear
// transfer, a fixed coupled step, a fluid faster than 5 m/s taken as a blow-up.
SwimmerConfig config(int cells, double hz, double dt_s, bool semi_implicit = true) {
  SwimmerConfig c = paperSwimmer();
  c.fluid.cells_x = c.fluid.cells_y = cells;
  c.fluid.time_step_policy = fluid::TimeStepPolicy::fixed;
  c.fluid.fixed_step_s = dt_s;
  c.fluid.blowup_speed_m_per_s = 5.0;
  c.activation.contraction_hz = hz;
  c.coupling.semi_implicit = semi_implicit;
  c.dt_s = dt_s;
  return c;
}

long stepsPerCycle(const SwimmerConfig& c) { return std::lround(1.0 / (c.activation.contraction_hz * c.dt_s)); }

struct Summary {
  double min_ratio = std::numeric_limits<double>::infinity();
  double end_ratio = 0;
  double distance_m = 0;  // centroid's y displacement from the start
  double max_marker_speed_m_per_s = 0;
};

Summary run(Swimmer& s, long steps) {
  Summary out;
  const double y0 = s.observe().centroid_m.y;
  for (long k = 0; k < steps; ++k) {
    const auto report = s.step();
    out.max_marker_speed_m_per_s = std::max(out.max_marker_speed_m_per_s, report.max_marker_speed_m_per_s);
    out.min_ratio = std::min(out.min_ratio, s.observe().diameter_ratio);
  }
  out.end_ratio = s.observe().diameter_ratio;
  out.distance_m = s.observe().centroid_m.y - y0;
  return out;
}

// Determinism (STYLE.md: solvers are deterministic and own their state): two swimmers built from
// the same configuration and stepped the same number of times hold bitwise-identical markers and
// work tallies. 150 steps at 0.7 Hz is most of a cycle, so the bell has contracted and the check
// is not made on a bell at rest.
TEST(JellyfishSwim, TwoIdenticalRunsAreBitwiseIdentical) {
  const SwimmerConfig c = config(50, 0.7, 0.01);
  Swimmer a(c), b(c);
  const std::vector<fluid::Vec2> start = a.markers_m();
  for (int k = 0; k < 150; ++k) {
    a.step();
    b.step();
  }
  ASSERT_EQ(a.markers_m().size(), b.markers_m().size());
  double moved = 0;
  for (std::size_t i = 0; i < a.markers_m().size(); ++i) {
    EXPECT_EQ(a.markers_m()[i].x, b.markers_m()[i].x) << "marker " << i;
    EXPECT_EQ(a.markers_m()[i].y, b.markers_m()[i].y) << "marker " << i;
    moved = std::max(moved, std::hypot(a.markers_m()[i].x - start[i].x, a.markers_m()[i].y - start[i].y));
  }
  EXPECT_GT(moved, 1e-3);
  EXPECT_EQ(a.fluidWork_j_per_m(), b.fluidWork_j_per_m());
  EXPECT_EQ(a.muscleWork_j_per_m(), b.muscleWork_j_per_m());
}

// Mirror symmetry (§3.1: the organism is axially symmetric, and the slice through its axis is
// mirror-symmetric). The bell is drawn exactly symmetric, placed on the box's mid-line, the box
// and the solver are symmetric, so over one cycle at 0.5 Hz the bell's centroid stays on the
// mid-line and every marker stays the mirror image of its partner, to round-off amplified by the
// flow: asserted below 1e-9 m on both of the paper's grids.
TEST(JellyfishSwim, SymmetricBellStaysSymmetricOverOneCycle) {
  for (int cells : {50, 100}) {
    const SwimmerConfig c = config(cells, 0.5, 0.01);
    Swimmer s(c);
    const double centre = 0.5 * c.fluid.domain_width_m;
    const int n = s.body().model().bell_markers;
    double centroid_drift = 0, mirror_defect = 0, min_ratio = 1;
    for (long k = 0; k < stepsPerCycle(c); ++k) {
      s.step();
      centroid_drift = std::max(centroid_drift, std::abs(s.observe().centroid_m.x - centre));
      min_ratio = std::min(min_ratio, s.observe().diameter_ratio);
      const auto& x = s.markers_m();
      for (int i = 0; i < n; ++i)
        mirror_defect = std::max(
            {mirror_defect, std::abs(x[i].x + x[n - 1 - i].x - 2 * centre), std::abs(x[i].y - x[n - 1 - i].y)});
    }
    std::printf("[ measured ] %d^2, 0.5 Hz, one cycle: max |centroid_x - centre| %.3g m, max mirror defect %.3g m\n",
                cells, centroid_drift, mirror_defect);
    EXPECT_LT(min_ratio, 0.6) << "the bell did contract";
    EXPECT_LT(centroid_drift, 1e-9) << cells << "^2";
    EXPECT_LT(mirror_defect, 1e-9) << cells << "^2";
  }
}

// The body's static equilibrium with every muscle at the same rest-length factor (no fluid):
// Newton's method on the elastic energy at time t, with the Jacobian from central differences of
// the forces (exact, not the coupling's clamped stiffness) and a tiny Levenberg shift for the free
// body's rigid motions. Returns the aperture ratio of the equilibrium.
double staticEquilibriumRatio(const JellyfishBody& body, double t_s) {
  std::vector<fluid::Vec2> x = body.model().rest_positions_m;
  const int n = static_cast<int>(x.size());
  std::vector<fluid::Vec2> f(n), fp(n), fm(n);
  double residual = 1;
  for (int iteration = 0; iteration < 100 && residual > 1e-7; ++iteration) {
    body.forces(t_s, x, f);
    Eigen::VectorXd force(2 * n);
    residual = 0;
    for (int i = 0; i < n; ++i) {
      force[2 * i] = f[i].x;
      force[2 * i + 1] = f[i].y;
      residual = std::max(residual, std::hypot(f[i].x, f[i].y));
    }
    Eigen::MatrixXd hessian(2 * n, 2 * n);  // -dF/dX
    const double h = 1e-8;
    for (int c = 0; c < 2 * n; ++c) {
      std::vector<fluid::Vec2> xp = x, xm = x;
      (c % 2 ? xp[c / 2].y : xp[c / 2].x) += h;
      (c % 2 ? xm[c / 2].y : xm[c / 2].x) -= h;
      body.forces(t_s, xp, fp);
      body.forces(t_s, xm, fm);
      for (int i = 0; i < n; ++i) {
        hessian(2 * i, c) = -(fp[i].x - fm[i].x) / (2 * h);
        hessian(2 * i + 1, c) = -(fp[i].y - fm[i].y) / (2 * h);
      }
    }
    hessian.diagonal().array() += 1e-8 * hessian.diagonal().cwiseAbs().maxCoeff();
    const Eigen::VectorXd step = test::ldltSolve(hessian, force);
    // Backtracking on the energy keeps the iteration descending through the slack/taut switches.
    const double e0 = body.elasticEnergy(t_s, x);
    double scale = 1;
    std::vector<fluid::Vec2> trial = x;
    for (int halvings = 0; halvings < 40; ++halvings, scale *= 0.5) {
      for (int i = 0; i < n; ++i) trial[i] = {x[i].x + scale * step[2 * i], x[i].y + scale * step[2 * i + 1]};
      if (body.elasticEnergy(t_s, trial) <= e0) break;
    }
    x = trial;
  }
  EXPECT_LT(residual, 1e-5) << "static equilibrium did not converge";
  const int b = body.model().bell_markers;
  return std::hypot(x[b - 1].x - x[0].x, x[b - 1].y - x[0].y) / body.model().aperture_width_m;
}

// The muscles contract the bell (§3.3: the curve is normalised between 1 and 0.56, "a jellyfish may
// contract to 56% of its maximum diameter", Fig. 3), and the mesoglea re-opens it (§3.1: "the
// umbrella is pushed outward by the elastic properties of the surrounding tissue").
//
// The band. At 0.3 Hz the contraction takes 1 s, slow for the bell in water, so the deepest
// contraction should be the body's static equilibrium at factor 0.56. That equilibrium has an
// aperture ratio of 0.533, not 0.56: the aperture muscle goes slack and the bell's bending carries
// the pull of the muscles above it down to the aperture. Asserted: the minimum ratio on 100² at
// dt 0.01 s within 5e-3 of the static equilibrium, and by the end of the cycle the bell has re-opened.
TEST(JellyfishSwim, MusclesContractTheBellToItsStaticEquilibriumAndItReopens) {
  const SwimmerConfig c = config(100, 0.3, 0.01);
  const JellyfishBody body(buildBell(c.bell), c.activation, c.fluid.dynamicViscosity_pa_s());
  const double contracted_t = 0.3 / c.activation.contraction_hz;  // the default curve's 0.56 knot
  for (std::size_t m = 0; m < body.model().muscles.size(); ++m)
    ASSERT_NEAR(body.muscleFactor(static_cast<int>(m), contracted_t), 0.56, 1e-12);
  const double equilibrium = staticEquilibriumRatio(body, contracted_t);
  EXPECT_GT(equilibrium, 0.50);
  EXPECT_LT(equilibrium, 0.56);

  Swimmer s(c);
  const Summary r = run(s, stepsPerCycle(c));
  std::printf("[ measured ] 0.3 Hz, 100^2, dt 0.01: static equilibrium ratio %.5f, min ratio %.5f, end of cycle %.5f\n",
              equilibrium, r.min_ratio, r.end_ratio);
  EXPECT_NEAR(r.min_ratio, equilibrium, 5e-3);
  EXPECT_GT(r.end_ratio, 0.95);
}

// Energy (§3.3: the contraction pushes water out of the bell, the jet that drives the swimmer).
// After a warm-up cycle (as the kind measures), over each of the next two whole cycles the
// muscles' contractile elements do positive work (they feed the bell and the fluid) and the body
// does positive work on the fluid (which dissipates it), at 0.7 Hz on 100².
TEST(JellyfishSwim, MusclesAndBodyDoPositiveWorkOverWholeCycles) {
  const SwimmerConfig c = config(100, 0.7, 0.01);
  Swimmer s(c);
  const long cycle = stepsPerCycle(c);
  run(s, cycle);  // warm-up
  for (int k = 1; k <= 2; ++k) {
    const double muscle0 = s.muscleWork_j_per_m(), fluid0 = s.fluidWork_j_per_m();
    run(s, cycle);
    const double muscle = s.muscleWork_j_per_m() - muscle0, fluid = s.fluidWork_j_per_m() - fluid0;
    std::printf("[ measured ] 0.7 Hz, 100^2, dt 0.01, cycle %d: muscle work %.4g J/m, work on the fluid %.4g J/m\n",
                k + 1, muscle, fluid);
    EXPECT_GT(muscle, 0.0) << "cycle " << k + 1;
    EXPECT_GT(fluid, 0.0) << "cycle " << k + 1;
  }
}

// Energy balance of the coupled step (swimmer.hpp): the muscles' work, summed as tension times the
// shortening of their rest lengths, equals the elastic energy gained plus the work done on the fluid
// (-T dr/dt = dE/dt + F . U), and swimmer.hpp states that the two tallies "differ by the
// semi-implicit step's numerical dissipation", i.e. the step may lose energy but must not create
// it: over a cycle from rest, E(T) - E(0) + W_fluid <= W_muscle. The 5 % margin covers the direct
// tally's own O(dt) error, which has the same sign (it overestimates the muscle work by k dr^2 / 2
// per step). With the bilinear kernel and the local added mass (ib/coupling.hpp) the step created
// energy, which went into a grid-scale zigzag of the bell's angular springs: this test found it.
TEST(JellyfishSwim, CoupledStepCreatesNoEnergyOverACycle) {
  for (int cells : {100, 50}) {
    const SwimmerConfig c = config(cells, 0.7, 0.01);
    Swimmer s(c);
    double peak_elastic = 0;
    for (long k = 0; k < stepsPerCycle(c); ++k) {
      s.step();
      peak_elastic = std::max(peak_elastic, s.elasticEnergy_j_per_m());
    }
    const double direct = s.muscleWork_j_per_m(), balance = s.muscleWorkByBalance_j_per_m();
    std::printf(
        "[ measured ] %d^2, 0.7 Hz, dt 0.01, first cycle: muscle work %.4g J/m, elastic gained + fluid work %.4g J/m "
        "(elastic now %.4g, peak %.4g; fluid %.4g)\n",
        cells, direct, balance, s.elasticEnergy_j_per_m(), peak_elastic, s.fluidWork_j_per_m());
    EXPECT_GT(direct, 0.0);
    EXPECT_LE(balance, 1.05 * direct) << cells << "^2: the coupled step created " << balance - direct
                                      << " J/m over the first cycle";
  }
}

// Stability (§3.2 and §4: "time-steps of the order of 0.01 seconds begin to hit the stability limits";
// ib/coupling.hpp: an explicit marker spring needs dt below about 2 sqrt(rho dx^2 / k), ~5e-4 s for the
// bell's angular springs on 100²). The semi-implicit coupled step runs two cycles at dt = 0.01 s on both
// grids with the bell contracting and its markers moving slowly. The explicit coupling with the paper's
// bilinear kernel fails at the same step within a few steps and says so: either the fluid's blow-up error
// or the swimmer's "crumpled" error. (With Peskin's kernel the explicit step survives two cycles on 50²:
// its wider stencil spreads a marker's force over 16 faces, lowering the stiffness the grid sees.)
TEST(JellyfishSwim, SemiImplicitStepIsStableWhereExplicitBlowsUp) {
  for (int cells : {50, 100}) {
    const SwimmerConfig semi = config(cells, 0.7, 0.01, true);
    Swimmer s(semi);
    Summary r;
    ASSERT_NO_THROW(r = run(s, 2 * stepsPerCycle(semi))) << cells << "^2";
    for (const auto& p : s.markers_m()) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
    std::printf(
        "[ measured ] semi-implicit, %d^2, dt 0.01, two cycles at 0.7 Hz: min ratio %.4f, peak marker speed %.4g m/s\n",
        cells, r.min_ratio, r.max_marker_speed_m_per_s);
    EXPECT_LT(r.min_ratio, 0.6);
    EXPECT_LT(r.max_marker_speed_m_per_s, 1.0);

    SwimmerConfig explicit_bilinear = config(cells, 0.7, 0.01, false);
    explicit_bilinear.coupling.kernel = ib::Kernel::bilinear;
    Swimmer e(explicit_bilinear);
    std::string message;
    long steps = 0;
    try {
      for (; steps < 2 * stepsPerCycle(semi); ++steps) e.step();
    } catch (const std::exception& ex) {
      message = ex.what();
    }
    std::printf("[ measured ] explicit, %d^2, dt 0.01: threw in step %ld: %s\n", cells, steps + 1, message.c_str());
    ASSERT_FALSE(message.empty()) << "the explicit coupling survived two cycles at dt = 0.01 s on " << cells << "^2";
    EXPECT_LT(steps, 20);
    EXPECT_TRUE(message.find("blew up") != std::string::npos || message.find("crumpled") != std::string::npos)
        << message;
  }
}

// The kind's default force at the step's middle (implicit_theta = ½, kinds/jellyfish.cpp) on the
// paper's model (the swimmer's own defaults: rest-length muscles, semi-Lagrangian advection) at the paper's grid and step: θ = ½ damps the
// marker springs' fast modes less than θ = 1 (ib/coupling.hpp), so its stability at 0.01 s on 100²
// is checked over a whole measured window (one warm-up cycle and 10 s) at the sweep's ends and
// middle, not only over two cycles. Asserted: no blow-up or crumpling, finite markers, slow markers
// (< 1 m/s) and a bell that did contract (min ratio < 0.7). About 2 s in Release.
TEST(JellyfishSwim, HalfStepForceIsStableOnThePaperGridOverAWholeWindow) {
  for (double hz : {0.2, 0.7, 1.5}) {
    SwimmerConfig c = config(100, hz, 0.01);
    c.coupling.implicit_theta = 0.5;
    Swimmer s(c);
    const long steps = std::lround((1.0 / hz + 10.0) / c.dt_s);
    Summary r;
    ASSERT_NO_THROW(r = run(s, steps)) << hz << " Hz";
    for (const auto& p : s.markers_m()) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << hz << " Hz";
    std::printf("[ measured ] theta 0.5, 100^2, dt 0.01, %.1f Hz, %ld steps: min ratio %.4f, "
                "peak marker speed %.4g m/s, distance %.2f mm\n",
                hz, steps, r.min_ratio, r.max_marker_speed_m_per_s, 1e3 * r.distance_m);
    EXPECT_LT(r.min_ratio, 0.7) << hz << " Hz";
    EXPECT_LT(r.max_marker_speed_m_per_s, 1.0) << hz << " Hz";
  }
}

// Porous filaments (Miles & Battista 2019's tentacles; ib/coupling.hpp's porous slip) on the kind's default
// grid and step at the force's middle (θ = ½): tentacles spread with their own 4/3 mm kernel (a third of the bell's)
// and a Darcy coefficient of 0.034 m/(Pa s) (tentacle_permeability_m 1.7e-3 in water of ν = 5e-5). The
// stencil mobility over-predicts the fluid's response to such narrow, dense markers; a slip taken from the
// predicted end-of-step force then overshoots, undamped at θ = ½, and the chains tear within a few steps.
// Asserted over 0.1 s (30 steps) from rest: every tentacle segment within 25% of its drawn length.
TEST(JellyfishSwim, PorousFilamentsKeepTheirChainsAtTheHalfStepForce) {
  SwimmerConfig c;
  c.activation.contraction_hz = 0.7;
  c.tentacle_kernel_scale = 1;
  c.bell.tentacle_permeability_m = 1.7e-3;
  ASSERT_EQ(c.coupling.implicit_theta, 0.5);
  Swimmer s(c);
  const BellModel& model = s.body().model();
  ASSERT_FALSE(model.tentacle_chains.empty());
  const auto stretch = [&](const std::vector<fluid::Vec2>& x, int a, int b) {
    const fluid::Vec2 r0{model.rest_positions_m[b].x - model.rest_positions_m[a].x,
                         model.rest_positions_m[b].y - model.rest_positions_m[a].y};
    return std::hypot(x[b].x - x[a].x, x[b].y - x[a].y) / std::hypot(r0.x, r0.y);
  };
  double lo = 1, hi = 1;
  const long steps = std::lround(0.1 / c.dt_s);
  for (long k = 0; k < steps; ++k) {
    ASSERT_NO_THROW(s.step()) << "step " << k + 1;
    for (const auto& chain : model.tentacle_chains)
      for (std::size_t i = 1; i < chain.size(); ++i) {
        const double r = stretch(s.markers_m(), chain[i - 1], chain[i]);
        lo = std::min(lo, r);
        hi = std::max(hi, r);
      }
  }
  std::printf("[ measured ] porous 4/3 mm filaments, 2/3 mm grid, dt 1/300 s, theta 0.5, 0.1 s: segment stretch %.4f .. %.4f\n",
              lo, hi);
  EXPECT_GT(lo, 0.8);
  EXPECT_LT(hi, 1.25);
}

// Time-step convergence on 100² at 0.7 Hz, two cycles from rest, dt = 0.01, 0.005, 0.0025 s. (The bilinear
// kernel with the local added mass did not converge in the step.) Asserted: the contraction depths agree to
// 1e-2 and the bell swims forward (+y) at every step (§3.3); the distance's convergence is reported, not
// asserted.
TEST(JellyfishSwim, ContractionDepthAgreesAcrossTimeSteps) {
  std::vector<double> ratios;
  for (double dt : {0.01, 0.005, 0.0025}) {
    const SwimmerConfig c = config(100, 0.7, dt);
    Swimmer s(c);
    const Summary r = run(s, 2 * stepsPerCycle(c));
    std::printf("[ measured ] 100^2, 0.7 Hz, two cycles, dt %.4g: min ratio %.5f, distance %.4g m, end ratio %.4f\n",
                dt, r.min_ratio, r.distance_m, r.end_ratio);
    ratios.push_back(r.min_ratio);
    EXPECT_GT(r.distance_m, 0.0) << "dt " << dt;
  }
  const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
  EXPECT_LT(*hi - *lo, 1e-2);
}

}  // namespace
}  // namespace creaturelab::jellyfish
