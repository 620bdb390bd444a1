#include "fluid/upwind_advection2.hpp"

#include <algorithm>
#include <cmath>

#include "fluid/advection_rows2.hpp"
#include "fluid/boundary2.hpp"

namespace creaturelab::fluid {
namespace {

// Advective fluxes a q through the control-volume faces between the samples q0[i] and q1[i],
// i in [begin, end): a = ½ (a0[i] + a1[i]); q is Fromm's reconstruction from the upwind side,
// from q_{−1}, q_0 (below) or q_1, q_2 (above). a q_up = a (lo + hi)/2 − |a| (hi − lo)/2 picks
// the upwind value without a branch, so that the loop vectorises.
void frommFluxes(const double* __restrict__ a0, const double* __restrict__ a1, const double* __restrict__ qm1,
                  const double* __restrict__ q0, const double* __restrict__ q1, const double* __restrict__ q2,
                  int begin, int end, double* __restrict__ flux) {
  for (int i = begin; i < end; ++i) {
    const double a = 0.5 * (a0[i] + a1[i]);
    const double from_low = q0[i] + 0.25 * (q1[i] - qm1[i]);
    const double from_high = q1[i] - 0.25 * (q2[i] - q0[i]);
    flux[i] = 0.5 * (a * (from_low + from_high) - std::fabs(a) * (from_high - from_low));
  }
}

// One Heun stage on faces [begin, end) of a row: with the flux differences
// d = (fx_high − fx_low) + (fy_high − fy_low) and c = dt/dx,
//   predictor  out = q − c d                    (q = uⁿ)
//   corrector  out = ½ (uⁿ + (q − c d))         (q = u¹)
template <bool kCorrector>
void heunUpdate(const double* __restrict__ fx_low, const double* __restrict__ fx_high,
                 const double* __restrict__ fy_low, const double* __restrict__ fy_high, const double* __restrict__ q,
                 const double* __restrict__ un, double c, int begin, int end, double* __restrict__ out) {
  for (int i = begin; i < end; ++i) {
    const double stepped = q[i] - c * ((fx_high[i] - fx_low[i]) + (fy_high[i] - fy_low[i]));
    if constexpr (kCorrector) {
      out[i] = 0.5 * (un[i] + stepped);
    } else {
      out[i] = stepped;
    }
  }
}

// Per-thread rows of fluxes: along x, and along y below and above the row. Each has two spare
// entries before index 0 (a flux at i − ½ for i = 0 on an open wall).
struct FluxRows {
  double* x;
  double* y_low;
  double* y_high;
};
FluxRows fluxRows(std::vector<double>& scratch, int part, int length) {
  double* base = scratch.data() + static_cast<std::size_t>(part) * 3 * static_cast<std::size_t>(length) + 2;
  return {base, base + length, base + 2 * length};
}

// A Heun stage of u, rows [j0, j1): the u control volume of face (i, j) spans x ∈ [i − ½, i + ½]
// and y ∈ [j, j + 1] (cell units); its x faces are cell centres (advecting u: mean of u(i),
// u(i + 1)), its y faces cell corners (advecting v: mean of v(i − 1, j), v(i, j)).
template <bool kCorrector>
void uStageRows(const GhostedComponent2& u, const GhostedComponent2& v, const GhostedComponent2& un, double c,
                  const FaceBlock& b, int j0, int j1, FluxRows f, double* (*out_row)(void*, int), void* out) {
  // Flux through the line y = j (between u rows j − 1 and j).
  auto y_fluxes = [&](int j, double* flux) {
    const double* vj = v.row(j);
    frommFluxes(vj - 1, vj, u.row(j - 2), u.row(j - 1), u.row(j), u.row(j + 1), b.i_begin, b.i_end, flux);
  };
  y_fluxes(j0, f.y_low);
  for (int j = j0; j < j1; ++j) {
    y_fluxes(j + 1, f.y_high);
    const double* uj = u.row(j);
    frommFluxes(uj, uj + 1, uj - 1, uj, uj + 1, uj + 2, b.i_begin - 1, b.i_end, f.x);  // f.x[i]: at i + ½
    heunUpdate<kCorrector>(f.x - 1, f.x, f.y_low, f.y_high, uj, un.row(j), c, b.i_begin, b.i_end, out_row(out, j));
    std::swap(f.y_low, f.y_high);
  }
}

// A Heun stage of v, rows [j0, j1): the v control volume of face (i, j) spans x ∈ [i, i + 1]
// and y ∈ [j − ½, j + ½]; its x faces are cell corners (advecting u: mean of u(i, j − 1),
// u(i, j)), its y faces cell centres (advecting v: mean of v(i, j), v(i, j + 1)).
template <bool kCorrector>
void vStageRows(const GhostedComponent2& u, const GhostedComponent2& v, const GhostedComponent2& vn, double c,
                  const FaceBlock& b, int j0, int j1, FluxRows f, double* (*out_row)(void*, int), void* out) {
  // Flux through the line y = j + ½ (between v rows j and j + 1).
  auto y_fluxes = [&](int j, double* flux) {
    frommFluxes(v.row(j), v.row(j + 1), v.row(j - 1), v.row(j), v.row(j + 1), v.row(j + 2), b.i_begin, b.i_end, flux);
  };
  y_fluxes(j0 - 1, f.y_low);
  for (int j = j0; j < j1; ++j) {
    y_fluxes(j, f.y_high);
    const double* vj = v.row(j);
    frommFluxes(u.row(j - 1), u.row(j), vj - 2, vj - 1, vj, vj + 1, b.i_begin, b.i_end + 1, f.x);  // f.x[i]: at i
    heunUpdate<kCorrector>(f.x, f.x + 1, f.y_low, f.y_high, vj, vn.row(j), c, b.i_begin, b.i_end, out_row(out, j));
    std::swap(f.y_low, f.y_high);
  }
}

double* ghostedRow(void* target, int j) { return static_cast<GhostedComponent2*>(target)->row(j); }
double* arrayRow(void* target, int j) { return static_cast<Array2*>(target)->row(j); }

}  // namespace

void GhostedComponent2::prepare(FaceAxis axis, int nx, int ny) {
  axis_ = axis;
  nx_ = axis == FaceAxis::x ? nx + 1 : nx;
  ny_ = axis == FaceAxis::x ? ny : ny + 1;
  stride_ = nx_ + 2 * kGhost;
  data_.resize(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(ny_ + 2 * kGhost));
}

void GhostedComponent2::finish(const Walls& walls) {
  // Normal ghosts: odd about a solid wall's face value (zero, u·n = 0, or an inflow wall's speed);
  // constant across an open one (∂u/∂n = 0, boundary2.hpp). The inflow case is written apart so
  // the other solid walls keep −inside bit for bit (2·0 − 0 is +0 where −0 is −0).
  auto normal = [](const Wall& wall, double wall_value, double inside1, double inside2, double& ghost1,
                   double& ghost2) {
    if (wall.type == WallType::inflow) {
      ghost1 = 2.0 * wall_value - inside1;
      ghost2 = 2.0 * wall_value - inside2;
      return;
    }
    ghost1 = isSolid(wall) ? -inside1 : wall_value;
    ghost2 = isSolid(wall) ? -inside2 : wall_value;
  };
  const int n = axis_ == FaceAxis::x ? nx_ - 1 : ny_ - 1;  // index of the high wall's faces
  if (axis_ == FaceAxis::x) {
    for (int j = 0; j < ny_; ++j) {
      double* r = row(j);
      if (isSolid(walls.left)) r[0] = solidWallNormalVelocity(walls.left, false);
      if (isSolid(walls.right)) r[n] = solidWallNormalVelocity(walls.right, true);
      normal(walls.left, r[0], r[1], r[2], r[-1], r[-2]);
      normal(walls.right, r[n], r[n - 1], r[n - 2], r[n + 1], r[n + 2]);
    }
    // Tangential ghosts (mirrored, boundary2.hpp) over the full padded width.
    for (int i = -kGhost; i < nx_ + kGhost; ++i) {
      row(-1)[i] = tangentialGhost(walls.bottom, row(0)[i]);
      row(-2)[i] = tangentialGhost(walls.bottom, row(1)[i]);
      row(ny_)[i] = tangentialGhost(walls.top, row(ny_ - 1)[i]);
      row(ny_ + 1)[i] = tangentialGhost(walls.top, row(ny_ - 2)[i]);
    }
  } else {
    if (isSolid(walls.bottom)) std::fill(row(0), row(0) + nx_, solidWallNormalVelocity(walls.bottom, false));
    if (isSolid(walls.top)) std::fill(row(n), row(n) + nx_, solidWallNormalVelocity(walls.top, true));
    for (int i = 0; i < nx_; ++i) {
      normal(walls.bottom, row(0)[i], row(1)[i], row(2)[i], row(-1)[i], row(-2)[i]);
      normal(walls.top, row(n)[i], row(n - 1)[i], row(n - 2)[i], row(n + 1)[i], row(n + 2)[i]);
    }
    for (int j = -kGhost; j < ny_ + kGhost; ++j) {
      double* r = row(j);
      r[-1] = tangentialGhost(walls.left, r[0]);
      r[-2] = tangentialGhost(walls.left, r[1]);
      r[nx_] = tangentialGhost(walls.right, r[nx_ - 1]);
      r[nx_ + 1] = tangentialGhost(walls.right, r[nx_ - 2]);
    }
  }
}

double Upwind2Rk2Advection2::maxStableCfl() const { return maxStableCflNumber(AdvectionScheme::upwind2_rk2); }

void Upwind2Rk2Advection2::advectVelocity(const MacGrid2& grid, const Walls& walls, double dt_s, Array2& u_out,
                                           Array2& v_out) {
  const int nx = grid.nx;
  const int ny = grid.ny;
  u_out.resize(nx + 1, ny);
  v_out.resize(nx, ny + 1);
  for (GhostedComponent2* g : {&u0_, &u1_}) g->prepare(FaceAxis::x, nx, ny);
  for (GhostedComponent2* g : {&v0_, &v1_}) g->prepare(FaceAxis::y, nx, ny);
  const double c = dt_s / grid.dx_m;
  const FaceBlock ub = faceBlock<FaceAxis::x>(grid, unknownUColumns(grid, walls));
  const FaceBlock vb = faceBlock<FaceAxis::y>(grid, unknownVRows(grid, walls));
  const int length = nx + 6;
  scratch_.resize(3 * static_cast<std::size_t>(length) * static_cast<std::size_t>(pieceCount(workers_)));

  // uⁿ with its ghosts.
  const FaceBlock all_u{0, nx + 1, 0, ny};
  const FaceBlock all_v{0, nx, 0, ny + 1};
  forRowPieces(
      workers_, all_u, all_v,
      [&](int j0, int j1, int) {
        for (int j = j0; j < j1; ++j) std::copy_n(grid.u_m_per_s.row(j), nx + 1, u0_.row(j));
      },
      [&](int j0, int j1, int) {
        for (int j = j0; j < j1; ++j) std::copy_n(grid.v_m_per_s.row(j), nx, v0_.row(j));
      });
  u0_.finish(walls);
  v0_.finish(walls);

  // Predictor u¹ = uⁿ + dt L(uⁿ), then its ghosts.
  forRowPieces(
      workers_, ub, vb,
      [&](int j0, int j1, int part) {
        uStageRows<false>(u0_, v0_, u0_, c, ub, j0, j1, fluxRows(scratch_, part, length), ghostedRow, &u1_);
      },
      [&](int j0, int j1, int part) {
        vStageRows<false>(u0_, v0_, v0_, c, vb, j0, j1, fluxRows(scratch_, part, length), ghostedRow, &v1_);
      });
  u1_.finish(walls);
  v1_.finish(walls);

  // Corrector uⁿ⁺¹ = ½ uⁿ + ½ (u¹ + dt L(u¹)).
  forRowPieces(
      workers_, ub, vb,
      [&](int j0, int j1, int part) {
        uStageRows<true>(u1_, v1_, u0_, c, ub, j0, j1, fluxRows(scratch_, part, length), arrayRow, &u_out);
      },
      [&](int j0, int j1, int part) {
        vStageRows<true>(u1_, v1_, v0_, c, vb, j0, j1, fluxRows(scratch_, part, length), arrayRow, &v_out);
      });
  setSolidNormalFaces(walls, u_out, v_out);
}

}  // namespace creaturelab::fluid
