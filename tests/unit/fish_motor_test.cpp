// Motor controllers and schedules (spec §3; Tu 1996 ch. 5).
#include <gtest/gtest.h>

#include <cmath>

#include "fish/motor.hpp"
#include "fish/swim_mc.hpp"

#include "fish_test_settings.hpp"

namespace creaturelab::fish {
namespace {

TEST(Schedule, ParsesAndRejectsWithTheItemNamed) {
  const auto s = parseSchedule(" swim 10; left 3 ;glide 2.5;right 1");
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[1].action, Action::left);
  EXPECT_DOUBLE_EQ(s[2].start_s, 13.0);
  EXPECT_DOUBLE_EQ(scheduleDurationS(s), 16.5);
  for (const char* bad : {"swim 10; dance 3", "swim", "swim -1", "swim 2 3", ""}) {
    try {
      parseSchedule(bad);
      ADD_FAILURE() << bad;
    } catch (const std::invalid_argument& e) {
      if (std::string(bad).find("dance") != std::string::npos) {
        EXPECT_NE(std::string(e.what()).find("dance"), std::string::npos);
      }
    }
  }
}

TEST(Motor, ValidateNamesAlphaAndR) {
  MotorParams p = testMotor();
  p.swim.amplitude_anterior = 0;
  EXPECT_NE(p.validate().find("swim_amplitude"), std::string::npos);
  p = testMotor();
  p.swim.amplitude_posterior = 1.2;
  EXPECT_NE(p.validate().find("swim_amplitude"), std::string::npos);
  p = testMotor();
  p.turn_rate = 0.08;  // above r_max = 0.075
  EXPECT_NE(p.validate().find("turn_rate"), std::string::npos);
  p = testMotor();
  EXPECT_EQ(p.validate(), "");
}

// The swim-MC's triangle wave: the left middle muscle peaks at alpha (1 - f) l after half a period,
// the right side is still at rest then and peaks a half period later (out of phase); the posterior
// segment lags by lag / 2 pi of a period.
TEST(Motor, SwimWaveOutOfPhaseAndLagged) {
  const FishModel fish = testFish();
  MotorParams p = testMotor();
  p.swim = {0.5, 0.01, 0.5, 0.01};
  MotorController mc(fish, p, parseSchedule("swim 100"));
  int left_mid = -1, right_mid = -1, left_post = -1;
  for (int k = 0; k < kMuscles; ++k) {
    const auto& m = fish.muscles[k];
    if (m.segment == 1 && m.side == 0 && left_mid < 0) left_mid = k;
    if (m.segment == 1 && m.side == 1 && right_mid < 0) right_mid = k;
    if (m.segment == 2 && m.side == 0 && left_post < 0) left_post = k;
  }
  const double l = fish.network.rest_length_m[fish.muscles[left_mid].unit];
  // full_stroke reading: the alpha = 0.5 stroke ramps at alpha r l0 per reference step
  const double peak = 0.5 * (1 - p.contracted_fraction) * l, slope = 0.5 * 0.01 * l / 0.055;
  const double half = peak / slope;
  auto c = mc.targetContraction(half);
  EXPECT_NEAR(c[left_mid], peak, 1e-12);
  EXPECT_NEAR(c[right_mid], 0.0, 1e-15);  // the right side starts at exactly t = half (round-off)
  c = mc.targetContraction(2 * half);
  EXPECT_NEAR(c[left_mid], 0.0, 1e-12);
  EXPECT_NEAR(c[right_mid], peak, 1e-12);
  // posterior: a quarter period (half a half-period) later
  const double lp = fish.network.rest_length_m[fish.muscles[left_post].unit];
  const double peak_p = 0.5 * (1 - p.contracted_fraction) * lp;
  EXPECT_NEAR(mc.targetContraction(half + 0.5 * half)[left_post], peak_p, 1e-12);
  // anterior muscles do not swim
  for (int k = 0; k < kMuscles; ++k)
    if (fish.muscles[k].segment == 0) {
      EXPECT_EQ(c[k], 0.0);
    }
}

// The two readings of the rate: the full stroke's keeps the period whatever alpha, the rest length's
// shortens it in proportion to alpha.
TEST(Motor, RateReadings) {
  MotorParams p = testMotor();
  p.swim = {0.5, 0.01, 0.5, 0.01};
  const double full = swimPeriodS(p);
  EXPECT_NEAR(full, 2 * (1 - p.contracted_fraction) / 0.01 * p.reference_step_s, 1e-12);
  p.rate_reading = RateReading::rest_length;
  EXPECT_NEAR(swimPeriodS(p), 0.5 * full, 1e-12);
}

// A turn contracts the left anterior and middle muscles and, antagonistic, lengthens the right ones
// as much (contract: leaves them); the posterior segment swims on through it unless
// swim_during_turn is off; rest lengths never jump by more than r_max per reference step, also when
// the controller switches.
TEST(Motor, TurnLeftAndRateLimit) {
  const FishModel fish = testFish();
  MotorParams p = testMotor();
  p.swim_during_turn = false;
  const auto c = MotorController(fish, p, parseSchedule("swim 4; left 4; swim 4")).targetContraction(4.5);
  for (int k = 0; k < kMuscles; ++k) {
    const auto& m = fish.muscles[k];
    if (m.segment <= 1) {
      EXPECT_GT(m.side == 0 ? c[k] : -c[k], 0.0);
      EXPECT_NEAR(c[k], -c[k ^ 3], 1e-15);  // muscle k ^ 3 is k's mirror image (fish_model.cpp)
    } else {
      EXPECT_EQ(c[k], 0.0);
    }
  }
  p.turn_stroke = Stroke::contract;
  const auto only_left = MotorController(fish, p, parseSchedule("swim 4; left 4; swim 4")).targetContraction(4.5);
  for (int k = 0; k < kMuscles; ++k) EXPECT_EQ(only_left[k] > 0, fish.muscles[k].side == 0 && fish.muscles[k].segment <= 1);
  p.swim_during_turn = true;
  p.turn_stroke = Stroke::antagonistic;
  MotorController mc(fish, p, parseSchedule("swim 4; left 4; swim 4"));
  bool tail_beats = false;
  for (double t = 4.0; t < 8.0; t += 0.1)
    for (int k = 0; k < kMuscles; ++k) tail_beats = tail_beats || (fish.muscles[k].segment == 2 && mc.targetContraction(t)[k] > 0);
  EXPECT_TRUE(tail_beats);
  std::array<double, kUnits> rest{};
  for (int e = 0; e < kUnits; ++e) rest[e] = fish.network.rest_length_m[e];
  const double dt = 0.02;
  auto prev = rest;
  for (int n = 0; n < 600; ++n) {
    mc.apply(n * dt, dt, rest);
    for (const auto& m : fish.muscles) {
      const double l0 = fish.network.rest_length_m[m.unit];
      EXPECT_LE(std::fabs(rest[m.unit] - prev[m.unit]), p.r_max * l0 / p.reference_step_s * dt * (1 + 1e-12));
      EXPECT_GE(rest[m.unit], p.contracted_fraction * l0 - 1e-15);
      EXPECT_LE(rest[m.unit], (2 - p.contracted_fraction) * l0 + 1e-15);
    }
    prev = rest;
  }
}

TEST(Motor, SwimKnobScalesAmplitudeAndRate) {
  const SwimCommand half = swimCommandForKnob(0.5, 0.075), full = swimCommandForKnob(1.0, 0.075);
  EXPECT_DOUBLE_EQ(half.amplitude_anterior, 0.5);
  EXPECT_DOUBLE_EQ(half.rate_posterior, 0.0375);
  EXPECT_DOUBLE_EQ(full.rate_posterior, 0.075);
}

// The speed map interpolates log s linearly in log speed, hits its levels exactly, and refuses a
// speed outside its range or a map that does not rise.
TEST(Motor, SwimSpeedMapInverts) {
  SpeedMap map{{0.25, 0.5, 1.0}, {0.01, 0.04, 0.16}};
  std::string error;
  EXPECT_NEAR(knobForSpeed(map, 0.04, error), 0.5, 1e-12);
  EXPECT_NEAR(knobForSpeed(map, 0.02, error), std::sqrt(0.125), 1e-12);  // speed ~ s^2 here
  EXPECT_TRUE(error.empty());
  EXPECT_TRUE(std::isnan(knobForSpeed(map, 0.2, error)));
  EXPECT_NE(error.find("outside"), std::string::npos);
  error.clear();
  map.speed_body_lengths_per_s = {0.01, 0.04, 0.03};
  EXPECT_TRUE(std::isnan(knobForSpeed(map, 0.02, error)));
  EXPECT_NE(error.find("does not rise"), std::string::npos);
}

// The [reimpl] antagonistic stroke: each swim muscle swings l0 +- alpha (l0 - lc), its partner the
// opposite way (their contractions sum to zero once both run), from 0 at the start; the period is
// twice the contract stroke's at the same rate. mirror swaps the sides.
TEST(Motor, AntagonisticStrokeAndMirror) {
  const FishModel fish = testFish();
  MotorParams p = testMotor();
  p.swim = {0.5, 0.01, 0.5, 0.01};
  const double contract_period = swimPeriodS(p);
  p.stroke = Stroke::antagonistic;
  EXPECT_NEAR(swimPeriodS(p), 2 * contract_period, 1e-12);
  MotorController mc(fish, p, parseSchedule("swim 100"));
  int left = -1, right = -1;
  for (int k = 0; k < kMuscles; ++k) {
    if (fish.muscles[k].segment == 1 && fish.muscles[k].side == 0 && left < 0) left = k;
    if (fish.muscles[k].segment == 1 && fish.muscles[k].side == 1 && right < 0) right = k;
  }
  const double l = fish.network.rest_length_m[fish.muscles[left].unit];
  const double peak = 0.5 * (1 - p.contracted_fraction) * l, period = swimPeriodS(p);
  EXPECT_NEAR(mc.targetContraction(1e-9)[left], 0.0, 1e-9);
  EXPECT_NEAR(mc.targetContraction(0.25 * period)[left], peak, 1e-12);
  EXPECT_NEAR(mc.targetContraction(0.75 * period)[left], -peak, 1e-12);  // lengthened past rest
  double lo = 0, hi = 0;
  for (double t = 0.5 * period; t < 3 * period; t += 0.013 * period) {
    const auto c = mc.targetContraction(t);
    EXPECT_NEAR(c[left] + c[right], 0.0, 1e-12) << t;
    lo = std::min(lo, c[left]), hi = std::max(hi, c[left]);
  }
  EXPECT_NEAR(hi, peak, 0.03 * peak);
  EXPECT_NEAR(lo, -peak, 0.03 * peak);
  p.mirror = true;
  MotorController mirrored(fish, p, parseSchedule("swim 100"));
  for (double t : {0.1 * period, 0.6 * period, 1.3 * period}) {
    EXPECT_EQ(mirrored.targetContraction(t)[right], mc.targetContraction(t)[left]);
    EXPECT_EQ(mirrored.targetContraction(t)[left], mc.targetContraction(t)[right]);
  }
}

}  // namespace
}  // namespace creaturelab::fish
