// The 2-D render model (render/slice_model2.hpp, Rudolf & Mould 2009 §3.4): the spline fit matches
// Eigen's own interpolation, the exumbrella lies one thickness profile from the subumbrella, the
// muscle state maps to the rings, and degenerate outlines are refused with a reason.
#include "render/slice_model2.hpp"

#include <gtest/gtest.h>

#include <unsupported/Eigen/Splines>

#include "render_test_slice.hpp"

namespace creaturelab::render {
namespace {

using test::testSlice;

TEST(RenderSlice, SplineInterpolatesLikeEigensFit) {
  Eigen::Matrix2Xd pts(2, 9);
  for (int k = 0; k < 9; ++k) pts.col(k) << std::cos(0.3 * k), std::sin(0.7 * k) + 0.1 * k * k;
  const SplineInterpolator fit(9);
  const Spline2 s = fit.fit(pts);
  Eigen::RowVectorXd u(9);
  for (int k = 0; k < 9; ++k) u[k] = k / 8.0;
  const Spline2 eigen = Eigen::SplineFitting<Spline2>::Interpolate(pts, 3, u);
  for (int k = 0; k < 9; ++k) EXPECT_LT((s(k / 8.0).matrix() - pts.col(k)).norm(), 1e-12);
  for (double t = 0; t <= 1.0; t += 0.01) EXPECT_LT((s(t) - eigen(t)).matrix().norm(), 1e-12) << t;
}

TEST(RenderSlice, ThicknessProfile) {
  ThicknessProfile p;
  EXPECT_DOUBLE_EQ(p.at(0.0), 0.004);                     // Fig. 12: ϑ = 4 mm at the apex
  EXPECT_DOUBLE_EQ(p.at(1.0), 0.25 * 0.004);              // a quarter at the margin
  EXPECT_DOUBLE_EQ(p.at(0.5), 0.004 * (0.25 + 0.75 * 0.75));
  for (double d = 0; d < 1; d += 0.05) EXPECT_GT(p.at(d), p.at(d + 0.05));  // thinning toward the margin
}

TEST(RenderSlice, ExumbrellaIsOneThicknessOut) {
  const auto s = testSlice(32, 0);
  RenderParams params;
  params.rings = 17;  // ring i at marker i: u = 0.5 i / 16 = i / 32
  const SliceModel2 model(params, s.topology, s.markers());
  ASSERT_EQ(model.check(s.frame()), "");
  Slice2 out;
  model.build(s.frame(), out);
  for (int k = 0; k < 33; ++k) {
    const double d = std::abs(k - 16) / 16.0;
    EXPECT_NEAR((out.exum_markers[k] - out.sub_markers[k]).norm(), params.thickness.at(d), 1e-15) << k;
  }
  // On the rings through the markers, each exumbrellar point is one profile thickness out, along
  // the subumbrella's normal (so the distance to the subumbrellar surface is the profile) ...
  for (int i = 0; i < 17; ++i) {
    EXPECT_NEAR((out.exum_left[i] - out.sub_left[i]).norm(), out.thickness_m[i], 1e-12) << i;
    EXPECT_NEAR((out.exum_right[i] - out.sub_right[i]).norm(), out.thickness_m[i], 1e-12) << i;
    EXPECT_NEAR(out.thickness_m[i], params.thickness.at(1.0 - i / 16.0), 1e-15);
  }
  // ... and between the markers to within the splines' resolution.
  params.rings = 64;
  const SliceModel2 fine(params, s.topology, s.markers());
  fine.build(s.frame(), out);
  for (int i = 0; i < 63; ++i)
    EXPECT_NEAR((out.exum_left[i] - out.sub_left[i]).norm(), out.thickness_m[i], 0.01 * out.thickness_m[i]) << i;
  // The apex ring is a single point on each surface.
  EXPECT_EQ(out.sub_left[63], out.sub_right[63]);
  EXPECT_EQ(out.exum_left[63], out.exum_right[63]);
  EXPECT_NEAR(out.exum_left[63].y() - out.sub_left[63].y(), 0.004, 1e-12);  // the apex: straight up by ϑ
}

TEST(RenderSlice, MuscleStateToRings) {
  auto s = testSlice(32, 0);
  s.activation.assign(s.activation.size(), 1.0);
  RenderParams params;
  params.rings = 17;
  const SliceModel2 model(params, s.topology, s.markers());
  Slice2 out;
  model.build(s.frame(), out);
  for (int i = 0; i <= 13; ++i) EXPECT_EQ(out.contraction[i], 1.0) << i;  // within the band (markers 0..13)
  EXPECT_DOUBLE_EQ(out.contraction[16], 0.0);  // the apex, beyond the band
  EXPECT_DOUBLE_EQ(out.contraction[15], 1.0 / 3.0);  // linearly from marker 13 to the apex at 16
  // One element half contracted moves its own ring only and the neighbours' halfway.
  s.activation.assign(s.activation.size(), 0.0);
  s.activation[5] = 0.5;
  model.build(s.frame(), out);
  EXPECT_EQ(out.contraction[5], 0.5);
  EXPECT_EQ(out.contraction[4], 0.0);
  // Without a recorded muscle state there are no ridges to follow.
  model.build({0, s.xy, {}}, out);
  for (double c : out.contraction) EXPECT_EQ(c, 0.0);
}

TEST(RenderSlice, TentaclesResampledRootToTip) {
  const auto s = testSlice(32, 8);
  RenderParams params;
  params.tentacle_rings = 5;
  const SliceModel2 model(params, s.topology, s.markers());
  Slice2 out;
  model.build(s.frame(), out);
  ASSERT_EQ(out.tentacle_left.size(), 5u);
  EXPECT_LT((out.tentacle_left[0] - Eigen::Vector2d(s.xy[0], s.xy[1])).norm(), 1e-15);
  EXPECT_NEAR(out.tentacle_right[4].y(), s.xy[1] - 0.02, 1e-12);
  EXPECT_NEAR(out.tentacle_right[2].y(), s.xy[1] - 0.01, 1e-12);
}

TEST(RenderSlice, DegenerateOutlinesAreRefused) {
  const auto good = testSlice(32, 4);
  const SliceModel2 model(RenderParams{}, good.topology, good.markers());
  ASSERT_EQ(model.check(good.frame()), "");

  auto crossing = good;  // marker 10 pulled across the bell: the subumbrella crosses itself
  crossing.xy[20] = 0.012;
  EXPECT_NE(model.check(crossing.frame(0.5)).find("crosses itself"), std::string::npos)
      << model.check(crossing.frame(0.5));
  EXPECT_NE(model.check(crossing.frame(0.5)).find("t = 0.5 s"), std::string::npos);

  // Upside down is not degenerate: the exumbrella is made on the outside of the markers' travel
  // either way, and the surface is closed and outward (render_mesh_test.cpp).
  auto flipped = good;
  for (std::size_t k = 1; k < flipped.xy.size(); k += 2) flipped.xy[k] = -flipped.xy[k];
  EXPECT_EQ(model.check(flipped.frame()), "");

  auto nan = good;
  nan.xy[7] = std::nan("");
  EXPECT_NE(model.check(nan.frame()).find("not finite"), std::string::npos);

  auto doubled = good;
  doubled.xy[6] = doubled.xy[4];
  doubled.xy[7] = doubled.xy[5];
  EXPECT_NE(model.check(doubled.frame()).find("coincide"), std::string::npos);

  EXPECT_NE(model.check({0, std::span<const double>(good.xy).first(10), {}}).find("expected"), std::string::npos);
}

TEST(RenderSlice, TopologyIsChecked) {
  SliceTopology t;
  t.bell_markers = 4;
  EXPECT_NE(t.validate(10), "");
  t.bell_markers = 9;
  EXPECT_EQ(t.validate(9), "");
  EXPECT_NE(t.validate(8), "");
  t.left_tentacle = {0, 9};
  EXPECT_NE(t.validate(10), "");  // no right tentacle
  t.right_tentacle = {8, 9};
  EXPECT_EQ(t.validate(10), "");
  t.muscle_markers = {2, 1};
  EXPECT_NE(t.validate(10), "");
  RenderParams too_few;
  too_few.rings = 2;
  SliceTopology bell;
  bell.bell_markers = 9;
  EXPECT_THROW(SliceModel2(too_few, bell, 9), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::render
