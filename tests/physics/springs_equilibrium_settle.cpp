// Newton's static equilibrium equals a long damped dynamic settle (thesis §5.1, Fig. 5.1: a strand
// laid out at rest lengths between two anchors sags under gravity and settles).
// Thesis values: m = 10 ug per particle, k = 0.01 N/m, drag 1e-8 N s/m (c/m = 1/s).
#include <gtest/gtest.h>

#include <cmath>

#include "springs/equilibrium.hpp"
#include "springs/simulate.hpp"

namespace sp = creaturelab::springs;

namespace {
sp::System<3> strand(sp::State<3>& s, int particles) {
  sp::Network<3> n;
  s = sp::zeroState<3>(particles);
  for (int p = 0; p < particles; ++p) {
    n.addParticle(10e-9, p == 0 || p == particles - 1);
    s.x_m.col(p) << 1e-3 * p, 0, 0;  // springs at rest length (Fig. 5.1)
  }
  for (int p = 0; p + 1 < particles; ++p) n.addSpring(p, p + 1, 1e-3, 0.01);
  n.gravity_m_per_s2 << 0, 0, -9.81;
  n.drag_ns_per_m = 1e-8;
  return sp::System<3>(n);
}
}  // namespace

TEST(SpringsEquilibriumSettle, NewtonMatchesLongDynamicSettle) {
  const int particles = 21;
  sp::State<3> newton, dynamic;
  const auto sys = strand(newton, particles);
  dynamic = newton;

  // From the straight strand, where the transverse stiffness k (1 - r/|l|) vanishes: the Hessian
  // is singular, so this also exercises the regularised fallback.
  const auto eq = sp::solveStaticEquilibrium(sys, newton);
  ASSERT_TRUE(eq.converged) << "residual " << eq.max_residual_force_n << " after " << eq.iterations;

  sp::SimulationOptions opt;
  opt.integrator = sp::IntegratorKind::SymplecticEuler;
  opt.end_time_s = 45;  // every mode decays at least as exp(-t/2): 45 s leaves ~2e-10
  const auto summary = sp::simulate(sys, dynamic, opt);
  ASSERT_TRUE(summary.settling_time_s.has_value());

  const double sag = -newton.x_m.row(2).minCoeff();
  EXPECT_GT(sag, 1e-3);
  const double diff = (newton.x_m - dynamic.x_m).cwiseAbs().maxCoeff();
  EXPECT_LT(diff, 1e-6 * sag) << "sag " << sag << " m, settle " << *summary.settling_time_s << " s";
  // The middle particle is lowest, and the shape is symmetric.
  EXPECT_NEAR(newton.x_m(2, particles / 2), -sag, 1e-15);
  EXPECT_NEAR(newton.x_m(0, particles / 2), 1e-3 * (particles / 2), 1e-12);
}
