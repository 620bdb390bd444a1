// simulate(): frame bookkeeping, step rounding, settling time over substeps.
#include <gtest/gtest.h>

#include <cmath>

#include "springs/simulate.hpp"

namespace sp = creaturelab::springs;

TEST(SpringsSimulate, FramesStepsAndSettling) {
  // One particle on a spring with drag: kinetic energy envelope exp(-(c/m) t).
  sp::Network<2> n;
  n.addParticle(10e-9, true);
  n.addParticle(10e-9, false);
  n.addSpring(0, 1, 1e-3, 0.01);
  n.drag_ns_per_m = 1e-8;  // c/m = 1/s
  const sp::System<2> sys(n);
  sp::State<2> s = sp::zeroState<2>(2);
  s.x_m.col(1) << 1.1e-3, 0;
  sp::SimulationOptions opt;
  opt.integrator = sp::IntegratorKind::SymplecticEuler;
  opt.dt_s = 0.3e-3;  // rounds down to 0.02 / 67
  opt.end_time_s = 15;
  int calls = 0;
  double last_t = -1;
  const auto summary = sp::simulate(sys, s, opt, [&](int frame, double t_s, const sp::State<2>&) {
    EXPECT_EQ(frame, calls);
    EXPECT_NEAR(t_s, frame * 0.02, 1e-12);
    ++calls;
    last_t = t_s;
  });
  EXPECT_EQ(calls, 751);
  EXPECT_NEAR(last_t, 15.0, 1e-12);
  EXPECT_EQ(summary.substeps_per_frame, 67);
  EXPECT_DOUBLE_EQ(summary.dt_used_s, 0.02 / 67);
  EXPECT_EQ(summary.steps, 750L * 67);
  EXPECT_EQ(summary.time_s.size(), 751u);
  EXPECT_EQ(summary.kinetic_energy_j.size(), 751u);
  EXPECT_NEAR(summary.omega_max_rad_per_s, 1000.0, 1e-9);
  // Peak kinetic energy is close to the initial potential energy 0.5 k A^2 (drag is weak); symplectic
  // Euler's energy wobbles by about omega dt / 2 = 15 % around it.
  EXPECT_NEAR(summary.peak_kinetic_energy_j, 0.5 * 0.01 * 1e-8, 0.15 * 0.5 * 0.01 * 1e-8);
  // KE peaks follow exp(-t): below 1e-4 of the peak after about ln(1e4) = 9.2 s.
  ASSERT_TRUE(summary.settling_time_s.has_value());
  EXPECT_NEAR(*summary.settling_time_s, std::log(1e4), 0.1);
}

TEST(SpringsSimulate, RejectsBadOptionsAndState) {
  sp::Network<2> n;
  n.addParticle(1, false);
  const sp::System<2> sys(n);
  sp::State<2> s = sp::zeroState<2>(1);
  sp::SimulationOptions opt;
  opt.frame_interval_s = 0;
  EXPECT_THROW(sp::simulate(sys, s, opt), std::invalid_argument);
  opt = {};
  opt.provot.passes = 0;
  EXPECT_EQ(opt.validate(), "provot passes is 0; at least one pass is needed");
  sp::State<2> wrong = sp::zeroState<2>(3);
  EXPECT_THROW(sp::simulate(sys, wrong, sp::SimulationOptions{}), std::invalid_argument);
}
