// The swimmer's rise (control/swimmer_run.hpp; Lentine et al. 2010 §7.2): on a free box falling
// under gravity, the series it records per frame and the rise per cycle over the last cycles.
#include <gtest/gtest.h>

#include "control/swimmer_run.hpp"
#include "control_models.hpp"

namespace creaturelab::control {
namespace {

class SwimmerRunTest : public testing::ScratchDirTest {
 protected:
  SwimmerRunTest() : ScratchDirTest("control_swimmer_run") {}
};

// A 1 kg box on a free joint, 1 m up, falling under 10 m/s^2 at steps of 0.01 s.
std::string fallingBoxXml() {
  return "<mujoco><option timestep=\"0.01\" gravity=\"0 0 -10\"/><worldbody><body name=\"box\" pos=\"0 0 1\">"
         "<freejoint/><geom type=\"box\" size=\"0.1 0.1 0.1\" mass=\"1\"/></body></worldbody></mujoco>";
}

// Two phases of 0.05 s each in a 0.1 s cycle (10 frames), the mouth expelling 0.5 m/s in the first
// and drawing in 0.25 m/s in the second; the rise over the last 2 cycles of 30 frames.
TEST_F(SwimmerRunTest, RiseIsTheHeightGainedPerCycleOverTheLastCycles) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("box.xml"), fallingBoxXml()));
  rigid::RigidData data(model);
  RiseSettings s;
  s.body = 1;
  s.mouth.body = "box";
  s.mouth.schedule = {0.1, {0.5, 0.5}};
  s.mouth.flux_m_per_s = {0.5, -0.25};
  s.frames_per_cycle = 10;
  s.cycles = 2;
  RiseRecorder rise(s);
  ASSERT_TRUE(rise.active());
  data.kinematics();
  rise.start(data);
  for (int f = 0; f < 30; ++f) {
    data.step();
    rise.record(data);
  }
  const auto& series = rise.series().all();
  ASSERT_EQ(series.size(), 3u);
  const auto& z = series[0].values;
  ASSERT_EQ(z.size(), 30u);
  EXPECT_LT(z.back(), z.front());  // it falls
  for (int f = 0; f < 30; ++f) {
    EXPECT_EQ(series[1].values[f], (f % 10) < 5 ? 0 : 1) << f;
    EXPECT_EQ(series[2].values[f], (f % 10) < 5 ? 0.5 : -0.25) << f;
  }
  const auto values = rise.measure(2.5);
  ASSERT_EQ(values.size(), 3u);
  EXPECT_EQ(values[0].name, "creature_density_ratio");
  EXPECT_EQ(values[0].value, 2.5);
  EXPECT_EQ(values[1].name, "rise_per_cycle_m");
  EXPECT_DOUBLE_EQ(values[1].value, (z[29] - z[9]) / 2);
  EXPECT_EQ(values[2].name, "rise_total_m");
  EXPECT_NEAR(values[2].value, z[29] - 1.0, 1e-12);  // from the start height, 1 m
}

// Without a tracked body: no series, the density ratio alone.
TEST(SwimmerRun, WithoutABodyOnlyTheDensityRatio) {
  RiseRecorder rise(RiseSettings{});
  EXPECT_FALSE(rise.active());
  EXPECT_TRUE(rise.series().all().empty());
  ASSERT_EQ(rise.measure(0.5).size(), 1u);
}

}  // namespace
}  // namespace creaturelab::control
