// The controller over the 3-D fluid with the creature wrapped in flesh (control/coupled_flesh_fluid3.hpp;
// Lentine et al. 2010 §4.3, §5, Fig. 13): the snapshot is exact (grid, flesh, last forces, pending
// reaction), so the evaluations share one copy per thread and the frames are bitwise the same for any
// evaluation and fluid thread count, with moved and with placed perturbations (the placed pose carrying
// the flesh with its bodies).
#include <gtest/gtest.h>

#include <cstring>

#include "control/coupled_flesh_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "control_fluid3_scene.hpp"

namespace creaturelab::control {
namespace {

class ControlFleshTest : public testing::ScratchDirTest {
 protected:
  ControlFleshTest() : ScratchDirTest("control_flesh") {}
};

// Two frames of the chain in flesh in a stream of air (control_fluid3_scene.hpp; 1.2 kg/m^3): angles,
// derivatives and objectives, then the flesh's positions and the fluid's u.
std::vector<double> run3(const std::string& xml, int threads, int fluid_threads, Perturbation perturbation) {
  const rigid::RigidModel model = testing::chainModel3(xml);
  fluid3d::FluidParams3 air = testing::chainStream3(fluid_threads);
  air.density_kg_per_m3 = 1.2;
  coupling3d::RigidFluidParams3 cp = testing::chainCoupling3();
  cp.forcing_regularisation = 3e-2;
  FluidController c(model, testing::chainController3(threads), testing::chainEvaluations3(perturbation),
                    testing::chainInitialRad3(), fleshFluid(air, cp, {}));
  std::vector<double> out;
  testing::recordFrames(c, 2, out);
  const auto& coupling = dynamic_cast<const CoupledFleshFluid3&>(c.coupledFluid()).coupling();
  testing::appendValues(coupling.flesh().positions_m(), out);
  testing::appendValues(coupling.fluid().grid().velocity_m_per_s[0], out);
  return out;
}

// One thread against two evaluation threads with two fluid threads (moved), and with one (placed).
// About 7 s of CPU.
TEST_F(ControlFleshTest, BitwiseSameForAnyThreadCount) {
  const std::string xml = testing::writeText(file("chain.xml"), testing::chainXml(2));
  for (const Perturbation perturbation : {Perturbation::moved, Perturbation::placed}) {
    const auto one = run3(xml, 1, 1, perturbation);
    {
      const int threads = 2, fluid_threads = perturbation == Perturbation::moved ? 2 : 1;
      const auto parallel = run3(xml, threads, fluid_threads, perturbation);
      ASSERT_EQ(one.size(), parallel.size());
      EXPECT_EQ(0, std::memcmp(one.data(), parallel.data(), one.size() * sizeof(double)))
          << threads << " threads, " << fluid_threads << " fluid threads, "
          << (perturbation == Perturbation::moved ? "moved" : "placed");
    }
  }
}

}  // namespace
}  // namespace creaturelab::control
