// The immersed-boundary coupling (ib/coupling.hpp) stage by stage, and the closed membrane it is
// tested with (ib/membrane_body.hpp): the membrane's forces are minus the gradient of its energy and
// its stiffness is their Jacobian (finite differences); its markers start equally spaced on the
// ellipse; the polygon measures are exact for polygons and ellipses. Then the coupled step: with no
// forces the markers move with a uniform flow exactly; one step puts dt Σ F of momentum into the
// fluid; the semi-implicit force of a tethered body at rest is the backward-Euler answer
// F m / (m + dt² κ); two runs are bitwise equal. Small grids: each test well under 1 s under ASan.
#include <gtest/gtest.h>


#include <cmath>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Dense>

#include "fluid/fluid_solver2.hpp"
#include "ib/coupling.hpp"
#include "ib/membrane_body.hpp"
#include "test_random.hpp"
#include "support/dense_linalg.hpp"

namespace creaturelab::ib {
namespace {

using test::uniform;

using fluid::Vec2;

// A membrane of n markers near a circle of radius 0.05 m about (0.08, 0.08), jittered so no
// symmetry hides an index error.
std::vector<Vec2> jitteredRing(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Vec2> x;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    const double jx = uniform(rng, -2e-3, 2e-3), jy = uniform(rng, -2e-3, 2e-3);
    x.push_back({0.08 + 0.05 * std::cos(a) + jx, 0.08 + 0.05 * std::sin(a) + jy});
  }
  return x;
}

Eigen::MatrixXd denseStiffness(const ElasticBody& body, const std::vector<Vec2>& x, double scale) {
  std::vector<Eigen::Triplet<double>> triplets;
  body.stiffness(0.0, x, scale, triplets);
  Eigen::SparseMatrix<double> k(2 * body.markerCount(), 2 * body.markerCount());
  k.setFromTriplets(triplets.begin(), triplets.end());
  return Eigen::MatrixXd(k);
}

// ---------------------------------------------------------------------------------- the membrane

TEST(MembraneBody, ForcesAreMinusTheEnergyGradientAndSumToZero) {
  const MembraneBody body(12, 250.0);
  std::vector<Vec2> x = jitteredRing(12, 3);
  std::vector<Vec2> f(12);
  body.forces(0.0, x, f);
  Vec2 total{0, 0};
  const double h = 1e-7;
  for (int k = 0; k < 12; ++k) {
    total = {total.x + f[k].x, total.y + f[k].y};
    for (int axis = 0; axis < 2; ++axis) {
      double& c = axis == 0 ? x[k].x : x[k].y;
      const double keep = c;
      c = keep + h;
      const double up = body.elasticEnergy(x);
      c = keep - h;
      const double down = body.elasticEnergy(x);
      c = keep;
      // E is quadratic, so the central difference is exact up to the round-off of E (~1e-16 E / h).
      EXPECT_NEAR(axis == 0 ? f[k].x : f[k].y, -(up - down) / (2 * h), 1e-6) << "marker " << k << " axis " << axis;
    }
  }
  // Internal forces: Newton's third law, the membrane pushes the fluid with no net force.
  EXPECT_NEAR(total.x, 0.0, 1e-13);
  EXPECT_NEAR(total.y, 0.0, 1e-13);
}

TEST(MembraneBody, StiffnessIsTheForceJacobianAndNegativeSemiDefinite) {
  const int n = 9;
  const double k = 40.0, scale = 0.5;
  const MembraneBody body(n, k);
  const std::vector<Vec2> x = jitteredRing(n, 5);
  const Eigen::MatrixXd stiffness = denseStiffness(body, x, scale);
  // The force is linear in X: one difference of any size is exact, up to round-off.
  std::vector<Vec2> f0(n), f1(n);
  body.forces(0.0, x, f0);
  for (int col = 0; col < 2 * n; ++col) {
    std::vector<Vec2> moved = x;
    (col % 2 == 0 ? moved[col / 2].x : moved[col / 2].y) += 1e-3;
    body.forces(0.0, moved, f1);
    for (int row = 0; row < 2 * n; ++row) {
      const double df = row % 2 == 0 ? f1[row / 2].x - f0[row / 2].x : f1[row / 2].y - f0[row / 2].y;
      EXPECT_NEAR(stiffness(row, col), scale * df / 1e-3, 1e-9) << "row " << row << " col " << col;
    }
  }
  EXPECT_TRUE(stiffness.isApprox(stiffness.transpose()));
  // k times the ring Laplacian: eigenvalues -scale k (2 sin(pi q / n))^2 in [-4 scale k, 0].
  const Eigen::VectorXd eig = test::symmetricEigenvalues(stiffness);
  EXPECT_LE(eig.maxCoeff(), 1e-12);
  EXPECT_GE(eig.minCoeff(), -4 * scale * k - 1e-9);
  // Translations cost nothing: two zero eigenvalues (one per axis).
  EXPECT_NEAR(eig[2 * n - 1], 0.0, 1e-12);
  EXPECT_NEAR(eig[2 * n - 2], 0.0, 1e-12);
}

TEST(MembraneBody, ElasticEnergyAndTensionOfARegularPolygon) {
  const int n = 6;
  std::vector<Vec2> x;
  for (int k = 0; k < n; ++k) x.push_back({std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n)});  // side 1
  const MembraneBody body(n, 3.0);
  EXPECT_NEAR(body.elasticEnergy(x), 0.5 * 3.0 * n, 1e-13);
  EXPECT_NEAR(body.meanTension(x), 3.0, 1e-14);
  // Each marker is pulled toward the centre by 2 T sin(pi / n) = T for the hexagon.
  std::vector<Vec2> f(n);
  body.forces(0.0, x, f);
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(f[k].x, -3.0 * x[k].x, 1e-13);
    EXPECT_NEAR(f[k].y, -3.0 * x[k].y, 1e-13);
  }
}

TEST(MembraneBody, RefusesTooFewMarkersAndBadStiffness) {
  EXPECT_THROW(MembraneBody(2, 1.0), std::invalid_argument);
  EXPECT_THROW(MembraneBody(8, 0.0), std::invalid_argument);
  EXPECT_THROW(MembraneBody(8, std::nan("")), std::invalid_argument);
  MembraneParams p;
  p.markers = 2;
  p.semi_axis_y_m = -1;
  const std::string err = p.validate();
  EXPECT_NE(err.find("at least 3 markers (got 2)"), std::string::npos) << err;
  EXPECT_NE(err.find("semi-axes must be positive"), std::string::npos) << err;
  EXPECT_THROW(ellipseMarkers(p), std::invalid_argument);
  EXPECT_EQ(MembraneParams{}.validate(), "");
}

TEST(EllipseMarkers, EquallySpacedOnTheEllipseCounterClockwise) {
  MembraneParams p;
  p.centre_x_m = 0.3;
  p.centre_y_m = 0.2;
  p.semi_axis_x_m = 0.25;
  p.semi_axis_y_m = 0.15;
  p.markers = 64;
  const std::vector<Vec2> x = ellipseMarkers(p);
  ASSERT_EQ(x.size(), 64u);
  EXPECT_DOUBLE_EQ(x[0].x, 0.55);
  EXPECT_DOUBLE_EQ(x[0].y, 0.2);
  // Arc length between parameter angles by Simpson's rule on 2000 panels (error ~1e-13 here).
  auto arc = [](double t0, double t1) {
    const int n = 2000;
    const double h = (t1 - t0) / n;
    auto speed = [](double t) { return std::hypot(0.25 * std::sin(t), 0.15 * std::cos(t)); };
    double sum = speed(t0) + speed(t1);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * speed(t0 + i * h);
    return sum * h / 3;
  };
  std::vector<double> theta;
  for (int k = 0; k < 64; ++k) {
    const double u = (x[k].x - 0.3) / 0.25, v = (x[k].y - 0.2) / 0.15;
    EXPECT_NEAR(u * u + v * v, 1.0, 1e-14) << "marker " << k;
    theta.push_back(std::atan2(v, u) + (v < 0 ? 2 * M_PI : 0.0));
  }
  theta.push_back(2 * M_PI);
  const double perimeter = arc(0, 2 * M_PI);
  for (int k = 0; k < 64; ++k) {
    ASSERT_GT(theta[k + 1], theta[k]) << "marker " << k;  // counter-clockwise, in order
    // Equal arcs to the header's 1e-4.
    EXPECT_NEAR(arc(theta[k], theta[k + 1]) / (perimeter / 64) - 1, 0.0, 1e-4) << "marker " << k;
  }
  EXPECT_GT(polygonShape(x).area_m2, 0.0);  // counter-clockwise
}

TEST(PolygonShape, RegularPolygonIsRoundWhateverItsOrientation) {
  const int n = 7;
  for (double turn : {0.0, 0.3, 1.1}) {
    std::vector<Vec2> x;
    for (int k = 0; k < n; ++k) {
      const double a = turn + 2 * M_PI * k / n;
      x.push_back({2.0 + 0.5 * std::cos(a), -1.0 + 0.5 * std::sin(a)});
    }
    const PolygonShape s = polygonShape(x);
    EXPECT_NEAR(s.area_m2, 0.5 * n * 0.25 * std::sin(2 * M_PI / n), 1e-14);
    EXPECT_NEAR(s.centroid_m.x, 2.0, 1e-14);
    EXPECT_NEAR(s.centroid_m.y, -1.0, 1e-14);
    EXPECT_NEAR(s.perimeter_m, n * 2 * 0.5 * std::sin(M_PI / n), 1e-14);
    EXPECT_NEAR(s.aspect_ratio, 1.0, 1e-12);
  }
}

TEST(PolygonShape, RectangleAndRotatedEllipse) {
  // A 3 x 1 rectangle, clockwise: second moments w^3 h / 12 and w h^3 / 12, aspect exactly 3.
  const std::vector<Vec2> rect = {{0, 0}, {0, 1}, {3, 1}, {3, 0}};
  const PolygonShape r = polygonShape(rect);
  EXPECT_NEAR(r.area_m2, -3.0, 1e-15);
  EXPECT_NEAR(r.centroid_m.x, 1.5, 1e-15);
  EXPECT_NEAR(r.centroid_m.y, 0.5, 1e-15);
  EXPECT_NEAR(r.aspect_ratio, 3.0, 1e-14);
  // A finely sampled ellipse, turned by 40 degrees: aspect a / b, area pi a b (inscribed polygon:
  // relative area deficit ~ (2 pi / n)^2 / 6 = 4e-7 at n = 4096).
  std::vector<Vec2> e;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (int k = 0; k < 4096; ++k) {
    const double a = 2 * M_PI * k / 4096, u = 0.4 * std::cos(a), v = 0.1 * std::sin(a);
    e.push_back({c * u - s * v, s * u + c * v});
  }
  const PolygonShape es = polygonShape(e);
  EXPECT_NEAR(es.aspect_ratio, 4.0, 1e-5);
  EXPECT_NEAR(es.area_m2 / (M_PI * 0.04) - 1, 0.0, 1e-6);
}

// ------------------------------------------------------------------------------- the coupled step

// No elastic forces at all.
class ZeroBody : public ElasticBody {
 public:
  explicit ZeroBody(int n) : n_(n) {}
  int markerCount() const override { return n_; }
  void forces(double, std::span<const Vec2>, std::span<Vec2> f) const override {
    for (auto& v : f) v = {0, 0};
  }
  void stiffness(double, std::span<const Vec2>, double, std::vector<Eigen::Triplet<double>>&) const override {}

 private:
  int n_;
};

// Each marker tied to its own anchor by a zero-rest spring: F = −κ (X − A), ∂F/∂X = −κ I. Unlike the
// membrane its forces do not sum to zero.
class TetheredBody : public ElasticBody {
 public:
  TetheredBody(std::vector<Vec2> anchors, double kappa) : anchors_(std::move(anchors)), kappa_(kappa) {}
  int markerCount() const override { return int(anchors_.size()); }
  void forces(double, std::span<const Vec2> x, std::span<Vec2> f) const override {
    for (std::size_t k = 0; k < anchors_.size(); ++k)
      f[k] = {-kappa_ * (x[k].x - anchors_[k].x), -kappa_ * (x[k].y - anchors_[k].y)};
  }
  void stiffness(double, std::span<const Vec2>, double scale, std::vector<Eigen::Triplet<double>>& out) const override {
    for (int r = 0; r < 2 * markerCount(); ++r) out.emplace_back(r, r, -scale * kappa_);
  }

 private:
  std::vector<Vec2> anchors_;
  double kappa_;
};

// A 16 x 16 box of 1 cm cells.
fluid::FluidParams smallBox() {
  fluid::FluidParams p;
  p.domain_width_m = p.domain_height_m = 0.16;
  p.cells_x = p.cells_y = 16;
  p.kinematic_viscosity_m2_per_s = 1e-4;
  p.time_step_policy = fluid::TimeStepPolicy::fixed;
  p.fixed_step_s = 0.01;
  return p;
}

void stagesOff(fluid::FluidSolver2& s, bool keep_external_forces) {
  s.stages() = {keep_external_forces, false, false, false, false};
}

// x and y momentum per metre of depth: ρ dx² Σ over the faces.
Vec2 momentum(const fluid::FluidSolver2& s) {
  const auto& g = s.grid();
  const double w = s.params().density_kg_per_m3 * g.dx_m * g.dx_m;
  double px = 0, py = 0;
  for (std::size_t i = 0; i < g.u_m_per_s.size(); ++i) px += g.u_m_per_s.data()[i];
  for (std::size_t i = 0; i < g.v_m_per_s.size(); ++i) py += g.v_m_per_s.data()[i];
  return {w * px, w * py};
}

class CouplingTest : public ::testing::TestWithParam<std::tuple<Kernel, bool>> {
 protected:
  CouplingParams params() const {
    CouplingParams c;
    c.kernel = std::get<0>(GetParam());
    c.semi_implicit = std::get<1>(GetParam());
    return c;
  }
};

// Move stage alone: with no forces and the fluid's own stages off, the velocity stays uniform and
// every marker moves by dt U exactly (the weights sum to one up to an ulp).
TEST_P(CouplingTest, WithoutForcesMarkersMoveWithAUniformFlow) {
  fluid::FluidSolver2 fluid(smallBox());
  stagesOff(fluid, true);
  fluid.grid().u_m_per_s.fill(0.3);
  fluid.grid().v_m_per_s.fill(-0.2);
  const std::vector<Vec2> start = jitteredRing(24, 11);
  const ZeroBody body(24);
  ImmersedBoundary2 ib(fluid, body, start, params());
  for (int step = 1; step <= 3; ++step) {
    const CouplingStepReport report = ib.step(0.01);
    EXPECT_NEAR(report.max_marker_speed_m_per_s, std::hypot(0.3, 0.2), 1e-15);
    for (int k = 0; k < 24; ++k) {
      EXPECT_NEAR(ib.markers_m()[k].x, start[k].x + step * 0.01 * 0.3, 1e-15) << "marker " << k;
      EXPECT_NEAR(ib.markers_m()[k].y, start[k].y - step * 0.01 * 0.2, 1e-15) << "marker " << k;
      EXPECT_EQ(ib.appliedForce_n_per_m()[k].x, 0.0);
    }
  }
}

// Spread + external-force stage: a step changes the fluid's momentum by dt times the force that
// was spread (the spread conserves force, transfer.hpp), for a body with a net force.
TEST_P(CouplingTest, OneStepPutsDtTimesTheForceIntoTheFluidMomentum) {
  fluid::FluidSolver2 fluid(smallBox());
  stagesOff(fluid, true);
  std::vector<Vec2> anchors = jitteredRing(20, 13);
  for (auto& a : anchors) a = {a.x + 0.004, a.y - 0.003};
  const TetheredBody body(anchors, 50.0);
  ImmersedBoundary2 ib(fluid, body, jitteredRing(20, 13), params());
  const double dt = 0.01;
  ib.step(dt);
  Vec2 total{0, 0};
  for (const auto& f : ib.appliedForce_n_per_m()) total = {total.x + f.x, total.y + f.y};
  ASSERT_GT(std::fabs(total.x), 1.0);  // 20 markers x 50 N/m^2 x 4 mm
  const Vec2 p = momentum(fluid);
  EXPECT_NEAR(p.x, dt * total.x, 1e-14 * std::fabs(dt * total.x) * 20);
  EXPECT_NEAR(p.y, dt * total.y, 1e-14 * std::fabs(dt * total.y) * 20);
}

// The membrane's forces are internal: whatever the kernel and the implicit correction (K has zero
// column sums), no net momentum goes into the fluid.
TEST_P(CouplingTest, TheMembranePutsNoNetMomentumIntoTheFluid) {
  fluid::FluidSolver2 fluid(smallBox());
  stagesOff(fluid, true);
  const MembraneBody body(30, 500.0);
  ImmersedBoundary2 ib(fluid, body, jitteredRing(30, 17), params());
  ib.step(0.01);
  double scale = 0;
  for (const auto& f : ib.appliedForce_n_per_m()) scale += std::hypot(f.x, f.y);
  ASSERT_GT(scale, 1.0);
  const Vec2 p = momentum(fluid);
  EXPECT_NEAR(p.x, 0.0, 1e-14 * 0.01 * scale);
  EXPECT_NEAR(p.y, 0.0, 1e-14 * 0.01 * scale);
}

std::string modeName(const ::testing::TestParamInfo<std::tuple<Kernel, bool>>& mode) {
  return std::string(to_string(std::get<0>(mode.param))) + (std::get<1>(mode.param) ? "_semi_implicit" : "_explicit");
}

INSTANTIATE_TEST_SUITE_P(KernelsAndModes, CouplingTest,
                         ::testing::Combine(::testing::Values(Kernel::bilinear, Kernel::peskin4), ::testing::Bool()),
                         modeName);

// Implicit stage against its analytic answer: fluid at rest (U = 0), F = −κ (X − A), K = −κ I, so
// (m + dt² κ) U* = dt F and the spread force is F + dt K U* = F m / (m + dt² κ), m = factor ρ dx².
TEST(Coupling, SemiImplicitForceOfATetheredBodyAtRestIsBackwardEuler) {
  for (double factor : {1.0, 0.25}) {
    fluid::FluidSolver2 fluid(smallBox());
    stagesOff(fluid, false);
    const std::vector<Vec2> x = jitteredRing(10, 19);
    std::vector<Vec2> anchors = x;
    for (auto& a : anchors) a = {a.x + 0.002, a.y + 0.001};
    const double kappa = 2000.0, dt = 0.01;
    const TetheredBody body(anchors, kappa);
    CouplingParams c;
    c.mobility = ImplicitMobility::local_mass;
    c.implicit_mass_factor = factor;
    ImmersedBoundary2 ib(fluid, body, x, c);
    ib.step(dt);
    const double m = factor * 1000.0 * 0.01 * 0.01;
    const double reduction = m / (m + dt * dt * kappa);
    for (int k = 0; k < 10; ++k) {
      EXPECT_NEAR(ib.appliedForce_n_per_m()[k].x, kappa * 0.002 * reduction, 1e-13) << "marker " << k;
      EXPECT_NEAR(ib.appliedForce_n_per_m()[k].y, kappa * 0.001 * reduction, 1e-13) << "marker " << k;
    }
  }
}

// The stencil mobility against its analytic answer: one tethered marker in fluid at rest, so
// (1 + dt κ M) U* = M F with M = dt G / (ρ dx²), G = Σ_faces w² of its own stencil (per component),
// and the spread force is F / (1 + dt² κ G / (ρ dx²)). G differs between kernels and with the
// marker's place in its cell, which is the point of the stencil mobility.
TEST(Coupling, StencilMobilityOfOneTetheredMarkerAtRest) {
  for (Kernel kernel : {Kernel::bilinear, Kernel::peskin4}) {
    fluid::FluidSolver2 fluid(smallBox());
    stagesOff(fluid, false);
    const std::vector<Vec2> x = {{0.0537, 0.0461}};
    const std::vector<Vec2> anchors = {{0.0557, 0.0471}};
    const double kappa = 2000.0, dt = 0.01, rho = 1000.0, dx = fluid.grid().dx_m;
    const TetheredBody body(anchors, kappa);
    CouplingParams c;
    c.kernel = kernel;
    c.mobility = ImplicitMobility::stencil;
    ImmersedBoundary2 ib(fluid, body, x, c);
    ib.step(dt);
    Transfer t;
    t.locate(fluid.grid(), kernel, x);
    Eigen::MatrixXd g;
    t.gram(g);
    ASSERT_EQ(g.rows(), 2);
    EXPECT_EQ(g(0, 1), 0.0);
    const double fx = kappa * 0.002 / (1 + dt * dt * kappa * g(0, 0) / (rho * dx * dx));
    const double fy = kappa * 0.001 / (1 + dt * dt * kappa * g(1, 1) / (rho * dx * dx));
    EXPECT_NEAR(ib.appliedForce_n_per_m()[0].x, fx, 1e-12 * kappa * 0.002) << to_string(kernel);
    EXPECT_NEAR(ib.appliedForce_n_per_m()[0].y, fy, 1e-12 * kappa * 0.001) << to_string(kernel);
    EXPECT_LT(fx, kappa * 0.002);  // the implicit force is softer than the explicit one
  }
}

// The Gram matrix of the stencils is symmetric, positive semi-definite, zero between components,
// and its diagonal is the sum of squared weights (3/8 squared in 2-D for Peskin's kernel in
// expectation; here checked against the stencil directly).
TEST(Coupling, StencilGramMatrixIsSymmetricAndMatchesTheWeights) {
  fluid::FluidSolver2 fluid(smallBox());
  const std::vector<Vec2> x = jitteredRing(12, 7);
  for (Kernel kernel : {Kernel::bilinear, Kernel::peskin4}) {
    Transfer t;
    t.locate(fluid.grid(), kernel, x);
    Eigen::MatrixXd g;
    t.gram(g);
    EXPECT_LT((g - g.transpose()).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_GT(test::symmetricEigenvalues(g).minCoeff(), -1e-14);
    for (int k = 0; k < 12; ++k) {
      const auto& u = t.uStencil(k);
      double sx = 0, sy = 0;
      for (int a = 0; a < kernelSupportCells(kernel); ++a) sx += u.wx[a] * u.wx[a];
      for (int b = 0; b < kernelSupportCells(kernel); ++b) sy += u.wy[b] * u.wy[b];
      EXPECT_NEAR(g(2 * k, 2 * k), sx * sy, 1e-15);
      for (int l = 0; l < 12; ++l) EXPECT_EQ(g(2 * k, 2 * l + 1), 0.0);
    }
  }
}

// The coupling's mobility uses the sparse Gram matrix: it must be the dense one scaled (to
// round-off), hold only the overlapping stencils, and be exactly symmetric (each entry's products
// summed in the same order both ways), so that M stays symmetric in the implicit solve.
TEST(Coupling, SparseGramMatrixIsTheScaledDenseOneAndExactlySymmetric) {
  fluid::FluidSolver2 fluid(smallBox());
  const std::vector<Vec2> x = jitteredRing(12, 7);
  for (Kernel kernel : {Kernel::bilinear, Kernel::peskin4}) {
    Transfer t;
    t.locate(fluid.grid(), kernel, x);
    Eigen::MatrixXd dense;
    t.gram(dense);
    Eigen::SparseMatrix<double> sparse;
    const double scale = 0.37;
    t.gram(scale, sparse);
    const Eigen::MatrixXd from_sparse(sparse);
    // (scale · a) · b against scale · (a · b): equal to the last bit or two.
    EXPECT_LE((from_sparse - scale * dense).cwiseAbs().maxCoeff(), 4e-16 * scale * dense.cwiseAbs().maxCoeff())
        << to_string(kernel);
    EXPECT_EQ((from_sparse - from_sparse.transpose()).cwiseAbs().maxCoeff(), 0.0) << to_string(kernel);
    EXPECT_LT(sparse.nonZeros(), from_sparse.size()) << to_string(kernel);  // some stencils do not overlap
    for (int k = 0; k < sparse.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator e(sparse, k); e; ++e) EXPECT_NE(e.value(), 0.0);
  }
}

// The coupling's refinement sweeps apply G through the stencils (Transfer::apply_gram) instead of
// forming it: the product must be the formed matrix's to round-off, on both kernels and stretches
// (support 2 to 8 faces, the templated and the general loop), and refuse vectors of the wrong size.
TEST(Coupling, AppliedGramIsTheFormedOnesProduct) {
  fluid::FluidParams p = smallBox();
  p.cells_x = p.cells_y = 48;
  fluid::FluidSolver2 fluid(p);
  const std::vector<Vec2> x = jitteredRing(150, 3);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> patch;
  for (const int stretch : {1, 2, 3})
    for (Kernel kernel : {Kernel::bilinear, Kernel::peskin4}) {
      Transfer t;
      t.locate(fluid.grid(), kernel, x, stretch);
      Eigen::SparseMatrix<double> g;
      t.gram(1.0, g);
      Eigen::VectorXd v(300);
      for (double& e : v) e = unit(rng);
      const Eigen::VectorXd want = g * v;
      std::vector<double> in(v.data(), v.data() + v.size()), got(300, 0.0);
      t.applyGram(in, got, patch);
      double largest = 0.0, error = 0.0;
      for (int i = 0; i < 300; ++i) {
        largest = std::max(largest, std::abs(want[i]));
        error = std::max(error, std::abs(got[i] - want[i]));
      }
      EXPECT_GT(largest, 1e-3) << to_string(kernel) << " x" << stretch;  // not a product of zeros
      EXPECT_LE(error, 1e-14 * largest) << to_string(kernel) << " x" << stretch << " (support " << t.stencilFaces()
                                        << ")";
    }
  Transfer t;
  t.locate(fluid.grid(), Kernel::peskin4, x);
  std::vector<double> wrong(299), out(300);
  EXPECT_THROW(t.applyGram(wrong, out, patch), std::invalid_argument);
}

// Each stored entry of the sparse Gram matrix is, bit for bit, scale · (Σ_a wx_k[a] wx_l[a + di]) ·
// (Σ_b wy_k[b] wy_l[b + dj]) of its own row k and column l, summed over ascending offsets (gram()
// computes the entries on and below the diagonal and copies each one above from its mirror); rows
// ascend in each column, and every overlapping pair is stored. 150 markers: the bit set of the
// neighbour search spans three words.
TEST(Coupling, SparseGramEntriesAreTheirOverlapsBitForBit) {
  fluid::FluidParams p = smallBox();
  p.cells_x = p.cells_y = 32;
  fluid::FluidSolver2 fluid(p);
  const std::vector<Vec2> x = jitteredRing(150, 3);
  for (const int stretch : {1, 2})
    for (Kernel kernel : {Kernel::bilinear, Kernel::peskin4}) {
      Transfer t;
      t.locate(fluid.grid(), kernel, x, stretch);
      const double scale = 0.37;
      Eigen::SparseMatrix<double> g;
      t.gram(scale, g);
      const int s = t.stencilFaces();
      auto overlap = [s](const double* wk, const double* wl, int shift) {
        double sum = 0.0;
        for (int a = 0; a < s; ++a)
          if (a + shift >= 0 && a + shift < s) sum += wk[a] * wl[a + shift];
        return sum;
      };
      long stored = 0, overlapping = 0;
      for (int col = 0; col < g.outerSize(); ++col) {
        int previous = -1;
        for (Eigen::SparseMatrix<double>::InnerIterator e(g, col); e; ++e, ++stored) {
          const int row = static_cast<int>(e.row()), k = row / 2, l = col / 2, c = col % 2;
          ASSERT_EQ(row % 2, c);
          ASSERT_GT(row, previous);
          previous = row;
          const FaceStencil& sk = c == 0 ? t.uStencil(k) : t.vStencil(k);
          const FaceStencil& sl = c == 0 ? t.uStencil(l) : t.vStencil(l);
          const double want = scale * overlap(sk.wx, sl.wx, sk.i0 - sl.i0) * overlap(sk.wy, sl.wy, sk.j0 - sl.j0);
          ASSERT_EQ(e.value(), want) << to_string(kernel) << " x" << stretch << " (" << row << ", " << col << ")";
        }
      }
      for (int c = 0; c < 2; ++c)
        for (int k = 0; k < 150; ++k)
          for (int l = 0; l < 150; ++l) {
            const FaceStencil& sk = c == 0 ? t.uStencil(k) : t.vStencil(k);
            const FaceStencil& sl = c == 0 ? t.uStencil(l) : t.vStencil(l);
            overlapping += std::abs(sk.i0 - sl.i0) < s && std::abs(sk.j0 - sl.j0) < s;
          }
      EXPECT_EQ(stored, overlapping) << to_string(kernel) << " x" << stretch;
    }
}

// The whole coupled step (all fluid stages on) twice from the same start: bitwise equal markers
// and velocities (DESIGN.md: determinism).
TEST(Coupling, TwoRunsAreBitwiseEqual) {
  auto run = [] {
    fluid::FluidParams p = smallBox();
    p.cells_x = p.cells_y = 24;
    p.domain_width_m = p.domain_height_m = 0.24;
    fluid::FluidSolver2 fluid(p);
    MembraneParams mp;
    mp.centre_x_m = mp.centre_y_m = 0.12;
    mp.semi_axis_x_m = 0.06;
    mp.semi_axis_y_m = 0.04;
    mp.markers = 48;
    mp.stiffness_n_per_m = 200.0;
    const MembraneBody body(mp.markers, mp.stiffness_n_per_m);
    CouplingParams c;
    c.kernel = Kernel::peskin4;
    ImmersedBoundary2 ib(fluid, body, ellipseMarkers(mp), c);
    for (int s = 0; s < 15; ++s) ib.step(0.01);
    return std::make_tuple(ib.markers_m(), fluid.grid().u_m_per_s, fluid.grid().v_m_per_s);
  };
  const auto [x1, u1, v1] = run();
  const auto [x2, u2, v2] = run();
  ASSERT_EQ(x1.size(), x2.size());
  for (std::size_t k = 0; k < x1.size(); ++k) {
    EXPECT_EQ(x1[k].x, x2[k].x) << "marker " << k;
    EXPECT_EQ(x1[k].y, x2[k].y) << "marker " << k;
  }
  EXPECT_TRUE(u1 == u2);
  EXPECT_TRUE(v1 == v2);
  // And the membrane did move (the test is not vacuous).
  EXPECT_NE(x1[0].x, 0.12 + 0.06);
}

// A body with a solve order of at least kBandedFromMarkers markers solves the semi-implicit system
// banded (ib/banded_lu.hpp) instead of dense: the same system, so the same steps to round-off.
// A stiff membrane of 320 markers (a jittered ring, so no symmetry hides an index error), ordered
// in left/right pairs as the jellyfish orders its bell.
class OrderedMembrane : public MembraneBody {
 public:
  using MembraneBody::MembraneBody;
  std::vector<int> solveOrder() const override {
    std::vector<int> order;
    const int last = markerCount() - 1;
    for (int k = 0; k <= last - k; ++k) {
      order.push_back(k);
      if (last - k != k) order.push_back(last - k);
    }
    return order;
  }
};

TEST(Coupling, BandedSolveOfAnOrderedBodyMatchesTheDenseOne) {
  constexpr int kMarkers = 320;
  static_assert(kMarkers >= kBandedFromMarkers);
  auto run = [](const ElasticBody& body) {
    fluid::FluidParams p = smallBox();
    fluid::FluidSolver2 fluid(p);
    CouplingParams c;
    c.kernel = Kernel::peskin4;
    c.factor_reuse.tolerance = 0;  // a fresh factorisation every step: the banded LU itself
    ImmersedBoundary2 ib(fluid, body, jitteredRing(kMarkers, 5), c);
    for (int s = 0; s < 4; ++s) ib.step(0.01);
    return ib.markers_m();
  };
  const MembraneBody plain(kMarkers, 2000.0);
  const OrderedMembrane ordered(kMarkers, 2000.0);
  const std::vector<Vec2> dense = run(plain), banded = run(ordered);
  const std::vector<Vec2> start = jitteredRing(kMarkers, 5);
  double moved = 0, differ = 0;
  for (int k = 0; k < kMarkers; ++k) {
    moved = std::max(moved, std::hypot(dense[k].x - start[k].x, dense[k].y - start[k].y));
    differ = std::max(differ, std::hypot(dense[k].x - banded[k].x, dense[k].y - banded[k].y));
  }
  EXPECT_GT(moved, 1e-4);            // the jitter relaxes: the system did something
  EXPECT_LT(differ, 1e-12 * moved);  // and both solves agree to round-off
}

// The banded solve refines on an earlier step's factors (ib/reused_banded_solve.hpp): over steps
// that change the system little it factors less often than it solves, and the markers follow the
// run that factors every step to within the refinement's tolerance.
TEST(Coupling, ReusedFactorsGiveTheStepsOfFreshOnes) {
  constexpr int kMarkers = 320;
  const OrderedMembrane body(kMarkers, 2000.0);
  auto run = [&](double tolerance, long* factorizations) {
    fluid::FluidSolver2 fluid(smallBox());
    CouplingParams c;
    c.kernel = Kernel::peskin4;
    c.factor_reuse.tolerance = tolerance;
    ImmersedBoundary2 ib(fluid, body, jitteredRing(kMarkers, 5), c);
    for (int s = 0; s < 10; ++s) ib.step(0.002);
    *factorizations = ib.bandedSolver().factorizations();
    EXPECT_EQ(ib.bandedSolver().solves(), 10);
    return ib.markers_m();
  };
  long fresh_count = 0, reused_count = 0;
  const std::vector<Vec2> fresh = run(0.0, &fresh_count), reused = run(1e-12, &reused_count);
  const std::vector<Vec2> start = jitteredRing(kMarkers, 5);
  double moved = 0, differ = 0;
  for (int k = 0; k < kMarkers; ++k) {
    moved = std::max(moved, std::hypot(fresh[k].x - start[k].x, fresh[k].y - start[k].y));
    differ = std::max(differ, std::hypot(fresh[k].x - reused[k].x, fresh[k].y - reused[k].y));
  }
  EXPECT_EQ(fresh_count, 10);
  EXPECT_LT(reused_count, 5);
  EXPECT_GT(moved, 1e-5);
  EXPECT_LT(differ, 1e-10 * moved);
  RecordProperty("factorizations", std::to_string(reused_count));
}

TEST(Coupling, FactorReuseNeedsASweepAndATolerance) {
  fluid::FluidSolver2 fluid(smallBox());
  const MembraneBody body(8, 1.0);
  CouplingParams c;
  c.factor_reuse.max_sweeps = 0;
  EXPECT_THROW(ImmersedBoundary2(fluid, body, jitteredRing(8, 1), c), std::invalid_argument);
  c.factor_reuse = {};
  c.factor_reuse.tolerance = -1;
  EXPECT_THROW(ImmersedBoundary2(fluid, body, jitteredRing(8, 1), c), std::invalid_argument);
}

TEST(Coupling, MarkerCountMustMatchTheBody) {
  fluid::FluidSolver2 fluid(smallBox());
  const MembraneBody body(8, 1.0);
  try {
    ImmersedBoundary2 ib(fluid, body, jitteredRing(7, 1), CouplingParams{});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("7 markers for a body of 8"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace creaturelab::ib
