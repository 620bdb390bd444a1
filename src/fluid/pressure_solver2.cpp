#include "fluid/pressure_solver2.hpp"

#include <algorithm>
#include <cmath>

#include "fluid/boundary2.hpp"
#include "fluid/diagnostics2.hpp"
#include "fluid/fast_pressure_solver2.hpp"
#include "fluid/pcg_pressure_solver2.hpp"

namespace creaturelab::fluid {

std::unique_ptr<PressureSolver2> makePressureSolver(const FluidParams& params) {
  switch (params.pressure_solver) {
    case PressureSolverType::fast_direct:
      return std::make_unique<FastPressureSolver2>();
    case PressureSolverType::pcg:
      return std::make_unique<PcgPressureSolver2>(params.pressure_tolerance, params.pressure_max_iterations);
  }
  return std::make_unique<FastPressureSolver2>();
}

void projectionRhs(const MacGrid2& grid, Array2& b) {
  b.resize(grid.nx, grid.ny);
  const double dx = grid.dx_m;
  for (int j = 0; j < grid.ny; ++j) {
    const double* u = grid.u_m_per_s.row(j);
    const double* v_s = grid.v_m_per_s.row(j);
    const double* v_n = grid.v_m_per_s.row(j + 1);
    double* out = b.row(j);
    for (int i = 0; i < grid.nx; ++i) out[i] = -dx * ((u[i + 1] - u[i]) + (v_n[i] - v_s[i]));
  }
}

double maxAbsCellFlux_m2_per_s(const MacGrid2& grid, WorkerPool* workers) {
  return grid.dx_m * maxAbsFluxSum_m_per_s(grid, workers);
}

void subtractGradient(MacGrid2& grid, const Walls& walls, const Array2& q, double factor_per_m,
                       WorkerPool* workers) {
  const int nx = grid.nx;
  const int ny = grid.ny;
  const double inv_dx = factor_per_m;
  // Rows of u and the interior rows of v, cut among threads; each face's update is independent.
  forPieces(workers, 0, ny, [&](int j0, int j1, int) {
    for (int j = j0; j < j1; ++j) {
      const double* qr = q.row(j);
      double* u = grid.u_m_per_s.row(j);
      for (int i = 1; i < nx; ++i) u[i] -= (qr[i] - qr[i - 1]) * inv_dx;
      // Open walls: ghost q = −q_interior half a cell beyond the wall (p = 0 on the wall).
      if (!isSolid(walls.left)) u[0] -= (qr[0] + qr[0]) * inv_dx;
      if (!isSolid(walls.right)) u[nx] += (qr[nx - 1] + qr[nx - 1]) * inv_dx;
    }
    for (int j = std::max(j0, 1); j < j1; ++j) {
      const double* q_s = q.row(j - 1);
      const double* q_n = q.row(j);
      double* v = grid.v_m_per_s.row(j);
      for (int i = 0; i < nx; ++i) v[i] -= (q_n[i] - q_s[i]) * inv_dx;
    }
  });
  if (!isSolid(walls.bottom)) {
    double* v = grid.v_m_per_s.row(0);
    const double* qr = q.row(0);
    for (int i = 0; i < nx; ++i) v[i] -= (qr[i] + qr[i]) * inv_dx;
  }
  if (!isSolid(walls.top)) {
    double* v = grid.v_m_per_s.row(ny);
    const double* qr = q.row(ny - 1);
    for (int i = 0; i < nx; ++i) v[i] += (qr[i] + qr[i]) * inv_dx;
  }
}

void pressureMatrixDiagonal(const Walls& walls, int nx, int ny, Array2& diagonal) {
  diagonal.resize(nx, ny);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      double d = 0.0;
      d += i > 0 ? 1.0 : (isSolid(walls.left) ? 0.0 : 2.0);
      d += i < nx - 1 ? 1.0 : (isSolid(walls.right) ? 0.0 : 2.0);
      d += j > 0 ? 1.0 : (isSolid(walls.bottom) ? 0.0 : 2.0);
      d += j < ny - 1 ? 1.0 : (isSolid(walls.top) ? 0.0 : 2.0);
      diagonal(i, j) = d;
    }
  }
}

void applyPressureMatrix(const Walls& walls, const Array2& x, Array2& y) {
  const int nx = x.nx();
  const int ny = x.ny();
  y.resize(nx, ny);
  const double left = isSolid(walls.left) ? 0.0 : 2.0;
  const double right = isSolid(walls.right) ? 0.0 : 2.0;
  const double bottom = isSolid(walls.bottom) ? 0.0 : 2.0;
  const double top = isSolid(walls.top) ? 0.0 : 2.0;
  // Σ over neighbours of (x_c − x_nb), written as differences so constants give exactly 0;
  // a wall adds (0 or 2) x_c instead.
  auto cell = [&](const double* c, const double* s, const double* n, int i) {
    double sum = 0.0;
    sum += i > 0 ? c[i] - c[i - 1] : left * c[i];
    sum += i < nx - 1 ? c[i] - c[i + 1] : right * c[i];
    sum += s ? c[i] - s[i] : bottom * c[i];
    sum += n ? c[i] - n[i] : top * c[i];
    return sum;
  };
  for (int j = 0; j < ny; ++j) {
    const double* __restrict__ c = x.row(j);
    const double* __restrict__ s = j > 0 ? x.row(j - 1) : nullptr;
    const double* __restrict__ n = j < ny - 1 ? x.row(j + 1) : nullptr;
    double* __restrict__ out = y.row(j);
    out[0] = cell(c, s, n, 0);
    if (nx > 1) out[nx - 1] = cell(c, s, n, nx - 1);
    if (s != nullptr && n != nullptr) {
      for (int i = 1; i < nx - 1; ++i) {
        out[i] = (((c[i] - c[i - 1]) + (c[i] - c[i + 1])) + (c[i] - s[i])) + (c[i] - n[i]);
      }
    } else {
      for (int i = 1; i < nx - 1; ++i) out[i] = cell(c, s, n, i);
    }
  }
}

}  // namespace creaturelab::fluid
