// The 3-D swimmer's rise (control/swimmer_run3.hpp; Lentine et al. 2010 §7.2): the rise per whole
// cycle with its standard error from the cycles' scatter, the geoms' volumes behind the density
// ratio, and the recorder on a free box falling under gravity.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "control/swimmer_run3.hpp"
#include "control_models.hpp"

namespace creaturelab::control {
namespace {

class Swimmer3Test : public testing::ScratchDirTest {
 protected:
  Swimmer3Test() : ScratchDirTest("control_swimmer3") {}
};

// Three cycles of 4 frames rising 1, 2 and 6 mm after a first one of 50 mm: the last three's mean is
// 3 mm and its standard error sqrt(((1-3)^2 + (2-3)^2 + (6-3)^2) / 2) / sqrt(3) = sqrt(7/3) mm.
TEST(CycleRise, MeanAndStandardErrorOfTheLastWholeCycles) {
  std::vector<double> z{0.0};
  for (double rise : {0.050, 0.001, 0.002, 0.006})
    for (int f = 0; f < 4; ++f) z.push_back(z.back() + rise / 4);
  const CycleRise r = cycleRise(z, 4, 3);
  EXPECT_NEAR(r.mean_m, 0.003, 1e-15);
  EXPECT_NEAR(r.stderr_m, 1e-3 * std::sqrt(7.0 / 3.0), 1e-15);
  // All four: the first cycle's 50 mm counts.
  EXPECT_NEAR(cycleRise(z, 4, 4).mean_m, 0.059 / 4, 1e-15);
}

TEST(CycleRise, NaNWhereTheCyclesCannotTellTheScatter) {
  const std::vector<double> z{0, 1, 2, 3, 4, 5, 6};  // six frames after the start
  EXPECT_DOUBLE_EQ(cycleRise(z, 3, 1).mean_m, 3.0);
  EXPECT_TRUE(std::isnan(cycleRise(z, 3, 1).stderr_m));  // one cycle: no scatter
  EXPECT_DOUBLE_EQ(cycleRise(z, 3, 2).stderr_m, 0.0);    // equal cycles
  EXPECT_TRUE(std::isnan(cycleRise(z, 3, 3).mean_m));    // three cycles need nine frames
}

TEST(GeomVolume, PrimitivesFromMuJoCoSizes) {
  constexpr double pi = std::numbers::pi;
  EXPECT_DOUBLE_EQ(geomVolume_m3(2, {0.15, 0, 0}), 4.0 / 3.0 * pi * 0.15 * 0.15 * 0.15);
  // A capsule of radius 0.025 and half-length 0.11: a cylinder 0.22 m long and a sphere.
  EXPECT_NEAR(geomVolume_m3(3, {0.025, 0.11, 0}), pi * 0.025 * 0.025 * 0.22 + 4.0 / 3.0 * pi * std::pow(0.025, 3), 1e-18);
  EXPECT_DOUBLE_EQ(geomVolume_m3(6, {0.5, 0.25, 0.1}), 0.1);
  EXPECT_DOUBLE_EQ(geomVolume_m3(7, {1, 1, 1}), 0.0);  // a mesh: not counted
}

// A 2 kg box of 0.2 m sides (8 litres) on a free joint, 1 m up, falling under 10 m/s^2 at 0.01 s steps;
// a world geom beside it that the ratio leaves out.
TEST_F(Swimmer3Test, RecorderOnAFallingBox) {
  const std::string xml =
      "<mujoco><option timestep=\"0.01\" gravity=\"0 0 -10\"/><worldbody><geom type=\"box\" size=\"1 1 0.01\" "
      "pos=\"0 0 -5\"/><body name=\"box\" pos=\"0.3 0 1\"><freejoint/><geom type=\"box\" size=\"0.1 0.1 0.1\" "
      "mass=\"2\"/></body></worldbody></mujoco>";
  const auto model = rigid::RigidModel::load(testing::writeText(file("box.xml"), xml));
  EXPECT_NEAR(densityRatio3(model, 1000.0), 2.0 / 8.0, 1e-12);
  rigid::RigidData data(model);
  data.kinematics();
  RiseRecorder3 rec({1, {0.1, {0.5, 0.5}}, {-0.25, 0.5}, 10, 2});
  rec.start(data);
  for (int f = 0; f < 30; ++f) {
    data.step();
    data.kinematics();
    rec.record(data);
  }
  const auto& z = rec.series().all()[2].values;
  ASSERT_EQ(z.size(), 30u);
  const auto m = rec.measure(0.25);
  ASSERT_EQ(m[0].name, "rise_per_cycle_m");
  // The last two cycles' mean fall, from the recorded heights.
  EXPECT_DOUBLE_EQ(m[0].value, ((z[29] - z[19]) + (z[19] - z[9])) / 2);
  EXPECT_LT(m[0].value, 0.0);
  EXPECT_GT(m[1].value, 0.0);  // the fall accelerates: the cycles differ
  EXPECT_DOUBLE_EQ(m[2].value, z[29] - 1.0);
  EXPECT_NEAR(m[3].value, 0.0, 1e-12);  // no drift
  // The phase at each frame's start: frames 0-4 in the first, 5-9 in the second.
  const auto& phase = rec.series().all()[3].values;
  EXPECT_EQ(phase[4], 0.0);
  EXPECT_EQ(phase[5], 1.0);
  const auto& flux = rec.series().all()[4].values;
  EXPECT_EQ(flux[4], -0.25);
  EXPECT_EQ(flux[5], 0.5);
}

}  // namespace
}  // namespace creaturelab::control
