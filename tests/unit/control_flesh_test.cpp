// The controller over the 3-D fluid with the creature wrapped in flesh (control/coupled_flesh_fluid3.hpp;
// Lentine et al. 2010 §4.3, §5, Fig. 13): the snapshot is exact (grid, flesh, last forces, pending
// reaction), so the evaluations share one copy per thread and the frames are bitwise the same for any
// evaluation and fluid thread count, with moved and with placed perturbations (the placed pose carrying
// the flesh with its bodies).
#include <gtest/gtest.h>

#include <cstring>

#include "control/coupled_flesh_fluid3.hpp"
#include "control/fluid_controller.hpp"
#include "control_models.hpp"

namespace creaturelab::control {
namespace {

class ControlFleshTest : public testing::ScratchDirTest {
 protected:
  ControlFleshTest() : ScratchDirTest("control_flesh") {}
};

// The chain's two hinged capsules (0.4 m, along +x from the origin) in flesh, in a 0.5 m/s stream of air
// entering at x low, a 1.6 x 0.8 x 1.2 m box of 16 x 8 x 12 cells, 60 frames a second.
fluid3d::FluidParams3 airStream(int fluid_threads) {
  fluid3d::FluidParams3 f;
  f.domain_x_m = 1.6;
  f.domain_y_m = 0.8;
  f.domain_z_m = 1.2;
  f.cells_x = 16;
  f.cells_y = 8;
  f.cells_z = 12;
  f.density_kg_per_m3 = 1.2;
  f.kinematic_viscosity_m2_per_s = 0;
  f.boundaries.axis[0].low = fluid3d::BoundaryType3::inflow;
  f.boundaries.axis[0].low_inflow_m_per_s = 0.5;
  f.boundaries.axis[0].high = fluid3d::BoundaryType3::open;
  f.time_step_policy = fluid3d::TimeStepPolicy3::fixed;
  f.fixed_step_s = 1.0 / 60;
  f.threads = fluid_threads;
  return f;
}

// Two frames: angles, derivatives and objectives, then the flesh's positions and the fluid's u.
std::vector<double> run3(const std::string& xml, int threads, int fluid_threads, Perturbation perturbation) {
  rigid::RigidModel model = rigid::RigidModel::load(xml);
  model.setGravity({0, 0, 0});
  model.setTimestep(1.0 / 60);
  coupling3d::RigidFluidParams3 cp;
  cp.origin_m = {-0.4, -0.4, -0.6};
  cp.forcing_regularisation = 3e-2;
  ControllerParams p;
  p.controlled = {"j0", "j1"};
  p.objectives = {Objective::drag_along, Objective::drag};
  p.senses = {Sense::minimize, Sense::maximize};
  p.threads = threads;
  p.delta_rad = 0.02;
  FluidControlParams f;
  f.settle_steps = 1;
  f.planar_fluid = false;
  f.perturbation = perturbation;
  FluidController c(model, p, f, {{"j0", -0.3}, {"j1", 0.2}}, fleshFluid(airStream(fluid_threads), cp, {}));
  std::vector<double> out;
  for (int k = 0; k < 2; ++k) {
    const FrameRecord r = c.frame();
    out.insert(out.end(), r.angle_rad.begin(), r.angle_rad.end());
    out.insert(out.end(), r.derivative.begin(), r.derivative.end());
    out.insert(out.end(), r.objective.begin(), r.objective.end());
  }
  const auto& coupling = dynamic_cast<const CoupledFleshFluid3&>(c.coupledFluid()).coupling();
  const Eigen::Matrix3Xd& x = coupling.flesh().positions_m();
  out.insert(out.end(), x.data(), x.data() + x.size());
  const auto& u = coupling.fluid().grid().velocity_m_per_s[0];
  out.insert(out.end(), u.data(), u.data() + u.size());
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
