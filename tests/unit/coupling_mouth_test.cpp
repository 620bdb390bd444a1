// The swimmer's mouth and free creature in the coupled fluid (Lentine et al. 2010 §7.2):
// the flux the mouth enforces moves the fluid across it, the force it takes enters the fluid as
// momentum and the body gets minus it (to round-off); a free creature too light for the staggered
// coupling stops with the stability error instead of exploding silently, and the armature
// stabilisation (fluid_controller.hpp) runs it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "control/fluid_controller.hpp"
#include "control_models.hpp"
#include "coupling/rigid_fluid_coupling.hpp"

namespace creaturelab::coupling {
namespace {

// A free disc (slide x, slide z, hinge y) with one hinged leg; masses scale with `mass_kg`.
std::string swimmerXml(double body_kg, double leg_kg, double armature) {
  const std::string a = std::to_string(armature), ar = std::to_string(armature / 30);
  return "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\" gravity=\"0 0 0\"/><default><geom "
         "contype=\"0\" conaffinity=\"0\"/></default><worldbody><body name=\"body\" pos=\"0 0 0\">"
         "<joint name=\"x\" type=\"slide\" axis=\"1 0 0\" armature=\"" + a + "\"/>"
         "<joint name=\"z\" type=\"slide\" axis=\"0 0 1\" armature=\"" + a + "\"/>"
         "<joint name=\"pitch\" type=\"hinge\" axis=\"0 1 0\" armature=\"" + ar + "\"/>"
         "<geom type=\"sphere\" size=\"0.15\" mass=\"" + std::to_string(body_kg) + "\"/>"
         "<body name=\"leg\" pos=\"0.15 0 0\"><joint name=\"leg\" type=\"hinge\" axis=\"0 1 0\"/>"
         "<geom type=\"capsule\" fromto=\"0.05 0 0 0.28 0 0\" size=\"0.03\" mass=\"" + std::to_string(leg_kg) + "\"/>"
         "</body></body></worldbody></mujoco>";
}

MouthParams expelling(double flux) {
  MouthParams m;
  m.body = "body";
  m.centre_z_m = -0.22;
  m.width_m = 0.14;
  m.schedule.fractions = {1.0};
  m.flux_m_per_s = {flux};
  return m;
}

fluid::FluidParams box64() {
  fluid::FluidParams f;
  f.domain_width_m = f.domain_height_m = 2.0;
  f.cells_x = f.cells_y = 64;
  f.kinematic_viscosity_m2_per_s = 0;
  return f;
}

class MouthTest : public testing::ScratchDirTest {
 protected:
  MouthTest() : ScratchDirTest("mouth") {}
};

// Fluid momentum per metre of depth (world x, z).
std::pair<double, double> momentum(const fluid::MacGrid2& g, double rho) {
  double px = 0, pz = 0;
  const double a = rho * g.dx_m * g.dx_m;
  for (std::size_t k = 0; k < g.u_m_per_s.size(); ++k) px += a * g.u_m_per_s.data()[k];
  for (std::size_t k = 0; k < g.v_m_per_s.size(); ++k) pz += a * g.v_m_per_s.data()[k];
  return {px, pz};
}

// Phases by share of the cycle, repeating; the flux follows them; a table that does not add up, or
// whose fluxes do not match its phases, is refused with the key named.
TEST_F(MouthTest, PhasesFollowTheFractionsAndRepeat) {
  MouthParams m = expelling(0.5);
  m.schedule = {2.0, {0.2, 0.1, 0.7}};
  m.flux_m_per_s = {-0.25, 0.5, 0.0};
  EXPECT_EQ(m.validate(), "");
  EXPECT_EQ(phaseAt(m.schedule, 0.0), 0);
  EXPECT_EQ(phaseAt(m.schedule, 0.39), 0);
  EXPECT_EQ(phaseAt(m.schedule, 0.41), 1);
  EXPECT_EQ(phaseAt(m.schedule, 0.61), 2);
  EXPECT_EQ(phaseAt(m.schedule, 2.5), 1);  // the second cycle
  EXPECT_EQ(mouthFlux_m_per_s(m, 2.1), -0.25);
  EXPECT_EQ(mouthFlux_m_per_s(m, 3.9), 0.0);
  m.schedule.fractions = {0.5, 0.1, 0.7};
  EXPECT_NE(m.validate().find("phase_fractions must sum to 1"), std::string::npos);
  m.schedule.fractions = {0.2, 0.8};
  EXPECT_NE(m.validate().find("phase_flux_m_per_s"), std::string::npos);
}

// The mouth's forcing stage on a fluid at rest with the body still: the momentum the fluid gains is
// minus the force on the bodies times dt (round-off), pointing out of the mouth (down) when it
// expels: the body is pushed up.
TEST_F(MouthTest, ExpellingPushesFluidDownAndBodyUpWithMomentumBalanced) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("s.xml"), swimmerXml(100, 10, 0)));
  rigid::RigidData data(model);
  data.kinematics();
  RigidFluidParams p;
  p.forcing = Forcing::sweeps;  // no projection inside forceFluid: the grid's change is the exchange
  p.origin_x_m = -1.0;
  p.origin_z_m = -1.0;
  p.mouth = expelling(0.5);
  RigidFluidCoupling c(data, box64(), p);
  ASSERT_LT(c.mouthBegin(), c.markers().size());
  const double dt = 0.01, rho = c.fluid().params().density_kg_per_m3;
  c.advanceFluid(dt);
  const auto before = momentum(c.fluid().grid(), rho);
  c.forceFluid(data, dt);
  const auto after = momentum(c.fluid().grid(), rho);
  double fx = 0, fz = 0;
  for (const auto& f : c.bodyForce_n()) fx += f[0], fz += f[2];
  ASSERT_GT(fz, 1.0);  // the body is pushed up by a real force
  EXPECT_NEAR((after.first - before.first) / dt, -fx, 1e-11 * fz);
  EXPECT_NEAR((after.second - before.second) / dt, -fz, 1e-11 * fz);
  // All of it on the mouth's body (the leg's markers have nothing to do).
  EXPECT_NEAR(c.bodyForce_n()[1][2], fz, 1e-9 * fz);
}

// With the projected forcing over a few steps, the fluid at the mouth's centre moves with the flux
// (the flux is enforced, not just a force): -0.5 m/s along z within 5%, and drawing in reverses it.
TEST_F(MouthTest, FluidCrossesTheMouthAtTheFlux) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("s.xml"), swimmerXml(100, 10, 0)));
  for (double flux : {0.5, -0.5}) {
    rigid::RigidData data(model);
    data.kinematics();
    RigidFluidParams p;
    p.origin_x_m = -1.0;
    p.origin_z_m = -1.0;
    p.max_forcing_iterations = 200;
    p.mouth = expelling(flux);
    RigidFluidCoupling c(data, box64(), p);
    for (int s = 0; s < 5; ++s) {
      c.advanceFluid(0.01);
      c.forceFluid(data, 0.01);
      c.project(0.01);
    }
    const auto& g = c.fluid().grid();
    // v faces nearest the mouth centre (world 0, -0.22 -> fluid 1.0, 0.78).
    const int i = int(1.0 / g.dx_m), j = int(std::lround(0.78 / g.dx_m));
    const double v = 0.5 * (g.v_m_per_s(i - 1, j) + g.v_m_per_s(i, j));
    // Volume flux per metre across the mouth's row (the jet and its return within 6 cells of it).
    double q = 0;
    for (int k = i - 8; k < i + 8; ++k) q += g.v_m_per_s(k, j) * g.dx_m;
    std::printf("flux %.2f: v at the centre %.3f m/s, volume flux across the row +-8 cells %.4f m^2/s (mouth %.4f), "
                "CG miss %.2e m/s\n", flux, v, q, -flux * 0.14, c.forcingResidual_m_per_s());
    // The markers meet their velocity (kernel-averaged, what the coupling enforces) to the CG's
    // tolerance; the face on the centre line moves faster, the kernel averaging its profile.
    EXPECT_LT(c.forcingResidual_m_per_s(), 0.01 * 0.5);  // 1% of the flux (tolerance 1e-3 of the top speed)
    EXPECT_GT(-v / flux, 1.0) << "flux " << flux;
    EXPECT_LT(-v / flux, 1.6) << "flux " << flux;
  }
}

// A free creature as dense as the water it displaces, coupled explicitly, stops at the coupled
// stability limit (the error the kind reports as exit 3); with its armature taken as added mass
// (600 kg on 0.09 m^2 of outline) it runs the same two seconds of a leg beating.
control::ControllerParams legController() {
  control::ControllerParams p;
  p.controlled = {"leg"};
  p.objectives = {control::Objective::drag_along};
  p.drag_direction = {0, 0, -1};
  p.senses = {control::Sense::minimize};
  p.strength_rad_per_s = 1.0;
  p.frame_s = 1.0 / 60;
  return p;
}

RigidFluidParams mouthBox() {
  RigidFluidParams cp;
  cp.origin_x_m = -1.0;
  cp.origin_z_m = -1.0;
  cp.mouth = expelling(0.5);
  return cp;
}

int stepsBeforeFailure(bool armature_added_mass) {
  const std::string path = testing::writeText(
      std::filesystem::temp_directory_path() / "mouth_light.xml", swimmerXml(70, 10, 600));
  auto model = rigid::RigidModel::load(path);
  model.setTimestep(1.0 / 60);
  control::ControllerParams p = legController();
  p.search_every_frames = 1000;  // one search: the leg then sweeps at full strength
  control::FluidControlParams f;
  f.armature_added_mass = armature_added_mass;
  control::FluidController c(model, p, f, {}, box64(), mouthBox());
  for (int k = 0; k < 120; ++k) {
    try {
      c.frame();
    } catch (const CouplingError& e) {
      EXPECT_NE(std::string(e.what()).find("coupled stability limit"), std::string::npos) << e.what();
      return k;
    }
  }
  return 120;
}

TEST_F(MouthTest, LightFreeCreatureStopsAtTheStabilityLimitUnlessStabilised) {
  EXPECT_LT(stepsBeforeFailure(false), 120);
  EXPECT_EQ(stepsBeforeFailure(true), 120);
}

// The stabilised free creature with its mouth, controlled for four frames on 1 and 2 threads: the
// armature's force reads the acceleration each evaluation's snapshot restores, so the runs are
// bitwise the same (the root's pose and the fluid).
std::vector<double> stabilisedRun(int threads) {
  const std::string path = testing::writeText(
      std::filesystem::temp_directory_path() / "mouth_threads.xml", swimmerXml(70, 10, 600));
  auto model = rigid::RigidModel::load(path);
  model.setTimestep(1.0 / 60);
  control::ControllerParams p = legController();
  p.threads = threads;
  control::FluidControlParams f;
  f.armature_added_mass = true;
  control::FluidController c(model, p, f, {}, box64(), mouthBox());
  for (int k = 0; k < 4; ++k) c.frame();
  std::vector<double> out(c.data().qpos(), c.data().qpos() + model.positions());
  const auto& g = c.coupling().fluid().grid();
  out.insert(out.end(), g.v_m_per_s.data(), g.v_m_per_s.data() + g.v_m_per_s.size());
  return out;
}

TEST_F(MouthTest, StabilisedSwimmerIsBitwiseTheSameOnOneAndTwoThreads) {
  const auto one = stabilisedRun(1), two = stabilisedRun(2);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_NE(one[1], 0.0);  // the root moved
  EXPECT_EQ(0, std::memcmp(one.data(), two.data(), one.size() * sizeof(double)));
}

}  // namespace
}  // namespace creaturelab::coupling
