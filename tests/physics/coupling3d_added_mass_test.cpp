// The added-mass limit of the staggered reaction and the coupled solve (coupling3d/rigid_fluid_coupling3.hpp,
// Forcing3::projected against Forcing3::coupled; Lentine et al. 2010 §4.2 Eq. 9): a free sphere thrown
// through a closed box of still water at several density ratios. The projected forcing's body feels the
// fluid's force one step late, and the force includes accelerating the fluid it carries and its added
// mass, so it blows up for light bodies; the coupled solve gives the body this step's force and stays
// stable at every ratio. Where both are stable they move the sphere alike (the step's first-order
// difference), and fluid + body momentum is kept to round-off within every coupled step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "../unit/coupling3d_scenes.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"

namespace creaturelab::coupling3d {
namespace {

constexpr double kPi = std::numbers::pi;

struct Throw {
  bool stable = true;
  int steps = 0;           // steps done (all when stable)
  double end_ratio = 0;    // v_x / v0 after the last step
  double mean_ratio = 0;   // mean of v_x / v0 over the steps
  double peak_ratio = 0;   // max |v| / v0 over the steps
  double leak = 0;         // |net flow out through the sphere's surface markers| / (v π r²), last step
  double momentum_drift = 0;  // max over steps |Δ(fluid + body momentum)| / (body mass v0): periodic, advection off
};

// ρ dx³ Σ u of one component over every face (kg m/s): the fluid's momentum in a periodic box (a closed box's
// walls take momentum: there it is zero for any divergence-free field).
double fluidMomentum(const fluid3d::FluidSolver3& f, int a) {
  const fluid3d::MacGrid3& g = f.grid();
  double p = 0;
  for (std::size_t t = 0; t < g.velocity_m_per_s[a].size(); ++t) p += g.velocity_m_per_s[a].data()[t];
  return p * f.params().density_kg_per_m3 * g.cellVolume_m3();
}

// A sphere of radius 0.06 m (2.4 cells) at the centre of a closed no-slip box of side 0.4 m (16³ cells, water,
// ν = 1e-4 m²/s), thrown at v0 = 0.1 m/s along x, `steps` steps of 0.01 s; density ratio ρ_body / ρ_fluid.
Throw throwSphere(const std::filesystem::path& dir, double ratio, Forcing3 forcing, int steps, bool advection = true,
                  bool periodic = false) {
  const double dt = 0.01, v0 = 0.1, r = 0.06;
  const auto model = testing::loadScene(dir, "throw",
                                        "<body pos=\"0.2 0.2 0.2\"><freejoint/><geom type=\"sphere\" size=\"0.06\" density=\"" +
                                            std::to_string(1000 * ratio) + "\"/></body>",
                                        dt);
  rigid::RigidData data(model);
  data.qvel()[0] = v0;
  data.kinematics();
  fluid3d::FluidParams3 f = testing::cube(
      16, 0.4, periodic ? fluid3d::Boundaries3::allPeriodic() : fluid3d::Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip),
      1e-4);
  f.blowup_speed_m_per_s = 100 * v0;
  RigidFluidParams3 p;
  p.forcing = forcing;
  RigidFluidCoupling3 c(data, f, p);
  c.fluid().stages().advection = advection;
  const double mass = model.bodyMass_kg(1);
  Throw out;
  auto total = [&](int a) { return fluidMomentum(c.fluid(), a) + mass * data.qvel()[a]; };
  for (out.steps = 0; out.steps < steps; ++out.steps) {
    Vec3 before{};
    for (int a = 0; a < 3; ++a) before[a] = total(a);
    try {
      c.advanceFluid(dt);
      for (int d = 0; d < model.dofs(); ++d) data.appliedForces()[d] = 0;
      c.applyReaction(data);
      data.step();
      data.kinematics();
      c.forceFluid(data, dt);
    } catch (const std::runtime_error&) {
      out.stable = false;
      break;
    }
    const double speed = std::hypot(data.qvel()[0], data.qvel()[1], data.qvel()[2]);
    if (!(speed < 10 * v0)) {
      out.stable = false;
      break;
    }
    for (int a = 0; a < 3; ++a)
      out.momentum_drift = std::max(out.momentum_drift, std::abs(total(a) - before[a]) / (mass * v0));
    out.end_ratio = data.qvel()[0] / v0;
    out.mean_ratio += out.end_ratio / steps;
    out.peak_ratio = std::max(out.peak_ratio, speed / v0);
  }
  if (!out.stable) return out;
  // The net flow out through the surface markers, Σ_k (I u)_k · n_k dA_k, against the sphere's own flux scale.
  Transfer3 t;
  std::vector<Vec3> u(c.markers().size());
  t.locate(c.fluid().grid(), ib::Kernel::peskin4, c.markerPosition_m());
  t.interpolate(c.fluid().grid().velocity_m_per_s, u);
  double flux = 0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    if (c.markers()[k].area_m2 == 0) continue;  // an interior marker
    const Vec3& x = c.markers()[k].local_m;     // the sphere's frame: the outward normal is x / |x|
    const double len = std::hypot(x[0], x[1], x[2]);
    flux += (u[k][0] * x[0] + u[k][1] * x[1] + u[k][2] * x[2]) / len * c.markers()[k].area_m2;
  }
  out.leak = std::abs(flux) / (std::max(std::abs(data.qvel()[0]), 1e-3 * v0) * kPi * r * r);
  return out;
}

class Coupling3AddedMass : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_ = testing::scratch("added_mass");
};

// The mechanism: at a neutral density the projected forcing's lagged reaction blows up within a few
// steps (the case resolves the instability), the coupled solve does not. If the coupled option fell back
// to the staggered reaction, the second half fails.
TEST_F(Coupling3AddedMass, NeutralSphereBlowsUpProjectedAndStaysStableCoupled) {
  const Throw projected = throwSphere(dir_, 1.0, Forcing3::projected, 20);
  EXPECT_FALSE(projected.stable) << "projected survived 20 steps at ratio 1 (peak v/v0 " << projected.peak_ratio << ")";
  const Throw coupled = throwSphere(dir_, 1.0, Forcing3::coupled, 20);
  ASSERT_TRUE(coupled.stable) << "coupled blew up after " << coupled.steps << " steps";
  // The fluid takes momentum from the sphere but cannot reverse it: it slows monotonically to a fraction.
  EXPECT_LT(coupled.end_ratio, 0.9);
  EXPECT_GT(coupled.end_ratio, 0.1);
  EXPECT_LT(coupled.peak_ratio, 1.0 + 1e-9);
  EXPECT_LT(coupled.leak, 0.05);
  std::printf("ratio 1: projected blew up after %d steps; coupled v/v0 %.4f after 20 steps, leak %.2e\n",
              projected.steps, coupled.end_ratio, coupled.leak);
}

// Where the projected forcing is stable (a heavy sphere) the two agree to the step's first-order error.
TEST_F(Coupling3AddedMass, HeavySphereMovesAlikeProjectedAndCoupled) {
  const Throw projected = throwSphere(dir_, 10.0, Forcing3::projected, 20);
  const Throw coupled = throwSphere(dir_, 10.0, Forcing3::coupled, 20);
  ASSERT_TRUE(projected.stable);
  ASSERT_TRUE(coupled.stable);
  EXPECT_NEAR(coupled.end_ratio, projected.end_ratio, 0.02);
  EXPECT_LT(coupled.end_ratio, 0.99);  // the fluid did slow it
  std::printf("ratio 10: v/v0 after 20 steps projected %.4f coupled %.4f\n", projected.end_ratio, coupled.end_ratio);
}

// Momentum: in a periodic box with advection off (semi-Lagrangian advection does not keep it), fluid + body
// momentum is the same after each coupled step to round-off: the fluid gets dt Σ F, the body −dt Σ F in the
// same step.
TEST_F(Coupling3AddedMass, CoupledStepKeepsMomentum) {
  const Throw coupled = throwSphere(dir_, 1.5, Forcing3::coupled, 5, false, true);
  ASSERT_TRUE(coupled.stable);
  EXPECT_LT(coupled.momentum_drift, 1e-10);
  EXPECT_LT(coupled.end_ratio, 0.95);
}

}  // namespace
}  // namespace creaturelab::coupling3d
