// RK4 at omega dt = 2.7 (inside 2 sqrt 2) stays bounded; at 3.0 simulate() reports divergence
// with a message that names the stability bound.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "springs/simulate.hpp"
#include "springs/stability.hpp"

namespace sp = creaturelab::springs;

namespace {
// One free particle on an undamped spring to a pinned one: the estimate is exact, omega = 1000.
// The start is a 1e-5 strain so that a 1e8 growth of energy (1e4 in amplitude) stays in the
// linear range: a larger start flips the particle through the pin and the blow-up saturates.
struct Oscillator {
  sp::System<3> system;
  sp::State<3> state;
};
Oscillator oscillator() {
  sp::Network<3> n;
  n.addParticle(10e-9, true);
  n.addParticle(10e-9, false);
  n.addSpring(0, 1, 1e-3, 0.01);
  sp::State<3> s = sp::zeroState<3>(2);
  s.x_m.col(1) << 1e-3 + 1e-8, 0, 0;
  return {sp::System<3>(n), s};
}
sp::SimulationOptions rk4At(double omega_dt) {
  sp::SimulationOptions opt;
  opt.integrator = sp::IntegratorKind::RK4;
  opt.dt_s = omega_dt / 1000.0;
  opt.frame_interval_s = 10 * opt.dt_s;
  opt.end_time_s = 2000 * opt.dt_s;
  return opt;
}
}  // namespace

TEST(SpringsDivergence, RK4StableAtOmegaDt2p7) {
  auto [sys, s] = oscillator();
  EXPECT_NEAR(sp::estimateOmegaMaxRadPerS(sys.network(), s), 1000.0, 1e-9);
  const double e0 = sys.potentialEnergy(s);
  const auto summary = sp::simulate(sys, s, rk4At(2.7));
  EXPECT_EQ(summary.substeps_per_frame, 10);
  EXPECT_NEAR(summary.dt_used_s * summary.omega_max_rad_per_s, 2.7, 1e-12);
  EXPECT_EQ(summary.steps, 2000);
  EXPECT_LE(summary.peak_kinetic_energy_j, e0 * (1 + 1e-6));
  EXPECT_LT(sys.kineticEnergy(s) + sys.potentialEnergy(s), e0);  // RK4 damps numerically here
}

TEST(SpringsDivergence, RK4ReportsDivergenceAtOmegaDt3) {
  auto [sys, s] = oscillator();
  try {
    sp::simulate(sys, s, rk4At(3.0));
    FAIL() << "expected DivergenceError";
  } catch (const sp::DivergenceError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("omega_max*dt = 3 "), std::string::npos) << what;
    EXPECT_NE(what.find("stability bound 2.828"), std::string::npos) << what;
    EXPECT_NE(what.find("rk4"), std::string::npos) << what;
    EXPECT_NE(what.find("step " + std::to_string(e.step())), std::string::npos) << what;
    EXPECT_GT(e.step(), 5);
    EXPECT_LT(e.step(), 200);  // energy grows x2.27 per step: caught long before overflow
    EXPECT_NEAR(e.timeS(), e.step() * 3e-3, 1e-12);
  }
}

TEST(SpringsDivergence, ExplicitEulerWithoutDampingHasNoAutoStep) {
  auto [sys, s] = oscillator();
  sp::SimulationOptions opt;
  opt.integrator = sp::IntegratorKind::ExplicitEuler;
  EXPECT_THROW(sp::simulate(sys, s, opt), std::invalid_argument);
}
