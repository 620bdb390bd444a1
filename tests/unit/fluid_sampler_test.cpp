// The sampler's lanes (fluid/staggered_sampler2.hpp): its two-, four- and eight-lane interpolations promise
// the scalar sample()'s arithmetic in every lane, so that advection's results do not depend on how
// faces are grouped (row tails, thread pieces; DESIGN.md's determinism). The threads test compares
// whole runs; this one compares single samples bit for bit at positions that reach every branch:
// inside the domain, whole numbers and halves, its edges and corners, beyond it, ±∞, NaN and −0,
// four or eight neighbouring stencils in a row (the contiguous loads) and scattered ones (the gather),
// with and without the limiter's bounds, on both components. The wide lanes are compiled with the
// fluid library's instruction set (tests/unit/fluid.cmake: CREATURELAB_FLUID_SIMD_FLAGS, -mavx2 and,
// where the machine runs it, -mavx512f).
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "fluid/staggered_sampler2.hpp"

namespace creaturelab::fluid {
namespace {

constexpr int kNx = 13;  // odd sizes: rows are not a multiple of the lanes
constexpr int kNy = 9;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A component on `axis` faces of a kNx × kNy grid, random values (no two alike), free-slip walls.
StaggeredComponent2 component(FaceAxis axis, unsigned seed) {
  Array2 values(axis == FaceAxis::x ? kNx + 1 : kNx, axis == FaceAxis::x ? kNy : kNy + 1);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int j = 0; j < values.ny(); ++j) {
    for (int i = 0; i < values.nx(); ++i) values(i, j) = value(rng);
  }
  StaggeredComponent2 c;
  c.assign(axis, values, Walls{});
  return c;
}

struct Position {
  double x, y;
};

constexpr int kGroup = 8;  // the widest sampler's lanes
using Group = std::array<Position, kGroup>;

// Groups of eight positions (cell units) that reach every branch of the samplers.
std::vector<Group> groups() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Group> out;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  std::uniform_real_distribution<double> wide_x(-2.0, kNx + 2.0), wide_y(-2.0, kNy + 2.0);
  // Eight neighbouring stencils in a row, as a row of faces traced a fraction of a cell: contiguous
  // (those that run past the domain's edge are clamped, and four of them are still in a row).
  for (int j = 0; j <= kNy; ++j) {
    for (int i = -1; i <= kNx; ++i) {
      const double fx = fraction(rng), y = j + fraction(rng);
      Group g;
      for (int k = 0; k < kGroup; ++k) g[k] = {i + k + fx, y};
      out.push_back(g);
    }
  }
  // Scattered positions, inside and beyond the domain: the gather.
  for (int k = 0; k < 400; ++k) {
    Group g;
    for (Position& p : g) p = {wide_x(rng), wide_y(rng)};
    out.push_back(g);
  }
  // Whole numbers and halves (stencil edges, where truncation decides the stencil).
  for (int j = 0; j <= 2 * kNy; ++j) {
    for (int i = 0; i <= 2 * kNx; i += 4) {
      Group g;
      for (int k = 0; k < kGroup; ++k) g[k] = {0.5 * (i + k), 0.5 * j};
      out.push_back(g);
    }
  }
  // The domain's edges and corners, just inside and beyond, infinities, NaN and negative zero.
  const double x_max = kNx, y_max = kNy;
  const double below = std::nextafter(x_max, 0.0), beyond = std::nextafter(x_max, 2 * x_max);
  const Group edges{{{0.0, 0.0}, {x_max, 0.0}, {0.0, y_max}, {x_max, y_max}, {below, std::nextafter(y_max, 0.0)},
                     {beyond, std::nextafter(y_max, 2 * y_max)}, {-0.0, -0.0}, {-1e-300, 1e-300}}};
  const Group specials{{{nan, 1.5}, {2.5, nan}, {nan, nan}, {inf, -inf}, {-inf, inf}, {1e300, -1e300}, {-0.0, 3.25},
                        {4.75, -0.0}}};
  out.push_back(edges);
  out.push_back(specials);
  // The same values in other lanes (the upper halves of the wide samplers).
  for (const Group* g : {&edges, &specials}) {
    Group rotated;
    for (int k = 0; k < kGroup; ++k) rotated[k] = (*g)[(k + kGroup / 2) % kGroup];
    out.push_back(rotated);
  }
  return out;
}

struct Scalar {
  std::array<double, kGroup> value, bounded, lo, hi;
};

Scalar scalar_samples(const SampleView& view, const Group& g) {
  Scalar s;
  for (int k = 0; k < kGroup; ++k) {
    s.value[k] = view.sample(g[k].x, g[k].y);
    s.bounded[k] = view.sample(g[k].x, g[k].y, s.lo[k], s.hi[k]);
  }
  return s;
}

void expect_lanes(const char* what, const Group& g, const double* expected, const double* got,
                  int lanes, int first) {
  for (int k = 0; k < lanes; ++k) {
    EXPECT_TRUE(same_bits(expected[first + k], got[k]))
        << what << " at (" << g[first + k].x << ", " << g[first + k].y << "): lane " << got[k] << ", scalar "
        << expected[first + k];
  }
}

template <FaceAxis kAxis>
void compare_lanes(const SampleView& view) {
  int four_lane_groups = 0, eight_lane_groups = 0;
  for (const auto& g : groups()) {
    const Scalar s = scalar_samples(view, g);
    // The unbounded and the bounded scalar paths are written apart (SSE2 pairs and plain doubles).
    expect_lanes("bounded scalar", g, s.value.data(), s.bounded.data(), kGroup, 0);
#if defined(__SSE2__)
    for (int first = 0; first < kGroup; first += 2) {
      const __m128d X = _mm_set_pd(g[first + 1].x, g[first].x);
      const __m128d Y = _mm_set_pd(g[first + 1].y, g[first].y);
      std::array<double, 2> value{}, lo{}, hi{};
      _mm_storeu_pd(value.data(), view.sample2On<kAxis>(X, Y));
      expect_lanes("two lanes", g, s.value.data(), value.data(), 2, first);
      __m128d lo2, hi2;
      _mm_storeu_pd(value.data(), view.sample2On<kAxis>(X, Y, &lo2, &hi2));
      _mm_storeu_pd(lo.data(), lo2);
      _mm_storeu_pd(hi.data(), hi2);
      expect_lanes("two lanes, bounded", g, s.value.data(), value.data(), 2, first);
      expect_lanes("two lanes' lower bound", g, s.lo.data(), lo.data(), 2, first);
      expect_lanes("two lanes' upper bound", g, s.hi.data(), hi.data(), 2, first);
    }
#endif
#if defined(__AVX2__)
    for (int first : {0, 4}) {
      const __m256d X = _mm256_set_pd(g[first + 3].x, g[first + 2].x, g[first + 1].x, g[first].x);
      const __m256d Y = _mm256_set_pd(g[first + 3].y, g[first + 2].y, g[first + 1].y, g[first].y);
      std::array<double, 4> value{}, lo{}, hi{};
      _mm256_storeu_pd(value.data(), view.sample4On<kAxis>(X, Y));
      expect_lanes("four lanes", g, s.value.data(), value.data(), 4, first);
      __m256d lo4, hi4;
      _mm256_storeu_pd(value.data(), view.sample4On<kAxis>(X, Y, &lo4, &hi4));
      _mm256_storeu_pd(lo.data(), lo4);
      _mm256_storeu_pd(hi.data(), hi4);
      expect_lanes("four lanes, bounded", g, s.value.data(), value.data(), 4, first);
      expect_lanes("four lanes' lower bound", g, s.lo.data(), lo.data(), 4, first);
      expect_lanes("four lanes' upper bound", g, s.hi.data(), hi.data(), 4, first);
      ++four_lane_groups;
    }
#endif
#if defined(__AVX512F__)
    {
      std::array<double, kGroup> xs{}, ys{}, value{}, lo{}, hi{};
      for (int k = 0; k < kGroup; ++k) xs[k] = g[k].x, ys[k] = g[k].y;
      const __m512d X = _mm512_loadu_pd(xs.data());
      const __m512d Y = _mm512_loadu_pd(ys.data());
      _mm512_storeu_pd(value.data(), view.sample8On<kAxis>(X, Y));
      expect_lanes("eight lanes", g, s.value.data(), value.data(), kGroup, 0);
      __m512d lo8, hi8;
      _mm512_storeu_pd(value.data(), view.sample8On<kAxis>(X, Y, &lo8, &hi8));
      _mm512_storeu_pd(lo.data(), lo8);
      _mm512_storeu_pd(hi.data(), hi8);
      expect_lanes("eight lanes, bounded", g, s.value.data(), value.data(), kGroup, 0);
      expect_lanes("eight lanes' lower bound", g, s.lo.data(), lo.data(), kGroup, 0);
      expect_lanes("eight lanes' upper bound", g, s.hi.data(), hi.data(), kGroup, 0);
      ++eight_lane_groups;
    }
#endif
    if (::testing::Test::HasFailure()) return;  // one group's report is enough
  }
#if defined(__AVX2__)
  EXPECT_GT(four_lane_groups, 1000);
#endif
#if defined(__AVX512F__)
  EXPECT_GT(eight_lane_groups, 500);
#endif
}

TEST(FluidSampler, LanesGiveTheScalarBitsOnUFaces) { compare_lanes<FaceAxis::x>(component(FaceAxis::x, 1).view()); }

TEST(FluidSampler, LanesGiveTheScalarBitsOnVFaces) { compare_lanes<FaceAxis::y>(component(FaceAxis::y, 2).view()); }

// The test reaches both load paths of the four- and the eight-lane sampler only if some groups are
// contiguous and some are not: a guard against groups() drifting into one case.
TEST(FluidSampler, GroupsReachTheContiguousAndTheGatheredLoads) {
  const SampleView view = component(FaceAxis::x, 3).view();
  for (int lanes : {4, 8}) {
    int contiguous = 0, scattered = 0;
    for (const auto& g : groups()) {
      double tx = 0.0, ty = 0.0;
      const double* first = view.locate(g[0].x, g[0].y, tx, ty);
      bool in_a_row = true;
      for (int k = 1; k < lanes; ++k) in_a_row = in_a_row && view.locate(g[k].x, g[k].y, tx, ty) == first + k;
      (in_a_row ? contiguous : scattered) += 1;
    }
    EXPECT_GT(contiguous, 50) << lanes << " lanes";
    EXPECT_GT(scattered, 50) << lanes << " lanes";
  }
}

}  // namespace
}  // namespace creaturelab::fluid
