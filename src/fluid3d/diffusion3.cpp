#include "fluid3d/diffusion3.hpp"

#include <algorithm>

#include "fluid3d/conjugate_gradients3.hpp"
#include "fluid3d/pressure_operator3.hpp"

namespace creaturelab::fluid3d {
namespace diffusion3_detail {

// The known inflow face beside the first (last) unknown face along axis a is a neighbour that the
// stencil's factor 0 leaves out: every scheme's update has α U_side for it (backward Euler α U,
// Crank–Nicolson ½α U on each side, explicit α U), added here to the right-hand side b.
void addInflowNeighbours(const MacGrid3& grid, int a, double alpha, Array3& b) {
  const AxisBoundary3& sides = grid.boundaries.axis[a];
  const int n = grid.n[a];
  for (const bool high : {false, true}) {
    if ((high ? sides.high : sides.low) != BoundaryType3::inflow) continue;
    const double add = alpha * sides.normalVelocity_m_per_s(high);
    const int m_row = high ? n - 1 : 1;
    std::array<int, 3> e = grid.faceExtents(a);
    for (int k = 0; k < e[2]; ++k)
      for (int j = 0; j < e[1]; ++j)
        for (int i = 0; i < e[0]; ++i) {
          const int m = a == 0 ? i : a == 1 ? j : k;
          if (m == m_row) b(i, j, k) += add;
        }
  }
}

}  // namespace diffusion3_detail

SolveReport3 ViscositySolver3::solveComponent(int a, double diag, double off, const Array3& b, Array3& x) {
  WorkerPool* pool = workers_;
  const Stencil3& st = stencils_[a];
  SolveReport3 report;
  const double b_norm = maxAbs3(b, pool, per_slab_);
  if (b_norm == 0.0) {
    x.fill(0.0);
    return report;
  }
  stencilDiagonal(st, diag, off, inv_diag_);
  for (std::size_t t = 0; t < inv_diag_.size(); ++t) inv_diag_.data()[t] = 1.0 / inv_diag_.data()[t];
  r_.resize(b.nx(), b.ny(), b.nz());
  applyStencil(st, diag, off, x, r_, pool);
  xpay3(b, -1.0, r_, pool);
  double r_norm = maxAbs3(r_, pool, per_slab_);
  const double target = tolerance_ * b_norm;
  const std::size_t slab = b.slabSize();
  auto precondition = [&] {
    z_.resize(b.nx(), b.ny(), b.nz());
    forSlabs(pool, b.nz(), [&](int k0, int k1) {
      for (std::size_t t = k0 * slab; t < k1 * slab; ++t) z_.data()[t] = inv_diag_.data()[t] * r_.data()[t];
    });
  };
  const int it = conjugateGradients3(st, diag, off, target, max_iterations_, precondition, x, r_, r_norm, z_, s_, as_,
                                     per_slab_, pool);
  report.iterations = it;
  report.relative_residual = r_norm / b_norm;
  report.converged = r_norm <= target;
  return report;
}

SolveReport3 ViscositySolver3::diffuse(MacGrid3& grid, double viscosity_m2_per_s, double dt_s) {
  SolveReport3 worst;
  if (viscosity_m2_per_s == 0.0) return worst;
  bool same = ready_ && grid.n == cells_;
  for (int a = 0; a < 3; ++a)
    same = same && grid.boundaries.axis[a].low == sides_.axis[a].low && grid.boundaries.axis[a].high == sides_.axis[a].high;
  if (!same) {
    for (int a = 0; a < 3; ++a) stencils_[a] = velocityStencil(a, grid.n, grid.boundaries);
    cells_ = grid.n, sides_ = grid.boundaries, ready_ = true;
  }
  const double alpha = viscosity_m2_per_s * dt_s / (grid.dx_m * grid.dx_m);
  for (int a = 0; a < 3; ++a) {
    Array3& u = grid.velocity_m_per_s[a];
    b_.resize(u.nx(), u.ny(), u.nz());
    SolveReport3 report;
    switch (scheme_) {
      case ViscosityScheme3::explicit_euler:
        applyStencil(stencils_[a], 1.0 - 6.0 * alpha, alpha, u, b_, workers_);
        diffusion3_detail::addInflowNeighbours(grid, a, alpha, b_);
        u = b_;
        break;
      case ViscosityScheme3::backward_euler:
        applyStencil(stencils_[a], 1.0, 0.0, u, b_, workers_);  // b = u on the unknowns
        diffusion3_detail::addInflowNeighbours(grid, a, alpha, b_);
        report = solveComponent(a, 1.0 + 6.0 * alpha, -alpha, b_, u);
        break;
      case ViscosityScheme3::crank_nicolson:
        applyStencil(stencils_[a], 1.0 - 3.0 * alpha, 0.5 * alpha, u, b_, workers_);
        diffusion3_detail::addInflowNeighbours(grid, a, alpha, b_);
        report = solveComponent(a, 1.0 + 3.0 * alpha, -0.5 * alpha, b_, u);
        break;
    }
    worst.iterations = std::max(worst.iterations, report.iterations);
    worst.relative_residual = std::max(worst.relative_residual, report.relative_residual);
    worst.converged = worst.converged && report.converged;
  }
  enforceSolidWalls(grid);  // the known faces, which the explicit update and the solves zero
  return worst;
}

}  // namespace creaturelab::fluid3d
