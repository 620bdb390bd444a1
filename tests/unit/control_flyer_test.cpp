// The driven flyer's additions (Lentine et al. 2010 §7.1; experiments/control/flyer.toml): the
// controlled joints' sense follows the stroke of an inboard pattern, PD-driven wing joints flap in
// the coupled step (FluidController::coupledStep: one servo substep per coupled step applies the
// PD torques), strength 0 holds the controlled joints, the mean over whole cycles, bad stroke_sense
// entries, the cost estimate's coupled steps per frame. The small simulations run a 32^2 fluid for a few frames (well under a second each).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "control/fluid_controller.hpp"
#include "control/stroke_sense.hpp"
#include "control/run_measures.hpp"
#include "kinds/control_params.hpp"

namespace creaturelab::control {
namespace {

constexpr double kPi = std::numbers::pi;

Pattern sine(double amplitude_rad, double hz) {
  Pattern p;
  p.kind = Pattern::Kind::sine;
  p.amplitude_rad = amplitude_rad;
  p.frequency_hz = hz;
  return p;
}

TEST(StrokeSense, FlipsWithTheSignOfThePatternRate) {
  const Pattern p = sine(0.5, 1.0);  // rate > 0 for t in [0, 0.25) and (0.75, 1], < 0 between
  EXPECT_EQ(senseAt(Sense::maximize, &p, 1.0, 0.1), Sense::maximize);
  EXPECT_EQ(senseAt(Sense::maximize, &p, 1.0, 0.5), Sense::minimize);
  EXPECT_EQ(senseAt(Sense::maximize, &p, -1.0, 0.5), Sense::maximize);
  EXPECT_EQ(senseAt(Sense::minimize, &p, 1.0, 0.9), Sense::minimize);
  EXPECT_EQ(senseAt(Sense::minimize, &p, 1.0, 0.4), Sense::maximize);
  EXPECT_EQ(senseAt(Sense::minimize, nullptr, 1.0, 0.4), Sense::minimize);
}

TEST(StrokeSense, RefusesJointsWithoutAStroke) {
  ControllerParams p;
  p.controlled = {"outer"};
  p.pd_driven = {"inner", "still"};
  p.pd_patterns = {sine(0.5, 1.0), Pattern{}};
  EXPECT_EQ(validate(std::vector<StrokeFollow>{{"inner", 1.0}}, p), "");
  EXPECT_NE(validate(std::vector<StrokeFollow>{{"still", 1.0}}, p).find("holds"), std::string::npos);
  EXPECT_NE(validate(std::vector<StrokeFollow>{{"nowhere", 1.0}}, p).find("not a pd_driven"), std::string::npos);
  EXPECT_NE(validate(std::vector<StrokeFollow>{{"inner", 1.0}, {"inner", 1.0}}, p).find("2 entries"),
            std::string::npos);
}

TEST(StrokeSense, ParsesTheKindParameter) {
  const auto f = kinds::parseStrokeSense("b = -inner_b, a=inner_a", {"a", "b", "c"});
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].joint, "inner_a");
  EXPECT_EQ(f[0].sign, 1.0);
  EXPECT_EQ(f[1].joint, "inner_b");
  EXPECT_EQ(f[1].sign, -1.0);
  EXPECT_EQ(f[2].joint, "");
  EXPECT_TRUE(kinds::parseStrokeSense(" ", {"a"}).empty());
  EXPECT_THROW(kinds::parseStrokeSense("x = inner", {"a"}), std::invalid_argument);
  EXPECT_THROW(kinds::parseStrokeSense("a inner", {"a"}), std::invalid_argument);
  EXPECT_THROW(kinds::parseStrokeSense("a = -", {"a"}), std::invalid_argument);
}

TEST(CostEstimate, CountsTheSearchesCoupledSteps) {
  kinds::ControllerSettings k;
  k.controlled = "outer_r, outer_l";
  k.substeps = 8;
  EXPECT_EQ(k.coupledStepsPerFrame(264), 8 + 4 * 264);
  k.search_every_frames = 16;
  EXPECT_EQ(k.coupledStepsPerFrame(264), 8 + 4 * 264 / 16.0);
  k.strength_rad_per_s = 0;  // no search: the frame's own steps
  EXPECT_EQ(k.coupledStepsPerFrame(264), 8);
}

TEST(FlapCycles, MeanOverWholeCycles) {
  EXPECT_EQ(kinds::framesPerCycle(2.0, 1.0 / 60), 120);
  EXPECT_THROW(kinds::framesPerCycle(0.51, 1.0 / 60), std::invalid_argument);
  const std::vector<double> v = {100, 1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(lastCyclesMean(v, 2, 2), 2.5);
  EXPECT_TRUE(std::isnan(lastCyclesMean(v, 3, 2)));
  // cycle means 1.5 and 3.5: sample deviation sqrt(2), over sqrt(2) cycles
  EXPECT_DOUBLE_EQ(lastCyclesStandardError(v, 2, 2), 1.0);
  EXPECT_TRUE(std::isnan(lastCyclesStandardError(v, 2, 1)));
  EXPECT_TRUE(std::isnan(lastCyclesStandardError(v, 3, 2)));
}

// One phase of the flap: each cycle's mean over its frames of that sense, the cycles' means averaged (so a
// cycle with more frames of the phase weighs no more), with their standard error.
TEST(FlapCycles, PhaseMeanOverTheFramesOfOneSense) {
  const std::vector<double> v = {100, 1, 2, 3, 10, 20, 30};
  const std::vector<double> sense = {1, 1, 1, -1, 1, -1, -1};
  // maximising: cycle (1, 2, 3) -> 1.5, cycle (10, 20, 30) -> 10; minimising: 3 and 25
  const PhaseMean up = lastCyclesPhaseMean(v, sense, +1, 3, 2);
  EXPECT_DOUBLE_EQ(up.mean, 5.75);
  EXPECT_DOUBLE_EQ(up.standard_error, 4.25);
  const PhaseMean down = lastCyclesPhaseMean(v, sense, -1, 3, 2);
  EXPECT_DOUBLE_EQ(down.mean, 14.0);
  EXPECT_DOUBLE_EQ(down.standard_error, 11.0);
  EXPECT_DOUBLE_EQ(lastCyclesPhaseMean(v, sense, -1, 3, 1).mean, 25.0);
  EXPECT_TRUE(std::isnan(lastCyclesPhaseMean(v, sense, -1, 3, 1).standard_error));
  // a cycle without a frame of the phase, a sense series of another length, too few frames
  EXPECT_TRUE(std::isnan(lastCyclesPhaseMean(v, std::vector<double>(7, 1.0), -1, 3, 2).mean));
  EXPECT_TRUE(std::isnan(lastCyclesPhaseMean(v, {1, -1}, +1, 1, 1).mean));
  EXPECT_TRUE(std::isnan(lastCyclesPhaseMean(v, sense, +1, 4, 2).mean));
}

// models/flyer.xml in a 4 m, 32^2 box with the floor source: inner joints PD-driven to a 30 deg,
// 2 Hz sine, outer joints controlled (drag, max on the down-stroke) at `strength`.
struct SmallFlyer {
  rigid::RigidModel model;
  FluidController controller;
  static rigid::RigidModel load() {
    auto m = rigid::RigidModel::load(std::string(CREATURELAB_TEST_SOURCE_DIR) + "/experiments/control/models/flyer.xml");
    m.setGravity({0, 0, 0});
    m.setTimestep(1.0 / 120);
    return m;
  }
  static ControllerParams params(double strength) {
    ControllerParams p;
    p.controlled = {"outer_r", "outer_l"};
    p.objectives = {Objective::drag, Objective::drag};
    p.senses = {Sense::maximize, Sense::maximize};
    p.pd_driven = {"inner_r", "inner_l"};
    p.pd_patterns = {sine(30 * kPi / 180, 2.0), sine(30 * kPi / 180, 2.0)};
    p.pd_kp_n_m_per_rad = 800;
    p.pd_kd_n_m_s_per_rad = 40;
    p.substeps = 2;
    p.strength_rad_per_s = strength;
    p.delta_rad = 0.02;
    return p;
  }
  static FluidControlParams fluidControl() {
    FluidControlParams f;
    f.stroke = {{"inner_r", 1.0}, {"inner_l", 1.0}};
    return f;
  }
  static fluid::FluidParams box() {
    fluid::FluidParams fp;
    fp.domain_width_m = fp.domain_height_m = 4.0;
    fp.cells_x = fp.cells_y = 32;
    fp.density_kg_per_m3 = 1.2;
    fp.kinematic_viscosity_m2_per_s = 0;
    fp.walls.top.type = fluid::WallType::open;
    fp.walls.bottom.type = fluid::WallType::inflow;  // the floor source (coupling/inflow.hpp)
    fp.walls.bottom.inflow_m_per_s = 0.5;
    return fp;
  }
  static coupling::RigidFluidParams source() {
    coupling::RigidFluidParams cp;
    cp.origin_x_m = cp.origin_z_m = -2.0;
    cp.inflow.source_m_per_s = 0.5;
    return cp;
  }
  explicit SmallFlyer(double strength)
      : model(load()), controller(model, params(strength), fluidControl(), {}, box(), source()) {}
  double angle(const char* joint) { return controller.data().qpos()[model.joint(model.findJoint(joint)).qpos]; }
};

TEST(Flyer, SenseFollowsTheStrokeAndPdWingsFlapInTheFluid) {
  SmallFlyer f(2.0);
  const double frame_s = 1.0 / 60;
  double lowest = 0, highest = 0;
  int flips = 0;
  Sense last = Sense::maximize;
  for (int k = 0; k < 45; ++k) {  // 0.75 s: one and a half flaps
    const double mid_s = (k + 0.5) * frame_s;
    f.controller.frame();
    // Positive inner angle turns the wing down: the pattern's rising half is the down-stroke (max).
    const double rate = std::cos(2 * kPi * 2.0 * mid_s);
    const Sense expected = rate >= 0 ? Sense::maximize : Sense::minimize;
    if (std::abs(rate) > 1e-9) {  // frames centred on a turning point may go either way (round-off in t)
      EXPECT_EQ(f.controller.frameSenses()[0], expected) << "frame " << k;
      EXPECT_EQ(f.controller.frameSenses()[1], expected) << "frame " << k;
    }
    flips += f.controller.frameSenses()[0] != last;
    last = f.controller.frameSenses()[0];
    lowest = std::min(lowest, f.angle("inner_r"));
    highest = std::max(highest, f.angle("inner_r"));
    EXPECT_TRUE(std::isfinite(f.controller.frameBodiesForce_n()[2]));
  }
  EXPECT_GE(flips, 3);
  // The PD drive flaps the wing through its +-30 deg in the coupled step (with the PD's overshoot at
  // 2 Hz), and both wings alike: the model is mirror-symmetric, the fluid on the grid nearly so.
  EXPECT_GT(highest, 20 * kPi / 180);
  EXPECT_LT(lowest, -20 * kPi / 180);
  EXPECT_LT(highest, 40 * kPi / 180);
  EXPECT_NEAR(f.angle("inner_r"), f.angle("inner_l"), 1e-3);
  EXPECT_NE(f.angle("outer_r"), 0.0);  // the controller moved the outer joints
}

TEST(Flyer, StrengthZeroHoldsTheControlledJoints) {
  SmallFlyer f(0.0);
  for (int k = 0; k < 10; ++k) f.controller.frame();
  EXPECT_NEAR(f.angle("outer_r"), 0.0, 1e-9);
  EXPECT_NEAR(f.angle("outer_l"), 0.0, 1e-9);
  EXPECT_GT(std::abs(f.angle("inner_r")), 0.1);  // while the wings flap
}

}  // namespace
}  // namespace creaturelab::control
