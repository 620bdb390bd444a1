// What a controller run measures the same way in wind and fluid (control/run_measures.hpp): the angle between
// lines, the axial mean of lines wandering about a flat optimum, and the converged frame of Fig. 2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "control/run_measures.hpp"

namespace {

using namespace creaturelab::control;

Vec3 line(double deg) {
  const double a = deg * std::numbers::pi / 180;
  return {std::cos(a), 0.0, std::sin(a)};
}

TEST(ControlParams, LineAngleIgnoresDirection) {
  EXPECT_NEAR(lineAngleDeg(line(30), {1, 0, 0}), 30.0, 1e-12);
  EXPECT_NEAR(lineAngleDeg(line(150), {1, 0, 0}), 30.0, 1e-12);
  EXPECT_NEAR(lineAngleDeg(line(-90), {-1, 0, 0}), 90.0, 1e-12);
}

// A block wandering 5 degrees either side of perpendicular: the mean of the folded angles says 85,
// the mean line says 90; the same about the stream (0), where folding biases the mean upwards.
TEST(ControlParams, MeanLineIsNotBiasedByTheFold) {
  EXPECT_NEAR(meanLineAngleDeg({line(-85), line(-95)}, {1, 0, 0}), 90.0, 1e-9);
  EXPECT_NEAR(meanLineAngleDeg({line(3), line(-3), line(183), line(177)}, {1, 0, 0}), 0.0, 1e-9);
  EXPECT_NEAR(meanLineAngleDeg({line(40), line(40)}, {1, 0, 0}), 40.0, 1e-9);
  // Lines that do not straddle anything: the axial mean of 80 and 84 lies between them.
  const double m = meanLineAngleDeg({line(80), line(84)}, {1, 0, 0});
  EXPECT_GT(m, 80.0);
  EXPECT_LT(m, 84.0);
}

TEST(ControlParams, ConvergedFrameIsWhereTheAnglesStayNearTheirFinalMean) {
  // Frames count from 1: the angle reaches 10 at frame 4 and stays.
  EXPECT_EQ(convergedFrame({{0, 4, 8, 10, 10, 10, 10}}, 0.5, 3), 4.0);
  // Not settled at the end (the last frame is 2 off the mean of the last two): frames + 1.
  EXPECT_EQ(convergedFrame({{0, 4, 8, 12}}, 0.5, 2), 4.0 + 1);
}

}  // namespace
