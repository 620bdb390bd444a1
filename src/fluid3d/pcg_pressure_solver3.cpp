#include "fluid3d/pcg_pressure_solver3.hpp"

#include <cmath>

#include "fluid3d/conjugate_gradients3.hpp"

namespace creaturelab::fluid3d {

SolveReport3 MgPcgPressureSolver3::solve(const std::array<int, 3>& cells, const Boundaries3& sides, const Array3& b,
                                         Array3& q) {
  WorkerPool* pool = workers_;
  preconditioner_.prepare(cells, sides);
  bool same_sides = true;
  for (int a = 0; a < 3; ++a)
    same_sides = same_sides && sides.axis[a].low == stencil_sides_.axis[a].low &&
                 sides.axis[a].high == stencil_sides_.axis[a].high;
  if (cells != stencil_cells_ || !same_sides) {
    stencil_ = pressureStencil(cells, sides);
    stencil_cells_ = cells, stencil_sides_ = sides;
  }
  const bool singular = sides.closed();
  const double mean_count = static_cast<double>(b.size());
  if (!q.sameShape(b)) q = Array3(cells[0], cells[1], cells[2]);
  SolveReport3 report;
  const double b_norm = maxAbs3(b, pool, per_slab_);
  if (b_norm == 0.0) {
    q.fill(0.0);
    return report;
  }
  // r = b − A q
  r_.resize(cells[0], cells[1], cells[2]);
  applyStencil(stencil_, 6.0, -1.0, q, r_, pool);
  xpay3(b, -1.0, r_, pool);
  double r_norm = maxAbs3(r_, pool, per_slab_);
  if (r_norm > b_norm) {  // zero is the closer start
    q.fill(0.0);
    r_ = b;
    r_norm = b_norm;
  }
  const double target = tolerance_ * b_norm;
  auto precondition = [&] {
    preconditioner_.apply(r_, z_, pool);
    if (singular) subtractConstant3(sum3(z_, pool, per_slab_) / mean_count, z_, pool);
  };
  const int it = conjugateGradients3(stencil_, 6.0, -1.0, target, max_iterations_, precondition, q, r_, r_norm, z_, s_,
                                     as_, per_slab_, pool);
  if (singular) subtractConstant3(sum3(q, pool, per_slab_) / mean_count, q, pool);
  report.iterations = it;
  report.relative_residual = r_norm / b_norm;
  report.converged = r_norm <= target;
  return report;
}

}  // namespace creaturelab::fluid3d
