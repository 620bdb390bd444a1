// Unary forces and momentum: drag alone (Eq. 4.7) decays speed as exp(-k_d t / m); internal
// forces (damped springs, bends) leave total linear momentum unchanged by every integrator.
#include <gtest/gtest.h>

#include <cmath>

#include "springs/integrator.hpp"

namespace sp = creaturelab::springs;

TEST(SpringsUnaryForces, DragAloneDecaysExponentially) {
  sp::Network<3> n;
  n.addParticle(2e-8, false);
  n.drag_ns_per_m = 1e-8;  // k_d / m = 0.5 / s
  const sp::System<3> sys(n);
  sp::State<3> s = sp::zeroState<3>(1);
  s.v_m_per_s.col(0) << 0.3, -0.4, 1.2;
  const sp::Vec<3> v0 = s.v_m_per_s.col(0);
  auto rk4 = sp::makeIntegrator<3>(sp::IntegratorKind::RK4);
  const double dt = 1e-3;
  for (int i = 0; i < 2000; ++i) rk4->step(sys, s, {i * dt, dt});
  const sp::Vec<3> expected = v0 * std::exp(-0.5 * 2.0);
  EXPECT_LT((s.v_m_per_s.col(0) - expected).norm(), 1e-12 * v0.norm());
  // x(t) = x0 + v0 m/k_d (1 - exp(-k_d t/m))
  EXPECT_LT((s.x_m.col(0) - v0 * 2.0 * (1 - std::exp(-1.0))).norm(), 1e-12);
}

TEST(SpringsUnaryForces, GravityAloneIsFreeFall) {
  sp::Network<2> n;
  n.addParticle(1e-8, false);
  n.addParticle(1e-8, true);
  n.gravity_m_per_s2 << 0, -9.81;
  const sp::System<2> sys(n);
  sp::State<2> s = sp::zeroState<2>(2);
  auto euler = sp::makeIntegrator<2>(sp::IntegratorKind::SymplecticEuler);
  euler->step(sys, s, {0.0, 0.01});  // one 0.01 s step under g gives v = -0.0981 (STYLE.md, Jet)
  EXPECT_DOUBLE_EQ(s.v_m_per_s(1, 0), -0.0981);
  EXPECT_EQ(s.v_m_per_s.col(1), sp::Vec<2>::Zero());
  EXPECT_EQ(s.x_m.col(1), sp::Vec<2>::Zero());
}

TEST(SpringsUnaryForces, InternalForcesConserveMomentumForEveryIntegrator) {
  // Free triangle strip with damped springs at various strains and bends; no pins, gravity, drag.
  sp::Network<3> n;
  const int count = 8;
  sp::State<3> s0 = sp::zeroState<3>(count);
  for (int p = 0; p < count; ++p) {
    n.addParticle(1.0 + 0.25 * p, false);
    s0.x_m.col(p) << 0.5 * p, (p % 2) * 0.7, 0.1 * p * p;
    s0.v_m_per_s.col(p) << std::sin(1.0 + p), std::cos(2.0 * p), 0.3 * p - 1.0;
  }
  for (int p = 0; p + 1 < count; ++p) n.addSpring(p, p + 1, 0.8 * (s0.x_m.col(p) - s0.x_m.col(p + 1)).norm(), 2.0, 0.3);
  for (int p = 0; p + 2 < count; ++p) {
    n.addSpring(p, p + 2, 1.2 * (s0.x_m.col(p) - s0.x_m.col(p + 2)).norm(), 1.0, 0.1);
    n.addBend(p, p + 1, p + 2, 0.5, 0.4);
  }
  const sp::System<3> sys(n);
  auto momentum = [&](const sp::State<3>& s) { return sp::Vec<3>(s.v_m_per_s * n.mass_kg); };
  const sp::Vec<3> p0 = momentum(s0);
  const double scale = (s0.v_m_per_s.colwise().norm().transpose().cwiseProduct(n.mass_kg)).sum();
  using K = sp::IntegratorKind;
  for (K kind : {K::ExplicitEuler, K::SymplecticEuler, K::RK4, K::ImplicitEuler}) {
    sp::State<3> s = s0;
    auto integrator = sp::makeIntegrator<3>(kind);
    for (int i = 0; i < 500; ++i) integrator->step(sys, s, {i * 1e-3, 1e-3});
    // Explicit methods: round-off only. Implicit Euler: the CG solve (relative tolerance 1e-12)
    // leaves a residual whose sum need not vanish.
    const double tol = kind == K::ImplicitEuler ? 1e-9 : 1e-13;
    EXPECT_LT((momentum(s) - p0).norm(), tol * scale) << sp::integratorName(kind);
    EXPECT_GT((s.x_m - s0.x_m).norm(), 0.1) << "the network must actually move";
  }
}
