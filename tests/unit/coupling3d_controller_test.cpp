// The controller over the 3-D fluid with the coupled solve (coupling3d Forcing3::coupled, Lentine et al. 2010
// Eq. 9; control/fluid_controller.hpp): the servo's prescribed joints are held in the solve (they reach
// their targets), the passive joint feels this step's fluid force, and the frames are bitwise the same for
// 1 and 2 evaluation threads (the snapshot is exact: each thread's copy restores everything).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "control/coupled_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "control_models.hpp"
#include "scratch_dir_test.hpp"

namespace creaturelab::control {
namespace {

class Coupling3ControllerTest : public testing::ScratchDirTest {
 protected:
  Coupling3ControllerTest() : ScratchDirTest("coupling3d_controller") {}
};

// A chain of three hinged capsules (0.4 m, 2 kg each: lighter than the water they displace) in a 0.5 m/s
// stream entering at x low, a 2.0 x 0.8 x 1.2 m box of 20 x 8 x 12 cells, 60 frames a second; j0 and j1
// controlled, j2 passive. Two frames: angles, derivatives, objectives, servo residuals, j2's angle, then the
// fluid's u.
std::vector<double> run(const std::string& xml, int threads, coupling3d::Forcing3 forcing, double& servo_residual_rad) {
  rigid::RigidModel model = rigid::RigidModel::load(xml);
  model.setGravity({0, 0, 0});
  model.setTimestep(1.0 / 60);
  fluid3d::FluidParams3 f;
  f.domain_x_m = 2.0;
  f.domain_y_m = 0.8;
  f.domain_z_m = 1.2;
  f.cells_x = 20;
  f.cells_y = 8;
  f.cells_z = 12;
  f.kinematic_viscosity_m2_per_s = 0;
  f.boundaries.axis[0].low = fluid3d::BoundaryType3::inflow;
  f.boundaries.axis[0].low_inflow_m_per_s = 0.5;
  f.boundaries.axis[0].high = fluid3d::BoundaryType3::open;
  f.time_step_policy = fluid3d::TimeStepPolicy3::fixed;
  f.fixed_step_s = 1.0 / 60;
  coupling3d::RigidFluidParams3 cp;
  cp.origin_m = {-0.4, -0.4, -0.6};
  cp.forcing = forcing;
  ControllerParams p;
  p.controlled = {"j0", "j1"};
  p.objectives = {Objective::drag_along, Objective::drag};
  p.senses = {Sense::minimize, Sense::maximize};
  p.threads = threads;
  p.delta_rad = 0.02;
  FluidControlParams fc;
  fc.planar_fluid = false;
  FluidController c(model, p, fc, {{"j0", -0.3}, {"j1", 0.2}}, spatialFluid(f, cp));
  std::vector<double> out;
  servo_residual_rad = 0;
  for (int k = 0; k < 2; ++k) {
    const FrameRecord r = c.frame();
    out.insert(out.end(), r.angle_rad.begin(), r.angle_rad.end());
    out.insert(out.end(), r.derivative.begin(), r.derivative.end());
    out.insert(out.end(), r.objective.begin(), r.objective.end());
    servo_residual_rad = std::max(servo_residual_rad, r.servo_residual_rad);
    for (int a = 0; a < 2; ++a)  // the controlled joints end on their targets
      servo_residual_rad = std::max(servo_residual_rad, std::abs(r.angle_rad[a] - r.target_rad[a]));
  }
  out.push_back(c.data().qpos()[model.joint(model.findJoint("j2")).qpos]);
  const auto& u = dynamic_cast<const CoupledFluid3&>(c.coupledFluid()).coupling().fluid().grid().velocity_m_per_s[0];
  out.insert(out.end(), u.data(), u.data() + u.size());
  return out;
}

TEST_F(Coupling3ControllerTest, CoupledSolveHoldsTheServoAndIsThreadIndependent) {
  const std::string xml = testing::writeText(file("chain.xml"), testing::chainXml(3));
  double residual_one = 0, residual_two = 0, residual_projected = 0;
  const auto one = run(xml, 1, coupling3d::Forcing3::coupled, residual_one);
  const auto two = run(xml, 2, coupling3d::Forcing3::coupled, residual_two);
  std::printf("j2 %.6g after two frames (coupled)\n", one[12]);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(0, std::memcmp(one.data(), two.data(), one.size() * sizeof(double)));
  EXPECT_LT(residual_one, 1e-6);
  EXPECT_NE(one[2], 0.0);  // the fluid pushes on the capsules: a derivative is not zero
  // The passive joint moves, and differently from the projected forcing's (the fluid's force in its own step).
  const double j2 = one[12];
  EXPECT_GT(std::abs(j2), 1e-5);
  // The projected forcing's lagged reaction on the light passive link: unstable, or at least another motion.
  try {
    const auto projected = run(xml, 1, coupling3d::Forcing3::projected, residual_projected);
    EXPECT_NE(projected[12], j2);
  } catch (const coupling3d::CouplingError3& e) {
    std::printf("projected: %s\n", e.what());
  } catch (const fluid3d::FluidBlowUpError3& e) {
    std::printf("projected: %s\n", e.what());
  }
}

}  // namespace
}  // namespace creaturelab::control
