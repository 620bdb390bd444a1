// The controller over the 3-D coupled fluid (control/coupled_fluid3.hpp; Lentine et al. 2010 §4.3,
// §5): its snapshot is exact (grid, markers, warm start, pending reaction), so the derivative
// evaluations share one fluid copy per thread; the frames are bitwise the same for any evaluation and
// fluid thread count. The snapshot brings the grid back.
#include <gtest/gtest.h>

#include <cstring>

#include "control/coupled_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "control_models.hpp"

namespace creaturelab::control {
namespace {

class ControlFluid3Test : public testing::ScratchDirTest {
 protected:
  ControlFluid3Test() : ScratchDirTest("control_fluid3") {}
};

// The chain's two hinged capsules (0.4 m, along +x from the origin) in a 0.5 m/s stream entering
// at x low, a 1.6 x 0.8 x 1.2 m box of 16 x 8 x 12 cells, 60 frames a second.
fluid3d::FluidParams3 stream3(int fluid_threads) {
  fluid3d::FluidParams3 f;
  f.domain_x_m = 1.6;
  f.domain_y_m = 0.8;
  f.domain_z_m = 1.2;
  f.cells_x = 16;
  f.cells_y = 8;
  f.cells_z = 12;
  f.kinematic_viscosity_m2_per_s = 0;
  f.boundaries.axis[0].low = fluid3d::BoundaryType3::inflow;
  f.boundaries.axis[0].low_inflow_m_per_s = 0.5;
  f.boundaries.axis[0].high = fluid3d::BoundaryType3::open;
  f.time_step_policy = fluid3d::TimeStepPolicy3::fixed;
  f.fixed_step_s = 1.0 / 60;
  f.threads = fluid_threads;
  return f;
}

// Three frames: angles, derivatives and objectives, then the fluid's u.
std::vector<double> run3(const std::string& xml, int threads, int fluid_threads) {
  rigid::RigidModel model = rigid::RigidModel::load(xml);
  model.setGravity({0, 0, 0});
  model.setTimestep(1.0 / 60);
  coupling3d::RigidFluidParams3 cp;
  cp.origin_m = {-0.4, -0.4, -0.6};
  ControllerParams p;
  p.controlled = {"j0", "j1"};
  p.objectives = {Objective::drag_along, Objective::drag};
  p.senses = {Sense::minimize, Sense::maximize};
  p.threads = threads;
  p.delta_rad = 0.02;
  FluidControlParams f;
  f.settle_steps = 1;
  f.planar_fluid = false;
  FluidController c(model, p, f, {{"j0", -0.3}, {"j1", 0.2}}, spatialFluid(stream3(fluid_threads), cp));
  std::vector<double> out;
  for (int k = 0; k < 3; ++k) {
    const FrameRecord r = c.frame();
    out.insert(out.end(), r.angle_rad.begin(), r.angle_rad.end());
    out.insert(out.end(), r.derivative.begin(), r.derivative.end());
    out.insert(out.end(), r.objective.begin(), r.objective.end());
  }
  const auto& u = dynamic_cast<const CoupledFluid3&>(c.coupledFluid()).coupling().fluid().grid().velocity_m_per_s[0];
  out.insert(out.end(), u.data(), u.data() + u.size());
  return out;
}

TEST_F(ControlFluid3Test, BitwiseSameForAnyThreadCount) {
  const std::string xml = testing::writeText(file("chain.xml"), testing::chainXml(2));
  const auto one = run3(xml, 1, 1);
  // 2 threads: one joint's two evaluations each; 3: split 1, 1, 2 (a joint's two on different threads);
  // and two fluid threads in the frame's steps.
  for (const auto& [threads, fluid_threads] : {std::pair{2, 1}, std::pair{3, 1}, std::pair{2, 2}}) {
    const auto parallel = run3(xml, threads, fluid_threads);
    ASSERT_EQ(one.size(), parallel.size());
    EXPECT_EQ(0, std::memcmp(one.data(), parallel.data(), one.size() * sizeof(double)))
        << threads << " threads, " << fluid_threads << " fluid threads";
  }
  // The fluid pushes on the capsules: the derivatives are not zero.
  EXPECT_NE(one[2], 0.0);
  EXPECT_NE(one[3], 0.0);
}

TEST_F(ControlFluid3Test, SnapshotRestoresTheGrid) {
  const std::string xml = testing::writeText(file("chain.xml"), testing::chainXml(2));
  rigid::RigidModel model = rigid::RigidModel::load(xml);
  rigid::RigidData data(model);
  data.kinematics();
  coupling3d::RigidFluidParams3 cp;
  cp.origin_m = {-0.4, -0.4, -0.6};
  CoupledFluid3 fluid(data, stream3(1), cp);
  const double dt = 1.0 / 60;
  fluid.advanceFluid(dt);
  fluid.forceAndProject(data, dt);
  std::unique_ptr<FluidSnapshot> s;
  fluid.save(s);
  const fluid3d::MacGrid3 saved = fluid.coupling().fluid().grid();
  fluid.advanceFluid(dt);
  fluid.forceAndProject(data, dt);
  const auto& u = fluid.coupling().fluid().grid().velocity_m_per_s[2];
  ASSERT_NE(0, std::memcmp(u.data(), saved.velocity_m_per_s[2].data(), u.size() * sizeof(double)));
  fluid.restore(*s, data);
  for (int a = 0; a < 3; ++a) {
    const auto& v = fluid.coupling().fluid().grid().velocity_m_per_s[a];
    EXPECT_EQ(0, std::memcmp(v.data(), saved.velocity_m_per_s[a].data(), v.size() * sizeof(double))) << a;
  }
}

}  // namespace
}  // namespace creaturelab::control
