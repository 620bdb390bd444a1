// WebParams::validate(): every bad input is named in words a user understands, before any construction
// (a clear error before any simulation), and build() refuses it with the same message.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "web/build.hpp"
#include "web/web_params.hpp"
#include "web_test_shapes.hpp"

namespace web = creaturelab::web;
using ::testing::HasSubstr;
using web::Point2;
using creaturelab::test::regularPolygon;

namespace {

web::WebParams withPoints(std::vector<Point2> pts) {
  web::WebParams p;
  p.attachment_points_m = std::move(pts);
  return p;
}


}  // namespace

TEST(WebParams, DefaultsAreValidAndNaturalFrame) {
  const web::WebParams p;
  EXPECT_EQ(p.validate(), "");
  EXPECT_GE(p.attachment_points_m.size(), 6u);
  EXPECT_LE(p.attachment_points_m.size(), 8u);
  const Point2 first = p.attachment_points_m[0];
  double w_lo = first.x(), w_hi = first.x(), h_lo = first.y(), h_hi = first.y();
  for (const auto& q : p.attachment_points_m)
    w_lo = std::min(w_lo, q.x()), w_hi = std::max(w_hi, q.x()), h_lo = std::min(h_lo, q.y()), h_hi = std::max(h_hi, q.y());
  EXPECT_NEAR(w_hi - w_lo, 1.0, 0.1);  // "about 1 m across"
  EXPECT_NEAR(h_hi - h_lo, 1.0, 0.1);
}

TEST(WebParams, PointCount) {
  EXPECT_EQ(withPoints({{0, 0}, {1, 0}}).validate(),
            "there are 2 attachment points; an orb web needs 3 to 10 (thesis §5.2)");
  EXPECT_EQ(withPoints(regularPolygon(11, 0.5)).validate(),
            "there are 11 attachment points; an orb web needs 3 to 10 (thesis §5.2)");
  EXPECT_EQ(withPoints(regularPolygon(3, 0.5)).validate(), "");
  EXPECT_EQ(withPoints(regularPolygon(10, 0.5)).validate(), "");
}

TEST(WebParams, NonFinitePoint) {
  auto pts = regularPolygon(5, 0.5);
  pts[2].y() = NAN;
  EXPECT_EQ(withPoints(pts).validate(), "attachment point 2 has a coordinate that is not a finite number");
}

TEST(WebParams, DuplicatePoints) {
  auto pts = regularPolygon(6, 0.5);
  pts[4] = pts[1] + Point2(0.0002, 0);
  EXPECT_EQ(withPoints(pts).validate(), "attachment points 1 and 4 are the same point (closer than 1 mm); remove one");
}

TEST(WebParams, CollinearPoints) {
  const auto p = withPoints({{-0.5, -0.5}, {0.0, -0.5}, {0.5, -0.5}, {0.0, 0.5}});
  EXPECT_EQ(p.validate(),
            "attachment points 0, 1 and 2 are collinear; move one of them off the line (a frame corner needs a bend)");
  EXPECT_THAT(withPoints({{0, 0}, {0.5, 0.5}, {1, 1}}).validate(), HasSubstr("are collinear"));  // all on one line
}

TEST(WebParams, SelfIntersectingFrame) {
  EXPECT_EQ(withPoints({{-0.5, -0.5}, {0.5, 0.5}, {0.5, -0.5}, {-0.5, 0.5}}).validate(),
            "the frame crosses itself: the side from attachment point 0 to 1 meets the side from 2 to 3; list the "
            "points in order around the frame");
}

TEST(WebParams, CentreOutsideFrame) {
  // A thin crescent ("C" shape): the middle of its bounding box is in the gap.
  const auto p = withPoints({{0.5, 0.5}, {-0.5, 0.5}, {-0.5, -0.5}, {0.5, -0.5}, {0.5, -0.3}, {-0.3, -0.3},
                             {-0.3, 0.3}, {0.5, 0.3}});
  EXPECT_THAT(p.validate(), HasSubstr("lies outside the frame"));
}

TEST(WebParams, FrameTooSmallForItsSpacing) {
  web::WebParams p = withPoints(regularPolygon(10, 0.11));
  EXPECT_THAT(p.validate(), HasSubstr("shorter than two frame placements"));
  p = web::WebParams{};
  p.move_outer_m = 0.4;
  EXPECT_THAT(p.validate(), HasSubstr("more than half the distance from attachment point"));
  p = web::WebParams{};
  p.spiral_free_masses = 60;
  EXPECT_THAT(p.validate(), HasSubstr("reaches the inner frame"));
  p = web::WebParams{};
  p.spiral_free_masses = 0;
  EXPECT_EQ(p.validate(), "spiral_free_masses is 0; it must be 1 or more (the hub mass of each radius carries no spiral)");
}

TEST(WebParams, NonPositiveLengthsAndConstantsAreNamed) {
  struct Case {
    double web::WebParams::*field;
    const char* name;
  };
  const Case cases[] = {
      {&web::WebParams::move_outer_m, "move_outer_m"},
      {&web::WebParams::outer_frame_placement_m, "outer_frame_placement_m"},
      {&web::WebParams::outer_frame_rest_length_m, "outer_frame_rest_length_m"},
      {&web::WebParams::outer_frame_k_n_per_m, "outer_frame_k_n_per_m"},
      {&web::WebParams::frame_placement_m, "frame_placement_m"},
      {&web::WebParams::frame_rest_length_m, "frame_rest_length_m"},
      {&web::WebParams::frame_k_n_per_m, "frame_k_n_per_m"},
      {&web::WebParams::spoke_placement_m, "spoke_placement_m"},
      {&web::WebParams::spoke_rest_length_m, "spoke_rest_length_m"},
      {&web::WebParams::spoke_k_n_per_m, "spoke_k_n_per_m"},
      {&web::WebParams::hub_radius_m, "hub_radius_m"},
      {&web::WebParams::spiral_placement_m, "spiral_placement_m"},
      {&web::WebParams::spiral_rest_length_m, "spiral_rest_length_m"},
      {&web::WebParams::spiral_k_n_per_m, "spiral_k_n_per_m"},
      {&web::WebParams::particle_mass_kg, "particle_mass_kg"},
  };
  for (const auto& c : cases)
    for (double bad : {0.0, -1.0, double(NAN)}) {
      web::WebParams p;
      p.*c.field = bad;
      const std::string msg = p.validate();
      EXPECT_THAT(msg, HasSubstr(std::string(c.name) + " is ")) << c.name << " = " << bad;
      EXPECT_THAT(msg, HasSubstr("must be positive")) << c.name;
    }
  web::WebParams p;
  p.frame_k_n_per_m = -0.001;
  EXPECT_EQ(p.validate(), "frame_k_n_per_m is -0.001 N/m; it must be positive");
}

TEST(WebParams, NegativeForcesAndCountsAreNamed) {
  web::WebParams p;
  p.air_drag_ns_per_m = -1e-8;
  EXPECT_EQ(p.validate(), "air_drag_ns_per_m is -1e-08 N*s/m; it must be zero or positive");
  p = {};
  p.gravity_m_per_s2 = -9.81;
  EXPECT_THAT(p.validate(), HasSubstr("gravity_m_per_s2 is -9.81"));
  p = {};
  p.inner_frame_inward_force_n_per_m = -1;
  EXPECT_THAT(p.validate(), HasSubstr("inner_frame_inward_force_n_per_m is -1"));
  p = {};
  p.secondary_spoke_stride = 0;
  EXPECT_THAT(p.validate(), HasSubstr("secondary_spoke_stride is 0"));
  p = {};
  p.hub_attach_choices = 0;
  EXPECT_THAT(p.validate(), HasSubstr("hub_attach_choices is 0"));
  p = {};
  p.spiral_density = -1;
  EXPECT_THAT(p.validate(), HasSubstr("spiral_density is -1"));
  p = {};
  p.spiral_jitter = 1.5;
  EXPECT_EQ(p.validate(), "spiral_jitter is 1.5; it is a probability, from 0 to 1");
  p = {};
  p.overextension = 0.0;
  EXPECT_EQ(p.validate(), "overextension is 0; it must be positive");
  p = {};
  p.gravity_m_per_s2 = 0;  // no gravity and no drag are allowed
  p.air_drag_ns_per_m = 0;
  p.inner_frame_inward_force_n_per_m = 0;
  EXPECT_EQ(p.validate(), "");
}

TEST(WebParams, PlacementShorterThanRest) {
  web::WebParams p;
  p.frame_placement_m = 0.010;
  EXPECT_EQ(p.validate(),
            "the inner-frame placement (0.01 m) is shorter than its rest length (0.015 m); strands are laid at or "
            "beyond their rest length (thesis §5.1)");
  p = {};
  p.spoke_rest_length_m = 0.008;
  EXPECT_THAT(p.validate(), HasSubstr("the spoke placement (0.007 m) is shorter than its rest length (0.008 m)"));
  p = {};
  p.outer_frame_rest_length_m = 0.006;
  EXPECT_THAT(p.validate(), HasSubstr("the outer-frame placement"));
  p = {};
  p.spiral_rest_length_m = 0.03;
  EXPECT_THAT(p.validate(), HasSubstr("the spiral placement"));
  p.overextension = 1.5;  // the override replaces every rest length: nothing left to contradict
  EXPECT_EQ(p.validate(), "");
}

TEST(WebParams, BuildRefusesBadInputWithTheSameMessage) {
  const auto p = withPoints({{0, 0}, {1, 0}});
  try {
    web::build(p);
    FAIL() << "build accepted two attachment points";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), p.validate());
  }
}
