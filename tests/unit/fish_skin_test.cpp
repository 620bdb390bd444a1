// The NURBS skin (X. Tu 1996, ch. 7; docs/fish-spec.md §4): the evaluator against the exact
// rational circle, control points carried by a rigid motion, a closed skin where the halves meet,
// no fold-over over a swim.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "fish/fish_run.hpp"
#include "fish/skin.hpp"

#include "fish_test_settings.hpp"

namespace creaturelab::fish {
namespace {

// The unit circle as a rational quadratic NURBS: 9 control points on the square, weights 1 at the
// corners' neighbours and sqrt(2)/2 at the corners, knots {0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}
// (The NURBS Book, Ex. 7.2). Every point lies on the circle exactly, up to round-off.
TEST(Nurbs, ExactRationalCircle) {
  NurbsCurve c;
  c.degree = 2;
  c.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  const double w = std::sqrt(0.5);
  const double pts[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  for (int k = 0; k < 9; ++k) {
    const double wk = k % 2 ? w : 1.0;
    c.control.emplace_back(wk * pts[k][0], wk * pts[k][1], 0.0, wk);
  }
  double worst = 0;
  for (int i = 0; i <= 1000; ++i) worst = std::max(worst, std::fabs(c.point(i / 1000.0).norm() - 1.0));
  EXPECT_LT(worst, 4e-16);
  EXPECT_LT((c.point(0.125) - Eigen::Vector3d(std::sqrt(0.5), std::sqrt(0.5), 0)).norm(), 1e-15);  // 45 degrees
  // the non-rational reading (all weights 1) is not a circle: the test can fail
  for (auto& h : c.control) h /= h[3];
  EXPECT_GT(std::fabs(c.point(0.125).norm() - 1.0), 1e-3);
}

TEST(Nurbs, BasisIsAPartitionOfUnityAndValidateNamesTheDegree) {
  const auto k = clampedUniformKnots(9, 3);
  double n[4];
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    basisFunctions(findSpan(9, 3, u, k), u, 3, k, n);
    EXPECT_NEAR(n[0] + n[1] + n[2] + n[3], 1.0, 1e-15);
  }
  EXPECT_NE(validateNurbs(9, 9, clampedUniformKnots(9, 3)).find("degree 9"), std::string::npos);
  SkinParams p;
  p.degree_around = 9;
  EXPECT_NE(p.validate().find("skin_degree_around"), std::string::npos);
  p = {};
  p.degree_along = 21;
  EXPECT_NE(p.validate().find("skin_degree_along"), std::string::npos);
}

// A rigid motion of the nodes carries every control point with it (spec §4: to round-off);
// a uniform scaling does not (the offsets are fixed lengths).
TEST(FishSkin, RigidMotionCarriesEveryControlPoint) {
  const FishModel fish = testFish();
  FishSkin skin(fish, {});
  const auto rest = skin.controlPoints();
  ASSERT_EQ(rest.size(), size_t(2 * 9 * 21 + 2 * 15));
  for (size_t c = 0; c < rest.size(); ++c) EXPECT_LT((rest[c] - skin.restControlPoints()[c]).norm(), 1e-14);
  const Eigen::Matrix3d R = Eigen::Quaterniond(Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, -0.5, 0.8).normalized())).toRotationMatrix();
  const Eigen::RowVector3d t(1.7, -0.4, 2.5);
  NodeMatrix moved = (fish.rest_positions_m * R.transpose()).rowwise() + t;
  skin.update(moved);
  const auto now = skin.controlPoints();
  double worst = 0;
  for (size_t c = 0; c < rest.size(); ++c) worst = std::max(worst, (now[c] - (R * rest[c] + t.transpose())).norm());
  EXPECT_LT(worst, 1e-12);
  skin.update(1.5 * fish.rest_positions_m);
  const auto scaled = skin.controlPoints();
  double off = 0;
  for (size_t c = 0; c < rest.size(); ++c) off = std::max(off, (scaled[c] - 1.5 * rest[c]).norm());
  EXPECT_GT(off, 1e-3);
}

// The halves meet exactly along the dorsal and ventral midlines, at the snout and at the tail's edge.
void expectClosed(const SkinMesh& m) {
  const int nu = m.samples_around, nv = m.samples_along, right = nu * nv;
  for (int iv = 0; iv < nv; ++iv) {
    EXPECT_EQ(m.positions[iv], m.positions[right + iv]) << "dorsal, station " << iv;
    EXPECT_EQ(m.positions[(nu - 1) * nv + iv], m.positions[right + (nu - 1) * nv + iv]) << "ventral, station " << iv;
  }
  for (int iu = 0; iu < nu; ++iu) {
    EXPECT_EQ(m.positions[iu * nv + nv - 1], m.positions[right + iu * nv + nv - 1]) << "tail edge " << iu;
    EXPECT_LT((m.positions[iu * nv] - m.positions[0]).norm(), 1e-15) << "snout " << iu;
  }
}

TEST(FishSkin, ClosedAndOutwardOverASwim) {
  const FishModel fish = testFish();
  FishSkin skin(fish, {});
  SolverParams p = testSolver();
  p.dt_s = 0.02;
  RunOptions opt;
  opt.frame_every_steps = 25;
  MotorParams strong = testMotor();
  strong.swim = {1.0, 0.008, 1.0, 0.008};  // the largest bends of the swim experiment
  const FishRecord rec = runSchedule(fish, p, strong, parseSchedule("swim 30; left 10"), opt);
  ASSERT_FALSE(rec.blew_up);
  SkinMesh mesh;
  // At rest every body triangle points outward (away from its section, an ellipse).
  skin.mesh(32, 64, mesh);
  const FoldCheck rest = checkOutward(mesh);
  EXPECT_EQ(rest.inward, 0);
  EXPECT_EQ(rest.checked, 2 * 2 * 31 * 63 - 2 * 31);  // all but one degenerate triangle per cell at the snout's pole
  EXPECT_GT(rest.worst_cosine, -1e-9);
  // Over the swim and a turn: closed, and no neighbouring triangles more than 90 degrees apart.
  // (The section-ellipse test is not used here: where the caudal fin thins to its zero-thickness
  // trailing edge and swings sideways by more than it is thick between two stations, the section's
  // outward direction is ill-defined; it flags up to 17 of 7,812 triangles in the last two stations
  // while their neighbours stay within 25 degrees of them.)
  double worst = 1;
  for (int f = 0; f < rec.frames(); ++f) {
    NodeMatrix x;
    for (int k = 0; k < kNodes; ++k)
      for (int d = 0; d < 3; ++d) x(k, d) = rec.nodes_m[(size_t(f) * kNodes + k) * 3 + d];
    skin.update(x);
    skin.mesh(32, 64, mesh);
    expectClosed(mesh);
    const FoldCheck fold = checkOutward(mesh);
    EXPECT_EQ(fold.creases, 0) << "frame " << f << " t = " << rec.time_s[f];
    worst = std::min(worst, fold.worst_neighbour_cosine);
  }
  EXPECT_GT(worst, 0.5);  // no crease sharper than 60 degrees (cos 60° = 0.5)
  ASSERT_EQ(mesh.positions.size(), mesh.normals.size());
  EXPECT_EQ(mesh.body_triangles, 2 * 2 * 31 * 63);
}

// The skin checks can fail: the rest skin with one half turned inside out (its triangles' winding
// reversed) has inward triangles, and with one half moved 1 mm sideways its seam opens by 1 mm.
TEST(FishSkin, OutwardAndSeamChecksSeeABrokenSkin) {
  const FishModel fish = testFish();
  FishSkin skin(fish, {});
  SkinMesh mesh;
  skin.mesh(16, 32, mesh);
  ASSERT_EQ(checkOutward(mesh).inward, 0);
  ASSERT_EQ(seamGapM(mesh), 0.0);
  SkinMesh inside_out = mesh;
  for (int k = 0; k < inside_out.body_triangles / 2; ++k) std::swap(inside_out.triangles[k][1], inside_out.triangles[k][2]);
  EXPECT_GT(checkOutward(inside_out).inward, inside_out.body_triangles / 4);
  SkinMesh opened = mesh;
  const size_t half = size_t(mesh.samples_around) * mesh.samples_along;
  for (size_t v = half; v < 2 * half; ++v) opened.positions[v].y() -= 1e-3;
  EXPECT_NEAR(seamGapM(opened), 1e-3, 1e-12);
}

// The pectoral fins are posed in the fish frame: mirror images at rest, carried exactly by a rigid
// motion of the nodes, below the body's axis beside ring 1-2, and pitched leading edge up by a
// positive pitch; the mesh appends them (5 vertices each) after the fins.
TEST(FishSkin, PectoralFinsPosedInTheFishFrame) {
  const FishModel fish = testFish();
  const NodeMatrix& x0 = fish.rest_positions_m;
  FishSkin skin(fish, {});
  const auto rest = skin.pectoralFins(x0);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(rest[k].x(), rest[5 + k].x(), 1e-15);
    EXPECT_NEAR(rest[k].y(), -rest[5 + k].y(), 1e-15);
    EXPECT_NEAR(rest[k].z(), rest[5 + k].z(), 1e-15);
    EXPECT_GT(rest[k].y(), 0.0);  // the left fin on the left
    EXPECT_LT(rest[k].z(), 0.0);  // below the axis
  }
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(1.5, -2.0, 0.25);
  NodeMatrix x;
  for (int i = 0; i < kNodes; ++i) x.row(i) = (rot * x0.row(i).transpose() + shift).transpose();
  const auto moved = skin.pectoralFins(x);
  for (int k = 0; k < 10; ++k) EXPECT_LT((moved[k] - (rot * rest[k] + shift)).norm(), 1e-12);
  SkinParams pitched;
  pitched.pectoral_pitch_deg = 30;
  const auto up = FishSkin(fish, pitched).pectoralFins(x0);
  EXPECT_GT(up[0].z() - up[1].z(), 0.01);  // the root's front vertex above its back one
  EXPECT_NEAR(rest[0].z(), rest[1].z(), 1e-15);
  SkinMesh mesh;
  skin.update(x0);
  skin.mesh(8, 16, mesh);
  ASSERT_GE(mesh.positions.size(), 10u);
  for (int k = 0; k < 10; ++k) EXPECT_LT((mesh.positions[mesh.positions.size() - 10 + k] - rest[k]).norm(), 1e-15);
}

// A surface point from the grid evaluator equals the direct evaluation.
TEST(FishSkin, GridEqualsPointwise) {
  const FishModel fish = testFish();
  FishSkin skin(fish, {});
  SkinMesh mesh;
  skin.mesh(5, 7, mesh);
  const NurbsSurface& left = skin.surfaces()[0];
  for (int iu = 0; iu < 5; ++iu)
    for (int iv = 0; iv < 7; ++iv)
      EXPECT_LT((mesh.positions[iu * 7 + iv] - left.point(iu / 4.0, iv / 6.0)).norm(), 1e-15);
}

}  // namespace
}  // namespace creaturelab::fish
