#include "fluid/advection2.hpp"

#include <algorithm>
#include <vector>

#include "fluid/boundary2.hpp"

namespace creaturelab::fluid {
namespace {

// Semi-Lagrangian transport of the staggered component `q` (on kAxis faces) along the
// velocity (U, V): out(face) = q(x_face − trajectory), RK2 midpoint backtrace. `c` is dt/dx,
// so that c·u is a displacement in cells; c < 0 traces forward (MacCormack's reverse step).
// With kBounds the four interpolated values' range is stored in lo/hi.
template <FaceAxis kAxis, bool kBounds>
void trace_and_sample(const StaggeredComponent2& U_component, const StaggeredComponent2& V_component,
                      const StaggeredComponent2& q_component, double c, FaceRange unknown, Array2& out, Array2* lo,
                      Array2* hi, std::vector<double>& scratch) {
  const SampleView U = U_component.view();
  const SampleView V = V_component.view();
  const SampleView q = q_component.view();
  scratch.resize(2 * static_cast<std::size_t>(out.nx()));
  double* __restrict__ xs = scratch.data();
  double* __restrict__ ys = xs + out.nx();
  const double half_c = 0.5 * c;
  const int nx = out.nx() - (kAxis == FaceAxis::x ? 1 : 0);
  const int ny = out.ny() - (kAxis == FaceAxis::y ? 1 : 0);
  const int i_begin = kAxis == FaceAxis::x ? unknown.begin : 0;
  const int i_end = kAxis == FaceAxis::x ? unknown.end : nx;
  const int j_begin = kAxis == FaceAxis::y ? unknown.begin : 0;
  const int j_end = kAxis == FaceAxis::y ? unknown.end : ny;
  for (int j = j_begin; j < j_end; ++j) {
    double* __restrict__ out_row = out.row(j);
    double* lo_row = kBounds ? lo->row(j) : nullptr;
    double* hi_row = kBounds ? hi->row(j) : nullptr;
    // Padded rows holding the face's own component and the four surrounding other ones.
    const double* own;
    const double* other0;
    const double* other1;
    if constexpr (kAxis == FaceAxis::x) {
      own = U.data + static_cast<long>(j + 1) * U.stride;  // u(i, j) = padded(i, j + 1)
      other0 = V.data + static_cast<long>(j) * V.stride;   // v(i − 1 .. i, j) = padded(i .. i + 1, j)
      other1 = other0 + V.stride;                          // v(i − 1 .. i, j + 1)
    } else {
      own = V.data + static_cast<long>(j) * V.stride + 1;  // v(i, j) = padded(i + 1, j)
      other0 = U.data + static_cast<long>(j) * U.stride;   // u(i .. i + 1, j − 1) = padded(i .. i + 1, j)
      other1 = other0 + U.stride;                          // u(i .. i + 1, j)
    }
    const double Y = kAxis == FaceAxis::x ? j + 0.5 : j;
    // Three short passes over the row instead of one long dependent chain per face, so that
    // the processor overlaps the independent faces (about 1.5× faster than one fused loop).
    for (int i = i_begin; i < i_end; ++i) {
      // Face position (cells) and velocity: its own component and the mean of the other one.
      const double X = kAxis == FaceAxis::x ? i : i + 0.5;
      const double own_velocity = own[i];
      const double other_velocity = 0.25 * ((other0[i] + other0[i + 1]) + (other1[i] + other1[i + 1]));
      const double vel_x = kAxis == FaceAxis::x ? own_velocity : other_velocity;
      const double vel_y = kAxis == FaceAxis::x ? other_velocity : own_velocity;
      xs[i] = X - half_c * vel_x;  // midpoint of the trajectory
      ys[i] = Y - half_c * vel_y;
    }
    int i = i_begin;
#if defined(__SSE2__)
    // Two faces at a time (same arithmetic per face as the scalar loop below).
    const __m128d c2 = _mm_set1_pd(c);
    const __m128d Y2 = _mm_set1_pd(Y);
    for (; i + 2 <= i_end; i += 2) {
      const double x0 = kAxis == FaceAxis::x ? i : i + 0.5;
      const __m128d X2 = _mm_set_pd(x0 + 1.0, x0);
      const __m128d xm = _mm_loadu_pd(xs + i);
      const __m128d ym = _mm_loadu_pd(ys + i);
      const __m128d u_mid = U.sample2(xm, ym);
      const __m128d v_mid = V.sample2(xm, ym);
      _mm_storeu_pd(xs + i, _mm_sub_pd(X2, _mm_mul_pd(c2, u_mid)));  // foot of the trajectory
      _mm_storeu_pd(ys + i, _mm_sub_pd(Y2, _mm_mul_pd(c2, v_mid)));
    }
#endif
    for (; i < i_end; ++i) {
      const double X = kAxis == FaceAxis::x ? i : i + 0.5;
      const double u_mid = U.sample(xs[i], ys[i]);
      const double v_mid = V.sample(xs[i], ys[i]);
      xs[i] = X - c * u_mid;  // foot of the trajectory
      ys[i] = Y - c * v_mid;
    }
    if constexpr (kBounds) {
      int k = i_begin;
#if defined(__SSE2__)
      for (; k + 2 <= i_end; k += 2) {
        __m128d lo2, hi2;
        _mm_storeu_pd(out_row + k, q.sample2(_mm_loadu_pd(xs + k), _mm_loadu_pd(ys + k), &lo2, &hi2));
        _mm_storeu_pd(lo_row + k, lo2);
        _mm_storeu_pd(hi_row + k, hi2);
      }
#endif
      for (; k < i_end; ++k) out_row[k] = q.sample(xs[k], ys[k], lo_row[k], hi_row[k]);
    } else {
      int k = i_begin;
#if defined(__SSE2__)
      for (; k + 2 <= i_end; k += 2) _mm_storeu_pd(out_row + k, q.sample2(_mm_loadu_pd(xs + k), _mm_loadu_pd(ys + k)));
#endif
      for (; k < i_end; ++k) out_row[k] = q.sample(xs[k], ys[k]);
    }
  }
}

void zero_solid_normal_faces(const Walls& walls, Array2& u, Array2& v) {
  const int nx = v.nx();
  const int ny = u.ny();
  if (is_solid(walls.left)) {
    for (int j = 0; j < ny; ++j) u(0, j) = 0.0;
  }
  if (is_solid(walls.right)) {
    for (int j = 0; j < ny; ++j) u(nx, j) = 0.0;
  }
  if (is_solid(walls.bottom)) {
    for (int i = 0; i < nx; ++i) v(i, 0) = 0.0;
  }
  if (is_solid(walls.top)) {
    for (int i = 0; i < nx; ++i) v(i, ny) = 0.0;
  }
}

}  // namespace

void SemiLagrangianAdvection2::advect_velocity(const MacGrid2& grid, const Walls& walls, double dt_s, Array2& u_out,
                                               Array2& v_out) {
  u_out.resize(grid.nx + 1, grid.ny);
  v_out.resize(grid.nx, grid.ny + 1);
  u_.assign(FaceAxis::x, grid.u_m_per_s, walls);
  v_.assign(FaceAxis::y, grid.v_m_per_s, walls);
  const double c = dt_s / grid.dx_m;
  trace_and_sample<FaceAxis::x, false>(u_, v_, u_, c, unknown_u_columns(grid, walls), u_out, nullptr, nullptr,
                                       scratch_);
  trace_and_sample<FaceAxis::y, false>(u_, v_, v_, c, unknown_v_rows(grid, walls), v_out, nullptr, nullptr, scratch_);
  zero_solid_normal_faces(walls, u_out, v_out);
}

void MacCormackAdvection2::advect_velocity(const MacGrid2& grid, const Walls& walls, double dt_s, Array2& u_out,
                                           Array2& v_out) {
  const int nx = grid.nx;
  const int ny = grid.ny;
  u_out.resize(nx + 1, ny);
  v_out.resize(nx, ny + 1);
  for (Array2* a : {&u_fwd_, &u_lo_, &u_hi_, &u_rev_}) a->resize(nx + 1, ny);
  for (Array2* a : {&v_fwd_, &v_lo_, &v_hi_, &v_rev_}) a->resize(nx, ny + 1);
  u_.assign(FaceAxis::x, grid.u_m_per_s, walls);
  v_.assign(FaceAxis::y, grid.v_m_per_s, walls);
  const double c = dt_s / grid.dx_m;
  const FaceRange u_cols = unknown_u_columns(grid, walls);
  const FaceRange v_rows = unknown_v_rows(grid, walls);

  // Forward semi-Lagrangian step φ̂ = A(φ), remembering the interpolation bounds.
  trace_and_sample<FaceAxis::x, true>(u_, v_, u_, c, u_cols, u_fwd_, &u_lo_, &u_hi_, scratch_);
  trace_and_sample<FaceAxis::y, true>(u_, v_, v_, c, v_rows, v_fwd_, &v_lo_, &v_hi_, scratch_);
  zero_solid_normal_faces(walls, u_fwd_, v_fwd_);

  // Backward step φ̃ = A_reversed(φ̂) along the same velocity u^n.
  u_hat_.assign(FaceAxis::x, u_fwd_, walls);
  v_hat_.assign(FaceAxis::y, v_fwd_, walls);
  trace_and_sample<FaceAxis::x, false>(u_, v_, u_hat_, -c, u_cols, u_rev_, nullptr, nullptr, scratch_);
  trace_and_sample<FaceAxis::y, false>(u_, v_, v_hat_, -c, v_rows, v_rev_, nullptr, nullptr, scratch_);

  // Correction φ̂ + ½ (φ − φ̃), clamped to [lo, hi] (Selle et al. 2008).
  auto correct = [](const Array2& phi, const Array2& fwd, const Array2& rev, const Array2& lo, const Array2& hi,
                    Array2& out) {
    const double* p = phi.data();
    const double* f = fwd.data();
    const double* r = rev.data();
    const double* l = lo.data();
    const double* h = hi.data();
    double* o = out.data();
    const std::size_t n = out.size();
    for (std::size_t k = 0; k < n; ++k) {
      const double corrected = f[k] + 0.5 * (p[k] - r[k]);
      o[k] = std::min(std::max(corrected, l[k]), h[k]);
    }
  };
  correct(grid.u_m_per_s, u_fwd_, u_rev_, u_lo_, u_hi_, u_out);
  correct(grid.v_m_per_s, v_fwd_, v_rev_, v_lo_, v_hi_, v_out);
  zero_solid_normal_faces(walls, u_out, v_out);
}

std::unique_ptr<AdvectionSolver2> make_advection_solver(AdvectionScheme scheme) {
  switch (scheme) {
    case AdvectionScheme::semi_lagrangian:
      return std::make_unique<SemiLagrangianAdvection2>();
    case AdvectionScheme::maccormack:
      return std::make_unique<MacCormackAdvection2>();
  }
  return std::make_unique<SemiLagrangianAdvection2>();
}

}  // namespace creaturelab::fluid
