// The flesh as the 3-D fluid's boundary (coupling3d/flesh_fluid_coupling3.hpp): fluid, flesh and bone
// together keep their linear momentum to round-off; in a still fluid the energy of flesh and bone
// (and of the fluid with them) does not grow; a snapshot restores the run bitwise; bad input is refused.
// CPU time of each TEST in its comment (Release).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "control_models.hpp"
#include "coupling3d/flesh_fluid_coupling3.hpp"
#include "flesh_models.hpp"
#include "fluid3_momentum.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::coupling3d {
namespace {

class FleshFluidTest : public testing::ScratchDirTest {
 protected:
  FleshFluidTest() : ScratchDirTest("flesh_fluid") {}
  rigid::RigidModel load(const std::string& xml) {
    return rigid::RigidModel::load(testing::writeText(file("model.xml"), xml));
  }
};

// A cube of n³ cells and side L around the world's origin; density ρ (kg/m³), viscosity ν.
fluid3d::FluidParams3 box(int n, double side_m, const fluid3d::Boundaries3& sides, double rho, double nu) {
  fluid3d::FluidParams3 f;
  f.domain_x_m = f.domain_y_m = f.domain_z_m = side_m;
  f.cells_x = f.cells_y = f.cells_z = n;
  f.boundaries = sides;
  f.density_kg_per_m3 = rho;
  f.kinematic_viscosity_m2_per_s = nu;
  f.pressure_solver = fluid3d::PressureSolverType3::spectral;
  return f;
}

RigidFluidParams3 centred(double side_m) {
  RigidFluidParams3 p;
  p.forcing_regularisation = 3e-2;  // the flesh's (flesh_fluid_coupling3.hpp)
  p.origin_m = {-0.5 * side_m, -0.5 * side_m, -0.5 * side_m};
  return p;
}

// Every vertex displaced by up to dx and moving at up to v (deterministic).
void disturb(flesh::Flesh& flesh, double dx_m, double v_m_per_s) {
  Eigen::Matrix3Xd x = flesh.positions_m(), v = flesh.velocities_m_per_s();
  for (int i = 0; i < flesh.vertices(); ++i)
    for (int d = 0; d < 3; ++d) {
      x(d, i) += dx_m * std::sin(1.3 * i + 2.1 * d);
      v(d, i) += v_m_per_s * std::cos(0.7 * i + 1.7 * d);
    }
  flesh.setState(x, v);
}

// One coupled step in the order of flesh_fluid_coupling3.hpp.
void coupledStep(FleshFluidCoupling3& c, rigid::RigidData& data) {
  const double dt = data.model().timestep_s();
  c.advanceFluid(dt);
  std::fill(data.appliedForces(), data.appliedForces() + data.model().dofs(), 0.0);
  c.applyReaction(data);
  data.step();
  data.kinematics();
  c.forceFluid(data, dt);
}

// A free sphere (r 0.06 m, 0.5 kg) in 1 cm of flesh, thrown at 0.2 m/s through a periodic box of a fluid
// of 10 kg/m³ (the staggered step needs flesh much heavier than the fluid its vertices drag: here
// 10.5 kg/m² of flesh against 0.25 kg/m² of fluid within a cell), advection off (semi-Lagrangian
// advection does not conserve momentum). The fluid gets dt Σ F at step n, flesh and bone −dt Σ F at
// step n + 1, so fluid + flesh + bone + the pending impulse dt Σ_b bodyForce stays constant to
// round-off (the flesh's solve at 1e-13) while the creature slows down. 10 steps, about 0.3 s of CPU.
TEST_F(FleshFluidTest, FluidFleshAndBoneConserveMomentum) {
  const auto model = load(testing::freeSphereXml(0.06, 0.5));
  rigid::RigidData data(model);
  data.qvel()[0] = 0.2;
  data.qvel()[1] = -0.1;
  data.kinematics();
  flesh::FleshParams fp;
  fp.cg_tolerance = 1e-13;
  FleshFluidCoupling3 c(data, box(16, 0.4, fluid3d::Boundaries3::allPeriodic(), 10.0, 1e-4), centred(0.4), fp);
  c.fluid().stages().advection = false;
  ASSERT_GT(c.surfaceMarkers(), 100);
  const double dt = model.timestep_s();
  auto total = [&]() -> Eigen::Vector3d {
    Eigen::Vector3d t = fluidMomentum(c.fluid()) + c.flesh().linearMomentum_kg_m_per_s();
    for (int a = 0; a < 3; ++a) t[a] += 0.5 * data.qvel()[a];
    for (const Vec3& F : c.bodyForce_n())
      for (int a = 0; a < 3; ++a) t[a] += dt * F[a];
    return t;
  };
  const Eigen::Vector3d start = total();
  const double scale = start.norm();
  double drift = 0;
  for (int step = 0; step < 10; ++step) {
    coupledStep(c, data);
    drift = std::max(drift, (total() - start).norm());
  }
  std::printf("momentum: |p| %.4e kg m/s, drift %.2e; bone %.4f m/s; CG %d its\n", scale, drift, data.qvel()[0],
              c.forcingIterations());
  EXPECT_LT(drift, 1e-12 * scale);
  EXPECT_LT(data.qvel()[0], 0.2 * 0.99);  // the fluid took some of the creature's momentum
  EXPECT_GT(data.qvel()[0], 0.0);
}

// A free sphere whose undamped flesh is set moving, in a still fluid in a closed box (no-slip walls,
// ν 1e-3 m²/s): nothing drives it, so the energy of flesh and bone (kinetic, stretch, binding) never
// exceeds its start and decays, and with the fluid's kinetic energy added it does not grow from one step
// to the next. 40 steps, about 1.5 s of CPU.
TEST_F(FleshFluidTest, EnergyDoesNotGrowInAStillFluid) {
  const double r = 0.06, m = 0.5;
  const auto model = load(testing::freeSphereXml(r, m));
  rigid::RigidData data(model);
  data.kinematics();
  flesh::FleshParams undamped;
  undamped.stretch_damping_ratio = undamped.binding_damping_ratio = 0;
  FleshFluidCoupling3 c(data, box(16, 0.4, fluid3d::Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip), 10.0, 1e-3),
                        centred(0.4), undamped);
  disturb(c.flesh(), 0.0, 0.05);
  auto solid = [&] {
    const double* u = data.qvel();
    const double bone = 0.5 * m * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) +
                        0.5 * 0.4 * m * r * r * (u[3] * u[3] + u[4] * u[4] + u[5] * u[5]);
    return bone + c.flesh().kineticEnergy_j() + c.flesh().stretchEnergy_j() + c.flesh().bindingEnergy_j(data);
  };
  const double e0 = solid();
  double most = 0, last_total = e0 + c.fluid().kineticEnergy_joule(), grew = 0;
  for (int step = 0; step < 40; ++step) {
    coupledStep(c, data);
    const double e = solid(), total = e + c.fluid().kineticEnergy_joule();
    most = std::max(most, e);
    grew = std::max(grew, total - last_total);
    last_total = total;
  }
  std::printf("energy: start %.4e J, most %.4e, end %.4e; largest step-to-step growth with the fluid %.2e J\n", e0,
              most, solid(), grew);
  EXPECT_LE(most, e0);
  EXPECT_LT(solid(), 0.5 * e0);
  EXPECT_LE(grew, 1e-9 * e0);
}

// save then restore continues bitwise as the saved run did (the controller's evaluations rely on it),
// also after a placed pose carries the flesh with its body. About 0.3 s of CPU.
TEST_F(FleshFluidTest, SnapshotRestoresBitwise) {
  const auto model = load(testing::freeSphereXml(0.06, 0.5));
  rigid::RigidData data(model);
  data.qvel()[0] = 0.1;
  data.kinematics();
  FleshFluidCoupling3 c(data, box(16, 0.4, fluid3d::Boundaries3::allPeriodic(), 10.0, 1e-4), centred(0.4), {});
  for (int s = 0; s < 2; ++s) coupledStep(c, data);
  FleshFluidState3 saved;
  c.save(saved);
  const rigid::RigidState pose = data.save();
  auto run = [&] {
    for (int s = 0; s < 3; ++s) coupledStep(c, data);
    return std::make_pair(c.flesh().positions_m(), c.fluid().grid().velocity_m_per_s[0]);
  };
  const auto first = run();
  data.restore(pose);
  data.kinematics();
  c.restore(saved, data);
  const auto second = run();
  EXPECT_TRUE(first.first == second.first);
  EXPECT_TRUE(std::equal(first.second.data(), first.second.data() + first.second.size(), second.second.data()));
  // A placed pose: the flesh turned and moved with its body, keeping its shape.
  const Eigen::Matrix3Xd before = c.flesh().positions_m();
  data.qpos()[0] += 0.01;
  data.kinematics();
  c.placeMarkers(data);
  const Eigen::Matrix3Xd shift = c.flesh().positions_m() - before;
  EXPECT_NEAR(shift.row(0).minCoeff(), 0.01, 1e-12);
  EXPECT_NEAR(shift.row(0).maxCoeff(), 0.01, 1e-12);
  EXPECT_NEAR(shift.bottomRows<2>().cwiseAbs().maxCoeff(), 0.0, 1e-12);
}

TEST_F(FleshFluidTest, BadInputIsRefused) {
  const auto model = load(testing::freeSphereXml(0.06, 0.5));
  rigid::RigidData data(model);
  data.kinematics();
  const auto f = box(16, 0.4, fluid3d::Boundaries3::allPeriodic(), 10.0, 1e-4);
  RigidFluidParams3 p = centred(0.4);
  p.viscosity_in_forcing = true;
  EXPECT_THROW(FleshFluidCoupling3(data, f, p, {}), std::invalid_argument);
  RigidFluidParams3 walls = centred(0.4);
  walls.origin_m = {-0.1, -0.2, -0.2};  // the flesh within the kernel's reach of the box's side
  EXPECT_THROW(FleshFluidCoupling3(data, box(16, 0.4, fluid3d::Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip),
                                             10.0, 1e-4), walls, {}),
               std::invalid_argument);
  flesh::FleshParams bad;
  bad.thickness_m = -1;
  EXPECT_THROW(FleshFluidCoupling3(data, f, centred(0.4), bad), std::invalid_argument);
  FleshFluidCoupling3 c(data, f, centred(0.4), {});
  EXPECT_THROW(c.advanceFluid(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::coupling3d
