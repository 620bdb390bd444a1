// MuJoCo bodies coupled to the 3-D fluid (coupling3d/rigid_fluid_coupling3.hpp): the momentum the
// fluid gets equals minus what the bodies get, the two-way exchange conserves the total momentum, a
// body carried by a uniform stream feels no force, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <tuple>

#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "coupling3d_scenes.hpp"

namespace creaturelab::coupling3d {
namespace {

using fluid3d::Boundaries3;

class Coupling3Test : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_ = testing::scratch("coupling");
};

// ρ dx³ Σ u per component over every face of a periodic box (kg m/s).
Vec3 fluidMomentum(const fluid3d::FluidSolver3& f) {
  const fluid3d::MacGrid3& g = f.grid();
  Vec3 p{};
  for (int a = 0; a < 3; ++a) {
    for (std::size_t t = 0; t < g.velocity_m_per_s[a].size(); ++t) p[a] += g.velocity_m_per_s[a].data()[t];
    p[a] *= f.params().density_kg_per_m3 * g.cellVolume_m3();
  }
  return p;
}

// A swirl of the fluid, so that every marker exchanges momentum.
void stir(fluid3d::FluidSolver3& f) {
  fluid3d::MacGrid3& g = f.grid();
  for (int a = 0; a < 3; ++a) {
    const auto e = g.faceExtents(a);
    for (int k = 0; k < e[2]; ++k)
      for (int j = 0; j < e[1]; ++j)
        for (int i = 0; i < e[0]; ++i)
          g.velocity_m_per_s[a](i, j, k) = 0.02 * std::sin(0.4 * (i + 2 * j + 3 * k) + a) + 0.01 * a;
  }
  f.makeDivergenceFree();
}

// The forcing stage changes the fluid's momentum by exactly dt Σ F (the periodic projection keeps
// it), and the bodies, world body included, receive −Σ F.
TEST_F(Coupling3Test, MomentumExchangedBalances) {
  const double dt = 0.02;
  const auto model = testing::loadScene(dir_, "scene",
                                        "<geom type=\"sphere\" size=\"0.06\" pos=\"0.12 0.12 0.3\"/>"
                                        "<body pos=\"0.25 0.22 0.15\"><freejoint/>"
                                        "<geom type=\"box\" size=\"0.05 0.03 0.04\" density=\"2000\"/></body>",
                                        dt);
  rigid::RigidData data(model);
  data.kinematics();
  RigidFluidCoupling3 c(data, testing::cube(16, 0.4, Boundaries3::allPeriodic(), 1e-4), {});
  stir(c.fluid());
  c.advanceFluid(dt);
  const Vec3 before = fluidMomentum(c.fluid());
  // Move and turn the box kinematically, so its markers have a velocity of their own.
  data.qpos()[0] += 0.004;
  data.qpos()[2] -= 0.002;
  data.qpos()[4] += 0.01;
  data.kinematics();
  c.forceFluid(data, dt);
  const Vec3 after = fluidMomentum(c.fluid());
  Vec3 spread{}, bodies{};
  for (const Vec3& F : c.markerForce_n())
    for (int a = 0; a < 3; ++a) spread[a] += F[a];
  for (const Vec3& F : c.bodyForce_n())
    for (int a = 0; a < 3; ++a) bodies[a] += F[a];
  double scale = 0;
  for (int a = 0; a < 3; ++a) scale = std::max(scale, std::abs(spread[a]));
  ASSERT_GT(scale, 1e-3);  // the markers did exchange momentum
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(after[a] - before[a], dt * spread[a], 1e-11 * dt * scale) << "axis " << a;
    EXPECT_NEAR(bodies[a], -spread[a], 1e-12 * scale) << "axis " << a;
  }
  EXPECT_GT(c.forcingIterations(), 0);
  EXPECT_LT(c.forcingResidual_m_per_s(), 1e-4 * 0.6);
}

// Two-way: a heavy free sphere (ten times the fluid's density: the staggered reaction is unstable for
// bodies not much heavier than the fluid the kernel drags along, the interior's included) thrown
// through a periodic box. The fluid gets dt Σ F at step n, the
// body −dt Σ F one step later (the staggered reaction), so fluid + body + the pending reaction
// impulse stays constant to round-off while the body slows down (5 steps).
TEST_F(Coupling3Test, TwoWayExchangeConservesMomentum) {
  const double dt = 0.01;
  const auto model = testing::loadScene(
      dir_, "scene", "<body pos=\"0.2 0.2 0.2\"><freejoint/><geom type=\"sphere\" size=\"0.06\" density=\"10000\"/></body>",
      dt);
  rigid::RigidData data(model);
  data.qvel()[0] = 0.2;
  data.qvel()[1] = -0.1;
  data.kinematics();
  fluid3d::FluidParams3 f = testing::cube(16, 0.4, Boundaries3::allPeriodic(), 1e-4);
  RigidFluidCoupling3 c(data, f, {});
  c.fluid().stages().advection = false;  // semi-Lagrangian advection does not conserve momentum
  const double mass = model.bodyMass_kg(1);
  auto total = [&]() {
    const Vec3 p = fluidMomentum(c.fluid());
    Vec3 t;
    for (int a = 0; a < 3; ++a) t[a] = p[a] + mass * data.qvel()[a] + dt * c.bodyForce_n()[1][a];
    return t;
  };
  const Vec3 start = total();
  for (int step = 0; step < 5; ++step) {
    c.advanceFluid(dt);
    for (int d = 0; d < model.dofs(); ++d) data.appliedForces()[d] = 0;
    c.applyReaction(data);
    data.step();
    data.kinematics();  // MuJoCo's step leaves the poses of the step's start
    c.forceFluid(data, dt);
  }
  const Vec3 end = total();
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(end[a], start[a], 1e-10 * mass * 0.2) << "axis " << a;
  EXPECT_LT(data.qvel()[0], 0.2 * 0.95);  // the fluid took some of the body's momentum
  EXPECT_GT(data.qvel()[0], 0.0);
}

// Galilean invariance: a body moving with a uniform stream meets the fluid's velocity already, so
// the forcing exerts nothing, however far it is carried.
TEST_F(Coupling3Test, BodyCarriedByAStreamFeelsNoForce) {
  const double dt = 0.02, U[3] = {0.1, -0.05, 0.08};
  const auto model = testing::loadScene(
      dir_, "scene", "<body pos=\"0.2 0.2 0.2\"><freejoint/><geom type=\"capsule\" size=\"0.04 0.05\"/></body>", dt);
  rigid::RigidData data(model);
  data.kinematics();
  RigidFluidCoupling3 c(data, testing::cube(16, 0.4, Boundaries3::allPeriodic(), 1e-4), {});
  for (int a = 0; a < 3; ++a) c.fluid().grid().velocity_m_per_s[a].fill(U[a]);
  for (int step = 0; step < 5; ++step) {
    c.advanceFluid(dt);
    for (int a = 0; a < 3; ++a) data.qpos()[a] += U[a] * dt;
    data.kinematics();
    c.forceFluid(data, dt);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(c.bodyForce_n()[1][a], 0.0, 1e-9) << "step " << step;
      EXPECT_NEAR(c.fluid().grid().velocity_m_per_s[a](3, 5, 7), U[a], 1e-12);
    }
  }
  // The same stream past the body held still: now the forcing must act (the test can fail).
  c.advanceFluid(dt);
  c.forceFluid(data, dt);
  EXPECT_GT(std::abs(c.bodyForce_n()[1][0]), 1e-3);
}

// Determinism: the transfer runs serially and the fluid's stages are bitwise the same for any thread
// count, so a coupled run is too (a wall box and MG-PCG: the solver with the most parallel sums).
TEST_F(Coupling3Test, BitwiseSameForAnyThreadCount) {
  const double dt = 0.02;
  const auto model = testing::loadScene(
      dir_, "scene", "<body pos=\"0.2 0.2 0.2\"><freejoint/><geom type=\"box\" size=\"0.05 0.03 0.04\"/></body>", dt);
  auto run = [&](int threads) {
    rigid::RigidData data(model);
    data.kinematics();
    fluid3d::FluidParams3 f = testing::cube(16, 0.4, Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip), 1e-4);
    f.pressure_solver = fluid3d::PressureSolverType3::mg_pcg;
    f.threads = threads;
    RigidFluidCoupling3 c(data, f, {});
    for (int step = 0; step < 3; ++step) {
      c.advanceFluid(dt);
      data.qpos()[0] += 0.002;
      data.qpos()[5] += 0.01;
      data.kinematics();
      c.forceFluid(data, dt);
    }
    return std::pair{c.fluid().grid().velocity_m_per_s, c.markerForce_n()};
  };
  const auto one = run(1), two = run(2);
  EXPECT_TRUE(one.first == two.first);
  EXPECT_TRUE(one.second == two.second);
}

TEST_F(Coupling3Test, BadInputIsRefused) {
  const auto model = testing::loadScene(
      dir_, "scene", "<body pos=\"0.02 0.2 0.2\"><freejoint/><geom type=\"sphere\" size=\"0.01\"/></body>", 0.01);
  rigid::RigidData data(model);
  data.kinematics();
  const fluid3d::FluidParams3 f = testing::cube(16, 0.4, Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip), 1e-4);
  EXPECT_THROW(RigidFluidCoupling3(data, f, {}), std::invalid_argument);  // within the kernel's reach of a wall
  RigidFluidParams3 p;
  p.marker_spacing_cells = 1.5;
  EXPECT_NE(p.validate(f), "");
  p = {};
  p.forcing_regularisation = -1;
  EXPECT_NE(p.validate(f), "");
  data.qpos()[0] = 0.2;
  data.kinematics();
  RigidFluidCoupling3 c(data, f, {});
  data.qpos()[0] += 0.1;  // four cells in one step
  data.kinematics();
  EXPECT_THROW(c.forceFluid(data, 0.01), CouplingError3);
}

// Exact snapshot: save the bodies and the coupling, step k, restore (after other steps in between, so that
// a warm start or reaction left over would show), step k again: bitwise the same fluid, forces and bodies.
// A free box in a walled box with two-way coupling, so the reaction and the warm start both matter; for
// the projected and the coupled forcing.
TEST_F(Coupling3Test, RestoreThenTheSameStepsGiveBitwiseTheSame) {
  const double dt = 0.01;
  const auto model = testing::loadScene(
      dir_, "scene",
      "<body pos=\"0.2 0.2 0.2\"><freejoint/><geom type=\"box\" size=\"0.05 0.03 0.04\" density=\"20000\"/></body>", dt);
  for (Forcing3 forcing : {Forcing3::projected, Forcing3::coupled}) {
    SCOPED_TRACE(forcing == Forcing3::coupled ? "coupled" : "projected");
    rigid::RigidData data(model);
    data.qvel()[0] = 0.1;
    data.qvel()[4] = 0.5;
    data.kinematics();
    RigidFluidParams3 p;
    p.forcing = forcing;
    RigidFluidCoupling3 c(data, testing::cube(16, 0.4, Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip), 1e-4), p);
    auto step = [&](double push_n) {
      c.advanceFluid(dt);
      for (int d = 0; d < model.dofs(); ++d) data.appliedForces()[d] = 0;
      c.applyReaction(data);
      data.appliedForces()[1] += push_n;
      data.step();
      data.kinematics();
      c.forceFluid(data, dt);
    };
    for (int s = 0; s < 2; ++s) step(0.0);
    const rigid::RigidState bodies = data.save();
    CouplingState3 saved;
    c.save(saved);
    auto run = [&]() {
      for (int s = 0; s < 3; ++s) step(0.0);
      return std::tuple{c.fluid().grid().velocity_m_per_s, c.markerForce_n(), data.save().qpos, data.save().qvel};
    };
    const auto first = run();
    for (int s = 0; s < 2; ++s) step(0.5);  // a different history before the restore
    data.restore(bodies);
    data.kinematics();
    c.restore(saved);
    const auto second = run();
    EXPECT_TRUE(std::get<0>(first) == std::get<0>(second)) << "fluid, forcing " << static_cast<int>(forcing);
    EXPECT_TRUE(std::get<1>(first) == std::get<1>(second)) << "marker forces, forcing " << static_cast<int>(forcing);
    EXPECT_TRUE(std::get<2>(first) == std::get<2>(second)) << "positions, forcing " << static_cast<int>(forcing);
    EXPECT_TRUE(std::get<3>(first) == std::get<3>(second)) << "velocities, forcing " << static_cast<int>(forcing);
    // Without restoring the coupling's own state (only the fluid's grid, as the snapshot once did), the
    // rerun differs: the test sees what restore brings back.
    for (int s = 0; s < 2; ++s) step(0.5);
    data.restore(bodies);
    data.kinematics();
    c.fluid().grid() = saved.grid;
    c.placeMarkers(data);
    const auto partial = run();
    EXPECT_FALSE(std::get<1>(first) == std::get<1>(partial)) << "forcing " << static_cast<int>(forcing);
  }
}

// A mouth (Mouth3): its disc's markers carry the geom's velocity plus the flux along the normal; the jet's
// momentum is what the body gets back (the fluid gains dt Σ F, the body −Σ F), and the fluid across the disc
// moves at the flux.
TEST_F(Coupling3Test, MouthPushesFluidAndTheBodyFeelsTheThrust) {
  const double dt = 0.02, flux = 0.05;
  const auto model = testing::loadScene(
      dir_, "scene", "<body pos=\"0.2 0.2 0.2\"><freejoint name=\"root\"/><geom type=\"sphere\" size=\"0.06\"/></body>", dt);
  rigid::RigidData data(model);
  data.kinematics();
  RigidFluidParams3 p;
  p.mouths.push_back({0, {0.0, 0.0, -0.11}, {0.0, 0.0, -1.0}, 0.04});  // a disc 2 cells below the sphere
  RigidFluidCoupling3 c(data, testing::cube(16, 0.4, Boundaries3::allPeriodic(), 1e-4), p);
  std::size_t first = 0, disc = 0;
  for (std::size_t k = 0; k < c.markers().size(); ++k)
    if (c.markers()[k].local_m[2] < -0.1) (disc++ == 0 ? first = k : first);
  ASSERT_GT(disc, 10u);
  double area = 0;
  for (std::size_t k = first; k < first + disc; ++k) area += c.markers()[k].area_m2;
  EXPECT_NEAR(area, 3.141592653589793 * 0.04 * 0.04, 1e-12);
  EXPECT_THROW(c.setMouthFlux(1, flux), std::invalid_argument);
  c.setMouthFlux(0, flux);
  c.advanceFluid(dt);
  const Vec3 before = fluidMomentum(c.fluid());
  c.forceFluid(data, dt);
  const Vec3 after = fluidMomentum(c.fluid());
  Vec3 spread{};
  for (const Vec3& F : c.markerForce_n())
    for (int a = 0; a < 3; ++a) spread[a] += F[a];
  EXPECT_LT(spread[2], -1e-3);  // the fluid is pushed down (−z), the body up
  EXPECT_GT(c.bodyForce_n()[1][2], 1e-3);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(after[a] - before[a], dt * spread[a], 1e-11 * dt * std::abs(spread[2]));
    EXPECT_NEAR(c.bodyForce_n()[1][a], -spread[a], 1e-12 * std::abs(spread[2]));
  }
  Transfer3 t;
  std::vector<Vec3> u(c.markers().size());
  t.locate(c.fluid().grid(), ib::Kernel::peskin4, c.markerPosition_m());
  t.interpolate(c.fluid().grid().velocity_m_per_s, u);
  double mean = 0;
  for (std::size_t k = first; k < first + disc; ++k) mean += -u[k][2] / static_cast<double>(disc);
  EXPECT_NEAR(mean, flux, 0.05 * flux) << c.forcingIterations() << " iterations, residual " << c.forcingResidual_m_per_s();
  p.mouths[0].geom = 5;
  EXPECT_THROW(RigidFluidCoupling3(data, testing::cube(16, 0.4, Boundaries3::allPeriodic(), 1e-4), p), std::invalid_argument);
  p.mouths[0].geom = 0;
  p.mouths[0].radius_m = 0;
  EXPECT_NE(p.validate(testing::cube(16, 0.4, Boundaries3::allPeriodic(), 1e-4)), "");
}

// Forcing3::coupled with the sphere's joint held (held_joints, or setHeldDofs): the fluid's impulse does not
// move it, the fluid still feels it; not held, the same step slows it.
TEST_F(Coupling3Test, CoupledForcingLeavesHeldJointsAlone) {
  const double dt = 0.01;
  const auto model = testing::loadScene(
      dir_, "scene", "<body pos=\"0.2 0.2 0.2\"><freejoint name=\"root\"/><geom type=\"sphere\" size=\"0.06\"/></body>", dt);
  auto step = [&](const std::vector<std::string>& held, const std::vector<int>* held_dofs) {
    rigid::RigidData data(model);
    data.qvel()[0] = 0.1;
    data.kinematics();
    RigidFluidParams3 p;
    p.forcing = Forcing3::coupled;
    p.held_joints = held;
    RigidFluidCoupling3 c(data, testing::cube(16, 0.4, Boundaries3::allPeriodic(), 1e-4), p);
    if (held_dofs) c.setHeldDofs(*held_dofs);
    c.advanceFluid(dt);
    data.step();
    data.kinematics();
    const std::vector<double> qpos(data.qpos(), data.qpos() + model.positions());
    c.forceFluid(data, dt);
    EXPECT_LT(c.bodyForce_n()[1][0], -1e-3);  // the fluid resists
    return std::pair{data.qvel()[0], std::vector<double>(data.qpos(), data.qpos() + model.positions()) == qpos};
  };
  const auto held = step({"root"}, nullptr);
  EXPECT_EQ(held.first, 0.1);
  EXPECT_TRUE(held.second);
  const std::vector<int> all{0, 1, 2, 3, 4, 5};
  const auto set = step({}, &all);
  EXPECT_EQ(set.first, 0.1);
  EXPECT_TRUE(set.second);
  const auto free = step({}, nullptr);
  EXPECT_LT(free.first, 0.09);
  EXPECT_FALSE(free.second);
  RigidFluidParams3 p;
  p.held_joints = {"no_such_joint"};
  rigid::RigidData data(model);
  data.kinematics();
  EXPECT_THROW(RigidFluidCoupling3(data, testing::cube(16, 0.4, Boundaries3::allPeriodic(), 1e-4), p), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::coupling3d
