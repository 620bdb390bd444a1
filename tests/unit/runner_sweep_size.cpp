// sweepPointCount: cases x axes counted without wrapping.
#include <gtest/gtest.h>

#include <string>

#include "runner/sweep_size.hpp"

namespace runner = creaturelab::runner;

namespace {

runner::Experiment withAxes(const std::vector<std::size_t>& sizes, std::size_t cases) {
  runner::Experiment e;
  e.path = "sweep.toml";
  for (std::size_t a = 0; a < sizes.size(); ++a)
    e.axes.push_back({"axis" + std::to_string(a), std::vector<runner::Value>(sizes[a], runner::Value(1.0))});
  for (std::size_t c = 0; c < cases; ++c) e.cases.push_back(runner::Case{"case" + std::to_string(c), {}, {}});
  return e;
}

TEST(SweepPointCount, CasesTimesAxes) {
  EXPECT_EQ(runner::sweepPointCount(withAxes({}, 0)), 1u);
  EXPECT_EQ(runner::sweepPointCount(withAxes({3, 4}, 0)), 12u);
  EXPECT_EQ(runner::sweepPointCount(withAxes({3, 4}, 2)), 24u);
}

TEST(SweepPointCount, AMillionPointsIsTheLimit) {
  EXPECT_EQ(runner::sweepPointCount(withAxes({1000, 1000}, 0)), runner::kMaxSweepPoints);
  EXPECT_THROW(runner::sweepPointCount(withAxes({1000, 1000}, 2)), runner::ExperimentError);
  EXPECT_THROW(runner::sweepPointCount(withAxes({1000001}, 0)), runner::ExperimentError);
}

TEST(SweepPointCount, TwoToTheSixtyFourIsRefusedNotWrappedToZero) {
  try {
    runner::sweepPointCount(withAxes({65536, 65536, 65536, 65536}, 0));
    FAIL() << "2^64 points were accepted";
  } catch (const runner::ExperimentError& e) {
    EXPECT_NE(std::string(e.what()).find("sweep.toml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("more than 1000000 points"), std::string::npos) << e.what();
  }
}

}  // namespace
