// The controller over the 3-D fluid with the creature wrapped in flesh in the coupled solve
// (control/coupled_flesh_fluid3.hpp with Forcing3::coupled; Lentine et al. 2010 §4.3, §5 Eq. 9): the
// snapshot is exact, so the frames are bitwise the same for any evaluation and fluid thread count, with moved
// and with placed perturbations; the servo's joint is held in the solve, the chain's second joint is free.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "control/coupled_flesh_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "control_fluid3_scene.hpp"

namespace creaturelab::control {
namespace {

class ControlFleshCoupledTest : public testing::ScratchDirTest {
 protected:
  ControlFleshCoupledTest() : ScratchDirTest("control_flesh_coupled") {}
};

// Two frames of the chain in flesh in a stream of water (control_fluid3_scene.hpp; 1000 kg/m^3, the capsules
// about as dense), j0 controlled, j1 free: angles, derivatives and objectives, then the flesh's positions, the
// fluid's u and the free joint's angle and speed.
std::vector<double> run3(const std::string& xml, int threads, int fluid_threads, Perturbation perturbation) {
  const rigid::RigidModel model = testing::chainModel3(xml);
  const fluid3d::FluidParams3 water = testing::chainStream3(fluid_threads);
  coupling3d::RigidFluidParams3 cp = testing::chainCoupling3();
  cp.forcing = coupling3d::Forcing3::coupled;
  cp.forcing_regularisation = 3e-2;
  ControllerParams p = testing::chainController3(threads);
  p.controlled.resize(1);
  p.objectives.resize(1);
  p.senses.resize(1);
  FluidController c(model, p, testing::chainEvaluations3(perturbation),
                    testing::chainInitialRad3(), fleshFluid(water, cp, {}));
  EXPECT_TRUE(c.coupledFluid().coupledSolve());
  std::vector<double> out;
  testing::recordFrames(c, 2, out);
  const auto& coupling = dynamic_cast<const CoupledFleshFluid3&>(c.coupledFluid()).coupling();
  testing::appendValues(coupling.flesh().positions_m(), out);
  testing::appendValues(coupling.fluid().grid().velocity_m_per_s[0], out);
  out.push_back(c.data().qpos()[1]);
  out.push_back(c.data().qvel()[1]);
  return out;
}

// One thread against two evaluation threads with two fluid threads (moved), and with one (placed); the free
// joint moved by the stream and the flesh. About 3 s of CPU.
TEST_F(ControlFleshCoupledTest, BitwiseSameForAnyThreadCount) {
  const std::string xml = testing::writeText(file("chain.xml"), testing::chainXml(2));
  for (const Perturbation perturbation : {Perturbation::moved, Perturbation::placed}) {
    const auto one = run3(xml, 1, 1, perturbation);
    EXPECT_TRUE(std::isfinite(one.back()));
    EXPECT_NE(one.back(), 0.0);  // the free joint took the fluid's and flesh's impulse
    const int threads = 2, fluid_threads = perturbation == Perturbation::moved ? 2 : 1;
    const auto parallel = run3(xml, threads, fluid_threads, perturbation);
    ASSERT_EQ(one.size(), parallel.size());
    EXPECT_EQ(0, std::memcmp(one.data(), parallel.data(), one.size() * sizeof(double)))
        << threads << " threads, " << fluid_threads << " fluid threads, "
        << (perturbation == Perturbation::moved ? "moved" : "placed");
  }
}

// FluidControlParams::objective_force: a frame's force on j0's bodies (one coupled step a frame) is the sum of
// the coupling's bodyForce_n over them with fluid_on_flesh, of its boneForce_n with flesh_on_bone, bitwise; the
// two differ (the flesh's rate of change of momentum), so each check tells which force was read. Two frames of
// the chain in flesh each, about 2 s of CPU.
TEST_F(ControlFleshCoupledTest, ObjectiveForceReadsTheFleshOrTheBones) {
  const std::string xml = testing::writeText(file("chain.xml"), testing::chainXml(2));
  const rigid::RigidModel model = testing::chainModel3(xml);
  coupling3d::RigidFluidParams3 cp = testing::chainCoupling3();
  cp.forcing = coupling3d::Forcing3::coupled;
  cp.forcing_regularisation = 3e-2;
  ControllerParams p = testing::chainController3(1);
  p.controlled.resize(1);
  p.objectives.resize(1);
  p.senses.resize(1);
  std::vector<double> read[2], surface[2], bones[2];
  for (const ObjectiveForce force : {ObjectiveForce::fluid_on_flesh, ObjectiveForce::flesh_on_bone}) {
    FluidControlParams f = testing::chainEvaluations3();
    f.objective_force = force;
    FluidController c(model, p, f, testing::chainInitialRad3(), fleshFluid(testing::chainStream3(1), cp, {}));
    const int k = force == ObjectiveForce::flesh_on_bone;
    for (int frame = 0; frame < 2; ++frame) {
      const FrameRecord r = c.frame();
      const auto& coupling = dynamic_cast<const CoupledFleshFluid3&>(c.coupledFluid()).coupling();
      Vec3 on_surface{}, on_bones{};
      for (int b = 1; b < model.bodies(); ++b)  // j0 moves both capsules
        for (int a = 0; a < 3; ++a) {
          on_surface[a] += coupling.bodyForce_n()[b][a];
          on_bones[a] += coupling.boneForce_n()[b][a];
        }
      read[k].insert(read[k].end(), r.measures.drag_vector_n[0].begin(), r.measures.drag_vector_n[0].end());
      surface[k].insert(surface[k].end(), on_surface.begin(), on_surface.end());
      bones[k].insert(bones[k].end(), on_bones.begin(), on_bones.end());
    }
  }
  EXPECT_TRUE(read[0] == surface[0]);
  EXPECT_TRUE(read[1] == bones[1]);
  double differ = 0, scale = 0;
  for (std::size_t i = 0; i < surface[0].size(); ++i) {
    differ = std::max(differ, std::abs(surface[0][i] - bones[0][i]));
    scale = std::max(scale, std::abs(surface[0][i]));
  }
  std::printf("objective force: |fluid on flesh| up to %.4e N, |fluid on flesh - on bones| up to %.4e N\n", scale,
              differ);
  EXPECT_GT(differ, 1e-3 * scale);
}

}  // namespace
}  // namespace creaturelab::control
