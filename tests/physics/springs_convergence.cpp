// Damped oscillator against its closed form; measured convergence order over three step sizes.
// One free particle on a damped spring (Eq. 4.14) to a pinned one: m u'' + k_d u' + k u = 0,
// Eq. 4.12, with u the extension. Expected orders: explicit Euler 1, symplectic Euler 1, RK4 4,
// implicit Euler 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "springs/integrator.hpp"

namespace sp = creaturelab::springs;

namespace {

constexpr double kMass = 1.0, kStiff = 1.0, kDamp = 0.2, kRest = 1.0, kAmp = 0.1, kEnd = 10.0;

// u(t) for u(0) = A, u'(0) = 0.
double exactExtension(double t) {
  const double w0 = std::sqrt(kStiff / kMass), zeta = kDamp / (2 * std::sqrt(kStiff * kMass));
  const double wd = w0 * std::sqrt(1 - zeta * zeta);
  return std::exp(-zeta * w0 * t) * kAmp * (std::cos(wd * t) + zeta * w0 / wd * std::sin(wd * t));
}

// Largest |u_numerical - u_exact| over every step up to kEnd.
double maxError(sp::IntegratorKind kind, double dt) {
  sp::Network<3> n;
  n.addParticle(kMass, true);
  n.addParticle(kMass, false);
  n.addSpring(0, 1, kRest, kStiff, kDamp);
  const sp::System<3> sys(n);
  sp::State<3> s = sp::zeroState<3>(2);
  s.x_m.col(1) << 0.6 * (kRest + kAmp), 0.8 * (kRest + kAmp), 0;  // oblique: exercises the 3D geometry
  auto integrator = sp::makeIntegrator<3>(kind);
  const int steps = static_cast<int>(std::lround(kEnd / dt));
  double err = 0;
  for (int i = 0; i < steps; ++i) {
    integrator->step(sys, s, {i * dt, dt});
    err = std::max(err, std::abs(s.x_m.col(1).norm() - kRest - exactExtension((i + 1) * dt)));
  }
  return err;
}

void expectOrder(sp::IntegratorKind kind, double h, double expected_order, double tol) {
  const double e1 = maxError(kind, h), e2 = maxError(kind, h / 2), e3 = maxError(kind, h / 4);
  const double p1 = std::log2(e1 / e2), p2 = std::log2(e2 / e3);
  std::printf("[ order    ] %-16s h = %g: errors %.3e %.3e %.3e, orders %.3f %.3f\n",
              std::string(sp::integratorName(kind)).c_str(), h, e1, e2, e3, p1, p2);
  EXPECT_NEAR(p1, expected_order, tol);
  EXPECT_NEAR(p2, expected_order, tol);
}

}  // namespace

TEST(SpringsConvergence, ExplicitEulerIsFirstOrder) { expectOrder(sp::IntegratorKind::ExplicitEuler, 0.01, 1.0, 0.1); }
TEST(SpringsConvergence, SymplecticEulerIsFirstOrder) { expectOrder(sp::IntegratorKind::SymplecticEuler, 0.01, 1.0, 0.1); }
TEST(SpringsConvergence, RK4IsFourthOrder) { expectOrder(sp::IntegratorKind::RK4, 0.05, 4.0, 0.15); }
TEST(SpringsConvergence, ImplicitEulerIsFirstOrder) { expectOrder(sp::IntegratorKind::ImplicitEuler, 0.01, 1.0, 0.1); }
