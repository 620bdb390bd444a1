#include "fluid3d/stencil3.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace creaturelab::fluid3d {
namespace stencil3_detail {

AxisStencil3 periodicAxis(int n) {
  AxisStencil3 s;
  s.size = n;
  s.lo.resize(n), s.hi.resize(n), s.lo_factor.assign(n, 1.0), s.hi_factor.assign(n, 1.0), s.unknown.assign(n, 1);
  for (int m = 0; m < n; ++m) s.lo[m] = (m + n - 1) % n, s.hi[m] = (m + 1) % n;
  return s;
}

// Samples half a cell from each wall (cells, tangential components); ghost = factor · self.
AxisStencil3 centredAxis(int n, double low_ghost, double high_ghost) {
  AxisStencil3 s;
  s.size = n;
  s.lo.resize(n), s.hi.resize(n), s.lo_factor.assign(n, 1.0), s.hi_factor.assign(n, 1.0), s.unknown.assign(n, 1);
  for (int m = 0; m < n; ++m) s.lo[m] = m - 1, s.hi[m] = m + 1;
  s.lo[0] = 0, s.lo_factor[0] = low_ghost;
  s.hi[n - 1] = n - 1, s.hi_factor[n - 1] = high_ghost;
  return s;
}

// The run [plain_begin, plain_end) of samples with neighbours i ± 1, factors 1, unknown.
void findPlainRun(AxisStencil3& s) {
  auto plain = [&](int i) {
    return s.lo[i] == i - 1 && s.hi[i] == i + 1 && s.lo_factor[i] == 1.0 && s.hi_factor[i] == 1.0 && s.unknown[i];
  };
  int b = 0;
  while (b < s.size && !plain(b)) ++b;
  int e = b;
  while (e < s.size && plain(e)) ++e;
  s.plain_begin = b, s.plain_end = e;
}

// Sides whose normal faces are known (an inflow side's too: the pressure sees a wall there).
bool isSolid(BoundaryType3 t) { return t != BoundaryType3::open && t != BoundaryType3::periodic; }
// u_t = 0 on the side: no-slip walls and inflow sides.
double tangentialGhost(BoundaryType3 t) { return t == BoundaryType3::no_slip || t == BoundaryType3::inflow ? -1.0 : 1.0; }

}  // namespace stencil3_detail

Stencil3 pressureStencil(const std::array<int, 3>& cells, const Boundaries3& sides) {
  using namespace stencil3_detail;
  Stencil3 s;
  for (int a = 0; a < 3; ++a) {
    const AxisBoundary3& b = sides.axis[a];
    s.axis[a] = b.periodic() ? periodicAxis(cells[a])
                             : centredAxis(cells[a], isSolid(b.low) ? 1.0 : -1.0, isSolid(b.high) ? 1.0 : -1.0);
    findPlainRun(s.axis[a]);
  }
  return s;
}

Stencil3 velocityStencil(int a, const std::array<int, 3>& cells, const Boundaries3& sides) {
  using namespace stencil3_detail;
  Stencil3 s;
  for (int d = 0; d < 3; ++d) {
    const AxisBoundary3& b = sides.axis[d];
    const int n = cells[d];
    if (b.periodic()) {
      s.axis[d] = periodicAxis(n);
    } else if (d != a) {
      s.axis[d] = centredAxis(n, tangentialGhost(b.low), tangentialGhost(b.high));
    } else {
      // Normal faces 0..n; faces 0 and n lie on the walls.
      AxisStencil3 t;
      t.size = n + 1;
      t.lo.resize(n + 1), t.hi.resize(n + 1);
      t.lo_factor.assign(n + 1, 1.0), t.hi_factor.assign(n + 1, 1.0), t.unknown.assign(n + 1, 1);
      for (int m = 0; m <= n; ++m) t.lo[m] = m - 1, t.hi[m] = m + 1;
      t.unknown[0] = isSolid(b.low) ? 0 : 1;
      t.unknown[n] = isSolid(b.high) ? 0 : 1;
      t.lo[0] = 0, t.hi[n] = n;  // beyond an open side: ghost = self (factor 1)
      if (isSolid(b.low)) t.lo_factor[1] = 0.0;
      if (isSolid(b.high)) t.hi_factor[n - 1] = 0.0;
      s.axis[d] = t;
    }
    findPlainRun(s.axis[d]);
  }
  return s;
}

void applyStencil(const Stencil3& s, double diag, double off, const Array3& x, Array3& y, WorkerPool* pool) {
  const AxisStencil3 &sx = s.axis[0], &sy = s.axis[1], &sz = s.axis[2];
  const int nx = sx.size, ny = sy.size;
  forSlabs(pool, sz.size, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      for (int j = 0; j < ny; ++j) {
        double* out = y.row(j, k);
        if (!sz.unknown[k] || !sy.unknown[j]) {
          for (int i = 0; i < nx; ++i) out[i] = 0.0;
          continue;
        }
        const double* c = x.row(j, k);
        const double* ys = x.row(sy.lo[j], k);
        const double* yn = x.row(sy.hi[j], k);
        const double* zb = x.row(j, sz.lo[k]);
        const double* zt = x.row(j, sz.hi[k]);
        const double fys = sy.lo_factor[j], fyn = sy.hi_factor[j], fzb = sz.lo_factor[k], fzt = sz.hi_factor[k];
        // The ends through the tables, the plain run between them (neighbours i ± 1 with factor 1,
        // unknown) vectorised: the same arithmetic in the same order either way (1.0 · x = x).
        auto at = [&](int i) {
          const double neighbours = (sx.lo_factor[i] * c[sx.lo[i]] + sx.hi_factor[i] * c[sx.hi[i]]) +
                                    (fys * ys[i] + fyn * yn[i]) + (fzb * zb[i] + fzt * zt[i]);
          out[i] = sx.unknown[i] ? diag * c[i] + off * neighbours : 0.0;
        };
        for (int i = 0; i < sx.plain_begin; ++i) at(i);
        for (int i = sx.plain_begin; i < sx.plain_end; ++i) {
          const double neighbours =
              (1.0 * c[i - 1] + 1.0 * c[i + 1]) + (fys * ys[i] + fyn * yn[i]) + (fzb * zb[i] + fzt * zt[i]);
          out[i] = diag * c[i] + off * neighbours;
        }
        for (int i = sx.plain_end; i < nx; ++i) at(i);
      }
    }
  });
}

void stencilDiagonal(const Stencil3& s, double diag, double off, Array3& d) {
  const std::array<int, 3> e = s.extents();
  d.resize(e[0], e[1], e[2]);
  for (int k = 0; k < e[2]; ++k)
    for (int j = 0; j < e[1]; ++j)
      for (int i = 0; i < e[0]; ++i) {
        const int m[3] = {i, j, k};
        bool unknown = true;
        double self = 0.0;
        for (int a = 0; a < 3; ++a) {
          const AxisStencil3& t = s.axis[a];
          unknown = unknown && t.unknown[m[a]];
          if (t.lo[m[a]] == m[a]) self += t.lo_factor[m[a]];
          if (t.hi[m[a]] == m[a]) self += t.hi_factor[m[a]];
        }
        d(i, j, k) = unknown ? diag + off * self : 1.0;
      }
}

double dot3(const Array3& a, const Array3& b, WorkerPool* pool, std::vector<double>& per_slab) {
  const int nz = a.nz();
  const std::size_t slab = a.slabSize();
  per_slab.assign(nz, 0.0);
  forSlabs(pool, nz, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      const double* p = a.data() + k * slab;
      const double* q = b.data() + k * slab;
      double s0 = 0.0, s1 = 0.0;
      std::size_t m = 0;
      for (; m + 2 <= slab; m += 2) s0 += p[m] * q[m], s1 += p[m + 1] * q[m + 1];
      for (; m < slab; ++m) s0 += p[m] * q[m];
      per_slab[k] = s0 + s1;
    }
  });
  return sumInOrder(per_slab);
}

double maxAbs3(const Array3& a, WorkerPool* pool, std::vector<double>& per_slab) {
  const int nz = a.nz();
  const std::size_t slab = a.slabSize();
  per_slab.assign(nz, 0.0);
  forSlabs(pool, nz, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      const double* p = a.data() + k * slab;
      // Four running maxima (vectorisable) and Σ (v − v), which is NaN once a NaN or inf was seen.
      double m[4] = {0.0, 0.0, 0.0, 0.0}, z[4] = {0.0, 0.0, 0.0, 0.0};
      std::size_t t = 0;
      for (; t + 4 <= slab; t += 4)
        for (int l = 0; l < 4; ++l) {
          const double v = std::fabs(p[t + l]);
          m[l] = v > m[l] ? v : m[l];
          z[l] += v - v;
        }
      for (; t < slab; ++t) {
        const double v = std::fabs(p[t]);
        m[0] = v > m[0] ? v : m[0];
        z[0] += v - v;
      }
      const double nan_check = (z[0] + z[1]) + (z[2] + z[3]);
      const double largest = std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
      per_slab[k] = nan_check == 0.0 ? largest : std::numeric_limits<double>::quiet_NaN();
    }
  });
  return maxInOrder(per_slab);
}

double sum3(const Array3& a, WorkerPool* pool, std::vector<double>& per_slab) {
  const int nz = a.nz();
  const std::size_t slab = a.slabSize();
  per_slab.assign(nz, 0.0);
  forSlabs(pool, nz, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      const double* p = a.data() + k * slab;
      double s = 0.0;
      for (std::size_t t = 0; t < slab; ++t) s += p[t];
      per_slab[k] = s;
    }
  });
  return sumInOrder(per_slab);
}

void axpy3(double s, const Array3& x, Array3& y, WorkerPool* pool) {
  const std::size_t slab = x.slabSize();
  forSlabs(pool, x.nz(), [&](int k0, int k1) {
    const double* p = x.data();
    double* q = y.data();
    for (std::size_t t = k0 * slab; t < k1 * slab; ++t) q[t] += s * p[t];
  });
}

void xpay3(const Array3& x, double s, Array3& y, WorkerPool* pool) {
  const std::size_t slab = x.slabSize();
  forSlabs(pool, x.nz(), [&](int k0, int k1) {
    const double* p = x.data();
    double* q = y.data();
    for (std::size_t t = k0 * slab; t < k1 * slab; ++t) q[t] = p[t] + s * q[t];
  });
}

void subtractConstant3(double c, Array3& a, WorkerPool* pool) {
  const std::size_t slab = a.slabSize();
  forSlabs(pool, a.nz(), [&](int k0, int k1) {
    double* q = a.data();
    for (std::size_t t = k0 * slab; t < k1 * slab; ++t) q[t] -= c;
  });
}

}  // namespace creaturelab::fluid3d
