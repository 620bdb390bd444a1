// settlingTime on synthetic kinetic-energy series with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "springs/settling.hpp"

namespace sp = creaturelab::springs;

TEST(SpringsSettling, ExponentialDecayCrossesAtLogOfFraction) {
  // ke = exp(-t) from a peak of 1 at t = 0: below 1e-4 from t = ln(1e4) on.
  std::vector<double> t, ke;
  for (int i = 0; i <= 2000; ++i) {
    t.push_back(0.01 * i);
    ke.push_back(std::exp(-0.01 * i));
  }
  const auto ts = sp::settlingTime(t, ke, 1e-4);
  ASSERT_TRUE(ts.has_value());
  EXPECT_NEAR(*ts, std::log(1e4), 1e-3);
}

TEST(SpringsSettling, LateBumpMovesTheSettlingTime) {
  // Peak 10 at t = 1; a bump to 0.5 at t = 5 stays above 10 * 0.01 = 0.1 until it drops at t = 6.
  const std::vector<double> t = {0, 1, 2, 3, 4, 5, 6, 7};
  const std::vector<double> ke = {0, 10, 0.05, 0.01, 0.02, 0.5, 0.0, 0.0};
  const auto ts = sp::settlingTime(t, ke, 0.01);
  ASSERT_TRUE(ts.has_value());
  EXPECT_NEAR(*ts, 5.0 + (0.5 - 0.1) / 0.5, 1e-12);  // linear crossing between samples 5 and 6
}

TEST(SpringsSettling, NeverSettlesWhenLastSampleIsHigh) {
  const std::vector<double> t = {0, 1, 2, 3};
  const std::vector<double> ke = {1, 0.001, 0.0001, 0.9};
  EXPECT_FALSE(sp::settlingTime(t, ke, 1e-2).has_value());
}

TEST(SpringsSettling, AtRestIsSettledFromTheStart) {
  const std::vector<double> t = {0.5, 1, 2};
  const std::vector<double> ke = {0, 0, 0};
  EXPECT_EQ(sp::settlingTime(t, ke, 1e-4), 0.5);
  EXPECT_FALSE(sp::settlingTime({}, {}, 1e-4).has_value());
}

TEST(SpringsSettling, PeakLaterThanStartUsesFinalPeak) {
  // Running-peak tracking: early samples above fraction * early peak must not count.
  const std::vector<double> t = {0, 1, 2, 3, 4};
  const std::vector<double> ke = {1, 0.5, 100, 0.5, 0.01};
  // threshold = 0.01 * 100 = 1: last sample >= 1 is t = 2 (100), next is 0.5.
  EXPECT_NEAR(*sp::settlingTime(t, ke, 0.01), 2.0 + (100 - 1) / (100 - 0.5), 1e-12);
  sp::SettlingTracker tracker(0.01);
  for (size_t i = 0; i < t.size(); ++i) tracker.add(t[i], ke[i]);
  EXPECT_EQ(tracker.settlingTime(), sp::settlingTime(t, ke, 0.01));
  EXPECT_EQ(tracker.peak(), 100);
}

TEST(SpringsSettling, RejectsMismatchedSeries) {
  EXPECT_THROW(sp::settlingTime({0, 1}, {1}, 0.1), std::invalid_argument);
  EXPECT_THROW(sp::settlingTime({0, 0}, {1, 1}, 0.1), std::invalid_argument);
}
