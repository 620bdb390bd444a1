// The controller in the coupled fluid (Lentine et al. 2010 §4.3, §5): per-DOF
// evaluations on their own copies of the fluid give bitwise the same frames for any thread count,
// and a re-evaluation from the same state repeats itself exactly; effort (Eq. 1) in the fluid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "control/fluid_controller.hpp"
#include "control_models.hpp"

namespace creaturelab::control {
namespace {

class ControlFluidTest : public testing::ScratchDirTest {
 protected:
  ControlFluidTest() : ScratchDirTest("control_fluid") {}
};

// The chain's two hinged plates in a stream of 0.5 m/s, 2 m box of 32^2, at 60 frames a second.
struct PlateStream {
  rigid::RigidModel model;
  fluid::FluidParams fluid;
  coupling::RigidFluidParams coupling;
};
PlateStream plateStream(const std::string& xml) {
  PlateStream s{rigid::RigidModel::load(xml), {}, {}};
  s.model.setGravity({0, 0, 0});
  s.model.setTimestep(1.0 / 60);
  s.fluid.domain_width_m = s.fluid.domain_height_m = 2.0;
  s.fluid.cells_x = s.fluid.cells_y = 32;
  s.fluid.kinematic_viscosity_m2_per_s = 0;
  s.fluid.walls.left.type = s.fluid.walls.right.type = fluid::WallType::open;
  s.coupling.origin_x_m = -0.5;
  s.coupling.origin_z_m = -1.0;
  s.coupling.inflow.stream_m_per_s = 0.5;
  s.coupling.inflow.stream_columns = 2;
  return s;
}

// Two hinged plates in a stream on 32^2: three frames on `threads` threads for the evaluations
// and `fluid_threads` inside the fluid steps.
std::vector<double> run(const std::string& xml, int threads, Perturbation how = Perturbation::moved,
                        int fluid_threads = 1,
                        coupling::ForcingPreconditioner pc = coupling::ForcingPreconditioner::mass) {
  PlateStream s = plateStream(xml);
  s.fluid.threads = fluid_threads;
  s.coupling.forcing_preconditioner = pc;
  ControllerParams p;
  p.controlled = {"j0", "j1"};
  p.objectives = {Objective::drag_along, Objective::drag};
  p.senses = {Sense::minimize, Sense::maximize};
  p.threads = threads;
  p.delta_rad = 0.02;
  FluidControlParams f;
  f.settle_steps = 2;
  f.average_steps = 2;
  f.perturbation = how;
  FluidController c(s.model, p, f, {{"j0", -0.3}, {"j1", 0.2}}, s.fluid, s.coupling);
  std::vector<double> out;
  for (int k = 0; k < 3; ++k) {
    const FrameRecord r = c.frame();
    out.insert(out.end(), r.angle_rad.begin(), r.angle_rad.end());
    out.insert(out.end(), r.derivative.begin(), r.derivative.end());
    out.insert(out.end(), r.objective.begin(), r.objective.end());
  }
  const auto& g = c.coupling().fluid().grid();
  out.insert(out.end(), g.u_m_per_s.data(), g.u_m_per_s.data() + g.u_m_per_s.size());
  return out;
}

TEST_F(ControlFluidTest, BitwiseSameForAnyThreadCount) {
  const std::string xml = testing::writeText(file("chain.xml"), testing::chainXml(2));
  using coupling::ForcingPreconditioner;
  std::vector<std::vector<double>> single;  // one thread, each preconditioner and perturbation
  for (ForcingPreconditioner pc : {ForcingPreconditioner::mass, ForcingPreconditioner::gram})
    for (Perturbation how : {Perturbation::moved, Perturbation::placed}) {
      const std::string name = std::string(how == Perturbation::placed ? "placed" : "moved") +
                               (pc == ForcingPreconditioner::gram ? ", gram" : ", mass");
      const auto one = run(xml, 1, how, 1, pc);
      single.push_back(one);
      // 2 threads: one joint's two evaluations each; 3: the four evaluations split 1, 1, 2, so
      // joint 0's two run on different threads and scratch states.
      for (int threads : {2, 3}) {
        const auto parallel = run(xml, threads, how, 1, pc);
        ASSERT_EQ(one.size(), parallel.size());
        EXPECT_EQ(0, std::memcmp(one.data(), parallel.data(), one.size() * sizeof(double)))
            << threads << " threads, " << name;
      }
      // Fluid threads: with one evaluation thread every fluid takes them, with two only the frame's.
      for (int threads : {1, 2}) {
        const auto parallel = run(xml, threads, how, 2, pc);
        ASSERT_EQ(one.size(), parallel.size());
        EXPECT_EQ(0, std::memcmp(one.data(), parallel.data(), one.size() * sizeof(double)))
            << threads << " threads and 2 fluid threads, " << name;
      }
      // The derivatives are not zero: the fluid pushes on the plates.
      EXPECT_NE(one[2], 0.0);
      EXPECT_NE(one[3], 0.0);
    }
  // gram took its own path: it solves the same forcing to the same tolerance, not to the same bits.
  for (int how = 0; how < 2; ++how)
    EXPECT_NE(0, std::memcmp(single[how].data(), single[2 + how].data(), single[how].size() * sizeof(double)));
}

TEST_F(ControlFluidTest, SteadyStateIsRefused) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("block.xml"), testing::blockXml(0.02, 0)));
  ControllerParams p;
  p.controlled = {"hinge"};
  p.objectives = {Objective::drag};
  p.senses = {Sense::minimize};
  p.steady_state = true;
  EXPECT_NE(FluidControlParams{}.validate(p, model).find("settle_steps"), std::string::npos);
}

// The block's 4 m box of 32^2 inviscid water, the hinge 1.5 m from the left wall; with a stream
// (m/s), the left and right walls are open and the stream enters in a 2-column band.
struct BlockBox {
  fluid::FluidParams fluid;
  coupling::RigidFluidParams coupling;
};
BlockBox blockBox(double stream_m_per_s) {
  BlockBox b;
  b.fluid.domain_width_m = b.fluid.domain_height_m = 4.0;
  b.fluid.cells_x = b.fluid.cells_y = 32;
  b.fluid.kinematic_viscosity_m2_per_s = 0;
  b.coupling.origin_x_m = -1.5;
  b.coupling.origin_z_m = -2.0;
  if (stream_m_per_s != 0) {
    b.fluid.walls.left.type = b.fluid.walls.right.type = fluid::WallType::open;
    b.coupling.inflow.stream_m_per_s = stream_m_per_s;
    b.coupling.inflow.stream_columns = 2;
  }
  return b;
}

// Eq. 1 in the fluid: the block held across a stream (strength 0) needs the actuator torque that
// cancels the fluid's moment about the hinge, -(tau_b + (x_b - anchor) x F_b) . y from the
// coupling's last reaction; its effort is |torque| x frame and is the effort objective's value.
TEST_F(ControlFluidTest, EffortIsTheTorqueThatHoldsTheJointAgainstTheFluid) {
  auto model = rigid::RigidModel::load(testing::writeText(file("block.xml"), testing::blockXml(0.1, 0)));
  ControllerParams p;
  p.controlled = {"hinge"};
  p.objectives = {Objective::effort};
  p.senses = {Sense::minimize};
  p.strength_rad_per_s = 0;
  p.substeps = 1;
  model.setTimestep(p.frame_s);
  const BlockBox box = blockBox(0.5);
  FluidController c(model, p, FluidControlParams{}, {{"hinge", -1.2}}, box.fluid, box.coupling);
  c.hold(5);
  FrameRecord r;
  for (int k = 0; k < 3; ++k) r = c.frame();
  const auto& co = c.coupling();
  const int body = model.joint(model.findJoint("hinge")).body;
  const double* anchor = c.data().jointAnchor(model.findJoint("hinge"));
  const Vec3& f = co.bodyForce_n()[body];
  const Vec3& x = co.bodyPoint_m()[body];
  const double moment_y = co.bodyTorque_n_m()[body][1] + (x[2] - anchor[2]) * f[0] - (x[0] - anchor[0]) * f[2];
  ASSERT_GT(std::abs(moment_y), 1e-3);  // the stream pushes on the tilted block
  EXPECT_NEAR(r.measures.torque_n_m[0], -moment_y, 1e-9 * std::abs(moment_y));
  EXPECT_DOUBLE_EQ(r.measures.effort_n_m_s[0], std::abs(r.measures.torque_n_m[0]) * p.frame_s);
  EXPECT_DOUBLE_EQ(r.objective[0], r.measures.effort_n_m_s[0]);
}

// A block in still fluid (no stream, no gravity) evaluated at +delta. Moved (§4.3), the markers
// carry the pseudo-velocity delta / frame and push the fluid: the objective |F| is the fluid's
// resistance to that motion. Placed (§3.3's steady-state calculation), the pose is set at once
// with the joint at rest, so nothing moves the still fluid and |F| is zero to round-off.
double stillFluidDrag(const std::string& xml, Perturbation how) {
  auto model = rigid::RigidModel::load(xml);
  ControllerParams p;
  p.controlled = {"hinge"};
  p.objectives = {Objective::drag};
  p.senses = {Sense::minimize};
  p.substeps = 2;
  p.delta_rad = 0.02;
  model.setTimestep(p.frame_s / p.substeps);
  FluidControlParams f;
  f.perturbation = how;
  f.settle_steps = 2;
  f.average_steps = 2;
  const BlockBox box = blockBox(0.0);
  FluidController c(model, p, f, {{"hinge", -0.3}}, box.fluid, box.coupling);
  return c.evaluate(0, p.delta_rad);
}

TEST_F(ControlFluidTest, PlacedPerturbationCarriesNoPseudoVelocity) {
  const std::string xml = testing::writeText(file("block.xml"), testing::blockXml(0.1, 0));
  const double moved = stillFluidDrag(xml, Perturbation::moved);
  const double placed = stillFluidDrag(xml, Perturbation::placed);
  ASSERT_GT(moved, 1.0);  // N: the move pushes the water
  EXPECT_LT(placed, 1e-9 * moved);
}

// creature_force: every joint's drag objective is the force on the whole creature, the force the
// frame reports on all its bodies; without it each joint sees only the bodies it moves.
TEST_F(ControlFluidTest, CreatureForceIsTheForceOnAllBodies) {
  const std::string xml = testing::writeText(file("chain.xml"), testing::chainXml(2));
  for (bool creature : {false, true}) {
    const PlateStream s = plateStream(xml);
    ControllerParams p;
    p.controlled = {"j0", "j1"};
    p.objectives = {Objective::drag, Objective::drag};
    p.senses = {Sense::minimize, Sense::minimize};
    FluidControlParams f;
    f.creature_force = creature;
    FluidController c(s.model, p, f, {{"j0", -0.3}, {"j1", 0.2}}, s.fluid, s.coupling);
    c.frame();
    const FrameRecord r = c.frame();
    const Vec3& all = c.frameBodiesForce_n();
    const double all_n = std::sqrt(all[0] * all[0] + all[1] * all[1] + all[2] * all[2]);
    ASSERT_GT(all_n, 1.0);
    if (creature) {
      EXPECT_NEAR(r.measures.drag_n[0], all_n, 1e-12 * all_n);
      EXPECT_NEAR(r.measures.drag_n[1], all_n, 1e-12 * all_n);
    } else {
      EXPECT_GT(std::abs(r.measures.drag_n[0] - r.measures.drag_n[1]), 1e-3 * all_n);
    }
  }
}

}  // namespace
}  // namespace creaturelab::control
