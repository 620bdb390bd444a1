#include "fluid/fast_diffusion2.hpp"

#include <algorithm>
#include <array>

namespace creaturelab::fluid {

KroneckerOperator2 diffusionOperator(const DiffusionBlock2& block, int nx, int ny, double alpha) {
  using E = OperatorEnd;
  // Along the component's axis: a known zero face beyond the block (solid wall) or none (open).
  auto own = [](bool zero_beyond) { return zero_beyond ? E::dirichlet_node : E::neumann; };
  // Across: the ghost count of diffusion_operator2.hpp, 0 (ghost = x) or 2 (ghost = 2U − x).
  auto across = [](const Wall& wall) { return diffusionGhostCount(wall) == 0.0 ? E::neumann : E::dirichlet_half; };
  KroneckerOperator2 op;
  if (block.axis == FaceAxis::x) {
    op.x_low = own(block.i_begin > 0);
    op.x_high = own(block.i_end < nx);
    op.y_low = across(block.walls.bottom);
    op.y_high = across(block.walls.top);
  } else {
    op.x_low = across(block.walls.left);
    op.x_high = across(block.walls.right);
    op.y_low = own(block.j_begin > 0);
    op.y_high = own(block.j_end < ny);
  }
  op.shift = 1.0 / alpha;
  return op;
}

LinearSolveReport FastDiffusion2::solveComponent(FaceAxis axis, Array2& x, const Walls& walls, double alpha,
                                                  Workspace& w) {
  const int nx = x.nx();
  const int ny = x.ny();
  if (w.block.prepare(axis, nx, ny, walls)) w.ap.resize(0, 0);
  const DiffusionBlock2& block = w.block;
  const int ib = block.i_begin, jb = block.j_begin;
  const int width = block.i_end - ib;
  w.ap.resize(nx, ny);
  w.b.resize(width, block.j_end - jb);
  w.row_dots.resize(static_cast<std::size_t>(ny));
  w.solver.setWorkers(workers_);

  // b = x^n + α · (wall terms) on the block, with ‖b‖∞. Threads share rows; maxima merge
  // per piece (order-free), so any thread count gives the same bits (worker_pool.hpp).
  const int parts = pieceCount(workers_);
  std::array<MaxAbsAccumulator, kMaxParts> acc{};
  forPieces(workers_, jb, block.j_end, [&](int j0, int j1, int part) {
    for (int j = j0; j < j1; ++j) {
      const double* xr = x.row(j) + ib;
      const double* wall = block.wall_rhs.row(j) + ib;
      double* br = w.b.row(j - jb);
      if (block.has_wall_rhs) {
        for (int i = 0; i < width; ++i) br[i] = xr[i] + alpha * wall[i];
      } else {
        std::copy(xr, xr + width, br);
      }
      acc[part].merge(partialMaxAbs(br, static_cast<std::size_t>(width)));
    }
  });
  for (int part = 1; part < parts; ++part) acc[0].merge(acc[part]);
  const double b_norm = acc[0].result();
  if (b_norm == 0.0) {
    x.fill(0.0);
    return {};
  }

  // (σ I + K) x = b / α.
  w.solver.solve(diffusionOperator(block, nx, ny, alpha), w.b, w.q, false, 1.0 / alpha);

  // x ← q on the block, then ‖b − A x‖∞ with the iterative solver's operator (w.ap is scratch:
  // it is never read before it is written).
  forPieces(workers_, jb, block.j_end, [&](int j0, int j1, int) {
    for (int j = j0; j < j1; ++j) std::copy_n(w.q.row(j - jb), width, x.row(j) + ib);
  });
  acc.fill(MaxAbsAccumulator{});
  forPieces(workers_, jb, block.j_end, [&](int j0, int j1, int part) {
    applyDiffusionRows(block, j0, j1, alpha, x, w.ap, w.row_dots.data());
    for (int j = j0; j < j1; ++j) {
      const double* __restrict__ br = w.b.row(j - jb);
      double* __restrict__ r = w.ap.row(j) + ib;
      for (int i = 0; i < width; ++i) r[i] = br[i] - r[i];  // r = b − A x, then its maximum
      acc[part].merge(partialMaxAbs(r, static_cast<std::size_t>(width)));
    }
  });
  for (int part = 1; part < parts; ++part) acc[0].merge(acc[part]);
  const double residual = acc[0].result();
  return {0, residual / b_norm, residual <= tolerance_ * b_norm};
}

}  // namespace creaturelab::fluid
