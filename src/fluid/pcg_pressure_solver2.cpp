#include "fluid/pcg_pressure_solver2.hpp"

#include <algorithm>
#include <cmath>

#include "fluid/boundary2.hpp"

namespace creaturelab::fluid {
namespace {

bool sameWalls(const Walls& a, const Walls& b) {
  return a.left.type == b.left.type && a.right.type == b.right.type && a.bottom.type == b.bottom.type &&
         a.top.type == b.top.type;
}

double maxAbsVelocity(const MacGrid2& grid) { return std::max(maxAbs(grid.u_m_per_s), maxAbs(grid.v_m_per_s)); }

}  // namespace

void PcgPressureSolver2::factor(const Walls& walls, int nx, int ny) {
  if (factored_ && sameWalls(walls, factored_walls_) && precon_.nx() == nx && precon_.ny() == ny) return;
  pressureMatrixDiagonal(walls, nx, ny, diagonal_);
  precon_.resize(nx, ny);
  // Off-diagonals are −1 between neighbouring cells. With A(i−1,j)_{+x} = −1 when cell i−1
  // exists, Bridson's recurrence becomes
  //   e = A_cc − (pc_W)² − (pc_S)² − τ ((pc_W)² [W has a +y neighbour] + (pc_S)² [S has a +x neighbour]).
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double a_cc = diagonal_(i, j);
      double e = a_cc;
      if (i > 0) {
        const double w = precon_(i - 1, j);
        e -= w * w;
        if (j + 1 < ny) e -= kTau * w * w;
      }
      if (j > 0) {
        const double s = precon_(i, j - 1);
        e -= s * s;
        if (i + 1 < nx) e -= kTau * s * s;
      }
      if (e < kSigma * a_cc) e = a_cc;
      precon_(i, j) = 1.0 / std::sqrt(e);
    }
  }
  factored_ = true;
  factored_walls_ = walls;
}

// The two triangular solves are recurrences along i (each cell needs its west neighbour), so
// one row at a time runs at the latency of a multiply-add chain. Rows are therefore swept in
// groups of kWave as a wavefront, row g of the group lagging g cells behind row 0: every cell's
// west and south (north, going back) neighbours are done one step earlier, the group's chains
// are independent, and each cell still computes exactly the same expression as the plain
// row-by-row sweep (bitwise identical results).
void PcgPressureSolver2::applyPreconditioner(const Array2& r, Array2& z) const {
  const int nx = r.nx();
  const int ny = r.ny();
  constexpr int kWave = 4;
  // Forward substitution L t = r, stored in z.
  for (int j0 = 0; j0 < ny; j0 += kWave) {
    const int rows = std::min(kWave, ny - j0);
    for (int k = 0; k < nx + rows - 1; ++k) {
      for (int g = 0; g < rows; ++g) {
        const int i = k - g;
        if (i < 0 || i >= nx) continue;
        const int j = j0 + g;
        double t = r(i, j);
        if (i > 0) t += precon_(i - 1, j) * z(i - 1, j);
        if (j > 0) t += precon_(i, j - 1) * z(i, j - 1);
        z(i, j) = t * precon_(i, j);
      }
    }
  }
  // Backward substitution Lᵀ z = t, from the top row down.
  for (int j_top = ny - 1; j_top >= 0; j_top -= kWave) {
    const int rows = std::min(kWave, j_top + 1);
    for (int k = 0; k < nx + rows - 1; ++k) {
      for (int g = 0; g < rows; ++g) {
        const int i = nx - 1 - (k - g);
        if (i < 0 || i >= nx) continue;
        const int j = j_top - g;
        double t = z(i, j);
        const double pc = precon_(i, j);
        if (i + 1 < nx) t += pc * z(i + 1, j);
        if (j + 1 < ny) t += pc * z(i, j + 1);
        z(i, j) = t * pc;
      }
    }
  }
}

LinearSolveReport PcgPressureSolver2::solve(const Walls& walls, const Array2& b_in, Array2& q,
                                            double velocity_scale_m2_per_s) {
  const int nx = b_in.nx();
  const int ny = b_in.ny();
  factor(walls, nx, ny);
  for (Array2* a : {&b_, &r_, &z_, &s_, &as_}) a->resize(nx, ny);
  q.resize(nx, ny);
  b_ = b_in;
  const bool closed = walls.closed();
  if (closed) removeMean(b_);  // b must be orthogonal to the null space (constants)
  const double b_norm = maxAbs(b_);
  if (b_norm == 0.0) {
    q.fill(0.0);
    return {};
  }
  const double scale = velocity_scale_m2_per_s;
  const double target =
      scale > 0.0 ? std::max(tolerance_ * std::min(b_norm, scale), 1e-14 * scale) : tolerance_ * b_norm;

  // Warm start from q unless zero is the better guess.
  applyPressureMatrix(walls, q, as_);
  const std::size_t n = b_.size();
  double* r = r_.data();
  double* z = z_.data();
  double* s = s_.data();
  double* as = as_.data();
  double* x = q.data();
  const double* b = b_.data();
  for (std::size_t k = 0; k < n; ++k) r[k] = b[k] - as[k];
  double r_norm = maxAbs(r_);
  if (!(r_norm < b_norm)) {
    q.fill(0.0);
    r_ = b_;
    r_norm = b_norm;
  }
  int iteration = 0;
  if (r_norm > target) {
    applyPreconditioner(r_, z_);
    if (closed) removeMean(z_);
    std::copy(z, z + n, s);
    double rz = dot(r_, z_);
    while (iteration < max_iterations_) {
      ++iteration;
      applyPressureMatrix(walls, s_, as_);
      const double alpha = rz / dot(s_, as_);
      for (std::size_t k = 0; k < n; ++k) {
        x[k] += alpha * s[k];
        r[k] -= alpha * as[k];
      }
      r_norm = maxAbs(r_);
      if (r_norm <= target) break;
      applyPreconditioner(r_, z_);
      if (closed) removeMean(z_);
      const double rz_new = dot(r_, z_);
      const double beta = rz_new / rz;
      rz = rz_new;
      for (std::size_t k = 0; k < n; ++k) s[k] = z[k] + beta * s[k];
    }
  }
  if (closed) removeMean(q);
  return {iteration, r_norm / b_norm, r_norm <= target};
}

LinearSolveReport PcgPressureSolver2::project(MacGrid2& grid, const Walls& walls, double density_kg_per_m3,
                                              double dt_s) {
  projectionRhs(grid, rhs_);
  const double scale = dt_s / density_kg_per_m3;  // q = p dt / ρ
  q_.resize(grid.nx, grid.ny);
  {
    const double* p = grid.pressure_pa.data();
    double* q = q_.data();
    for (std::size_t k = 0; k < q_.size(); ++k) q[k] = p[k] * scale;
  }
  LinearSolveReport report = solve(walls, rhs_, q_, grid.dx_m * maxAbsVelocity(grid));
  subtractGradient(grid, walls, q_);
  const double inv_scale = density_kg_per_m3 / dt_s;
  {
    const double* q = q_.data();
    double* p = grid.pressure_pa.data();
    for (std::size_t k = 0; k < q_.size(); ++k) p[k] = q[k] * inv_scale;
  }
  const double b_norm = maxAbs(rhs_);
  report.relative_residual = b_norm > 0.0 ? maxAbsCellFlux_m2_per_s(grid) / b_norm : 0.0;
  return report;
}

}  // namespace creaturelab::fluid
