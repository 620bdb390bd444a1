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

}  // namespace
}  // namespace creaturelab::control
