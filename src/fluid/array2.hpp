#pragma once
// Dense 2-D array of doubles used for every field of the fluid solver.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace creaturelab::fluid {

/// Bytes in a cache line: the alignment of every Array2's storage.
inline constexpr std::size_t kCacheLineBytes = 64;

/// std::allocator on cache-line boundaries. glibc puts a large block 16 bytes past a page
/// boundary, so two threads writing the two halves of a row (the fast pressure solver's
/// lane-split transforms) would share, and fight over, one cache line in every row.
template <class T>
struct CacheLineAllocator {
  using value_type = T;
  CacheLineAllocator() = default;
  template <class U>
  CacheLineAllocator(const CacheLineAllocator<U>&) {}
  T* allocate(std::size_t n) {
    return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t{kCacheLineBytes}));
  }
  void deallocate(T* p, std::size_t) { ::operator delete(p, std::align_val_t{kCacheLineBytes}); }
  template <class U>
  bool operator==(const CacheLineAllocator<U>&) const { return true; }
};

/// A dense nx × ny array of doubles with the x index fastest: element (i, j) lives at
/// data()[j * nx + i]. Rows of constant j are contiguous, which the solvers rely on to
/// vectorise loops over i.
class Array2 {
 public:
  Array2() = default;
  Array2(int nx, int ny, double value = 0.0)
      : nx_(nx), ny_(ny), data_(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), value) {}

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  std::size_t size() const { return data_.size(); }

  double& operator()(int i, int j) { return data_[index(i, j)]; }
  double operator()(int i, int j) const { return data_[index(i, j)]; }

  double* data() { return data_.data(); }
  const double* data() const { return data_.data(); }
  double* row(int j) { return data_.data() + index(0, j); }
  const double* row(int j) const { return data_.data() + index(0, j); }

  void fill(double value) { std::fill(data_.begin(), data_.end(), value); }
  /// Reshapes (and zeroes) only when the shape changes, so scratch arrays are allocated once.
  void resize(int nx, int ny) {
    if (nx == nx_ && ny == ny_) return;
    nx_ = nx;
    ny_ = ny;
    data_.assign(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0.0);
  }
  /// Exact comparison of shape and values (== on doubles: no tolerance; NaN never equal).
  bool operator==(const Array2& other) const = default;

 private:
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
  }
  int nx_ = 0;
  int ny_ = 0;
  std::vector<double, CacheLineAllocator<double>> data_;
};

// Reductions. A single running sum (or maximum) is a chain of dependent additions, bound by
// their latency; these keep four independent partial results (plain locals, so that they
// stay in registers) in a fixed pattern and combine them in a fixed order: several times
// faster and still bitwise reproducible on every machine. The maxima also watch for NaN
// (v − v is NaN for NaN and ±inf), which a comparison would silently skip.

/// Σ a[k] b[k].
inline double dot(const double* a, const double* b, std::size_t n) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::size_t k = 0;
#if defined(__SSE2__)
  // The same four lanes as the scalar loop, two per register (the compiler does not pair them).
  __m128d s01 = _mm_setzero_pd(), s23 = _mm_setzero_pd();
  for (; k + 4 <= n; k += 4) {
    s01 = _mm_add_pd(s01, _mm_mul_pd(_mm_loadu_pd(a + k), _mm_loadu_pd(b + k)));
    s23 = _mm_add_pd(s23, _mm_mul_pd(_mm_loadu_pd(a + k + 2), _mm_loadu_pd(b + k + 2)));
  }
  s0 = _mm_cvtsd_f64(s01), s1 = _mm_cvtsd_f64(_mm_unpackhi_pd(s01, s01));
  s2 = _mm_cvtsd_f64(s23), s3 = _mm_cvtsd_f64(_mm_unpackhi_pd(s23, s23));
#else
  for (; k + 4 <= n; k += 4) {
    s0 += a[k] * b[k];
    s1 += a[k + 1] * b[k + 1];
    s2 += a[k + 2] * b[k + 2];
    s3 += a[k + 3] * b[k + 3];
  }
#endif
  for (; k < n; ++k) s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}

/// Σ p[k].
inline double sum(const double* p, std::size_t n) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    s0 += p[k];
    s1 += p[k + 1];
    s2 += p[k + 2];
    s3 += p[k + 3];
  }
  for (; k < n; ++k) s0 += p[k];
  return (s0 + s1) + (s2 + s3);
}

/// Running maximum of |values| in four lanes, with NaN detection.
#if defined(__SSE2__)
// Lanes (0, 1) and (2, 3) in one register each: maxpd(v, m) is v > m ? v : m per lane, the
// scalar rule below, so the result is bitwise the same as the scalar version's.
struct MaxAbsAccumulator {
  __m128d m01 = _mm_setzero_pd(), m23 = _mm_setzero_pd();  // maxima
  __m128d z01 = _mm_setzero_pd(), z23 = _mm_setzero_pd();  // Σ (v − v): NaN once a NaN or inf was seen
  static __m128d abs2(__m128d v) { return _mm_andnot_pd(_mm_set1_pd(-0.0), v); }
  void add2x2(__m128d v01, __m128d v23) {
    v01 = abs2(v01), v23 = abs2(v23);
    m01 = _mm_max_pd(v01, m01);
    m23 = _mm_max_pd(v23, m23);
    z01 = _mm_add_pd(z01, _mm_sub_pd(v01, v01));
    z23 = _mm_add_pd(z23, _mm_sub_pd(v23, v23));
  }
  void add4(double v0, double v1, double v2, double v3) { add2x2(_mm_set_pd(v1, v0), _mm_set_pd(v3, v2)); }
  /// Two values into lanes 0 and 1.
  void add2(__m128d v01) {
    v01 = abs2(v01);
    m01 = _mm_max_pd(v01, m01);
    z01 = _mm_add_pd(z01, _mm_sub_pd(v01, v01));
  }
  /// add4 of p[0..3].
  void add4(const double* p) { add2x2(_mm_loadu_pd(p), _mm_loadu_pd(p + 2)); }
  void add(double v) {
    const __m128d a = abs2(_mm_set_sd(v));
    m01 = _mm_move_sd(m01, _mm_max_sd(a, m01));
    z01 = _mm_move_sd(z01, _mm_add_sd(z01, _mm_sub_sd(a, a)));
  }
  /// The maximum; +infinity if an infinity was seen, NaN if a NaN was seen.
  double result() const {
    auto lo = [](__m128d x) { return _mm_cvtsd_f64(x); };
    auto hi = [](__m128d x) { return _mm_cvtsd_f64(_mm_unpackhi_pd(x, x)); };
    const double z = (lo(z01) + hi(z01)) + (lo(z23) + hi(z23));
    const double m = std::max(std::max(lo(m01), hi(m01)), std::max(lo(m23), hi(m23)));
    if (z != z) return m > std::numeric_limits<double>::max() ? m : std::numeric_limits<double>::quiet_NaN();
    return m;
  }
  /// Merges another accumulator (the maximum and the NaN flag do not depend on the order).
  void merge(const MaxAbsAccumulator& o) {
    m01 = _mm_max_pd(o.m01, m01), m23 = _mm_max_pd(o.m23, m23);
    z01 = _mm_add_pd(z01, o.z01), z23 = _mm_add_pd(z23, o.z23);
  }
};
#else
struct MaxAbsAccumulator {
  double m0 = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0;  // maxima
  double z0 = 0.0, z1 = 0.0, z2 = 0.0, z3 = 0.0;  // Σ (v − v): NaN once a NaN or inf was seen
  void add4(double v0, double v1, double v2, double v3) {
    v0 = std::abs(v0), v1 = std::abs(v1), v2 = std::abs(v2), v3 = std::abs(v3);
    m0 = v0 > m0 ? v0 : m0;
    m1 = v1 > m1 ? v1 : m1;
    m2 = v2 > m2 ? v2 : m2;
    m3 = v3 > m3 ? v3 : m3;
    z0 += v0 - v0;
    z1 += v1 - v1;
    z2 += v2 - v2;
    z3 += v3 - v3;
  }
  void add4(const double* p) { add4(p[0], p[1], p[2], p[3]); }
  void add2(double v0, double v1) { add(v0), add(v1); }
  void add(double v) {
    v = std::abs(v);
    m0 = v > m0 ? v : m0;
    z0 += v - v;
  }
  /// The maximum; +infinity if an infinity was seen, NaN if a NaN was seen.
  double result() const {
    const double z = (z0 + z1) + (z2 + z3);
    const double m = std::max(std::max(m0, m1), std::max(m2, m3));
    if (z != z) return m > std::numeric_limits<double>::max() ? m : std::numeric_limits<double>::quiet_NaN();
    return m;
  }
  void merge(const MaxAbsAccumulator& o) {
    m0 = o.m0 > m0 ? o.m0 : m0, m1 = o.m1 > m1 ? o.m1 : m1, m2 = o.m2 > m2 ? o.m2 : m2, m3 = o.m3 > m3 ? o.m3 : m3;
    z0 += o.z0, z1 += o.z1, z2 += o.z2, z3 += o.z3;
  }
};
#endif

/// The accumulator of |p[k]|, k < n (to merge partial results).
inline MaxAbsAccumulator partialMaxAbs(const double* p, std::size_t n) {
  MaxAbsAccumulator acc;
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) acc.add4(p + k);
  for (; k < n; ++k) acc.add(p[k]);
  return acc;
}

/// max |p[k]| (0 when n = 0); NaN if a value is NaN (unless an infinity is also present).
inline double maxAbs(const double* p, std::size_t n) { return partialMaxAbs(p, n).result(); }

/// max |a[k] − b[k]|, with the NaN rule of max_abs.
inline double maxAbsDifference(const double* a, const double* b, std::size_t n) {
  MaxAbsAccumulator acc;
  std::size_t k = 0;
#if defined(__SSE2__)
  for (; k + 4 <= n; k += 4) {
    acc.add2x2(_mm_sub_pd(_mm_loadu_pd(a + k), _mm_loadu_pd(b + k)),
               _mm_sub_pd(_mm_loadu_pd(a + k + 2), _mm_loadu_pd(b + k + 2)));
  }
#else
  for (; k + 4 <= n; k += 4) acc.add4(a[k] - b[k], a[k + 1] - b[k + 1], a[k + 2] - b[k + 2], a[k + 3] - b[k + 3]);
#endif
  for (; k < n; ++k) acc.add(a[k] - b[k]);
  return acc.result();
}

inline double maxAbs(const Array2& a) { return maxAbs(a.data(), a.size()); }
inline double dot(const Array2& a, const Array2& b) { return dot(a.data(), b.data(), a.size()); }

/// Subtracts the mean value.
inline void removeMean(Array2& a) {
  double* p = a.data();
  const std::size_t n = a.size();
  const double mean = sum(p, n) / static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k) p[k] -= mean;
}

/// A point or vector in the plane, SI units given by the name of the variable holding it.
struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

}  // namespace creaturelab::fluid
