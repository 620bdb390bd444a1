// Properties of the immersed-boundary spreading and interpolation operators (ib/transfer.hpp)
// on u and v faces, for both kernels, at many seeded random marker positions: weights that sum
// to one and equal the kernel at each face, force conservation, exact interpolation of linear
// fields, adjointness, walls left untouched, and the errors a user sees for bad markers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "fluid/mac_grid2.hpp"
#include "ib/kernel.hpp"
#include "ib/transfer.hpp"
#include "test_random.hpp"

namespace creaturelab::ib {
namespace {

using test::uniform01;
using test::uniform;

using fluid::FaceVectorField2;
using fluid::MacGrid2;
using fluid::Vec2;

// A non-square grid (x and y must not be mixed up) of 1 cm cells.
constexpr int kNx = 24;
constexpr int kNy = 19;
constexpr double kDx = 0.01;
constexpr int kTransferMarkers = 300;

// Neumaier's compensated sum: a reference total that the check's own round-off does not blur.
struct CompensatedSum {
  double sum = 0.0, correction = 0.0;
  void add(double v) {
    const double t = sum + v;
    correction += std::abs(sum) >= std::abs(v) ? (sum - t) + v : (v - t) + sum;
    sum = t;
  }
  double value() const { return sum + correction; }
};

// Random markers where the kernel's stencil fits (see transfer.hpp: [s/2 dx, (n − s/2) dx) per
// axis), plus the corner of that region and markers exactly on faces and cell centres, where a
// stencil weight is exactly 0 or the fraction t is exactly 0.
std::vector<Vec2> markers(Kernel kernel, std::uint64_t seed, int count = kTransferMarkers) {
  const double margin = 0.5 * kernelSupportCells(kernel) * kDx;
  const double inset = 1e-9 * kDx;
  std::mt19937_64 rng(seed);
  std::vector<Vec2> p;
  p.push_back({margin, margin});
  p.push_back({margin + 0.5 * kDx, margin + 0.5 * kDx});
  p.push_back({5.0 * kDx, 7.5 * kDx});  // on a u face
  p.push_back({8.5 * kDx, 6.0 * kDx});  // on a v face
  p.push_back({kNx * kDx - margin - inset, kNy * kDx - margin - inset});
  while (static_cast<int>(p.size()) < count) {
    p.push_back({uniform(rng, margin, kNx * kDx - margin - inset), uniform(rng, margin, kNy * kDx - margin - inset)});
  }
  return p;
}

std::vector<Vec2> random_vectors(std::uint64_t seed, int count, double scale) {
  std::mt19937_64 rng(seed);
  std::vector<Vec2> f(static_cast<std::size_t>(count));
  for (Vec2& v : f) v = {uniform(rng, -scale, scale), uniform(rng, -scale, scale)};
  return f;
}

void fill_random(fluid::Array2& a, std::mt19937_64& rng, double scale) {
  for (int j = 0; j < a.ny(); ++j)
    for (int i = 0; i < a.nx(); ++i) a(i, j) = uniform(rng, -scale, scale);
}

class TransferTest : public ::testing::TestWithParam<Kernel> {
 protected:
  Kernel kernel() const { return GetParam(); }
  int support() const { return kernelSupportCells(GetParam()); }
  MacGrid2 grid_{kNx, kNy, kDx};
};

// Each face weight is phi((X − x_face)/dx) phi((Y − y_face)/dx) at the face's MAC position (to
// the round-off of a position of ~20 cells, ~1e-14), the 2-D weights sum to one, and the stencil
// holds every face with a non-zero weight (the faces one step beyond it have phi = 0 up to that
// round-off). Peskin4 also: Σ weights² = (3/8)², the same everywhere.
TEST_P(TransferTest, StencilWeightsAreTheKernelAtEachFaceAndSumToOne) {
  const std::vector<Vec2> p = markers(kernel(), 21);
  Transfer transfer;
  transfer.locate(grid_, kernel(), p);
  ASSERT_EQ(transfer.markerCount(), kTransferMarkers);
  EXPECT_EQ(transfer.kernel(), kernel());
  const int s = support();
  for (int k = 0; k < kTransferMarkers; ++k) {
    for (bool on_u : {true, false}) {
      const FaceStencil& st = on_u ? transfer.uStencil(k) : transfer.vStencil(k);
      double sum = 0.0, squares = 0.0;
      for (int b = -1; b <= s; ++b) {
        for (int a = -1; a <= s; ++a) {
          const int i = st.i0 + a, j = st.j0 + b;
          const Vec2 face = on_u ? grid_.uPosition_m(i, j) : grid_.vPosition_m(i, j);
          const double expected =
              kernelWeight_1d(kernel(), (p[k].x - face.x) / kDx) * kernelWeight_1d(kernel(), (p[k].y - face.y) / kDx);
          if (a < 0 || b < 0 || a >= s || b >= s) {
            EXPECT_NEAR(expected, 0.0, 2e-14) << "marker " << k << (on_u ? " u" : " v") << " face " << i << "," << j;
            continue;
          }
          const double w = st.wx[a] * st.wy[b];
          EXPECT_NEAR(w, expected, 2e-14) << "marker " << k << (on_u ? " u" : " v") << " face " << i << "," << j;
          sum += w;
          squares += w * w;
        }
      }
      EXPECT_NEAR(sum, 1.0, 1e-15) << "marker " << k;
      if (kernel() == Kernel::peskin4) {
        EXPECT_NEAR(squares, 9.0 / 64.0, 1e-15) << "marker " << k;
      }
    }
  }
}

// A marker on a u face: its x force lands on that face with weight phi(0)² (1 for bilinear),
// its y force on the v faces around it at (±1/2, ±1/2) cells, each phi(1/2)².
TEST_P(TransferTest, MarkerOnAFaceSpreadsTheAnalyticDensity) {
  const double dx = 0x1.0p-7;  // a power of two: the face positions and every weight are exact
  const MacGrid2 grid(kNx, kNy, dx);
  const std::vector<Vec2> p{grid.uPosition_m(6, 9)};
  const std::vector<Vec2> f{{2.0, -3.0}};
  Transfer transfer;
  transfer.locate(grid, kernel(), p);
  FaceVectorField2 density(kNx, kNy);
  transfer.spread(f, density);
  const double area = dx * dx;
  const double phi0 = kernelWeight_1d(kernel(), 0.0), phi_half = kernelWeight_1d(kernel(), 0.5);
  EXPECT_DOUBLE_EQ(density.x(6, 9), 2.0 * phi0 * phi0 / area);
  for (int i : {5, 6})
    for (int j : {9, 10}) EXPECT_DOUBLE_EQ(density.y(i, j), -3.0 * phi_half * phi_half / area);
  if (kernel() == Kernel::bilinear) {  // the whole force on one u face, a quarter on each of four v faces
    EXPECT_EQ(density.x(6, 9), 2.0 / area);
    EXPECT_EQ(density.x(5, 9), 0.0);
    EXPECT_EQ(density.x(6, 10), 0.0);
    EXPECT_EQ(density.y(5, 9), -0.75 / area);
    EXPECT_EQ(density.y(4, 9), 0.0);
  }
}

// dx² Σ_faces f = Σ_k F_k per component, to 1e-13 of Σ_k |F_k|.
TEST_P(TransferTest, SpreadingConservesTheTotalForce) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const std::vector<Vec2> p = markers(kernel(), 100 + seed);
    const std::vector<Vec2> f = random_vectors(200 + seed, kTransferMarkers, 3.0);
    Transfer transfer;
    transfer.locate(grid_, kernel(), p);
    FaceVectorField2 density(kNx, kNy);
    transfer.spread(f, density);
    CompensatedSum fx, fy, gx, gy;
    double scale_x = 0.0, scale_y = 0.0;
    for (const Vec2& v : f) {
      fx.add(v.x), fy.add(v.y);
      scale_x += std::abs(v.x), scale_y += std::abs(v.y);
    }
    for (std::size_t n = 0; n < density.x.size(); ++n) gx.add(density.x.data()[n] * kDx * kDx);
    for (std::size_t n = 0; n < density.y.size(); ++n) gy.add(density.y.data()[n] * kDx * kDx);
    EXPECT_NEAR(gx.value(), fx.value(), 1e-13 * scale_x) << "seed " << seed;
    EXPECT_NEAR(gy.value(), fy.value(), 1e-13 * scale_y) << "seed " << seed;
  }
}

// Faces on the walls (u at i = 0, nx; v at j = 0, ny) never receive weight, even from markers
// as close to the walls as allowed; every stencil stays on interior faces.
TEST_P(TransferTest, WallFacesReceiveNothing) {
  const double margin = 0.5 * support() * kDx, inset = 1e-9 * kDx;
  const double w = kNx * kDx, h = kNy * kDx;
  std::vector<Vec2> p{{margin, margin},         {w - margin - inset, margin}, {margin, h - margin - inset},
                      {w - margin - inset, h - margin - inset}, {margin, 0.5 * h},   {0.5 * w, margin}};
  for (const Vec2& q : markers(kernel(), 31, 100)) p.push_back(q);
  const std::vector<Vec2> f = random_vectors(32, static_cast<int>(p.size()), 1.0);
  Transfer transfer;
  transfer.locate(grid_, kernel(), p);
  FaceVectorField2 density(kNx, kNy);
  transfer.spread(f, density);
  for (int j = 0; j < kNy; ++j) {
    EXPECT_EQ(density.x(0, j), 0.0);
    EXPECT_EQ(density.x(kNx, j), 0.0);
  }
  for (int i = 0; i < kNx; ++i) {
    EXPECT_EQ(density.y(i, 0), 0.0);
    EXPECT_EQ(density.y(i, kNy), 0.0);
  }
  EXPECT_NE(density.x(support() / 2, support() / 2), 0.0);  // the corner marker did spread
  for (int k = 0; k < transfer.markerCount(); ++k) {
    const FaceStencil& u = transfer.uStencil(k);
    const FaceStencil& v = transfer.vStencil(k);
    EXPECT_GE(u.i0, 1);
    EXPECT_LE(u.i0 + support() - 1, kNx - 1);
    EXPECT_GE(u.j0, 0);
    EXPECT_LE(u.j0 + support() - 1, kNy - 1);
    EXPECT_GE(v.i0, 0);
    EXPECT_LE(v.i0 + support() - 1, kNx - 1);
    EXPECT_GE(v.j0, 1);
    EXPECT_LE(v.j0 + support() - 1, kNy - 1);
  }
}

// spread() adds to what the field holds.
TEST_P(TransferTest, SpreadAddsToTheField) {
  const std::vector<Vec2> p = markers(kernel(), 41);
  const std::vector<Vec2> f = random_vectors(42, kTransferMarkers, 1.0);
  Transfer transfer;
  transfer.locate(grid_, kernel(), p);
  FaceVectorField2 alone(kNx, kNy), on_top(kNx, kNy);
  on_top.fill(5.0);
  transfer.spread(f, alone);
  transfer.spread(f, on_top);
  for (std::size_t n = 0; n < alone.x.size(); ++n) EXPECT_NEAR(on_top.x.data()[n] - 5.0, alone.x.data()[n], 1e-9);
  for (std::size_t n = 0; n < alone.y.size(); ++n) EXPECT_NEAR(on_top.y.data()[n] - 5.0, alone.y.data()[n], 1e-9);
}

// u = a + b x + c y and v = d + e x + f y on the faces interpolate to the same formula at each
// marker: both kernels have a zero first moment.
TEST_P(TransferTest, InterpolationIsExactForLinearFields) {
  std::mt19937_64 rng(51);
  for (int trial = 0; trial < 5; ++trial) {
    const double a = uniform(rng, -1, 1), b = uniform(rng, -5, 5), c = uniform(rng, -5, 5);
    const double d = uniform(rng, -1, 1), e = uniform(rng, -5, 5), g = uniform(rng, -5, 5);
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i <= kNx; ++i) {
        const Vec2 x = grid_.uPosition_m(i, j);
        grid_.u_m_per_s(i, j) = a + b * x.x + c * x.y;
      }
    for (int j = 0; j <= kNy; ++j)
      for (int i = 0; i < kNx; ++i) {
        const Vec2 x = grid_.vPosition_m(i, j);
        grid_.v_m_per_s(i, j) = d + e * x.x + g * x.y;
      }
    const std::vector<Vec2> p = markers(kernel(), 52 + trial);
    Transfer transfer;
    transfer.locate(grid_, kernel(), p);
    std::vector<Vec2> velocity(p.size(), Vec2{std::nan(""), std::nan("")});
    transfer.interpolate(grid_, velocity);
    const double scale = std::abs(a) + std::abs(b) * kNx * kDx + std::abs(c) * kNy * kDx +  //
                         std::abs(d) + std::abs(e) * kNx * kDx + std::abs(g) * kNy * kDx;
    for (std::size_t k = 0; k < p.size(); ++k) {
      EXPECT_NEAR(velocity[k].x, a + b * p[k].x + c * p[k].y, 1e-13 * scale) << "marker " << k;
      EXPECT_NEAR(velocity[k].y, d + e * p[k].x + g * p[k].y, 1e-13 * scale) << "marker " << k;
    }
  }
}

// The kernel stretched to 2 and 4 cells per kernel unit (a fixed physical width on a finer grid,
// Transfer::locate's kernel_scale): the total force is conserved, a linear field is interpolated
// exactly, spreading is the adjoint of interpolation, and the Gram matrix is interpolate(spread).
TEST_P(TransferTest, StretchedKernelKeepsConservationExactnessAndAdjointness) {
  std::mt19937_64 rng(91);
  for (int scale : {2, 4}) {
    const double margin = 0.5 * scale * support() * kDx;
    const double inset = 1e-9 * kDx;
    std::vector<Vec2> p;
    for (int k = 0; k < 60; ++k)
      p.push_back({uniform(rng, margin, kNx * kDx - margin - inset), uniform(rng, margin, kNy * kDx - margin - inset)});
    const std::vector<Vec2> f = random_vectors(92 + scale, static_cast<int>(p.size()), 1.0);
    Transfer transfer;
    transfer.locate(grid_, kernel(), p, scale);
    ASSERT_EQ(transfer.stencilFaces(), scale * support());
    ASSERT_EQ(transfer.kernelScale(), scale);

    FaceVectorField2 density(kNx, kNy);
    transfer.spread(f, density);
    CompensatedSum fx, fy, want_x, want_y;
    for (std::size_t n = 0; n < density.x.size(); ++n) fx.add(kDx * kDx * density.x.data()[n]);
    for (std::size_t n = 0; n < density.y.size(); ++n) fy.add(kDx * kDx * density.y.data()[n]);
    for (const Vec2& v : f) want_x.add(v.x), want_y.add(v.y);
    EXPECT_NEAR(fx.value(), want_x.value(), 1e-13) << "scale " << scale;
    EXPECT_NEAR(fy.value(), want_y.value(), 1e-13) << "scale " << scale;

    const double a = 0.3, b = -2.0, c = 1.5, d = -0.7, e = 4.0, g = 0.25;
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i <= kNx; ++i) {
        const Vec2 x = grid_.uPosition_m(i, j);
        grid_.u_m_per_s(i, j) = a + b * x.x + c * x.y;
      }
    for (int j = 0; j <= kNy; ++j)
      for (int i = 0; i < kNx; ++i) {
        const Vec2 x = grid_.vPosition_m(i, j);
        grid_.v_m_per_s(i, j) = d + e * x.x + g * x.y;
      }
    std::vector<Vec2> velocity(p.size());
    transfer.interpolate(grid_, velocity);
    for (std::size_t k = 0; k < p.size(); ++k) {
      EXPECT_NEAR(velocity[k].x, a + b * p[k].x + c * p[k].y, 1e-13) << "scale " << scale << ", marker " << k;
      EXPECT_NEAR(velocity[k].y, d + e * p[k].x + g * p[k].y, 1e-13) << "scale " << scale << ", marker " << k;
    }

    fill_random(grid_.u_m_per_s, rng, 0.3);
    fill_random(grid_.v_m_per_s, rng, 0.3);
    transfer.interpolate(grid_, velocity);
    CompensatedSum grid_side, marker_side;
    for (std::size_t n = 0; n < density.x.size(); ++n)
      grid_side.add(kDx * kDx * density.x.data()[n] * grid_.u_m_per_s.data()[n]);
    for (std::size_t n = 0; n < density.y.size(); ++n)
      grid_side.add(kDx * kDx * density.y.data()[n] * grid_.v_m_per_s.data()[n]);
    for (std::size_t k = 0; k < p.size(); ++k) marker_side.add(f[k].x * velocity[k].x + f[k].y * velocity[k].y);
    EXPECT_NEAR(grid_side.value(), marker_side.value(), 1e-13) << "scale " << scale;

    // G F / dx² = interpolate(spread(F)) on the located stencils.
    grid_.u_m_per_s = density.x;
    grid_.v_m_per_s = density.y;
    transfer.interpolate(grid_, velocity);
    Eigen::MatrixXd gram;
    transfer.gram(gram);
    Eigen::VectorXd fv(2 * p.size());
    for (std::size_t k = 0; k < p.size(); ++k) fv[2 * k] = f[k].x, fv[2 * k + 1] = f[k].y;
    const Eigen::VectorXd via_gram = gram * fv / (kDx * kDx);
    for (std::size_t k = 0; k < p.size(); ++k) {
      EXPECT_NEAR(via_gram[2 * k], velocity[k].x, 1e-9 * via_gram.cwiseAbs().maxCoeff()) << "scale " << scale;
      EXPECT_NEAR(via_gram[2 * k + 1], velocity[k].y, 1e-9 * via_gram.cwiseAbs().maxCoeff()) << "scale " << scale;
    }
  }
}

// Markers of two widths in one locate (a filament beside a wider body): each narrow marker spreads and
// interpolates exactly as it would located alone at its own stretch, the wide ones as at theirs, and G
// is the gram of the mixed stencils (interpolate(spread(F)) = G F / dx²).
TEST_P(TransferTest, MixedKernelWidthsActAsEachMarkersOwnKernel) {
  std::mt19937_64 rng(93);
  const double margin = 0.5 * 2 * support() * kDx;
  const double inset = 1e-9 * kDx;
  std::vector<Vec2> p;
  std::vector<int> scales;
  for (int k = 0; k < 40; ++k) {
    p.push_back({uniform(rng, margin, kNx * kDx - margin - inset), uniform(rng, margin, kNy * kDx - margin - inset)});
    scales.push_back(k % 3 == 0 ? 2 : 1);
  }
  const std::vector<Vec2> f = random_vectors(94, static_cast<int>(p.size()), 1.0);
  Transfer mixed;
  mixed.locate(grid_, kernel(), p, 1, scales);
  ASSERT_EQ(mixed.stencilFaces(), 2 * support());
  FaceVectorField2 density(kNx, kNy);
  mixed.spread(f, density);
  // The same spread, marker by marker, each alone at its own stretch.
  FaceVectorField2 alone(kNx, kNy);
  for (std::size_t k = 0; k < p.size(); ++k) {
    Transfer one;
    one.locate(grid_, kernel(), std::span<const Vec2>(&p[k], 1), scales[k]);
    one.spread(std::span<const Vec2>(&f[k], 1), alone);
  }
  for (std::size_t n = 0; n < density.x.size(); ++n) EXPECT_NEAR(density.x.data()[n], alone.x.data()[n], 1e-9);
  for (std::size_t n = 0; n < density.y.size(); ++n) EXPECT_NEAR(density.y.data()[n], alone.y.data()[n], 1e-9);

  fill_random(grid_.u_m_per_s, rng, 0.3);
  fill_random(grid_.v_m_per_s, rng, 0.3);
  std::vector<Vec2> velocity(p.size());
  mixed.interpolate(grid_, velocity);
  for (std::size_t k = 0; k < p.size(); ++k) {
    Transfer one;
    one.locate(grid_, kernel(), std::span<const Vec2>(&p[k], 1), scales[k]);
    Vec2 v;
    one.interpolate(grid_, std::span<Vec2>(&v, 1));
    EXPECT_DOUBLE_EQ(velocity[k].x, v.x) << "marker " << k;
    EXPECT_DOUBLE_EQ(velocity[k].y, v.y) << "marker " << k;
  }

  grid_.u_m_per_s = density.x;
  grid_.v_m_per_s = density.y;
  mixed.interpolate(grid_, velocity);
  Eigen::MatrixXd gram;
  mixed.gram(gram);
  Eigen::VectorXd fv(2 * p.size());
  for (std::size_t k = 0; k < p.size(); ++k) fv[2 * k] = f[k].x, fv[2 * k + 1] = f[k].y;
  const Eigen::VectorXd via_gram = gram * fv / (kDx * kDx);
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_NEAR(via_gram[2 * k], velocity[k].x, 1e-9 * via_gram.cwiseAbs().maxCoeff());
    EXPECT_NEAR(via_gram[2 * k + 1], velocity[k].y, 1e-9 * via_gram.cwiseAbs().maxCoeff());
  }
  EXPECT_THROW(mixed.locate(grid_, kernel(), p, 1, std::vector<int>(3, 1)), std::invalid_argument);
}

// dx² <S F, u> = Σ_k F_k · (I u)_k for random forces and random (not smooth) fields.
TEST_P(TransferTest, SpreadIsTheAdjointOfInterpolation) {
  std::mt19937_64 rng(61);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const std::vector<Vec2> p = markers(kernel(), 62 + seed);
    const std::vector<Vec2> f = random_vectors(70 + seed, kTransferMarkers, 2.0);
    fill_random(grid_.u_m_per_s, rng, 0.3);
    fill_random(grid_.v_m_per_s, rng, 0.3);
    Transfer transfer;
    transfer.locate(grid_, kernel(), p);
    FaceVectorField2 density(kNx, kNy);
    transfer.spread(f, density);
    std::vector<Vec2> velocity(p.size());
    transfer.interpolate(grid_, velocity);

    CompensatedSum grid_side, marker_side;
    double scale = 0.0;
    for (std::size_t n = 0; n < density.x.size(); ++n)
      grid_side.add(kDx * kDx * density.x.data()[n] * grid_.u_m_per_s.data()[n]);
    for (std::size_t n = 0; n < density.y.size(); ++n)
      grid_side.add(kDx * kDx * density.y.data()[n] * grid_.v_m_per_s.data()[n]);
    for (std::size_t k = 0; k < p.size(); ++k) {
      marker_side.add(f[k].x * velocity[k].x);
      marker_side.add(f[k].y * velocity[k].y);
      scale += (std::abs(f[k].x) + std::abs(f[k].y)) * 0.3;
    }
    EXPECT_NEAR(grid_side.value(), marker_side.value(), 1e-14 * scale) << "seed " << seed;
  }
}

// The same markers give bitwise the same stencils, densities and velocities, whether the
// Transfer is fresh or reused after locating a different number of markers.
TEST_P(TransferTest, ReusedTransferIsBitwiseDeterministic) {
  const std::vector<Vec2> p = markers(kernel(), 81);
  const std::vector<Vec2> fewer = markers(kernel(), 82, 40);
  const std::vector<Vec2> f = random_vectors(83, kTransferMarkers, 1.0);
  std::mt19937_64 rng(84);
  fill_random(grid_.u_m_per_s, rng, 1.0);
  fill_random(grid_.v_m_per_s, rng, 1.0);

  Transfer fresh, reused;
  fresh.locate(grid_, kernel(), p);
  reused.locate(grid_, kernel(), p);
  reused.locate(grid_, kernel(), fewer);
  EXPECT_EQ(reused.markerCount(), 40);
  reused.locate(grid_, kernel(), p);

  FaceVectorField2 d1(kNx, kNy), d2(kNx, kNy);
  fresh.spread(f, d1);
  reused.spread(f, d2);
  EXPECT_TRUE(d1.x == d2.x && d1.y == d2.y);
  std::vector<Vec2> v1(p.size()), v2(p.size());
  fresh.interpolate(grid_, v1);
  reused.interpolate(grid_, v2);
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_EQ(v1[k].x, v2[k].x);
    EXPECT_EQ(v1[k].y, v2[k].y);
  }
}

// A marker closer to any wall than the kernel reaches is refused, naming its index and place.
TEST_P(TransferTest, MarkerTooCloseToAWallThrowsNamingIt) {
  // A hair closer than support/2 cells to each wall. (Exactly support/2 cells is on the rounding
  // edge of floor(x / dx) and not tested.)
  const double too_close = 0.5 * support() * kDx * (1.0 - 1e-9);
  const double w = kNx * kDx, h = kNy * kDx;
  const std::string reach = support() == 2 ? "within 1 cell of the domain wall" : "within 2 cells of the domain wall";
  for (Vec2 bad : {Vec2{too_close, 0.5 * h}, Vec2{w - too_close, 0.5 * h}, Vec2{0.5 * w, too_close},
                   Vec2{0.5 * w, h - too_close}, Vec2{-0.5, 0.5 * h}, Vec2{0.5 * w, 7.0}, Vec2{1e300, -1e300}}) {
    std::vector<Vec2> p = markers(kernel(), 91, 20);
    p[12] = bad;
    Transfer transfer;
    try {
      transfer.locate(grid_, kernel(), p);
      ADD_FAILURE() << "no error for a marker at (" << bad.x << ", " << bad.y << ")";
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("immersed-boundary marker 12 at ("), std::string::npos) << message;
      EXPECT_NE(message.find(reach), std::string::npos) << message;
      EXPECT_NE(message.find(std::string(to_string(kernel()))), std::string::npos) << message;
    }
    EXPECT_EQ(transfer.markerCount(), 0);
  }
  // The example of the brief: a marker 0.31 cells from the left wall of a 0.4 m box of 100 cells.
  MacGrid2 box(100, 100, 0.004);
  const std::vector<Vec2> p{{0.2, 0.2}, {0.0031, 0.2}};
  Transfer transfer;
  try {
    transfer.locate(box, kernel(), p);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()).rfind("immersed-boundary marker 1 at (0.0031, 0.2) m is " + reach, 0), 0u)
        << error.what();
  }
}

TEST_P(TransferTest, NonFinitePositionThrowsNamingTheMarker) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (Vec2 bad : {Vec2{nan, 0.05}, Vec2{0.05, nan}, Vec2{inf, 0.05}, Vec2{0.05, -inf}}) {
    std::vector<Vec2> p = markers(kernel(), 95, 10);
    p[3] = bad;
    Transfer transfer;
    try {
      transfer.locate(grid_, kernel(), p);
      ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("immersed-boundary marker 3 at ("), std::string::npos) << message;
      EXPECT_NE(message.find("is not finite"), std::string::npos) << message;
    }
  }
}

TEST_P(TransferTest, MismatchedSizesAndGridsThrow) {
  const std::vector<Vec2> p = markers(kernel(), 97, 10);
  Transfer transfer;
  transfer.locate(grid_, kernel(), p);
  FaceVectorField2 density(kNx, kNy);
  std::vector<Vec2> too_few(9), velocity(10);
  EXPECT_THROW(transfer.spread(too_few, density), std::invalid_argument);
  EXPECT_THROW(transfer.interpolate(grid_, too_few), std::invalid_argument);
  FaceVectorField2 wrong_shape(kNx, kNy + 1);
  EXPECT_THROW(transfer.spread(std::vector<Vec2>(10), wrong_shape), std::invalid_argument);
  const MacGrid2 other(kNx + 1, kNy, kDx);
  EXPECT_THROW(transfer.interpolate(other, velocity), std::invalid_argument);
  EXPECT_THROW(transfer.locate(MacGrid2(kNx, kNy, 0.0), kernel(), p), std::invalid_argument);
  EXPECT_EQ(transfer.markerCount(), 0);
  // No markers: nothing to do, whatever the field.
  transfer.spread({}, wrong_shape);
  transfer.interpolate(other, {});
}

// Why the bell's segment count matters under the hat and hardly under Peskin's function (issue
// 13, experiments/jellyfish/convergence_fine.toml): a marker chain moves with the interpolated
// velocity, so its curvature changes at the rate of that velocity's second derivative along the
// chain. The hat's interpolant is only continuous (its slope jumps wherever a stencil edge crosses
// a face, stretched or not), so the second difference along the chain, (U_{k+1} − 2U_k + U_{k−1})
// / h², has spikes that grow as 1/h: a kink per face crossing that denser markers resolve ever more
// sharply and the chain's bending springs (B / h per joint) resist ever more. Peskin's 4-point
// function is C¹ with a bounded second derivative, so its second difference converges as h
// shrinks. Here: a smooth field, a chain slanted across the grid at spacings dx/8 to dx/512.
TEST(TransferSmoothness, SecondDifferenceAlongAChainGrowsAsOneOverSpacingOnlyForTheHat) {
  MacGrid2 grid(kNx, kNy, kDx);
  const double wave_m = 8 * kDx;
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i <= kNx; ++i) grid.u_m_per_s(i, j) = std::sin(2 * M_PI * grid.uPosition_m(i, j).x / wave_m);
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i < kNx; ++i) grid.v_m_per_s(i, j) = std::cos(2 * M_PI * grid.vPosition_m(i, j).y / wave_m);

  // Largest |second difference| of the interpolated velocity along the chain, 1/(m s).
  auto peak_second_difference = [&](Kernel kernel, int scale, int per_cell) {
    const double h = kDx / per_cell, angle = 0.3;
    std::vector<Vec2> chain;
    for (int k = 0; k <= 8 * per_cell; ++k)
      chain.push_back({6.13 * kDx + k * h * std::cos(angle), 5.37 * kDx + k * h * std::sin(angle)});
    Transfer transfer;
    transfer.locate(grid, kernel, chain, scale);
    std::vector<Vec2> velocity(chain.size());
    transfer.interpolate(grid, velocity);
    double peak = 0;
    for (std::size_t k = 1; k + 1 < chain.size(); ++k)
      for (double Vec2::*c : {&Vec2::x, &Vec2::y})
        peak = std::max(peak, std::abs(velocity[k + 1].*c - 2 * velocity[k].*c + velocity[k - 1].*c) / (h * h));
    return peak;
  };
  // The hat's peak grows more than tenfold from dx/8 to dx/128 (stretched or not); Peskin's levels off.
  // (The field's own second derivative is at most (2π / 8 dx)² ≈ 617: neither kernel reproduces it
  // at the grid scale, but only the hat's grows without bound.)
  for (int scale : {1, 2}) {
    const double coarse = peak_second_difference(Kernel::bilinear, scale, 8);
    const double mid = peak_second_difference(Kernel::bilinear, scale, 32);
    const double fine = peak_second_difference(Kernel::bilinear, scale, 128);
    EXPECT_GT(mid, 3 * coarse) << "hat, scale " << scale;  // about 4x per 4x denser chain: as 1/h
    EXPECT_GT(fine, 3 * mid) << "hat, scale " << scale;
  }
  const double fine = peak_second_difference(Kernel::peskin4, 1, 128);
  const double finer = peak_second_difference(Kernel::peskin4, 1, 512);
  EXPECT_NEAR(finer, fine, 0.03 * fine);
  EXPECT_LT(fine, 0.1 * peak_second_difference(Kernel::bilinear, 1, 128));
}

INSTANTIATE_TEST_SUITE_P(Kernels, TransferTest, ::testing::Values(Kernel::bilinear, Kernel::peskin4),
                         [](const ::testing::TestParamInfo<Kernel>& tested) { return std::string(to_string(tested.param)); });

}  // namespace
}  // namespace creaturelab::ib
