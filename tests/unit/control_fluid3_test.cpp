// The controller over the 3-D coupled fluid (control/coupled_fluid3.hpp; Lentine et al. 2010 §4.3,
// §5): its snapshot is exact (grid, markers, warm start, pending reaction), so the derivative
// evaluations share one fluid copy per thread; the frames are bitwise the same for any evaluation and
// fluid thread count. The snapshot brings the grid back.
#include <gtest/gtest.h>

#include <cstring>

#include "control/coupled_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "control_fluid3_scene.hpp"

namespace creaturelab::control {
namespace {

class ControlFluid3Test : public testing::ScratchDirTest {
 protected:
  ControlFluid3Test() : ScratchDirTest("control_fluid3") {}
};

// Three frames of the chain in the stream (control_fluid3_scene.hpp): angles, derivatives and objectives,
// then the fluid's u.
std::vector<double> run3(const std::string& xml, int threads, int fluid_threads) {
  const rigid::RigidModel model = testing::chainModel3(xml);
  FluidController c(model, testing::chainController3(threads), testing::chainEvaluations3(), testing::chainInitialRad3(),
                    spatialFluid(testing::chainStream3(fluid_threads), testing::chainCoupling3()));
  std::vector<double> out;
  testing::recordFrames(c, 3, out);
  testing::appendValues(dynamic_cast<const CoupledFluid3&>(c.coupledFluid()).coupling().fluid().grid().velocity_m_per_s[0],
                        out);
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
  CoupledFluid3 fluid(data, testing::chainStream3(1), testing::chainCoupling3());
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
