#pragma once
// Bilinear interpolation of face-centred (staggered) fields with wall ghost values.
//
// Each component is copied once into an array padded with one ghost layer across the two
// walls it is tangential to (see boundary2.hpp), so that sampling anywhere in the closed
// domain is a branch-free bilinear interpolation. Positions outside the domain are clamped to
// it. Interpolation is written as a + t (b − a), so a uniform field is reproduced exactly.

#include <algorithm>

#if defined(__AVX2__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "fluid/array2.hpp"
#include "fluid/boundary2.hpp"
#include "fluid/fluid_params.hpp"
#include "fluid/mac_grid2.hpp"

namespace creaturelab::fluid {

/// Which faces a component lives on: x = u faces (normal along x), y = v faces.
enum class FaceAxis { x, y };

/// Plain-data view of a padded component, for tight sampling loops (kept in registers).
struct SampleView {
  const double* data = nullptr;
  long stride = 0;
  double offset_x = 0.0, offset_y = 0.0;  // cell units → padded index space
  double x_max = 0.0, y_max = 0.0;        // domain, cell units
  int i_max = 0, j_max = 0;               // largest lower-left index of a stencil

  // Lower-left stencil value and fractions for (X, Y) in cell units, clamped to the domain.
  // Each clamp is one max and one min written so that NaN lands on 0 (maxsd semantics)
  // instead of producing an out-of-range index.
  const double* locate(double X, double Y, double& tx, double& ty) const {
    X = X > 0.0 ? X : 0.0;
    X = X < x_max ? X : x_max;
    Y = Y > 0.0 ? Y : 0.0;
    Y = Y < y_max ? Y : y_max;
    const double fx = X + offset_x;
    const double fy = Y + offset_y;
    const int i0 = std::min(static_cast<int>(fx), i_max);
    const int j0 = std::min(static_cast<int>(fy), j_max);
    tx = fx - i0;
    ty = fy - j0;
    return data + static_cast<long>(j0) * stride + i0;
  }

  /// Bilinear interpolation a + t (b − a): along y on both columns at once (one SSE2 pair
  /// per row), then along x.
  double sample(double X, double Y) const {
    double tx = 0.0, ty = 0.0;
    const double* r0 = locate(X, Y, tx, ty);
#if defined(__SSE2__)
    const __m128d low = _mm_loadu_pd(r0);
    const __m128d high = _mm_loadu_pd(r0 + stride);
    const __m128d column = _mm_add_pd(low, _mm_mul_pd(_mm_set1_pd(ty), _mm_sub_pd(high, low)));
    const double left = _mm_cvtsd_f64(column);
    const double right = _mm_cvtsd_f64(_mm_unpackhi_pd(column, column));
#else
    const double* r1 = r0 + stride;
    const double left = r0[0] + ty * (r1[0] - r0[0]);
    const double right = r0[1] + ty * (r1[1] - r0[1]);
#endif
    return left + tx * (right - left);
  }

#if defined(__SSE2__)
  /// Two samples at once, (X0, Y0) and (X1, Y1) in the lanes of X, Y, with exactly the
  /// arithmetic of sample() in each lane (so results do not depend on the pairing).
  /// With lo and hi, also the stencils' ranges as in the bounded sample().
  __m128d sample2(__m128d X, __m128d Y, __m128d* lo = nullptr, __m128d* hi = nullptr) const {
    const __m128d zero = _mm_setzero_pd();
    X = _mm_min_pd(_mm_max_pd(X, zero), _mm_set1_pd(x_max));  // maxpd returns 0 for NaN
    Y = _mm_min_pd(_mm_max_pd(Y, zero), _mm_set1_pd(y_max));
    return sample2Clamped(X, Y, lo, hi);
  }

  /// sample2() for positions already clamped to [0, x_max] × [0, y_max] (the u and v views of
  /// one grid share the domain, so a caller sampling both clamps once).
  __m128d sample2Clamped(__m128d X, __m128d Y, __m128d* lo = nullptr, __m128d* hi = nullptr) const {
    return sample2Shifted(_mm_add_pd(X, _mm_set1_pd(offset_x)), _mm_add_pd(Y, _mm_set1_pd(offset_y)), lo, hi);
  }

  /// sample2Clamped() of a component on kAxis faces, whose offset along kAxis is 0
  /// (StaggeredComponent2: u (0, ½), v (½, 0)). A clamped coordinate is ≥ +0 (maxpd(−0, 0) = +0),
  /// so adding the zero offset is exact and is skipped: the same bits, one addition fewer.
  template <FaceAxis kAxis>
  __m128d sample2ClampedOn(__m128d X, __m128d Y, __m128d* lo = nullptr, __m128d* hi = nullptr) const {
    if constexpr (kAxis == FaceAxis::x) return sample2Shifted(X, _mm_add_pd(Y, _mm_set1_pd(offset_y)), lo, hi);
    return sample2Shifted(_mm_add_pd(X, _mm_set1_pd(offset_x)), Y, lo, hi);
  }
  /// sample2() of a component on kAxis faces (see sample2_clamped_on).
  template <FaceAxis kAxis>
  __m128d sample2On(__m128d X, __m128d Y, __m128d* lo = nullptr, __m128d* hi = nullptr) const {
    const __m128d zero = _mm_setzero_pd();
    X = _mm_min_pd(_mm_max_pd(X, zero), _mm_set1_pd(x_max));  // maxpd returns 0 for NaN
    Y = _mm_min_pd(_mm_max_pd(Y, zero), _mm_set1_pd(y_max));
    return sample2ClampedOn<kAxis>(X, Y, lo, hi);
  }

  /// The interpolation at padded-index coordinates (fx, fy) = clamped position + offset.
  __m128d sample2Shifted(__m128d fx, __m128d fy, __m128d* lo, __m128d* hi) const {
    // Truncation of non-negative values, then the upper index limit, all in doubles.
    const __m128d i0 = _mm_min_pd(_mm_cvtepi32_pd(_mm_cvttpd_epi32(fx)), _mm_set1_pd(i_max));
    const __m128d j0 = _mm_min_pd(_mm_cvtepi32_pd(_mm_cvttpd_epi32(fy)), _mm_set1_pd(j_max));
    const __m128d tx = _mm_sub_pd(fx, i0);
    const __m128d ty = _mm_sub_pd(fy, j0);
    // The element offset j0 · stride + i0 is an integer far below 2^31, exact in doubles: one
    // conversion and two extractions instead of two and four.
    const __m128i offset = _mm_cvttpd_epi32(_mm_add_pd(_mm_mul_pd(j0, _mm_set1_pd(static_cast<double>(stride))), i0));
    const double* ra = data + _mm_cvtsi128_si32(offset);
    const double* rb = data + _mm_cvtsi128_si32(_mm_shuffle_epi32(offset, 1));
    const __m128d low_a = _mm_loadu_pd(ra), high_a = _mm_loadu_pd(ra + stride);
    const __m128d low_b = _mm_loadu_pd(rb), high_b = _mm_loadu_pd(rb + stride);
    const __m128d col_a = _mm_add_pd(low_a, _mm_mul_pd(_mm_unpacklo_pd(ty, ty), _mm_sub_pd(high_a, low_a)));
    const __m128d col_b = _mm_add_pd(low_b, _mm_mul_pd(_mm_unpackhi_pd(ty, ty), _mm_sub_pd(high_b, low_b)));
    const __m128d left = _mm_unpacklo_pd(col_a, col_b);
    const __m128d right = _mm_unpackhi_pd(col_a, col_b);
    if (lo != nullptr) {
      // Range of the four values of each stencil (the MacCormack limiter's bounds).
      const __m128d min_a = _mm_min_pd(low_a, high_a), min_b = _mm_min_pd(low_b, high_b);
      const __m128d max_a = _mm_max_pd(low_a, high_a), max_b = _mm_max_pd(low_b, high_b);
      *lo = _mm_min_pd(_mm_unpacklo_pd(min_a, min_b), _mm_unpackhi_pd(min_a, min_b));
      *hi = _mm_max_pd(_mm_unpacklo_pd(max_a, max_b), _mm_unpackhi_pd(max_a, max_b));
    }
    return _mm_add_pd(left, _mm_mul_pd(tx, _mm_sub_pd(right, left)));
  }
#endif

#if defined(__AVX2__)
  /// Four samples at once (the fluid library is built with AVX2 where the build machine runs it,
  /// CMakeLists.txt): exactly sample2Shifted()'s arithmetic in each lane, so that results do not
  /// depend on how faces are grouped. The four stencils' rows are loaded in pairs and transposed.
  __m256d sample4Shifted(__m256d fx, __m256d fy, __m256d* lo, __m256d* hi) const {
    // Truncation of the non-negative fx, fy in place (one rounding instead of a conversion to
    // integers and back): the same whole numbers as sample2Shifted()'s.
    constexpr int kTruncate = _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC;
    const __m256d i0 = _mm256_min_pd(_mm256_round_pd(fx, kTruncate), _mm256_set1_pd(i_max));
    const __m256d j0 = _mm256_min_pd(_mm256_round_pd(fy, kTruncate), _mm256_set1_pd(j_max));
    const __m256d tx = _mm256_sub_pd(fx, i0);
    const __m256d ty = _mm256_sub_pd(fy, j0);
    const __m128i offset =
        _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_mul_pd(j0, _mm256_set1_pd(static_cast<double>(stride))), i0));
    // Lanes a, b, c, d: the lower-left, lower-right, upper-left and upper-right values.
    __m256d ll, lr, hl, hr;
    const int first = _mm_cvtsi128_si32(offset);
    const __m128i consecutive = _mm_add_epi32(_mm_set1_epi32(first), _mm_setr_epi32(0, 1, 2, 3));
    if (_mm_movemask_epi8(_mm_cmpeq_epi32(offset, consecutive)) == 0xFFFF) {
      // Four neighbouring stencils in a row (the usual case: a row of faces traced a fraction of a
      // cell): each corner's four values are contiguous. The same values as the gather below.
      const double* r = data + first;
      ll = _mm256_loadu_pd(r);
      lr = _mm256_loadu_pd(r + 1);
      hl = _mm256_loadu_pd(r + stride);
      hr = _mm256_loadu_pd(r + stride + 1);
    } else {
      const double* ra = data + first;
      const double* rb = data + _mm_extract_epi32(offset, 1);
      const double* rc = data + _mm_extract_epi32(offset, 2);
      const double* rd = data + _mm_extract_epi32(offset, 3);
      const __m256d low_ac = _mm256_set_m128d(_mm_loadu_pd(rc), _mm_loadu_pd(ra));
      const __m256d low_bd = _mm256_set_m128d(_mm_loadu_pd(rd), _mm_loadu_pd(rb));
      const __m256d high_ac = _mm256_set_m128d(_mm_loadu_pd(rc + stride), _mm_loadu_pd(ra + stride));
      const __m256d high_bd = _mm256_set_m128d(_mm_loadu_pd(rd + stride), _mm_loadu_pd(rb + stride));
      ll = _mm256_unpacklo_pd(low_ac, low_bd);
      lr = _mm256_unpackhi_pd(low_ac, low_bd);
      hl = _mm256_unpacklo_pd(high_ac, high_bd);
      hr = _mm256_unpackhi_pd(high_ac, high_bd);
    }
    const __m256d left = _mm256_add_pd(ll, _mm256_mul_pd(ty, _mm256_sub_pd(hl, ll)));
    const __m256d right = _mm256_add_pd(lr, _mm256_mul_pd(ty, _mm256_sub_pd(hr, lr)));
    if (lo != nullptr) {
      *lo = _mm256_min_pd(_mm256_min_pd(ll, hl), _mm256_min_pd(lr, hr));
      *hi = _mm256_max_pd(_mm256_max_pd(ll, hl), _mm256_max_pd(lr, hr));
    }
    return _mm256_add_pd(left, _mm256_mul_pd(tx, _mm256_sub_pd(right, left)));
  }
  /// sample2ClampedOn() four lanes wide.
  template <FaceAxis kAxis>
  __m256d sample4ClampedOn(__m256d X, __m256d Y, __m256d* lo = nullptr, __m256d* hi = nullptr) const {
    if constexpr (kAxis == FaceAxis::x) return sample4Shifted(X, _mm256_add_pd(Y, _mm256_set1_pd(offset_y)), lo, hi);
    return sample4Shifted(_mm256_add_pd(X, _mm256_set1_pd(offset_x)), Y, lo, hi);
  }
  /// sample2On() four lanes wide.
  template <FaceAxis kAxis>
  __m256d sample4On(__m256d X, __m256d Y, __m256d* lo = nullptr, __m256d* hi = nullptr) const {
    const __m256d zero = _mm256_setzero_pd();
    X = _mm256_min_pd(_mm256_max_pd(X, zero), _mm256_set1_pd(x_max));  // maxpd returns 0 for NaN
    Y = _mm256_min_pd(_mm256_max_pd(Y, zero), _mm256_set1_pd(y_max));
    return sample4ClampedOn<kAxis>(X, Y, lo, hi);
  }
#endif

#if defined(__AVX512F__)
  /// Eight samples at once (the fluid library is built with AVX-512 where the build machine runs
  /// it, CMakeLists.txt): exactly sample4Shifted()'s arithmetic in each lane, so that results do
  /// not depend on how faces are grouped. Eight neighbouring stencils in a row are read with four
  /// loads; any others are gathered.
  __m512d sample8Shifted(__m512d fx, __m512d fy, __m512d* lo, __m512d* hi) const {
    constexpr int kTruncate = _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC;  // vrndscalepd: as vroundpd
    const __m512d i0 = _mm512_min_pd(_mm512_roundscale_pd(fx, kTruncate), _mm512_set1_pd(i_max));
    const __m512d j0 = _mm512_min_pd(_mm512_roundscale_pd(fy, kTruncate), _mm512_set1_pd(j_max));
    const __m512d tx = _mm512_sub_pd(fx, i0);
    const __m512d ty = _mm512_sub_pd(fy, j0);
    const __m256i offset =
        _mm512_cvttpd_epi32(_mm512_add_pd(_mm512_mul_pd(j0, _mm512_set1_pd(static_cast<double>(stride))), i0));
    __m512d ll, lr, hl, hr;
    const int first = _mm_cvtsi128_si32(_mm256_castsi256_si128(offset));
    const __m256i consecutive = _mm256_add_epi32(_mm256_set1_epi32(first), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(offset, consecutive)) == -1) {
      const double* r = data + first;
      ll = _mm512_loadu_pd(r);
      lr = _mm512_loadu_pd(r + 1);
      hl = _mm512_loadu_pd(r + stride);
      hr = _mm512_loadu_pd(r + stride + 1);
    } else {
      ll = _mm512_i32gather_pd(offset, data, 8);
      lr = _mm512_i32gather_pd(offset, data + 1, 8);
      hl = _mm512_i32gather_pd(offset, data + stride, 8);
      hr = _mm512_i32gather_pd(offset, data + stride + 1, 8);
    }
    const __m512d left = _mm512_add_pd(ll, _mm512_mul_pd(ty, _mm512_sub_pd(hl, ll)));
    const __m512d right = _mm512_add_pd(lr, _mm512_mul_pd(ty, _mm512_sub_pd(hr, lr)));
    if (lo != nullptr) {
      *lo = _mm512_min_pd(_mm512_min_pd(ll, hl), _mm512_min_pd(lr, hr));
      *hi = _mm512_max_pd(_mm512_max_pd(ll, hl), _mm512_max_pd(lr, hr));
    }
    return _mm512_add_pd(left, _mm512_mul_pd(tx, _mm512_sub_pd(right, left)));
  }
  /// sample4ClampedOn() eight lanes wide.
  template <FaceAxis kAxis>
  __m512d sample8ClampedOn(__m512d X, __m512d Y, __m512d* lo = nullptr, __m512d* hi = nullptr) const {
    if constexpr (kAxis == FaceAxis::x) return sample8Shifted(X, _mm512_add_pd(Y, _mm512_set1_pd(offset_y)), lo, hi);
    return sample8Shifted(_mm512_add_pd(X, _mm512_set1_pd(offset_x)), Y, lo, hi);
  }
  /// sample4On() eight lanes wide.
  template <FaceAxis kAxis>
  __m512d sample8On(__m512d X, __m512d Y, __m512d* lo = nullptr, __m512d* hi = nullptr) const {
    const __m512d zero = _mm512_setzero_pd();
    X = _mm512_min_pd(_mm512_max_pd(X, zero), _mm512_set1_pd(x_max));  // maxpd returns 0 for NaN
    Y = _mm512_min_pd(_mm512_max_pd(Y, zero), _mm512_set1_pd(y_max));
    return sample8ClampedOn<kAxis>(X, Y, lo, hi);
  }
#endif

  /// As sample(), also returning the smallest and largest of the four values interpolated
  /// (the clamping bounds of the MacCormack limiter, Selle et al. 2008).
  double sample(double X, double Y, double& lo, double& hi) const {
    double tx = 0.0, ty = 0.0;
    const double* r0 = locate(X, Y, tx, ty);
    const double* r1 = r0 + stride;
    lo = std::min(std::min(r0[0], r0[1]), std::min(r1[0], r1[1]));
    hi = std::max(std::max(r0[0], r0[1]), std::max(r1[0], r1[1]));
    const double left = r0[0] + ty * (r1[0] - r0[0]);  // same arithmetic as sample()
    const double right = r0[1] + ty * (r1[1] - r0[1]);
    return left + tx * (right - left);
  }
};

/// One staggered component padded with ghosts; samples in cell units (X, Y) = (x, y) / dx.
class StaggeredComponent2 {
 public:
  /// Copies `values` ((nx+1) × ny for FaceAxis::x, nx × (ny+1) for FaceAxis::y) and fills the
  /// ghost layer from the walls. Reuses its storage between calls.
  void assign(FaceAxis axis, const Array2& values, const Walls& walls);
  /// assign() in three parts, so that threads can share the copy: prepare() for the values'
  /// grid, copyRows() of every row j in [0, values.ny()), then fillGhosts().
  void copyRows(const Array2& values, int j0, int j1);
  void fillGhosts(const Walls& walls);

  /// For writing a component straight into the padded storage (no copy): shapes it for a grid of
  /// nx × ny cells and returns it. Element (i, j) of the component is interiorRow(j)[i]. Write
  /// every unknown face, then call finish(), which zeroes the solid walls' normal faces and
  /// fills the ghosts: the same state as assign() of those values.
  Array2& prepare(FaceAxis axis, int nx, int ny);
  double* interiorRow(int j) { return axis_ == FaceAxis::x ? padded_.row(j + 1) : padded_.row(j) + 1; }
  const double* interiorRow(int j) const { return axis_ == FaceAxis::x ? padded_.row(j + 1) : padded_.row(j) + 1; }
  void finish(const Walls& walls);

  /// Bilinear interpolation at (X, Y) in cell units, clamped to [0, nx] × [0, ny].
  double sample(double X, double Y) const { return view_.sample(X, Y); }
  double sample(double X, double Y, double& lo, double& hi) const { return view_.sample(X, Y, lo, hi); }

  /// The padded copy: for FaceAxis::x, padded(i, j + 1) = values(i, j) with ghost rows 0 and
  /// ny + 1; for FaceAxis::y, padded(i + 1, j) = values(i, j) with ghost columns 0 and nx + 1.
  const Array2& padded() const { return padded_; }
  const SampleView& view() const { return view_; }

 private:
  FaceAxis axis_ = FaceAxis::x;
  Array2 padded_;
  SampleView view_;
};

/// The velocity of a MAC grid, interpolated anywhere in the domain (positions in metres).
/// Used for advection backtraces, passive tracers and, later, immersed-boundary markers.
class VelocitySampler2 {
 public:
  void assign(const MacGrid2& grid, const Walls& walls) {
    u_.assign(FaceAxis::x, grid.u_m_per_s, walls);
    v_.assign(FaceAxis::y, grid.v_m_per_s, walls);
    inv_dx_per_m_ = 1.0 / grid.dx_m;
  }
  Vec2 velocityAt_m_per_s(Vec2 position_m) const {
    const double X = position_m.x * inv_dx_per_m_;
    const double Y = position_m.y * inv_dx_per_m_;
    return {u_.sample(X, Y), v_.sample(X, Y)};
  }
  const StaggeredComponent2& u() const { return u_; }
  const StaggeredComponent2& v() const { return v_; }

 private:
  StaggeredComponent2 u_;
  StaggeredComponent2 v_;
  double inv_dx_per_m_ = 0.0;
};

}  // namespace creaturelab::fluid
