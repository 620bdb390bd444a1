// The flesh in the coupled solve (coupling3d/flesh_fluid_coupling3.hpp, Forcing3::coupled; Lentine et al.
// 2010 §5 Eq. 9 with the flesh's backward Euler step as the vertices' mobility): a flesh as dense as the
// water round it is stable and its energy does not grow, where the staggered projected forcing on the same
// scene grows (the mechanism's breaking counterpart); fluid, flesh and bone keep their momentum to
// round-off; a mouth's jet lifts the creature; the force on the bone is the body's less the flesh's momentum
// rate; a flesh follows a bone swept through water only when bound stiffly; a snapshot restores the run bitwise;
// the fluid's thread count does not change a bit.
// CPU time of each TEST in its comment (Release).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "control_models.hpp"
#include "coupling3d/flesh_fluid_coupling3.hpp"
#include "flesh/binding.hpp"
#include "flesh_models.hpp"
#include "fluid3_momentum.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::coupling3d {
namespace {

class FleshCoupledTest : public testing::ScratchDirTest {
 protected:
  FleshCoupledTest() : ScratchDirTest("flesh_coupled") {}
  rigid::RigidModel load(const std::string& xml) {
    return rigid::RigidModel::load(testing::writeText(file("model.xml"), xml));
  }
};

constexpr double kWater = 1000.0;  // kg/m³
constexpr double kRadius = 0.06;   // the bone's, m
constexpr double kNeutralBone = 0.9;  // kg: 0.5% lighter than the water the bone displaces (4/3 π r³ ρ)

// A cube of n³ cells and side L around the world's origin.
fluid3d::FluidParams3 box(int n, double side_m, const fluid3d::Boundaries3& sides, double nu, int threads = 1) {
  fluid3d::FluidParams3 f;
  f.domain_x_m = f.domain_y_m = f.domain_z_m = side_m;
  f.cells_x = f.cells_y = f.cells_z = n;
  f.boundaries = sides;
  f.density_kg_per_m3 = kWater;
  f.kinematic_viscosity_m2_per_s = nu;
  f.pressure_solver = fluid3d::PressureSolverType3::spectral;
  f.threads = threads;
  return f;
}

RigidFluidParams3 centred(double side_m, Forcing3 forcing) {
  RigidFluidParams3 p;
  p.forcing = forcing;
  p.forcing_regularisation = 3e-2;  // the flesh's staggered weight (flesh_fluid_coupling3.hpp), for both forcings
  p.origin_m = {-0.5 * side_m, -0.5 * side_m, -0.5 * side_m};
  return p;
}

// Flesh as dense as the water, undamped (nothing but the fluid takes its energy).
flesh::FleshParams neutralFlesh() {
  flesh::FleshParams f;
  f.density_kg_per_m3 = kWater;
  f.stretch_damping_ratio = f.binding_damping_ratio = 0;
  return f;
}

// Every vertex moving at up to v (deterministic).
void disturb(flesh::Flesh& flesh, double v_m_per_s) {
  Eigen::Matrix3Xd v = flesh.velocities_m_per_s();
  for (int i = 0; i < flesh.vertices(); ++i)
    for (int d = 0; d < 3; ++d) v(d, i) += v_m_per_s * std::cos(0.7 * i + 1.7 * d);
  flesh.setState(flesh.positions_m(), v);
}

// One step in the header's order (with the coupled forcing applyReaction adds nothing and forceFluid
// corrects data).
void step(FleshFluidCoupling3& c, rigid::RigidData& data) {
  const double dt = data.model().timestep_s();
  c.advanceFluid(dt);
  std::fill(data.appliedForces(), data.appliedForces() + data.model().dofs(), 0.0);
  c.applyReaction(data);
  data.step();
  data.kinematics();
  c.forceFluid(data, dt);
}

// Kinetic energy of the free sphere of mass m (J).
double boneEnergy(const rigid::RigidData& data, double m) {
  const double* u = data.qvel();
  return 0.5 * m * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) +
         0.5 * 0.4 * m * kRadius * kRadius * (u[3] * u[3] + u[4] * u[4] + u[5] * u[5]);
}

struct EnergyRun {
  double start = 0, most = 0, end = 0;  // flesh, bone and fluid together (J)
  int steps = 0;                        // steps done before a blow-up (or all)
  bool failed = false;                  // a coupling or blow-up error
};

// The neutral sphere in flesh set moving in still water in a closed box (16³ cells of 2.5 cm, no-slip walls,
// ν 1e-4 m²/s): the water round a vertex within the kernel's reach (ρ dx = 25 kg/m²) is 2.5 times its flesh
// (ρ t = 10 kg/m²).
EnergyRun neutralSphere(const rigid::RigidModel& model, Forcing3 forcing, int steps) {
  rigid::RigidData data(model);
  data.kinematics();
  FleshFluidCoupling3 c(data, box(16, 0.4, fluid3d::Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip), 1e-4),
                        centred(0.4, forcing), neutralFlesh());
  disturb(c.flesh(), 0.05);
  auto energy = [&] {
    return boneEnergy(data, kNeutralBone) + c.flesh().kineticEnergy_j() + c.flesh().stretchEnergy_j() +
           c.flesh().bindingEnergy_j(data) + c.fluid().kineticEnergy_joule();
  };
  EnergyRun r;
  r.start = r.most = r.end = energy();
  try {
    for (int s = 0; s < steps; ++s) {
      step(c, data);
      r.end = energy();
      r.most = std::max(r.most, r.end);
      ++r.steps;
      if (!std::isfinite(r.end)) break;
    }
  } catch (const CouplingError3&) {
    r.failed = true;
  } catch (const fluid3d::FluidBlowUpError3&) {
    r.failed = true;
  }
  return r;
}

// Coupled: 40 steps (0.4 s) without growth, the energy decaying. About 2 s of CPU.
TEST_F(FleshCoupledTest, NeutralFleshIsStableInTheCoupledSolve) {
  const auto model = load(testing::freeSphereXml(kRadius, kNeutralBone));
  const EnergyRun r = neutralSphere(model, Forcing3::coupled, 40);
  std::printf("coupled: energy start %.4e J, most %.4e, end %.4e after %d steps\n", r.start, r.most, r.end, r.steps);
  EXPECT_FALSE(r.failed);
  EXPECT_EQ(r.steps, 40);
  EXPECT_LE(r.most, r.start * (1 + 1e-9));
  EXPECT_LT(r.end, 0.5 * r.start);
}

// The breaking counterpart: the same scene with the staggered projected forcing grows (or blows up) within
// the same steps (it blows up within a few). About 0.2 s of CPU.
TEST_F(FleshCoupledTest, NeutralFleshGrowsWithTheStaggeredForcing) {
  const auto model = load(testing::freeSphereXml(kRadius, kNeutralBone));
  const EnergyRun r = neutralSphere(model, Forcing3::projected, 40);
  std::printf("projected: energy start %.4e J, most %.4e, end %.4e after %d steps%s\n", r.start, r.most, r.end,
              r.steps, r.failed ? " (blew up)" : "");
  EXPECT_TRUE(r.failed || !(r.most <= 2 * r.start));
}

// The sphere in flesh thrown at 0.2 m/s through a periodic box of water, advection off (semi-Lagrangian
// advection does not conserve momentum): the fluid gets dt Σ F and flesh and bone −dt Σ F in the same step,
// so their momentum together stays constant to round-off while the creature slows down. 10 steps, about 1 s.
TEST_F(FleshCoupledTest, FluidFleshAndBoneConserveMomentum) {
  const auto model = load(testing::freeSphereXml(kRadius, kNeutralBone));
  rigid::RigidData data(model);
  data.qvel()[0] = 0.2;
  data.qvel()[1] = -0.1;
  data.kinematics();
  flesh::FleshParams fp;
  fp.density_kg_per_m3 = kWater;
  FleshFluidCoupling3 c(data, box(16, 0.4, fluid3d::Boundaries3::allPeriodic(), 1e-4), centred(0.4, Forcing3::coupled), fp);
  c.fluid().stages().advection = false;
  auto total = [&]() -> Eigen::Vector3d {
    Eigen::Vector3d t = fluidMomentum(c.fluid()) + c.flesh().linearMomentum_kg_m_per_s();
    for (int a = 0; a < 3; ++a) t[a] += kNeutralBone * data.qvel()[a];
    return t;
  };
  const Eigen::Vector3d start = total();
  const double solid0 = std::abs(data.qvel()[0]);
  double drift = 0;
  for (int s = 0; s < 10; ++s) {
    step(c, data);
    drift = std::max(drift, (total() - start).norm());
  }
  std::printf("momentum: |p| %.4e kg m/s, drift %.2e; bone %.4f m/s; CG %d its, residual %.2e m/s\n", start.norm(),
              drift, data.qvel()[0], c.forcingIterations(), c.forcingResidual_m_per_s());
  EXPECT_LT(drift, 1e-10 * start.norm());
  EXPECT_LT(data.qvel()[0], 0.9 * solid0);  // the water took a good share of it (added mass)
  EXPECT_GT(data.qvel()[0], 0.0);
}

// A mouth (Lentine et al. 2010 §7.2) below the sphere in flesh expels water downwards (0.5 m/s through a 3 cm
// disc 2 cells below the flesh) in a periodic box: the jet's reaction lifts the creature, and fluid, flesh and
// bone keep their momentum (the mouth's force is internal). The breaking counterpart: no flux, no lift.
// 10 steps each, about 2 s of CPU.
TEST_F(FleshCoupledTest, MouthJetLiftsTheCreature) {
  const auto model = load(testing::freeSphereXml(kRadius, kNeutralBone));
  auto run = [&](double flux_m_per_s, double& drift) {
    rigid::RigidData data(model);
    data.kinematics();
    RigidFluidParams3 p = centred(0.4, Forcing3::coupled);
    Mouth3 mouth;
    mouth.geom = 0;
    mouth.centre_geom_m = {0.0, 0.0, -(kRadius + 0.01 + 2 * 0.025)};
    mouth.radius_m = 0.03;
    p.mouths = {mouth};
    flesh::FleshParams fp;
    fp.density_kg_per_m3 = kWater;
    FleshFluidCoupling3 c(data, box(16, 0.4, fluid3d::Boundaries3::allPeriodic(), 1e-4), p, fp);
    c.fluid().stages().advection = false;
    c.setMouthFlux(0, flux_m_per_s);
    auto total = [&]() -> Eigen::Vector3d {
      Eigen::Vector3d t = fluidMomentum(c.fluid()) + c.flesh().linearMomentum_kg_m_per_s();
      for (int a = 0; a < 3; ++a) t[a] += kNeutralBone * data.qvel()[a];
      return t;
    };
    const Eigen::Vector3d start = total();
    drift = 0;
    for (int s = 0; s < 10; ++s) {
      step(c, data);
      drift = std::max(drift, (total() - start).norm());
    }
    return data.qvel()[2];
  };
  double drift = 0, still_drift = 0;
  const double lifted = run(0.5, drift), still = run(0.0, still_drift);
  std::printf("mouth: bone's vz %.4e m/s with the jet, %.2e without; momentum drift %.2e kg m/s\n", lifted, still, drift);
  EXPECT_GT(lifted, 1e-3);
  EXPECT_LT(std::abs(still), 1e-3 * lifted);
  EXPECT_LT(drift, 1e-12);
}

// The force on the bone (boneForce_n: the binding's reaction and the fluid's on the interior markers) is the
// fluid's force on the body (bodyForce_n: on its flesh and interior) less the rate of change of the flesh's
// momentum over the step, to round-off: the binding forces read are those at the step's end, which the flesh's
// backward Euler step integrated with. The breaking counterpart: the flesh (set shaking, 1050 kg/m³) takes a
// good share of the fluid's force, so the body's force read as the bone's misses by it. 5 steps, about 0.5 s.
TEST_F(FleshCoupledTest, BoneForceIsTheBodyForceLessTheFleshsMomentumRate) {
  const auto model = load(testing::freeSphereXml(kRadius, kNeutralBone));
  rigid::RigidData data(model);
  data.qvel()[0] = 0.2;
  data.kinematics();
  FleshFluidCoupling3 c(data, box(16, 0.4, fluid3d::Boundaries3::allPeriodic(), 1e-4), centred(0.4, Forcing3::coupled),
                        flesh::FleshParams{});
  disturb(c.flesh(), 0.05);
  const double dt = model.timestep_s();
  double miss = 0, scale = 0, inertia = 0;
  for (int s = 0; s < 5; ++s) {
    const Eigen::Vector3d p0 = c.flesh().linearMomentum_kg_m_per_s();
    step(c, data);
    const Eigen::Vector3d rate = (c.flesh().linearMomentum_kg_m_per_s() - p0) / dt;
    const Vec3& body = c.bodyForce_n()[1];
    const Vec3& bone = c.boneForce_n()[1];
    for (int a = 0; a < 3; ++a) {
      miss = std::max(miss, std::abs(bone[a] - (body[a] - rate[a])));
      scale = std::max(scale, std::abs(body[a]));
      inertia = std::max(inertia, std::abs(rate[a]));
    }
  }
  std::printf("bone force: |body - rate - bone| %.2e N, |body force| up to %.4e N, flesh's |dp/dt| up to %.4e N\n",
              miss, scale, inertia);
  EXPECT_LT(miss, 1e-9 * scale);
  EXPECT_GT(inertia, 0.1 * scale);
}

// The lag of the flesh behind its bone while a capsule in flesh (spinnerXml: 0.4 m, radius 4 cm; 1 cm of flesh at
// 1050 kg/m³), hinged at one end and held in the solve, is swept from rest at 2 rad/s through water in steps of
// 1/120 s on 0.1 m cells (the swimmer's power stroke, step and cells): the RMS over the vertices and the sweep's
// second half (0.075-0.15 s) of |v_i - w_i|, over the RMS of the anchors' speed |w_i|.
double sweptLag(const rigid::RigidModel& model, double binding_hz) {
  rigid::RigidData data(model);
  data.kinematics();
  RigidFluidParams3 p = centred(1.6, Forcing3::coupled);
  p.held_joints = {"spin"};
  flesh::FleshParams fp;
  fp.binding_hz = binding_hz;
  FleshFluidCoupling3 c(data, box(16, 1.6, fluid3d::Boundaries3::allPeriodic(), 0.0), p, fp);
  data.qvel()[0] = 2.0;
  data.kinematics();
  double lag2 = 0, speed2 = 0;
  Eigen::Matrix3Xd anchor, anchor_v;
  for (int s = 0; s < 18; ++s) {
    step(c, data);
    if (s < 9) continue;
    flesh::anchorStates(c.flesh().mesh(), data, anchor, anchor_v);
    lag2 += (c.flesh().velocities_m_per_s() - anchor_v).squaredNorm();
    speed2 += anchor_v.squaredNorm();
  }
  return std::sqrt(lag2 / speed2);
}

// A flesh bound at 200 Hz follows the swept bone (lag under 5%); the breaking counterpart, the flesh's default
// 10 Hz binding, loaded by the water its markers drag, still lags by more than 30% after 0.075 s, so a stroke of
// the bone reaches the water only in part (the 3-D swimmer's legs carry no markers of their own at 16 cells: the
// flesh is all the fluid sees of them). About 1.3 s of CPU.
TEST_F(FleshCoupledTest, FleshFollowsASweptBoneInWaterOnlyWhenBoundStiffly) {
  rigid::RigidModel model = load(testing::spinnerXml());
  model.setTimestep(1.0 / 120);
  const double stiff = sweptLag(model, 200.0), soft = sweptLag(model, flesh::FleshParams{}.binding_hz);
  std::printf("swept bone in water: the flesh lags %.4f bound at 200 Hz, %.4f at the default 10 Hz\n", stiff, soft);
  EXPECT_LT(stiff, 0.05);
  EXPECT_GT(soft, 0.3);
}

// A run restored from a snapshot continues bitwise as another restored from it later (the controller's
// evaluations rely on it; both restore MuJoCo's data too, whose kinematics renormalise the root's quaternion
// in place, an ulp each time); the fluid on 1 or 2 threads gives the same bits. About 2 s of CPU.
TEST_F(FleshCoupledTest, SnapshotAndThreadsAreBitwise) {
  const auto model = load(testing::freeSphereXml(kRadius, kNeutralBone));
  auto run = [&](int threads, int detour_steps) {
    rigid::RigidData data(model);
    data.qvel()[0] = 0.1;
    data.qvel()[5] = 1.0;
    data.kinematics();
    FleshFluidCoupling3 c(data, box(16, 0.4, fluid3d::Boundaries3::allPeriodic(), 1e-4, threads),
                          centred(0.4, Forcing3::coupled), neutralFlesh());
    for (int s = 0; s < 2; ++s) step(c, data);
    FleshFluidState3 saved;
    c.save(saved);
    const rigid::RigidState pose = data.save();
    for (int s = 0; s < detour_steps; ++s) step(c, data);
    data.restore(pose);
    data.kinematics();
    c.restore(saved, data);
    for (int s = 0; s < 3; ++s) step(c, data);
    const fluid3d::Array3& u = c.fluid().grid().velocity_m_per_s[0];
    return std::make_tuple(c.flesh().positions_m(), std::vector<double>(u.data(), u.data() + u.size()),
                           std::vector<double>(data.qvel(), data.qvel() + 6));
  };
  const auto once = run(1, 0);
  const auto again = run(1, 2);
  const auto threaded = run(2, 0);
  EXPECT_TRUE(std::get<0>(once) == std::get<0>(again));
  EXPECT_TRUE(std::get<1>(once) == std::get<1>(again));
  EXPECT_TRUE(std::get<2>(once) == std::get<2>(again));
  EXPECT_TRUE(std::get<0>(once) == std::get<0>(threaded));
  EXPECT_TRUE(std::get<1>(once) == std::get<1>(threaded));
  EXPECT_TRUE(std::get<2>(once) == std::get<2>(threaded));
}

// About 6 s of CPU (the thick flesh refined up to the cap).
TEST_F(FleshCoupledTest, BadInputIsRefused) {
  const auto model = load(testing::freeSphereXml(kRadius, kNeutralBone));
  rigid::RigidData data(model);
  data.kinematics();
  const auto f = box(16, 0.4, fluid3d::Boundaries3::allPeriodic(), 1e-4);
  flesh::FleshParams explicit_bones;
  explicit_bones.implicit_skeleton = false;
  EXPECT_THROW(FleshFluidCoupling3(data, f, centred(0.4, Forcing3::coupled), explicit_bones), std::invalid_argument);
  RigidFluidParams3 held = centred(0.4, Forcing3::coupled);
  held.held_joints = {"no such joint"};
  EXPECT_THROW(FleshFluidCoupling3(data, f, held, {}), std::invalid_argument);
  // A flesh far thicker than the bone's curvature allows at the markers' spacing: refused before it fills the
  // memory (flesh_mesh.cpp's vertex cap), not built.
  flesh::FleshParams thick;
  thick.thickness_m = 2.0;
  EXPECT_THROW(FleshFluidCoupling3(data, f, centred(0.4, Forcing3::coupled), thick), std::invalid_argument);
  FleshFluidCoupling3 c(data, f, centred(0.4, Forcing3::coupled), {});
  EXPECT_THROW(c.setHeldDofs({6}), std::invalid_argument);
  EXPECT_THROW(c.forceFluid(static_cast<const rigid::RigidData&>(data), 0.01), std::logic_error);
}

}  // namespace
}  // namespace creaturelab::coupling3d
