// Long-run behaviour: symplectic Euler keeps energy bounded over 1e4 undamped periods; implicit
// Euler stays stable far beyond every explicit limit (omega dt = 100).
#include <gtest/gtest.h>

#include <cmath>

#include "springs/integrator.hpp"
#include "springs/stability.hpp"

namespace sp = creaturelab::springs;

TEST(SpringsLongRun, SymplecticEulerEnergyErrorBoundedOver1e4Periods) {
  sp::Network<2> n;
  n.addParticle(1.0, true);
  n.addParticle(1.0, false);
  n.addSpring(0, 1, 1.0, 1.0);  // omega = 1 rad/s along the spring
  const sp::System<2> sys(n);
  sp::State<2> s = sp::zeroState<2>(2);
  s.x_m.col(1) << 1.1, 0;
  const double e0 = sys.kineticEnergy(s) + sys.potentialEnergy(s);
  const double dt = 0.1;  // omega dt = 0.1: 63 steps per period
  auto integrator = sp::makeIntegrator<2>(sp::IntegratorKind::SymplecticEuler);
  const long steps = std::lround(1e4 * 2 * M_PI / dt);
  double worst = 0, worst_last_period = 0;
  for (long i = 0; i < steps; ++i) {
    integrator->step(sys, s, {i * dt, dt});
    const double rel = std::abs(sys.kineticEnergy(s) + sys.potentialEnergy(s) - e0) / e0;
    worst = std::max(worst, rel);
    if (i >= steps - 63) worst_last_period = std::max(worst_last_period, rel);
  }
  // The modified energy 0.5 v^2 + 0.5 x^2 - 0.5 h x v is conserved exactly, so the true energy
  // oscillates with relative amplitude about omega h / 2 and never drifts.
  EXPECT_LT(worst, 0.06);
  EXPECT_GT(worst_last_period, 0.03);  // the oscillation is still the same size, not damped away
  EXPECT_LT(worst_last_period, 0.06);
}

TEST(SpringsLongRun, ImplicitEulerStableAtOmegaDt100) {
  // A chain of 20 particles pinned at one end, plucked; dt = 100 / omega_max.
  sp::Network<3> n;
  const int count = 20;
  sp::State<3> s = sp::zeroState<3>(count);
  for (int p = 0; p < count; ++p) {
    n.addParticle(10e-9, p == 0);
    s.x_m.col(p) << 1.3e-3 * p, 2e-4 * std::sin(0.7 * p), 0;
  }
  for (int p = 0; p + 1 < count; ++p) n.addSpring(p, p + 1, 1e-3, 0.01);
  n.gravity_m_per_s2 << 0, 0, -9.81;
  const sp::System<3> sys(n);
  const double omega = sp::estimateOmegaMaxRadPerS(n, s);
  const double dt = 100.0 / omega;
  const double e0 = sys.kineticEnergy(s) + sys.elasticEnergy(s);
  auto integrator = sp::makeIntegrator<3>(sp::IntegratorKind::ImplicitEuler);
  double e = e0;
  for (int i = 0; i < 200; ++i) {
    integrator->step(sys, s, {i * dt, dt});
    ASSERT_TRUE(s.x_m.allFinite());
    e = sys.kineticEnergy(s) + sys.elasticEnergy(s);
  }
  // Backward Euler is dissipative; with gravity the chain hangs down, so compare the elastic +
  // kinetic energy with a generous bound: the drop of the whole chain by its length.
  const double drop_bound = count * 10e-9 * 9.81 * count * 1.3e-3;
  EXPECT_LT(e, e0 + drop_bound);
  EXPECT_LT(sys.kineticEnergy(s), 1e-3 * drop_bound);  // at rest after 200 big steps
  // Single oscillator: the amplitude never grows.
  sp::Network<2> one;
  one.addParticle(1.0, true);
  one.addParticle(1.0, false);
  one.addSpring(0, 1, 1.0, 1.0);
  const sp::System<2> sys1(one);
  sp::State<2> s1 = sp::zeroState<2>(2);
  s1.x_m.col(1) << 1.5, 0;
  auto ie = sp::makeIntegrator<2>(sp::IntegratorKind::ImplicitEuler);
  double prev = 0.5;
  for (int i = 0; i < 50; ++i) {
    ie->step(sys1, s1, {i * 100.0, 100.0});
    const double amp = std::abs(s1.x_m.col(1).norm() - 1.0);
    EXPECT_LE(amp, prev + 1e-12);
    prev = amp;
  }
}
