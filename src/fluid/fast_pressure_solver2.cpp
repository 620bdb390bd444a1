#include "fluid/fast_pressure_solver2.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fluid/boundary2.hpp"

#if defined(__AVX512F__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace creaturelab::fluid {
namespace {

// Threads split the transforms' lanes on cache-line boundaries (worker_pool.hpp).
constexpr int kLanesPerCacheLine = static_cast<int>(kCacheLineBytes / sizeof(double));

// Radices of the FFT of length h = n/2 used by the DCT of length n, or empty when n is odd or
// h has a prime factor above 7 (the dense transform is used then). (A radix-4 butterfly was
// rejected: with SSE2's sixteen registers it spills. Two radix-2 stages fused into one pass,
// radix2_twice, keep the radix-2 arithmetic and use AVX-512's 32 registers.)
std::vector<int> fftRadices(int n) {
  if (n < 2 || n % 2 != 0) return {};
  int h = n / 2;
  std::vector<int> radices;
  for (int r : {2, 3, 5, 7}) {
    while (h % r == 0) radices.push_back(r), h /= r;
  }
  if (h != 1) return {};
  return radices;
}
bool fftApplies(int n) { return n == 2 || !fftRadices(n).empty(); }

// Whether stages `stage` and `stage` + 1 are both radix 2, and so run as one pass (radix2_twice).
bool twoRadix2At(const std::vector<int>& radices, std::size_t stage) {
  return radices[stage] == 2 && stage + 1 < radices.size() && radices[stage + 1] == 2;
}

// What the end of a lane changes in the diagonal 2 + λ + σ: −1 (Neumann), +1 (zero half a
// cell beyond), 0 (zero one cell beyond).
double endOffset(OperatorEnd end) {
  switch (end) {
    case OperatorEnd::neumann:
      return 1.0;
    case OperatorEnd::dirichlet_half:
      return -1.0;
    case OperatorEnd::dirichlet_node:
      return 0.0;
  }
  return 0.0;
}

// Eigenpairs of the 1-D operator along `lines` with the given ends (see the header).
double eigenvalue(bool low_neumann, bool high_neumann, int n, int k) {
  const double pi = std::numbers::pi;
  double theta = 0.0;
  if (low_neumann && high_neumann)
    theta = pi * k / n;
  else if (!low_neumann && !high_neumann)
    theta = pi * (k + 1) / n;
  else
    theta = pi * (k + 0.5) / n;
  const double s = std::sin(0.5 * theta);
  return 4.0 * s * s;  // = 2 − 2 cos θ without cancellation for small θ
}

double eigenvector(bool low_neumann, bool high_neumann, int n, int k, int j) {
  const double pi = std::numbers::pi;
  const double x = j + 0.5;
  if (low_neumann && high_neumann) return std::cos(pi * k * x / n);
  if (!low_neumann && !high_neumann) return std::sin(pi * (k + 1) * x / n);
  if (low_neumann) return std::cos(pi * (k + 0.5) * x / n);
  return std::sin(pi * (k + 0.5) * x / n);
}

// Radix-2 Stockham butterfly over one block: b0 = a0 + a1, b1 = w (a0 − a1).
void radix2(long block, const double* __restrict__ a0r, const double* __restrict__ a0i, const double* __restrict__ a1r,
            const double* __restrict__ a1i, double* __restrict__ b0r, double* __restrict__ b0i,
            double* __restrict__ b1r, double* __restrict__ b1i, double wc, double ws) {
  for (long l = 0; l < block; ++l) {
    const double dr = a0r[l] - a1r[l], di = a0i[l] - a1i[l];
    b0r[l] = a0r[l] + a1r[l];
    b0i[l] = a0i[l] + a1i[l];
    b1r[l] = wc * dr - ws * di;
    b1i[l] = wc * di + ws * dr;
  }
}

// Two radix-2 Stockham stages in one pass over four blocks a0..a3 (rows p, p + L/4, p + L/2,
// p + 3L/4 of a stage of length L): the first stage's b = a_t ± a_{t+2}, twiddled by w1a (p) and
// w1b (p + L/4), then the second's (length L/2, twice the stride) on those, twiddled by w2 (p),
// into rows 4p .. 4p + 3. The operations of radix2() twice, without storing the stage between:
// bitwise the same, half the passes over the panel.
void radix2Twice(long block, const double* __restrict__ a0r, const double* __restrict__ a0i,
                  const double* __restrict__ a1r, const double* __restrict__ a1i, const double* __restrict__ a2r,
                  const double* __restrict__ a2i, const double* __restrict__ a3r, const double* __restrict__ a3i,
                  double* __restrict__ b0r, double* __restrict__ b0i, double* __restrict__ b1r,
                  double* __restrict__ b1i, double* __restrict__ b2r, double* __restrict__ b2i,
                  double* __restrict__ b3r, double* __restrict__ b3i, double w1a_c, double w1a_s, double w1b_c,
                  double w1b_s, double w2_c, double w2_s) {
  for (long l = 0; l < block; ++l) {
    // First stage: rows 2p, 2p + 1 from (a0, a2) and rows 2p + L/2, 2p + L/2 + 1 from (a1, a3).
    const double d02r = a0r[l] - a2r[l], d02i = a0i[l] - a2i[l];
    const double y0r = a0r[l] + a2r[l], y0i = a0i[l] + a2i[l];
    const double y1r = w1a_c * d02r - w1a_s * d02i, y1i = w1a_c * d02i + w1a_s * d02r;
    const double d13r = a1r[l] - a3r[l], d13i = a1i[l] - a3i[l];
    const double y2r = a1r[l] + a3r[l], y2i = a1i[l] + a3i[l];
    const double y3r = w1b_c * d13r - w1b_s * d13i, y3i = w1b_c * d13i + w1b_s * d13r;
    // Second stage: (y0, y1) against (y2, y3).
    const double e0r = y0r - y2r, e0i = y0i - y2i;
    const double e1r = y1r - y3r, e1i = y1i - y3i;
    b0r[l] = y0r + y2r;
    b0i[l] = y0i + y2i;
    b1r[l] = y1r + y3r;
    b1i[l] = y1i + y3i;
    b2r[l] = w2_c * e0r - w2_s * e0i;
    b2i[l] = w2_c * e0i + w2_s * e0r;
    b3r[l] = w2_c * e1r - w2_s * e1i;
    b3i[l] = w2_c * e1i + w2_s * e1r;
  }
}

// Odd radix R = 3, 5, 7: the small DFT by its definition, b_u = w_u Σ_t a_t e^{sgn 2πi ut/R}.
// R known at compile time, so the coefficients stay in registers and the loop over l
// vectorises; the sums run in the order t = 0 .. R − 1 as before (bitwise the same).
template <int R>
void oddRadix(long block, const double* const* ar, const double* const* ai, double* const* br, double* const* bi,
               const double (&dft_cos)[7][7], const double (&dft_sin)[7][7], const double* wc, const double* ws) {
  for (int u = 0; u < R; ++u) {
    double cu[R], su[R];
    for (int t = 0; t < R; ++t) cu[t] = dft_cos[u][t], su[t] = dft_sin[u][t];
    const double wcu = wc[u], wsu = ws[u];
    double* __restrict__ out_r = br[u];
    double* __restrict__ out_i = bi[u];
    long l = 0;
#if defined(__AVX512F__)
    // Eight lanes per register, the same operations per lane as the loops below.
    const __m512d wc8 = _mm512_set1_pd(wcu), ws8 = _mm512_set1_pd(wsu);
    for (; l + 8 <= block; l += 8) {
      __m512d sr = _mm512_loadu_pd(ar[0] + l), si = _mm512_loadu_pd(ai[0] + l);
      for (int t = 1; t < R; ++t) {
        const __m512d xr = _mm512_loadu_pd(ar[t] + l), xi = _mm512_loadu_pd(ai[t] + l);
        const __m512d c = _mm512_set1_pd(cu[t]), sn = _mm512_set1_pd(su[t]);
        sr = _mm512_add_pd(sr, _mm512_sub_pd(_mm512_mul_pd(c, xr), _mm512_mul_pd(sn, xi)));
        si = _mm512_add_pd(si, _mm512_add_pd(_mm512_mul_pd(c, xi), _mm512_mul_pd(sn, xr)));
      }
      _mm512_storeu_pd(out_r + l, _mm512_sub_pd(_mm512_mul_pd(wc8, sr), _mm512_mul_pd(ws8, si)));
      _mm512_storeu_pd(out_i + l, _mm512_add_pd(_mm512_mul_pd(wc8, si), _mm512_mul_pd(ws8, sr)));
    }
#endif
#if defined(__SSE2__)
    // Two lanes per register (the compiler cannot prove the R input rows and the output apart).
    const __m128d wc2 = _mm_set1_pd(wcu), ws2 = _mm_set1_pd(wsu);
    for (; l + 2 <= block; l += 2) {
      __m128d sr = _mm_loadu_pd(ar[0] + l), si = _mm_loadu_pd(ai[0] + l);
      for (int t = 1; t < R; ++t) {
        const __m128d xr = _mm_loadu_pd(ar[t] + l), xi = _mm_loadu_pd(ai[t] + l);
        const __m128d c = _mm_set1_pd(cu[t]), sn = _mm_set1_pd(su[t]);
        sr = _mm_add_pd(sr, _mm_sub_pd(_mm_mul_pd(c, xr), _mm_mul_pd(sn, xi)));
        si = _mm_add_pd(si, _mm_add_pd(_mm_mul_pd(c, xi), _mm_mul_pd(sn, xr)));
      }
      _mm_storeu_pd(out_r + l, _mm_sub_pd(_mm_mul_pd(wc2, sr), _mm_mul_pd(ws2, si)));
      _mm_storeu_pd(out_i + l, _mm_add_pd(_mm_mul_pd(wc2, si), _mm_mul_pd(ws2, sr)));
    }
#endif
    for (; l < block; ++l) {
      double sr = ar[0][l], si = ai[0][l];
      for (int t = 1; t < R; ++t) {
        sr += cu[t] * ar[t][l] - su[t] * ai[t][l];
        si += cu[t] * ai[t][l] + su[t] * ar[t][l];
      }
      out_r[l] = wcu * sr - wsu * si;
      out_i[l] = wcu * si + wsu * sr;
    }
  }
}

}  // namespace

namespace {

// Transposed copies in tiles of kTile columns, so that the strided side touches kTile cache
// lines per row instead of one per element; each element gets the same single operation.
constexpr int kTile = 8;
// out(j, i) = f(in(i, j)) for the rows j in [j0, j1) of `in`.
template <class F>
void transposeRows(const Array2& in, int j0, int j1, F f, Array2& out) {
  const int nx = in.nx();
  for (int i0 = 0; i0 < nx; i0 += kTile) {
    const int i1 = std::min(nx, i0 + kTile);
    for (int j = j0; j < j1; ++j) {
      const double* src = in.row(j);
      for (int i = i0; i < i1; ++i) out(j, i) = f(src[i]);
    }
  }
}
// out(i, j) = in(j, i) for the rows j in [j0, j1) of `out`.
void transposeColumns(const Array2& in, int j0, int j1, Array2& out) {
  const int nx = out.nx();
  for (int i0 = 0; i0 < nx; i0 += kTile) {
    const int i1 = std::min(nx, i0 + kTile);
    for (int j = j0; j < j1; ++j) {
      double* dst = out.row(j);
      for (int i = i0; i < i1; ++i) dst[i] = in(j, i);
    }
  }
}

}  // namespace

KroneckerOperator2 pressureOperator(const Walls& walls) {
  auto end = [](const Wall& wall) { return isSolid(wall) ? OperatorEnd::neumann : OperatorEnd::dirichlet_half; };
  return {end(walls.left), end(walls.right), end(walls.bottom), end(walls.top), 0.0};
}

void FastPressureSolver2::setup(const KroneckerOperator2& op, int nx, int ny, bool prefer_dense) {
  if (ready_ && nx == nx_ && ny == ny_ && prefer_dense == prefer_dense_ && op == op_) return;
  ready_ = true;
  op_ = op;
  nx_ = nx;
  ny_ = ny;
  prefer_dense_ = prefer_dense;

  using E = OperatorEnd;
  const bool x_neumann = op.x_low == E::neumann && op.x_high == E::neumann;
  const bool y_neumann = op.y_low == E::neumann && op.y_high == E::neumann;
  const bool y_node = op.y_low == E::dirichlet_node || op.y_high == E::dirichlet_node;
  const bool x_node = op.x_low == E::dirichlet_node || op.x_high == E::dirichlet_node;
  if (!prefer_dense && y_neumann && fftApplies(ny))
    method_ = Method::fft_along_y;
  else if (!prefer_dense && x_neumann && fftApplies(nx))
    method_ = Method::fft_along_x;
  else if (!y_node)
    method_ = Method::dense_along_y;
  else if (!x_node)
    method_ = Method::dense_along_x;
  else
    throw std::invalid_argument("fast direct solver: both axes end one cell beyond a known zero; no transform applies");

  transposed_ = method_ == Method::fft_along_x || method_ == Method::dense_along_x;
  dense_ = method_ == Method::dense_along_y || method_ == Method::dense_along_x;
  const bool transposed = transposed_;
  lines_ = transposed ? nx : ny;
  lanes_ = transposed ? ny : nx;
  const E line_low = transposed ? op.x_low : op.y_low;
  const E line_high = transposed ? op.x_high : op.y_high;
  const E lane_low = transposed ? op.y_low : op.x_low;
  const E lane_high = transposed ? op.y_high : op.x_high;
  const bool line_low_n = line_low == E::neumann, line_high_n = line_high == E::neumann;
  const int n = lines_;
  const int m = lanes_;
  singular_ = line_low_n && line_high_n && lane_low == E::neumann && lane_high == E::neumann && op.shift == 0.0;

  // Thomas pivots of (T_lanes + λ_k I) for every mode k: forward elimination of
  // tridiag(−1, d_l, −1) gives pivots π_0 = d_0, π_l = d_l − 1/π_{l−1}; we store 1/π_l.
  pivots_.resize(m, n);
  for (int k = 0; k < n; ++k) {
    const double lambda = eigenvalue(line_low_n, line_high_n, n, k);
    double* inv = pivots_.row(k);
    for (int l = 0; l < m; ++l) {
      double d = 2.0 + lambda + op.shift;  // σ = 0 adds exactly nothing
      if (l == 0) d -= endOffset(lane_low);
      if (l == m - 1) d -= endOffset(lane_high);
      const double pivot = l == 0 ? d : d - inv[l - 1];
      inv[l] = 1.0 / pivot;  // the singular mode's last pivot is 0: never used (see solve_modes)
    }
  }

  work_.resize(m, n);
  panels_.clear();
  dense_out_.resize(0, 0);
  basis_.resize(0, 0);
  basis_t_.resize(0, 0);
  if (dense_) {
    basis_.resize(n, n);
    basis_t_.resize(n, n);
    for (int k = 0; k < n; ++k) {
      double norm2 = 0.0;
      for (int j = 0; j < n; ++j) {
        const double phi = eigenvector(line_low_n, line_high_n, n, k, j);
        norm2 += phi * phi;
      }
      const double inv_norm = 1.0 / std::sqrt(norm2);
      for (int j = 0; j < n; ++j) {
        const double phi = eigenvector(line_low_n, line_high_n, n, k, j) * inv_norm;
        basis_(j, k) = phi;
        basis_t_(k, j) = phi;
      }
    }
  } else {
    const int h = n / 2;  // the real transforms run as complex FFTs of half length
    radices_ = fftRadices(n);
    fft_cos_.assign(h, 0.0);
    fft_sin_.assign(h, 0.0);
    for (int t = 0; t < h; ++t) {
      const double angle = 2.0 * std::numbers::pi * t / h;
      fft_cos_[t] = std::cos(angle);
      fft_sin_[t] = std::sin(angle);
    }
    twiddle_cos_.assign(h, 0.0);
    twiddle_sin_.assign(h, 0.0);
    for (int t = 0; t < h; ++t) {
      const double angle = 2.0 * std::numbers::pi * t / n;
      twiddle_cos_[t] = std::cos(angle);
      twiddle_sin_[t] = std::sin(angle);
    }
    shift_cos_.assign(n + 1, 0.0);
    shift_sin_.assign(n + 1, 0.0);
    for (int k = 0; k <= n; ++k) {
      const double angle = std::numbers::pi * k / (2.0 * n);
      shift_cos_[k] = std::cos(angle);
      shift_sin_[k] = std::sin(angle);
    }
  }
}

// Passes over a panel: one per stage, but one for each two radix-2 stages in a row.
int FastPressureSolver2::fftPasses(const std::vector<int>& radices) {
  int passes = 0;
  for (std::size_t stage = 0; stage < radices.size(); ++passes) stage += twoRadix2At(radices, stage) ? 2 : 1;
  return passes;
}

// Mixed-radix (2, 3, 5, 7) Stockham FFT of length h = n/2 of every lane of a panel, on
// (re, im) in natural order, result in natural order (Van Loan 1992, "Computational
// Frameworks for the FFT", §1.7 and ch. 2). Stage with radix r, current length L, stride s:
//   y[q + s (r p + u)] = e^{∓2πi p u / L} Σ_t x[q + s (p + t L/r)] e^{∓2πi t u / r}
// for p < L/r, q < s. Forward: e^{−…}; inverse: e^{+…}, no 1/h. Rows q = 0..s−1 are adjacent,
// so every (p, t) is one contiguous vector of s·w values (w lanes) and the inner loops
// vectorise. Each lane gets the same arithmetic whatever the panel's width. Two radix-2 stages
// in a row run as one pass (radix2_twice). The passes alternate between (re, im) and (re2, im2):
// the result is in the second pair when their number is odd (resultInSecondBuffers()).
void FastPressureSolver2::fft(bool inverse, FftPanel& panel) {
  const int h = lines_ / 2;
  const long m = panel.re.nx();
  const double sgn = inverse ? 1.0 : -1.0;
  int length = h;
  long stride = 1;
  const double* xr = panel.re.data();
  const double* xi = panel.im.data();
  double* yr = panel.re2.data();
  double* yi = panel.im2.data();
  for (std::size_t stage = 0; stage < radices_.size();) {
    const bool fused = twoRadix2At(radices_, stage);
    const int r = fused ? 4 : radices_[stage];  // the pass divides the length by r
    const int mm = length / r;
    const long block = stride * m;  // one contiguous vector per (p, t)
    const int twiddle_scale = h / length;
    if (fused) {
      // Two radix-2 stages (radix2_twice): lengths L and L/2, strides s and 2s; mm = L/4.
      for (int p = 0; p < mm; ++p) {
        const int ia = (p * twiddle_scale) % h, ib = ((p + mm) * twiddle_scale) % h, i2 = (2 * p * twiddle_scale) % h;
        const long in = p * block, out = 4L * p * block, q = mm * block;
        radix2Twice(block, xr + in, xi + in, xr + in + q, xi + in + q, xr + in + 2 * q, xi + in + 2 * q,
                     xr + in + 3 * q, xi + in + 3 * q, yr + out, yi + out, yr + out + block, yi + out + block,
                     yr + out + 2 * block, yi + out + 2 * block, yr + out + 3 * block, yi + out + 3 * block,
                     fft_cos_[ia], sgn * fft_sin_[ia], fft_cos_[ib], sgn * fft_sin_[ib], fft_cos_[i2],
                     sgn * fft_sin_[i2]);
      }
    } else {
      double dft_cos[7][7], dft_sin[7][7];  // e^{sgn 2πi ut/r} of the odd radices
      if (r % 2 == 1) {
        for (int u = 0; u < r; ++u) {
          for (int t = 0; t < r; ++t) {
            const double angle = 2.0 * std::numbers::pi * ((u * t) % r) / r;
            dft_cos[u][t] = std::cos(angle);
            dft_sin[u][t] = sgn * std::sin(angle);
          }
        }
      }
      for (int p = 0; p < mm; ++p) {
        const double* ar[7];
        const double* ai[7];
        double* br[7];
        double* bi[7];
        double wc[7], ws[7];
        for (int t = 0; t < r; ++t) {
          ar[t] = xr + (p + static_cast<long>(t) * mm) * block;
          ai[t] = xi + (p + static_cast<long>(t) * mm) * block;
          br[t] = yr + (static_cast<long>(r) * p + t) * block;
          bi[t] = yi + (static_cast<long>(r) * p + t) * block;
          const int index = (p * t * twiddle_scale) % h;
          wc[t] = fft_cos_[index];
          ws[t] = sgn * fft_sin_[index];
        }
        if (r == 2) {
          radix2(block, ar[0], ai[0], ar[1], ai[1], br[0], bi[0], br[1], bi[1], wc[1], ws[1]);
        } else if (r == 3) {
          oddRadix<3>(block, ar, ai, br, bi, dft_cos, dft_sin, wc, ws);
        } else if (r == 5) {
          oddRadix<5>(block, ar, ai, br, bi, dft_cos, dft_sin, wc, ws);
        } else {
          oddRadix<7>(block, ar, ai, br, bi, dft_cos, dft_sin, wc, ws);
        }
      }
    }
    // The output of this pass is the input of the next.
    const double* next_r = yr;
    const double* next_i = yi;
    yr = const_cast<double*>(xr);
    yi = const_cast<double*>(xi);
    xr = next_r;
    xi = next_i;
    length = mm;
    stride *= r;
    stage += fused ? 2 : 1;
  }
}

// Forward transform along lines of the lanes [l0, l1): work_ (lines × lanes) ← its transform,
// reading line t of the input from source.row(t) × scale (scale 1: a copy). The FFT runs in
// `panel`, lane l at column l − l0 (the dense path writes dense_out_).
void FastPressureSolver2::forwardTransform(const Array2& source, double scale, int l0, int l1, FftPanel& panel) {
  const int n = lines_;
  if (dense_) {
    // out_k = Σ_j φ_k(j) in_j, four modes at a time; j ascending for every output.
    for (int k0 = 0; k0 < n; k0 += 4) {
      const int kb = std::min(4, n - k0);
      for (int kk = 0; kk < kb; ++kk) std::fill(dense_out_.row(k0 + kk) + l0, dense_out_.row(k0 + kk) + l1, 0.0);
      for (int j = 0; j < n; ++j) {
        const double* __restrict__ in = source.row(j);
        for (int kk = 0; kk < kb; ++kk) {
          const double c = basis_(j, k0 + kk);
          double* __restrict__ out = dense_out_.row(k0 + kk);
          for (int l = l0; l < l1; ++l) out[l] += c * in[l];
        }
      }
    }
    return;
  }
  // DCT-II by Makhoul's reordering, v_t = x_{2t} and v_{n−1−t} = x_{2t+1} (t < n/2), so that
  // X_k = Re(e^{−iπk/2n} V_k) with V = FFT_n(v). v is real: pack z_j = v_{2j} + i v_{2j+1},
  // Z = FFT_{n/2}(z), and unpack E_k = (Z_k + conj Z_{h−k})/2, O_k = (Z_k − conj Z_{h−k})/2i,
  // V_k = E_k + e^{−2πik/n} O_k for k ≤ n/2, V_{n−k} = conj V_k.
  const int h = n / 2;
  const int width = l1 - l0;
  auto source_row = [n, h](int t) { return t < h ? 2 * t : 2 * (n - 1 - t) + 1; };  // x row of v_t
  auto load = [&](int t, double* out) {
    const double* in = source.row(source_row(t));
    if (scale == 1.0) {
      std::copy(in + l0, in + l1, out);
    } else {
      for (int l = l0; l < l1; ++l) out[l - l0] = in[l] * scale;
    }
  };
  for (int j = 0; j < h; ++j) {
    load(2 * j, panel.re.row(j));
    load(2 * j + 1, panel.im.row(j));
  }
  fft(false, panel);
  const bool second = resultInSecondBuffers();
  const Array2& z_re = second ? panel.re2 : panel.re;
  const Array2& z_im = second ? panel.im2 : panel.im;
  for (int k = 0; k <= h / 2; ++k) {
    // Rows k and h − k of Z give V_k, V_{h−k} and their mirrors V_{n−k}, V_{n−h+k}.
    const int k2 = (h - k) % h;  // Z_h = Z_0
    const double* __restrict__ zr_a = z_re.row(k % h);  // panel column i holds lane l0 + i
    const double* __restrict__ zi_a = z_im.row(k % h);
    const double* __restrict__ zr_b = z_re.row(k2);
    const double* __restrict__ zi_b = z_im.row(k2);
    const int ka = k, kb = h - k;  // the two V indices produced
    const double wa_c = twiddle_cos_[ka % h], wa_s = ka == h ? 0.0 : twiddle_sin_[ka % h];
    const double wb_c = kb == h ? -1.0 : twiddle_cos_[kb], wb_s = kb == h ? 0.0 : twiddle_sin_[kb];
    const double ca = shift_cos_[ka], sa = shift_sin_[ka], cna = shift_cos_[n - ka], sna = shift_sin_[n - ka];
    const double cb = shift_cos_[kb], sb = shift_sin_[kb], cnb = shift_cos_[n - kb], snb = shift_sin_[n - kb];
    double* xa = work_.row(ka) + l0;  // rows kb and n − kb coincide when kb = h: no __restrict__
    double* xna = ka == 0 ? nullptr : work_.row(n - ka) + l0;
    double* xb = work_.row(kb) + l0;
    double* xnb = work_.row(n - kb) + l0;
    const bool do_b = kb != ka;
    for (int i = 0; i < width; ++i) {
      // E_a = (Z_a + conj Z_b)/2, O_a = (Z_a − conj Z_b)/(2i); E_b, O_b likewise with a ↔ b.
      const double ar = zr_a[i], ai = zi_a[i], br = zr_b[i], bi = zi_b[i];
      const double ea_r = 0.5 * (ar + br), ea_i = 0.5 * (ai - bi);
      const double oa_r = 0.5 * (ai + bi), oa_i = -0.5 * (ar - br);
      // V_a = E_a + e^{−2πi a/n} O_a, with e^{−iθ} = (cos θ, −sin θ).
      const double va_r = ea_r + (wa_c * oa_r + wa_s * oa_i);
      const double va_i = ea_i + (wa_c * oa_i - wa_s * oa_r);
      xa[i] = ca * va_r + sa * va_i;
      if (xna != nullptr) xna[i] = cna * va_r - sna * va_i;  // V_{n−a} = conj V_a
      if (do_b) {
        const double eb_r = 0.5 * (br + ar), eb_i = 0.5 * (bi - ai);
        const double ob_r = 0.5 * (bi + ai), ob_i = -0.5 * (br - ar);
        const double vb_r = eb_r + (wb_c * ob_r + wb_s * ob_i);
        const double vb_i = eb_i + (wb_c * ob_i - wb_s * ob_r);
        xb[i] = cb * vb_r + sb * vb_i;
        xnb[i] = cnb * vb_r - snb * vb_i;
      }
    }
  }
}

// Inverse transform along lines of the lanes [l0, l1) of work_, into `target` (lines × lanes),
// the FFT in `panel` as in forward_transform: the dense path writes dense_out_.
void FastPressureSolver2::inverseTransform(Array2& target, int l0, int l1, FftPanel& panel) {
  const int n = lines_;
  if (dense_) {
    // out_j = Σ_k φ_k(j) in_k, k ascending.
    for (int j0 = 0; j0 < n; j0 += 4) {
      const int jb = std::min(4, n - j0);
      for (int jj = 0; jj < jb; ++jj) std::fill(dense_out_.row(j0 + jj) + l0, dense_out_.row(j0 + jj) + l1, 0.0);
      for (int k = 0; k < n; ++k) {
        const double* __restrict__ in = work_.row(k);
        for (int jj = 0; jj < jb; ++jj) {
          const double c = basis_t_(k, j0 + jj);
          double* __restrict__ out = dense_out_.row(j0 + jj);
          for (int l = l0; l < l1; ++l) out[l] += c * in[l];
        }
      }
    }
    return;
  }
  // Inverse of the forward DCT-II: V_t = e^{iπt/2n} (X_t − i X_{n−t}) (X_n = 0) is the FFT of
  // the real v, so E_k = (V_k + conj V_{h−k})/2 and O_k = (V_k − conj V_{h−k}) e^{2πik/n}/2 are
  // the FFTs of its even and odd samples, and z = IFFT_h(E + iO)/h = v_{2j} + i v_{2j+1}.
  // Then x_{2t} = v_t, x_{2t+1} = v_{n−1−t}.
  const int h = n / 2;
  const int width = l1 - l0;
  for (int k = 0; k < h; ++k) {
    const double cw = twiddle_cos_[k], sw = twiddle_sin_[k];
    double* __restrict__ zr = panel.re.row(k);  // panel column i holds lane l0 + i
    double* __restrict__ zi = panel.im.row(k);
    const double ca = shift_cos_[k], sa = shift_sin_[k];
    const double cb = shift_cos_[h - k], sb = shift_sin_[h - k];
    const double* __restrict__ xa = work_.row(k) + l0;
    const double* __restrict__ xna = k == 0 ? nullptr : work_.row(n - k) + l0;
    const double* __restrict__ xb = work_.row(h - k) + l0;
    const double* __restrict__ xnb = work_.row(n - (h - k)) + l0;
    for (int i = 0; i < width; ++i) {
      const double a_x = xa[i], a_nx = xna != nullptr ? xna[i] : 0.0;
      const double ar = a_x * ca + a_nx * sa;  // V_k
      const double ai = a_x * sa - a_nx * ca;
      const double b_x = xb[i], b_nx = xnb[i];
      const double br = b_x * cb + b_nx * sb;  // conj V_{h−k}
      const double bi = -(b_x * sb - b_nx * cb);
      const double er = 0.5 * (ar + br), ei = 0.5 * (ai + bi);
      const double dr = 0.5 * (ar - br), di = 0.5 * (ai - bi);
      const double or_ = cw * dr - sw * di, oi = cw * di + sw * dr;  // × e^{2πik/n}
      zr[i] = er - oi;
      zi[i] = ei + or_;
    }
  }
  fft(true, panel);
  const bool second = resultInSecondBuffers();
  const Array2& z_re = second ? panel.re2 : panel.re;
  const Array2& z_im = second ? panel.im2 : panel.im;
  const double inv_h = 1.0 / h;
  auto target_row = [n, h](int t) { return t < h ? 2 * t : 2 * (n - 1 - t) + 1; };  // x row of v_t
  for (int j = 0; j < h; ++j) {
    const double* zr = z_re.row(j);
    const double* zi = z_im.row(j);
    double* even = target.row(target_row(2 * j)) + l0;
    double* odd = target.row(target_row(2 * j + 1)) + l0;
    for (int i = 0; i < width; ++i) {
      even[i] = zr[i] * inv_h;
      odd[i] = zi[i] * inv_h;
    }
  }
}

// For each mode k in [k0, k1) (row k of work_), solves (T_lanes + λ_k I) x = f in place. Eight
// modes are swept together so that their independent recurrences overlap in the pipeline.
void FastPressureSolver2::solveModes(int k0_begin, int k1) {
  const int m = lanes_;
  constexpr int kBlock = 8;
  const bool has_singular = singular_ && k0_begin == 0;
  const int first = has_singular ? 1 : k0_begin;
  for (int k0 = first; k0 < k1; k0 += kBlock) {
    const int kb = std::min(kBlock, k1 - k0);
    double* x[kBlock];
    const double* inv[kBlock];
    for (int kk = 0; kk < kb; ++kk) {
      x[kk] = work_.row(k0 + kk);
      inv[kk] = pivots_.row(k0 + kk);
    }
    for (int kk = 0; kk < kb; ++kk) x[kk][0] *= inv[kk][0];
    for (int l = 1; l < m; ++l) {
      for (int kk = 0; kk < kb; ++kk) x[kk][l] = (x[kk][l] + x[kk][l - 1]) * inv[kk][l];
    }
    for (int l = m - 2; l >= 0; --l) {
      for (int kk = 0; kk < kb; ++kk) x[kk][l] += inv[kk][l] * x[kk][l + 1];
    }
  }
  if (has_singular) {
    // Mode 0 of a closed box: T x = f with T the Neumann Laplacian (singular, f sums to 0).
    // With g_l = x_l − x_{l+1}: g_0 = f_0, g_l = g_{l−1} + f_l; x_0 = 0, x_{l+1} = x_l − g_l;
    // then mean zero.
    double* x = work_.row(0);
    // Mode 0 is constant along the lines, so removing the mean of b is removing the mean of
    // this lane vector (O(m) instead of a pass over b).
    const double f_mean = sum(x, static_cast<std::size_t>(m)) / m;
    for (int l = 0; l < m; ++l) x[l] -= f_mean;
    double g = 0.0;
    double previous = 0.0;
    double sum = 0.0;
    for (int l = 0; l < m; ++l) {
      g += x[l];
      x[l] = previous;
      sum += previous;
      previous -= g;
    }
    const double mean = sum / m;
    for (int l = 0; l < m; ++l) x[l] -= mean;
  }
}

void FastPressureSolver2::solve(const Walls& walls, const Array2& b, Array2& q, bool prefer_dense,
                                double output_scale) {
  solve(pressureOperator(walls), b, q, prefer_dense, output_scale);
}

void FastPressureSolver2::solve(const KroneckerOperator2& op, const Array2& b, Array2& q, bool prefer_dense,
                                double output_scale) {
  const int nx = b.nx();
  const int ny = b.ny();
  setup(op, nx, ny, prefer_dense);
  q.resize(nx, ny);
  if (dense_) dense_out_.resize(lanes_, lines_);
  const bool transposed = transposed_;
  const bool dense = dense_;
  const int h = lines_ / 2;
  panels_.resize(static_cast<std::size_t>(workers_ == nullptr ? 1 : workers_->threads()));
  // A thread's panel is sized (and first touched) by that thread, once per shape.
  auto panel_for = [&](int part, int l0, int l1) -> FftPanel& {
    FftPanel& panel = panels_[static_cast<std::size_t>(part)];
    if (!dense) {
      for (Array2* a : {&panel.re, &panel.im, &panel.re2, &panel.im2}) a->resize(l1 - l0, h);
    }
    return panel;
  };
  // The transform is linear: scaling its input scales the solution. In a closed box the mean of
  // b (round-off only, the fluxes telescope) is ignored by the singular mode's recurrence.
  // Threads share the lanes of the transforms and the modes of the tridiagonal solves; every
  // value gets the serial arithmetic (worker_pool.hpp).
  forThreadPieces(workers_, 0, lanes_, kLanesPerCacheLine, [&](int l0, int l1, int part) {
    FftPanel& panel = panel_for(part, l0, l1);
    if (transposed) {
      transposeRows(b, l0, l1, [output_scale](double value) { return value * output_scale; }, work_);
      forwardTransform(work_, 1.0, l0, l1, panel);
    } else if (dense) {
      for (int j = 0; j < ny; ++j) {
        const double* src = b.row(j);
        double* dst = work_.row(j);
        if (output_scale == 1.0) {
          std::copy(src + l0, src + l1, dst + l0);
        } else {
          for (int l = l0; l < l1; ++l) dst[l] = src[l] * output_scale;
        }
      }
      forwardTransform(work_, 1.0, l0, l1, panel);
    } else {
      forwardTransform(b, output_scale, l0, l1, panel);
    }
  });
  if (dense) std::swap(work_, dense_out_);
  forPieces(workers_, 0, lines_, [&](int k0, int k1, int) { solveModes(k0, k1); });
  forThreadPieces(workers_, 0, lanes_, kLanesPerCacheLine, [&](int l0, int l1, int part) {
    FftPanel& panel = panel_for(part, l0, l1);
    if (transposed) {
      inverseTransform(work_, l0, l1, panel);  // the dense path writes dense_out_
      const Array2& result = dense ? dense_out_ : work_;
      transposeColumns(result, l0, l1, q);
    } else {
      inverseTransform(q, l0, l1, panel);  // the dense path writes dense_out_
    }
  });
  if (dense && !transposed) std::swap(q, dense_out_);
}

namespace {

// projectionRhs (pressure_solver2.hpp) on rows [j0, j1), with max |b| of those rows.
void projectionRhsRows(const MacGrid2& grid, Array2& b, int j0, int j1, MaxAbsAccumulator& b_max) {
  const double dx = grid.dx_m;
  for (int j = j0; j < j1; ++j) {
    const double* u = grid.u_m_per_s.row(j);
    const double* v_s = grid.v_m_per_s.row(j);
    const double* v_n = grid.v_m_per_s.row(j + 1);
    double* out = b.row(j);
    for (int i = 0; i < grid.nx; ++i) out[i] = -dx * ((u[i + 1] - u[i]) + (v_n[i] - v_s[i]));
    int i = 0;
    for (; i + 4 <= grid.nx; i += 4) b_max.add4(out + i);
    for (; i < grid.nx; ++i) b_max.add(out[i]);
  }
}

}  // namespace

LinearSolveReport FastPressureSolver2::project(MacGrid2& grid, const Walls& walls, double density_kg_per_m3,
                                               double dt_s) {
  rhs_.resize(grid.nx, grid.ny);
  const int parts = pieceCount(workers_);
  std::vector<MaxAbsAccumulator>& acc = accumulators_;
  acc.assign(static_cast<std::size_t>(parts), MaxAbsAccumulator{});
  // Maxima do not depend on the order in which values meet: per-piece accumulators, merged.
  forPieces(workers_, 0, grid.ny, [&](int j0, int j1, int part) { projectionRhsRows(grid, rhs_, j0, j1, acc[part]); });
  for (int part = 1; part < parts; ++part) acc[0].merge(acc[part]);
  const double b_norm = acc[0].result();
  // Solve for p = q ρ / dt directly and subtract (dt/ρ) ∇p.
  solve(walls, rhs_, grid.pressure_pa, false, density_kg_per_m3 / dt_s);
  subtractGradient(grid, walls, grid.pressure_pa, dt_s / (density_kg_per_m3 * grid.dx_m), workers_);
  LinearSolveReport report;
  report.relative_residual = b_norm > 0.0 ? maxAbsCellFlux_m2_per_s(grid, workers_) / b_norm : 0.0;
  return report;
}

}  // namespace creaturelab::fluid
