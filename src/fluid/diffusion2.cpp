#include "fluid/diffusion2.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fluid/boundary2.hpp"
#include "fluid/diffusion_operator2.hpp"

namespace creaturelab::fluid {
namespace {

// How a sweep forms the new iterate from the Jacobi value J = b + α (Σ_nb x − d x) = x + r,
// r = b − A x: Richardson takes J itself; Chebyshev's first step takes x + ω r and its later
// steps x + ω r + γ (x − x_prev), with x_prev read from the output before it is overwritten.
enum class SweepRule { richardson, chebyshev_first, chebyshev };
struct SweepWeights {
  double omega = 1.0, gamma = 0.0;
};

// The new value of one face from its value c, Jacobi value jac and the output's old value;
// returns its residual r = jac − c (a Richardson sweep's change x_new − x).
template <SweepRule kRule>
inline double sweepFace(double c, double jac, double& out, SweepWeights w) {
  const double r = jac - c;
  if constexpr (kRule == SweepRule::richardson) {
    out = jac;
  } else if constexpr (kRule == SweepRule::chebyshev_first) {
    out = c + w.omega * r;
  } else {
    out = (c + w.omega * r) + w.gamma * (c - out);
  }
  return r;
}
#if defined(__AVX2__)
template <SweepRule kRule>
inline __m256d sweepFace4(__m256d c, __m256d jac, double* out, SweepWeights w) {
  const __m256d r = _mm256_sub_pd(jac, c);
  if constexpr (kRule == SweepRule::richardson) {
    _mm256_storeu_pd(out, jac);
  } else if constexpr (kRule == SweepRule::chebyshev_first) {
    _mm256_storeu_pd(out, _mm256_add_pd(c, _mm256_mul_pd(_mm256_set1_pd(w.omega), r)));
  } else {
    const __m256d step = _mm256_add_pd(c, _mm256_mul_pd(_mm256_set1_pd(w.omega), r));
    _mm256_storeu_pd(out,
                     _mm256_add_pd(step, _mm256_mul_pd(_mm256_set1_pd(w.gamma), _mm256_sub_pd(c, _mm256_loadu_pd(out)))));
  }
  return r;
}
#endif
#if defined(__SSE2__)
template <SweepRule kRule>
inline __m128d sweepFace2(__m128d c, __m128d jac, double* out, SweepWeights w) {
  const __m128d r = _mm_sub_pd(jac, c);
  if constexpr (kRule == SweepRule::richardson) {
    _mm_storeu_pd(out, jac);
  } else if constexpr (kRule == SweepRule::chebyshev_first) {
    _mm_storeu_pd(out, _mm_add_pd(c, _mm_mul_pd(_mm_set1_pd(w.omega), r)));
  } else {
    const __m128d step = _mm_add_pd(c, _mm_mul_pd(_mm_set1_pd(w.omega), r));
    _mm_storeu_pd(out, _mm_add_pd(step, _mm_mul_pd(_mm_set1_pd(w.gamma), _mm_sub_pd(c, _mm_loadu_pd(out)))));
  }
  return r;
}
#endif

// One sweep on rows [jb, je) of the block: the new iterate (by kRule) into x_new. Returns
// max |b − A x| over those rows, the residual of the old iterate x (NaN if any value is NaN).
// A Richardson sweep x_new = x + (b − A x) = b + α (Σ_nb x − d x) contracts every error mode
// by at least 10 α; Chebyshev's weights make the sweeps of a solve the optimal polynomial on
// the matrix's spectrum (ImplicitDiffusion2::chebyshev).
template <SweepRule kRule>
double sweepRows(int ib, int ie, int jb, int je, const Array2& count, double alpha, const Array2& b,
                  const Array2& x, Array2& x_new, SweepWeights w = {}) {
  const int nx = x.nx();
  const int ny = x.ny();
  double change = 0.0;
  for (int j = jb; j < je; ++j) {
    const double* __restrict__ c = x.row(j);
    const double* __restrict__ s = j > 0 ? x.row(j - 1) : nullptr;
    const double* __restrict__ n = j < ny - 1 ? x.row(j + 1) : nullptr;
    const double* __restrict__ d = count.row(j);
    const double* __restrict__ br = b.row(j);
    double* __restrict__ out = x_new.row(j);
    const int lo = std::max(ib, 1);
    const int hi = std::min(ie, nx - 1);
    // The residual of each face is accumulated as it is computed (the maximum and the NaN flag
    // of a row do not depend on the order in which its values meet).
    MaxAbsAccumulator row_max;
    int i = lo;
    if (s != nullptr && n != nullptr) {
#if defined(__AVX2__)
      // Four faces at a time, the same operations per face as the loops below. (Eight at a time under
      // AVX-512F was rejected: no faster.)
      const __m256d alpha4 = _mm256_set1_pd(alpha), four4 = _mm256_set1_pd(4.0);
      for (; i + 4 <= hi; i += 4) {
        const __m256d ci = _mm256_loadu_pd(c + i);
        const __m256d sum = _mm256_add_pd(_mm256_add_pd(_mm256_loadu_pd(c + i - 1), _mm256_loadu_pd(c + i + 1)),
                                          _mm256_add_pd(_mm256_loadu_pd(s + i), _mm256_loadu_pd(n + i)));
        const __m256d jac = _mm256_add_pd(_mm256_loadu_pd(br + i),
                                          _mm256_mul_pd(alpha4, _mm256_sub_pd(sum, _mm256_mul_pd(four4, ci))));
        const __m256d r = sweepFace4<kRule>(ci, jac, out + i, w);
        row_max.add2x2(_mm256_castpd256_pd128(r), _mm256_extractf128_pd(r, 1));
      }
#endif
#if defined(__SSE2__)
      const __m128d alpha2 = _mm_set1_pd(alpha), four = _mm_set1_pd(4.0);
      for (; i + 2 <= hi; i += 2) {
        const __m128d ci = _mm_loadu_pd(c + i);
        const __m128d sum = _mm_add_pd(_mm_add_pd(_mm_loadu_pd(c + i - 1), _mm_loadu_pd(c + i + 1)),
                                       _mm_add_pd(_mm_loadu_pd(s + i), _mm_loadu_pd(n + i)));
        const __m128d jac = _mm_add_pd(_mm_loadu_pd(br + i), _mm_mul_pd(alpha2, _mm_sub_pd(sum, _mm_mul_pd(four, ci))));
        row_max.add2(sweepFace2<kRule>(ci, jac, out + i, w));
      }
#endif
      for (; i < hi; ++i) {
        const double jac = br[i] + alpha * (((c[i - 1] + c[i + 1]) + (s[i] + n[i])) - 4.0 * c[i]);  // d = 4 here
        row_max.add(sweepFace<kRule>(c[i], jac, out[i], w));
      }
    } else {
      for (; i < hi; ++i) {
        const double vertical = (s != nullptr ? s[i] : 0.0) + (n != nullptr ? n[i] : 0.0);
        const double jac = br[i] + alpha * (((c[i - 1] + c[i + 1]) + vertical) - d[i] * c[i]);
        row_max.add(sweepFace<kRule>(c[i], jac, out[i], w));
      }
    }
    for (int e : {ib, ie - 1}) {
      if (e >= lo && e < hi) continue;
      double sum = 0.0;
      if (e > 0) sum += c[e - 1];
      if (e < nx - 1) sum += c[e + 1];
      if (s != nullptr) sum += s[e];
      if (n != nullptr) sum += n[e];
      row_max.add(sweepFace<kRule>(c[e], br[e] + alpha * (sum - d[e] * c[e]), out[e], w));
    }
    const double row_change = row_max.result();
    change = row_change > change || row_change != row_change ? row_change : change;  // NaN sticks
  }
  return change;
}

// The CG update x += a p, r −= a Ap on the elements [k0, k1), fused with the reductions that
// follow it: max |r| into r_max, and r·r returned (four partial sums in a fixed pattern, see
// array2.hpp). The solver calls it per row and sums the rows in row order, so that threads
// sharing the rows give the same bits.
double update(std::size_t k0, std::size_t k1, double a, double* __restrict__ x, const double* __restrict__ p,
              double* __restrict__ r, const double* __restrict__ ap, MaxAbsAccumulator& r_max) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::size_t k = k0;
#if defined(__SSE2__)
  // The scalar loop below, two lanes per register: the same operations per element.
  const __m128d a2 = _mm_set1_pd(a);
  __m128d s01 = _mm_setzero_pd(), s23 = _mm_setzero_pd();
  for (; k + 4 <= k1; k += 4) {
    _mm_storeu_pd(x + k, _mm_add_pd(_mm_loadu_pd(x + k), _mm_mul_pd(a2, _mm_loadu_pd(p + k))));
    _mm_storeu_pd(x + k + 2, _mm_add_pd(_mm_loadu_pd(x + k + 2), _mm_mul_pd(a2, _mm_loadu_pd(p + k + 2))));
    const __m128d r01 = _mm_sub_pd(_mm_loadu_pd(r + k), _mm_mul_pd(a2, _mm_loadu_pd(ap + k)));
    const __m128d r23 = _mm_sub_pd(_mm_loadu_pd(r + k + 2), _mm_mul_pd(a2, _mm_loadu_pd(ap + k + 2)));
    _mm_storeu_pd(r + k, r01);
    _mm_storeu_pd(r + k + 2, r23);
    r_max.add2x2(r01, r23);
    s01 = _mm_add_pd(s01, _mm_mul_pd(r01, r01));
    s23 = _mm_add_pd(s23, _mm_mul_pd(r23, r23));
  }
  s0 = _mm_cvtsd_f64(s01), s1 = _mm_cvtsd_f64(_mm_unpackhi_pd(s01, s01));
  s2 = _mm_cvtsd_f64(s23), s3 = _mm_cvtsd_f64(_mm_unpackhi_pd(s23, s23));
#else
  for (; k + 4 <= k1; k += 4) {
    for (std::size_t l = k; l < k + 4; ++l) {
      x[l] += a * p[l];
      r[l] -= a * ap[l];
    }
    r_max.add4(r[k], r[k + 1], r[k + 2], r[k + 3]);
    s0 += r[k] * r[k];
    s1 += r[k + 1] * r[k + 1];
    s2 += r[k + 2] * r[k + 2];
    s3 += r[k + 3] * r[k + 3];
  }
#endif
  for (; k < k1; ++k) {
    x[k] += a * p[k];
    r[k] -= a * ap[k];
    r_max.add(r[k]);
    s0 += r[k] * r[k];
  }
  return (s0 + s1) + (s2 + s3);
}

// Σ_j row_values[j] for j in [0, rows), in row order.
double sumRows(const std::vector<double>& row_values) {
  double total = 0.0;
  for (double value : row_values) total += value;
  return total;
}

// Per-thread maxima combined by the rule of sweep_rows's row loop (NaN sticks): the
// serial result, whatever the pieces.
double maxOfParts(const double* parts, int count) {
  double m = parts[0];
  for (int k = 1; k < count; ++k) m = parts[k] > m || parts[k] != parts[k] ? parts[k] : m;
  return m;
}

// The walls with every inflow speed set to zero (their faces then read u·n = 0).
Walls withoutInflowSpeeds(Walls walls) {
  for (Wall* wall : {&walls.left, &walls.right, &walls.bottom, &walls.top}) wall->inflow_m_per_s = 0.0;
  return walls;
}

}  // namespace

void DiffusionSolver2::explicitHalf(FaceAxis axis, Array2& x, const Walls& walls, double beta) {
  DiffusionBlock2& block = axis == FaceAxis::x ? explicit_u_ : explicit_v_;
  block.prepare(axis, x.nx(), x.ny(), walls);
  explicit_ax_.resize(x.nx(), x.ny());
  explicit_dots_.resize(static_cast<std::size_t>(x.ny()));
  // A x reads the neighbouring rows of x, so all of it is formed before x is overwritten.
  forPieces(workers_, block.j_begin, block.j_end, [&](int j0, int j1, int) {
    applyDiffusionRows(block, j0, j1, beta, x, explicit_ax_, explicit_dots_.data());
  });
  forPieces(workers_, block.j_begin, block.j_end, [&](int j0, int j1, int) {
    for (int j = j0; j < j1; ++j) {
      double* __restrict__ xr = x.row(j);
      const double* __restrict__ ax = explicit_ax_.row(j);
      const double* __restrict__ wall = block.wall_rhs.row(j);
      for (int i = block.i_begin; i < block.i_end; ++i) xr[i] = (2.0 * xr[i] - ax[i]) + beta * wall[i];
    }
  });
}

LinearSolveReport DiffusionSolver2::diffuseVelocity(MacGrid2& grid, const Walls& walls,
                                                     double kinematic_viscosity_m2_per_s, double dt_s,
                                                     ViscosityScheme scheme) {
  double alpha = kinematic_viscosity_m2_per_s * dt_s / (grid.dx_m * grid.dx_m);
  if (alpha == 0.0) return {};
  // The solvers take every face off the unknown block as zero; an inflow wall's speed enters
  // through the block's wall terms instead (diffusion_operator2.hpp). So its faces are cleared
  // for the solve and set again after it.
  const bool any_inflow = walls.anyInflow();
  if (any_inflow) enforceWallNormalVelocity(grid, withoutInflowSpeeds(walls));
  if (scheme == ViscosityScheme::crank_nicolson) {
    alpha *= 0.5;
    explicitHalf(FaceAxis::x, grid.u_m_per_s, walls, alpha);
    explicitHalf(FaceAxis::y, grid.v_m_per_s, walls, alpha);
  }
  const LinearSolveReport ru = diffuseComponent(FaceAxis::x, grid.u_m_per_s, walls, alpha);
  const LinearSolveReport rv = diffuseComponent(FaceAxis::y, grid.v_m_per_s, walls, alpha);
  if (any_inflow) enforceWallNormalVelocity(grid, walls);
  return {std::max(ru.iterations, rv.iterations), std::max(ru.relative_residual, rv.relative_residual),
          ru.converged && rv.converged};
}

LinearSolveReport ImplicitDiffusion2::solveComponent(FaceAxis axis, Array2& x, const Walls& walls, double alpha,
                                                      Workspace& w) {
  const int nx = x.nx();
  const int ny = x.ny();
  if (w.block.prepare(axis, nx, ny, walls)) {
    for (Array2* a : {&w.b, &w.r, &w.p, &w.ap}) {
      a->resize(0, 0);
      a->resize(nx, ny);
    }
  }
  const DiffusionBlock2& block = w.block;

  // Threads share rows everywhere below; every element gets the serial arithmetic, maxima merge
  // per thread (order-free) and sums are kept per row and added in row order (worker_pool.hpp).
  const int parts = pieceCount(workers_);
  const std::size_t row = static_cast<std::size_t>(nx);
  w.row_dots.resize(static_cast<std::size_t>(ny));
  w.row_rr.resize(static_cast<std::size_t>(ny));

  // b = x^n + α · (wall terms) on the unknown block (zero elsewhere: x is zero there).
  std::array<MaxAbsAccumulator, kMaxParts> acc{};
  {
    const double* __restrict__ xv = x.data();
    const double* __restrict__ wall = block.wall_rhs.data();
    double* __restrict__ b = w.b.data();
    forPieces(workers_, 0, ny, [&](int j0, int j1, int part) {
      const std::size_t k0 = j0 * row, k1 = j1 * row;
      if (block.has_wall_rhs) {
        for (std::size_t k = k0; k < k1; ++k) b[k] = xv[k] + alpha * wall[k];
      } else {
        std::copy(xv + k0, xv + k1, b + k0);
      }
      acc[part].merge(partialMaxAbs(b + k0, k1 - k0));
    });
  }
  for (int part = 1; part < parts; ++part) acc[0].merge(acc[part]);
  const double b_norm = acc[0].result();
  if (b_norm == 0.0) {
    x.fill(0.0);
    return {};
  }
  const double target = tolerance_ * b_norm;

  // Warm start for small α: Richardson sweeps x ← x + (b − A x) contract every error mode
  // by |1 − λ(A)| ≤ α max_row Σ|A_ij − δ_ij| ≤ 10 α, i.e. by ≥ 10× per sweep when 10 α ≤
  // 0.1, at the cost of one pass each (a CG iteration costs three). The limit 0.1 keeps water at
  // 256² and dt = 0.01 s (10 α = 0.053) on sweeps. Water on the paper's grid
  // has α ~ 1e-3: two to four sweeps reach the tolerance and CG is not needed.
  int sweeps = 0;
  if (10.0 * alpha <= kSweepContraction) {
    while (sweeps < kMaxSweeps) {
      std::array<double, kMaxParts> change{};
      forPieces(workers_, block.j_begin, block.j_end, [&](int j0, int j1, int part) {
        change[part] = sweepRows<SweepRule::richardson>(block.i_begin, block.i_end, j0, j1, block.count, alpha, w.b, x, w.p);
      });
      const double residual = maxOfParts(change.data(), parts);
      std::swap(x, w.p);  // O(1): the newest iterate is in x; w.p keeps zeros off the block
      ++sweeps;
      // `residual` belongs to the previous iterate; the new one's is r_new = (I − A) r with
      // ‖I − A‖∞ = α max_row (d + neighbours) ≤ 10 α, a rigorous bound we report.
      const double new_residual_bound = 10.0 * alpha * residual;
      if (new_residual_bound <= target) return {sweeps, new_residual_bound / b_norm, true};
      if (!(residual == residual)) return {sweeps, residual, false};
    }
  }

  const int budget = max_iterations_;
  // (max_row_sum = 0 only for a block with no neighbours at all, A = I: CG's one iteration.)
  const bool chebyshev_range = block.max_row_sum > 0.0 && alpha * block.max_row_sum <= kChebyshevSpread;
  const LinearSolveReport rest = chebyshev_range
                                     ? chebyshev(x, alpha, target, b_norm, budget, w)
                                     : conjugateGradients(x, alpha, target, b_norm, budget, w);
  return {sweeps + rest.iterations, rest.relative_residual, rest.converged};
}

LinearSolveReport ImplicitDiffusion2::chebyshev(Array2& x, double alpha, double target, double b_norm, int budget,
                                                Workspace& w) {
  // A's spectrum lies in [1, 1 + α g] (Gershgorin, g = block.max_row_sum). Chebyshev's
  // semi-iteration on that interval (Saad 2003, Algorithm 12.1) with the residual formed afresh
  // by each sweep: θ, δ the interval's centre and half-width, σ₁ = θ/δ; x₁ = x₀ + r₀/θ, then
  // x_{k+1} = x_k + ω_k r_k + γ_k (x_k − x_{k−1}), ρ_k = 1/(2σ₁ − ρ_{k−1}), ρ₀ = 1/σ₁,
  // ω_k = 2ρ_k/δ, γ_k = ρ_k ρ_{k−1}. The error contracts by (√κ − 1)/(√κ + 1) per sweep,
  // κ = 1 + α g, CG's worst-case rate, but a sweep is one pass over three arrays where a CG
  // iteration is three passes and two reductions. x_{k+1} overwrites x_{k−1} face by face.
  // Rejected: two or three sweeps fused into one pass over the rows (a row wavefront, bitwise the
  // same, with a spare array for the iterate the solve may stop at). It was no faster: the sweeps
  // are bound by their arithmetic more than by memory, while the spare array takes the pass beyond
  // L2 and a pass computes one sweep past the accepted iterate half the time.
  const DiffusionBlock2& block = w.block;
  const int parts = pieceCount(workers_);
  const double delta = 0.5 * alpha * block.max_row_sum;
  const double theta = 1.0 + delta;
  const double sigma = theta / delta;
  double rho = 1.0 / sigma;
  Array2* current = &x;
  Array2* other = &w.p;  // zero off the block, as x is
  double residual = 0.0;
  int sweeps = 0;
  for (;;) {
    std::array<double, kMaxParts> part_residual{};
    if (sweeps == 0) {
      const SweepWeights first{1.0 / theta, 0.0};
      forPieces(workers_, block.j_begin, block.j_end, [&](int j0, int j1, int part) {
        part_residual[part] = sweepRows<SweepRule::chebyshev_first>(block.i_begin, block.i_end, j0, j1, block.count,
                                                                      alpha, w.b, *current, *other, first);
      });
    } else {
      const double rho_next = 1.0 / (2.0 * sigma - rho);
      const SweepWeights later{2.0 * rho_next / delta, rho_next * rho};
      rho = rho_next;
      forPieces(workers_, block.j_begin, block.j_end, [&](int j0, int j1, int part) {
        part_residual[part] = sweepRows<SweepRule::chebyshev>(block.i_begin, block.i_end, j0, j1, block.count,
                                                                alpha, w.b, *current, *other, later);
      });
    }
    residual = maxOfParts(part_residual.data(), parts);  // that of *current
    ++sweeps;
    if (residual <= target || !(residual == residual) || sweeps >= budget) break;
    std::swap(current, other);
  }
  if (current != &x) std::swap(x, w.p);  // O(1): the accepted iterate into x
  return {sweeps, residual / b_norm, residual <= target};
}

LinearSolveReport ImplicitDiffusion2::conjugateGradients(Array2& x, double alpha, double target, double b_norm,
                                                          int budget, Workspace& w) {
  const DiffusionBlock2& block = w.block;
  const int parts = pieceCount(workers_);
  const int nx = x.nx();
  const int ny = x.ny();
  const std::size_t row = static_cast<std::size_t>(nx);
  std::array<MaxAbsAccumulator, kMaxParts> acc{};
  // Conjugate gradients for A x = b from the current x. Unpreconditioned: the diagonal 1 + α d
  // varies only at the walls (d = 2..6), so Jacobi scaling buys nothing; cond(A) ≤ 1 + 8α.
  // The inner products are sums of per-row partial sums in row order (so that threads can share
  // the rows); one pattern over the whole array would round differently
  // (tests/unit/fluid_stages_test.cpp compares the two to the tolerance).
  double* __restrict__ xv = x.data();
  double* __restrict__ r = w.r.data();
  double* __restrict__ p = w.p.data();
  const double* __restrict__ ap = w.ap.data();
  const double* __restrict__ b = w.b.data();
  auto apply_rows = [&](const Array2& in) {
    forPieces(workers_, block.j_begin, block.j_end, [&](int j0, int j1, int) {
      applyDiffusionRows(block, j0, j1, alpha, in, w.ap, w.row_dots.data());
    });
    double in_dot_ap = 0.0;
    for (int j = block.j_begin; j < block.j_end; ++j) in_dot_ap += w.row_dots[static_cast<std::size_t>(j)];
    return in_dot_ap;
  };
  auto merged_max = [&] {
    for (int part = 1; part < parts; ++part) acc[0].merge(acc[part]);
    return acc[0].result();
  };
  apply_rows(x);
  // r = p = b − A x (zero off the block), with ‖r‖∞ and r·r in the same pass.
  acc.fill(MaxAbsAccumulator{});
  forPieces(workers_, 0, ny, [&](int j0, int j1, int part) {
    for (int j = j0; j < j1; ++j) {
      const std::size_t k0 = j * row, k1 = k0 + row;
      for (std::size_t k = k0; k < k1; ++k) {
        r[k] = b[k] - ap[k];
        p[k] = r[k];
      }
      w.row_rr[static_cast<std::size_t>(j)] = dot(r + k0, r + k0, row);
      acc[part].merge(partialMaxAbs(r + k0, row));
    }
  });
  double rr = sumRows(w.row_rr);
  double r_norm = rr == rr ? merged_max() : rr;
  int iteration = 0;
  if (r_norm > target) {
    while (iteration < budget) {
      ++iteration;
      const double p_ap = apply_rows(w.p);
      const double a = rr / p_ap;
      acc.fill(MaxAbsAccumulator{});
      forPieces(workers_, 0, ny, [&](int j0, int j1, int part) {
        for (int j = j0; j < j1; ++j) {
          w.row_rr[static_cast<std::size_t>(j)] = update(j * row, (j + 1) * row, a, xv, p, r, ap, acc[part]);
        }
      });
      r_norm = merged_max();
      if (r_norm <= target || !(r_norm == r_norm)) break;
      const double r_squared = sumRows(w.row_rr);
      const double beta = r_squared / rr;
      rr = r_squared;
      forPieces(workers_, 0, ny, [&](int j0, int j1, int) {
        for (std::size_t k = j0 * row; k < j1 * row; ++k) p[k] = r[k] + beta * p[k];
      });
    }
  }
  return {iteration, r_norm / b_norm, r_norm <= target};
}

}  // namespace creaturelab::fluid
