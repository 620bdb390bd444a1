#include "fluid3d/multigrid3.hpp"

namespace creaturelab::fluid3d {

void MultigridPreconditioner3::prepare(const std::array<int, 3>& cells, const Boundaries3& sides) {
  bool same_sides = true;
  for (int a = 0; a < 3; ++a)
    same_sides = same_sides && sides.axis[a].low == sides_.axis[a].low && sides.axis[a].high == sides_.axis[a].high;
  if (ready_ && cells == cells_ && same_sides) return;
  cells_ = cells, sides_ = sides, ready_ = true;
  levels_.clear();
  std::array<int, 3> n = cells;
  while (true) {
    Level level;
    level.n = n;
    level.stencil = pressureStencil(n, sides);
    stencilDiagonal(level.stencil, 6.0, -1.0, level.inv_diag);
    for (std::size_t t = 0; t < level.inv_diag.size(); ++t) level.inv_diag.data()[t] = 1.0 / level.inv_diag.data()[t];
    level.x = Array3(n[0], n[1], n[2]);
    level.b = Array3(n[0], n[1], n[2]);
    level.r = Array3(n[0], n[1], n[2]);
    levels_.push_back(std::move(level));
    bool halve = true;
    for (int a = 0; a < 3; ++a) halve = halve && n[a] % 2 == 0 && n[a] >= 4;
    if (!halve) break;
    for (int a = 0; a < 3; ++a) n[a] /= 2;
  }
}

void MultigridPreconditioner3::jacobi(Level& level, int sweeps, bool from_zero, WorkerPool* pool) {
  const std::size_t slab = level.x.slabSize();
  for (int s = 0; s < sweeps; ++s) {
    if (from_zero && s == 0) {
      forSlabs(pool, level.n[2], [&](int k0, int k1) {
        for (std::size_t t = k0 * slab; t < k1 * slab; ++t)
          level.x.data()[t] = kOmega * level.inv_diag.data()[t] * level.b.data()[t];
      });
      continue;
    }
    applyStencil(level.stencil, 6.0, -1.0, level.x, level.r, pool);
    forSlabs(pool, level.n[2], [&](int k0, int k1) {
      for (std::size_t t = k0 * slab; t < k1 * slab; ++t)
        level.x.data()[t] += kOmega * level.inv_diag.data()[t] * (level.b.data()[t] - level.r.data()[t]);
    });
  }
}

void MultigridPreconditioner3::vcycle(int l, WorkerPool* pool) {
  Level& fine = levels_[l];
  if (l + 1 == levels()) {
    jacobi(fine, kCoarsestSweeps, true, pool);
    return;
  }
  jacobi(fine, kSweeps, true, pool);
  // r = b − A x, restricted: b_c = Pᵀ r / 2.
  applyStencil(fine.stencil, 6.0, -1.0, fine.x, fine.r, pool);
  const std::size_t slab = fine.x.slabSize();
  forSlabs(pool, fine.n[2], [&](int k0, int k1) {
    for (std::size_t t = k0 * slab; t < k1 * slab; ++t) fine.r.data()[t] = fine.b.data()[t] - fine.r.data()[t];
  });
  Level& coarse = levels_[l + 1];
  forSlabs(pool, coarse.n[2], [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < coarse.n[1]; ++j)
        for (int i = 0; i < coarse.n[0]; ++i) {
          const Array3& r = fine.r;
          const int fi = 2 * i, fj = 2 * j, fk = 2 * k;
          const double s = ((r(fi, fj, fk) + r(fi + 1, fj, fk)) + (r(fi, fj + 1, fk) + r(fi + 1, fj + 1, fk))) +
                           ((r(fi, fj, fk + 1) + r(fi + 1, fj, fk + 1)) +
                            (r(fi, fj + 1, fk + 1) + r(fi + 1, fj + 1, fk + 1)));
          coarse.b(i, j, k) = kCoarseWeight * s;
        }
  });
  vcycle(l + 1, pool);
  forSlabs(pool, fine.n[2], [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < fine.n[1]; ++j) {
        double* x = fine.x.row(j, k);
        const double* c = coarse.x.row(j / 2, k / 2);
        for (int i = 0; i < fine.n[0]; ++i) x[i] += c[i / 2];
      }
  });
  jacobi(fine, kSweeps, false, pool);
}

void MultigridPreconditioner3::apply(const Array3& r, Array3& z, WorkerPool* pool) {
  Level& top = levels_[0];
  top.b = r;
  vcycle(0, pool);
  z = top.x;
}

}  // namespace creaturelab::fluid3d
