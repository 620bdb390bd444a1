// What the construction parameters do to the web (Mehla 2005 §5.3): bigger
// frames and more attachment points give more particles (§5.3.1-5.3.2, Figs. 5.17-5.18), wider frame
// spacing fewer spokes (§5.3.5, Fig. 5.33 table), wider spoke spacing fewer spiral segments (§5.3.4,
// Fig. 5.28 table).
#include <gtest/gtest.h>

#include <cmath>

#include "web/build.hpp"
#include "web_test_shapes.hpp"

namespace web = creaturelab::web;

using creaturelab::test::regularPolygon;

TEST(WebSweeps, BiggerFrameHasMoreParticles) {
  int previous = 0;
  for (double scale : {0.5, 0.75, 1.0}) {
    web::WebParams p;
    for (auto& q : p.attachment_points_m) q *= scale;
    const auto c = web::build(p).counts;
    EXPECT_GT(c.particles, previous) << "scale " << scale;
    previous = c.particles;
  }
}

TEST(WebSweeps, MoreAttachmentPointsHaveMoreParticles) {
  // Thesis Fig. 5.18: triangle, 4, 6 and 10 points, here on one circle of radius 0.5 m.
  int previous = 0;
  for (int n : {3, 4, 6, 10}) {
    web::WebParams p;
    p.attachment_points_m = regularPolygon(n, 0.5);
    const auto c = web::build(p).counts;
    EXPECT_GT(c.particles, previous) << n << " points";
    previous = c.particles;
  }
}

TEST(WebSweeps, WiderFrameSpacingGivesFewerSpokes) {
  // Thesis Fig. 5.33 table: frame rest / placement 15/20, 25/30, 35/40, 50/57 mm.
  const double table[][2] = {{0.015, 0.020}, {0.025, 0.030}, {0.035, 0.040}, {0.050, 0.057}};
  int previous = 1 << 30;
  for (const auto& row : table) {
    web::WebParams p;
    p.frame_rest_length_m = row[0];
    p.frame_placement_m = row[1];
    const auto c = web::build(p).counts;
    EXPECT_LT(c.spokes, previous) << "frame placement " << row[1];
    previous = c.spokes;
  }
}

TEST(WebSweeps, WiderSpokeSpacingGivesFewerSpiralSegments) {
  // Thesis Fig. 5.28 table: spoke rest / placement 3/7, 3/9, 5/11, 7/15 mm.
  const double table[][2] = {{0.003, 0.007}, {0.003, 0.009}, {0.005, 0.011}, {0.007, 0.015}};
  int previous_segments = 1 << 30, previous_particles = 1 << 30;
  for (const auto& row : table) {
    web::WebParams p;
    p.spoke_rest_length_m = row[0];
    p.spoke_placement_m = row[1];
    const auto c = web::build(p).counts;
    EXPECT_LT(c.spiral_segments, previous_segments) << "spoke placement " << row[1];
    EXPECT_LT(c.particles, previous_particles) << "spoke placement " << row[1];
    previous_segments = c.spiral_segments;
    previous_particles = c.particles;
  }
}

TEST(WebSweeps, LargerSpokeStrideGivesFewerSpokes) {
  int previous = 1 << 30;
  for (int stride : {1, 2, 4, 8}) {
    web::WebParams p;
    p.secondary_spoke_stride = stride;
    const auto c = web::build(p).counts;
    EXPECT_LT(c.spokes, previous) << "stride " << stride;
    previous = c.spokes;
  }
}

TEST(WebSweeps, HigherSpiralDensityLeavesMoreUncovered) {
  // SPIRAL_DENSITY (Fig. 5.16 step 3): the processed spiral stops once no spoke has more than this
  // many uncovered masses, so a larger value lays no more spiral.
  web::WebParams p;
  p.spiral_density = 0;
  const int dense = web::build(p).counts.spiral_segments;
  p.spiral_density = 1000;  // initial spiral only (Fig. 5.15)
  const int initial_only = web::build(p).counts.spiral_segments;
  EXPECT_GE(dense, web::build(web::WebParams{}).counts.spiral_segments);
  EXPECT_GT(web::build(web::WebParams{}).counts.spiral_segments, initial_only);
}
