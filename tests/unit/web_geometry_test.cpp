// Plane geometry of the web construction against hand-computed answers: segment tests, polygon
// checks, the primary-spoke intersection, the frame centre and inner frame (thesis Fig. 5.5 steps
// 2-5) and the inward frame force (Fig. 5.8).
#include <gtest/gtest.h>

#include <cmath>

#include "web/frame_forces.hpp"
#include "web/frame_geometry.hpp"
#include "web/geometry2.hpp"

namespace web = creaturelab::web;
using web::Point2;

TEST(WebGeometry, SegmentsIntersect) {
  EXPECT_TRUE(web::segmentsIntersect({0, 0}, {1, 1}, {0, 1}, {1, 0}));    // crossing
  EXPECT_TRUE(web::segmentsIntersect({0, 0}, {1, 0}, {1, 0}, {2, 1}));    // touching at an end
  EXPECT_TRUE(web::segmentsIntersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));    // collinear overlap
  EXPECT_FALSE(web::segmentsIntersect({0, 0}, {1, 0}, {2, 0}, {3, 0}));   // collinear apart
  EXPECT_FALSE(web::segmentsIntersect({0, 0}, {1, 0}, {0, 1}, {1, 2}));   // parallel
}

TEST(WebGeometry, SelfIntersectionOfBowTie) {
  const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_FALSE(web::firstSelfIntersection(square));
  const std::vector<Point2> bow{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  const auto cross = web::firstSelfIntersection(bow);
  ASSERT_TRUE(cross);
  EXPECT_EQ(cross->first, 0);
  EXPECT_EQ(cross->second, 2);
}

TEST(WebGeometry, PointInPolygonAndDistance) {
  const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(web::pointInPolygon({0.5, 0.5}, square));
  EXPECT_FALSE(web::pointInPolygon({1.5, 0.5}, square));
  EXPECT_DOUBLE_EQ(web::distanceToSegment({0.5, 2}, {0, 0}, {1, 0}), 2.0);
  EXPECT_DOUBLE_EQ(web::distanceToSegment({3, 4}, {0, 0}, {-1, 0}), 5.0);  // beyond the end: to the end point
}

TEST(WebGeometry, LeastSquaresIntersection) {
  // Three lines through (0.3, -0.2).
  const Point2 x{0.3, -0.2};
  const std::vector<Point2> a{x + Point2(-1, 0), x + Point2(0, -2), x + Point2(-1, -1)};
  const std::vector<Point2> b{x + Point2(1, 0), x + Point2(0, 1), x + Point2(2, 2)};
  EXPECT_NEAR((web::leastSquaresIntersection(a, b) - x).norm(), 0.0, 1e-14);
  // Parallel lines have no intersection: the mean of the midpoints.
  const Point2 p = web::leastSquaresIntersection({{0, 0}, {0, 1}}, {{1, 0}, {1, 1}});
  EXPECT_NEAR((p - Point2(0.5, 0.5)).norm(), 0.0, 1e-15);
}

TEST(WebGeometry, CentreIsMiddleOfBoundingBoxAndInnerPointsMoveTowardIt) {
  const std::vector<Point2> pts{{-1, 0}, {0, 2}, {3, 1}, {1, -2}};
  const Point2 c = web::frameCentre(pts);
  EXPECT_DOUBLE_EQ(c.x(), 1.0);  // (xmin + xmax) / 2 = (-1 + 3) / 2   (Fig. 5.5 step 4)
  EXPECT_DOUBLE_EQ(c.y(), 0.0);  // (ymin + ymax) / 2 = (-2 + 2) / 2
  const auto inner = web::innerFramePoints(pts, c, 0.25);
  for (size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR((inner[i] - pts[i]).norm(), 0.25, 1e-15);
    EXPECT_NEAR((c - inner[i]).norm(), (c - pts[i]).norm() - 0.25, 1e-15);
  }
}

TEST(WebGeometry, InwardFrameForceIsLineLoadTowardCentre) {
  // Four masses on a 2 m square around the origin: each shares 2 m of frame (half of two 2 m sides).
  creaturelab::springs::Points<3> x(3, 5);
  x.col(0) << 1, 1, 0;
  x.col(1) << -1, 1, 0;
  x.col(2) << -1, -1, 0;
  x.col(3) << 1, -1, 0;
  x.col(4) << 5, 5, 0;  // not on the frame: no force
  const auto f = web::inwardFrameForces({0, 1, 2, 3}, x, Point2(0, 0), 1e-4, 5);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(f.col(i).norm(), 2e-4, 1e-18);
    EXPECT_NEAR(f.col(i).normalized().dot(-x.col(i).normalized()), 1.0, 1e-15);
  }
  EXPECT_EQ(f.col(4).norm(), 0.0);
}
