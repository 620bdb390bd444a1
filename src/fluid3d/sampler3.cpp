#include "fluid3d/sampler3.hpp"

namespace creaturelab::fluid3d {

void PaddedComponent3::fill(int a, const MacGrid3& grid, const Array3& values, WorkerPool* pool) {
  if (stencil_axis_ != a || stencil_.extents() != std::array<int, 3>{values.nx(), values.ny(), values.nz()}) {
    stencil_ = velocityStencil(a, grid.n, grid.boundaries);
    stencil_axis_ = a;
  }
  const int mx = values.nx(), my = values.ny(), mz = values.nz();
  padded_.resize(mx + 2, my + 2, mz + 2);
  sy_ = mx + 2;
  sz_ = static_cast<long>(mx + 2) * (my + 2);
  for (int d = 0; d < 3; ++d) {
    n_[d] = grid.n[d];
    periodic_[d] = grid.periodic(d);
    shift_[d] = d == a ? 0.0 : 0.5;
    max_index_[d] = values.extent(d);  // padded extent − 2
  }
  const AxisStencil3 &tx = stencil_.axis[0], &ty = stencil_.axis[1], &tz = stencil_.axis[2];
  // Interior and x ghosts, row by row.
  forSlabs(pool, mz, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < my; ++j) {
        const double* src = values.row(j, k);
        double* dst = padded_.row(j + 1, k + 1);
        for (int i = 0; i < mx; ++i) dst[i + 1] = src[i];
        dst[0] = tx.lo_factor[0] * src[tx.lo[0]];
        dst[mx + 1] = tx.hi_factor[mx - 1] * src[tx.hi[mx - 1]];
      }
  });
  // y ghosts from the padded rows (corners included).
  forSlabs(pool, mz, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      double* low = padded_.row(0, k + 1);
      const double* low_src = padded_.row(ty.lo[0] + 1, k + 1);
      double* high = padded_.row(my + 1, k + 1);
      const double* high_src = padded_.row(ty.hi[my - 1] + 1, k + 1);
      for (int i = 0; i < mx + 2; ++i) low[i] = ty.lo_factor[0] * low_src[i], high[i] = ty.hi_factor[my - 1] * high_src[i];
    }
  });
  // z ghost slabs.
  const std::size_t slab = padded_.slabSize();
  double* base = padded_.data();
  const double* low_src = base + (tz.lo[0] + 1) * slab;
  const double* high_src = base + (tz.hi[mz - 1] + 1) * slab;
  double* low = base;
  double* high = base + (mz + 1) * slab;
  for (std::size_t m = 0; m < slab; ++m) low[m] = tz.lo_factor[0] * low_src[m], high[m] = tz.hi_factor[mz - 1] * high_src[m];
}

}  // namespace creaturelab::fluid3d
