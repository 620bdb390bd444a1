// What the 3-D creature renders are drawn from (Lentine et al. 2010 Figs. 11, 13;
// control/fluid_run3.hpp): the run recorder's geom poses are MuJoCo's, bit for bit, and its stored Q
// is the fluid's at that frame.
#include <gtest/gtest.h>

#include <cstring>

#include "control/coupled_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "control/fluid_run3.hpp"
#include "control_models.hpp"

namespace creaturelab::control {
namespace {

// The chain's two hinged capsules (0.8 m along +x) in a still 1.6 x 0.8 x 1.2 m box of 16 x 8 x 12
// cells under the controller for three frames; the recorder's last pose and stored Q are compared.
class RenderCreatureRecord : public testing::ScratchDirTest {
 protected:
  RenderCreatureRecord() : ScratchDirTest("render_creature") {}
};

TEST_F(RenderCreatureRecord, PosesAreMujocosAndQIsTheFluids) {
  rigid::RigidModel model = rigid::RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(2)));
  model.setGravity({0, 0, 0});
  model.setTimestep(1.0 / 60);
  fluid3d::FluidParams3 f;
  f.domain_x_m = 1.6, f.domain_y_m = 0.8, f.domain_z_m = 1.2;
  f.cells_x = 16, f.cells_y = 8, f.cells_z = 12;
  f.kinematic_viscosity_m2_per_s = 0;
  f.time_step_policy = fluid3d::TimeStepPolicy3::fixed;
  f.fixed_step_s = 1.0 / 60;
  coupling3d::RigidFluidParams3 cp;
  cp.origin_m = {-0.4, -0.4, -0.6};
  ControllerParams p;
  p.controlled = {"j0", "j1"};
  p.objectives = {Objective::drag, Objective::drag};
  p.senses = {Sense::maximize, Sense::maximize};
  p.strength_rad_per_s = 2.0;
  FluidControlParams fp;
  fp.planar_fluid = false;
  FluidController c(model, p, fp, {{"j0", -0.3}, {"j1", 0.5}}, spatialFluid(f, cp));
  FluidRunRecorder3 recorder(model, p, {StoredFields3::volume, 2});
  for (int k = 0; k < 3; ++k) recorder.record(c.frame(), c);

  const GeomPoses3& g = recorder.geoms();
  ASSERT_EQ(g.geoms(), model.geoms());
  ASSERT_EQ(g.time_s.size(), 3u);
  EXPECT_EQ(g.time_s.back(), c.data().time_s());
  const std::size_t last = 2 * std::size_t(g.geoms());
  for (int k = 0; k < g.geoms(); ++k) {
    EXPECT_EQ(g.type[k], 3);  // capsules
    EXPECT_EQ(0, std::memcmp(&g.position_m[3 * (last + k)], c.data().geomPosition(k), 3 * sizeof(double))) << k;
    EXPECT_EQ(0, std::memcmp(&g.rotation[9 * (last + k)], c.data().geomRotation(k), 9 * sizeof(double))) << k;
  }
  EXPECT_NE(g.rotation[9 * last], g.rotation[9 * (last - g.geoms())]) << "the controlled chain moves between frames";

  // Fields after frames 0 and 2: the last is the grid's Q now.
  const FluidFrames3& fl = recorder.fluid();
  ASSERT_EQ(fl.time_s.size(), 2u);
  const auto& grid = dynamic_cast<const CoupledFluid3&>(c.coupledFluid()).coupling().fluid().grid();
  fluid3d::FlowObservables3 obs;
  obs.update(grid);
  const fluid3d::Array3& q = obs.q_per_s2();
  const auto& stored = fl.fields.back();
  ASSERT_EQ(stored.name, "q_per_s2");
  ASSERT_EQ(stored.values.size(), 2 * q.size());
  EXPECT_EQ(0, std::memcmp(stored.values.data() + q.size(), q.data(), q.size() * sizeof(double)));
}

}  // namespace
}  // namespace creaturelab::control
