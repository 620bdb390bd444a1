#include "fluid3d/pressure_operator3.hpp"

#include <cmath>

namespace creaturelab::fluid3d {

void projectionRhs(const MacGrid3& grid, Array3& b, WorkerPool* pool) {
  const int nx = grid.n[0], ny = grid.n[1], nz = grid.n[2];
  b.resize(nx, ny, nz);
  const Array3 &u = grid.velocity_m_per_s[0], &v = grid.velocity_m_per_s[1], &w = grid.velocity_m_per_s[2];
  const bool px = grid.periodic(0), py = grid.periodic(1), pz = grid.periodic(2);
  const double dx = grid.dx_m;
  forSlabs(pool, nz, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k) {
      const int kt = (pz && k + 1 == nz) ? 0 : k + 1;
      for (int j = 0; j < ny; ++j) {
        const int jn = (py && j + 1 == ny) ? 0 : j + 1;
        const double* ur = u.row(j, k);
        const double *vs = v.row(j, k), *vn = v.row(jn, k);
        const double *wb = w.row(j, k), *wt = w.row(j, kt);
        double* out = b.row(j, k);
        for (int i = 0; i < nx; ++i) {
          const int ie = (px && i + 1 == nx) ? 0 : i + 1;
          out[i] = -dx * ((ur[ie] - ur[i]) + (vn[i] - vs[i]) + (wt[i] - wb[i]));
        }
      }
    }
  });
}

void subtractGradient(MacGrid3& grid, const Array3& phi, double factor_per_m, WorkerPool* pool) {
  for (int a = 0; a < 3; ++a) {
    Array3& comp = grid.velocity_m_per_s[a];
    const int n = grid.n[a];
    const bool periodic = grid.periodic(a);
    const AxisBoundary3& b = grid.boundaries.axis[a];
    const bool open_low = b.low == BoundaryType3::open, open_high = b.high == BoundaryType3::open;
    const std::array<int, 3> e = grid.faceExtents(a);
    forSlabs(pool, e[2], [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < e[1]; ++j) {
          double* out = comp.row(j, k);
          for (int i = 0; i < e[0]; ++i) {
            int m[3] = {i, j, k};
            const int f = m[a];
            // Cells on the low (f − 1) and high (f) side of face f, and their ghosts.
            double lo = 0.0, hi = 0.0;
            if (periodic) {
              hi = phi(m[0], m[1], m[2]);
              m[a] = (f + n - 1) % n;
              lo = phi(m[0], m[1], m[2]);
            } else if (f == 0) {
              if (!open_low) continue;
              hi = phi(m[0], m[1], m[2]);
              lo = -hi;
            } else if (f == n) {
              if (!open_high) continue;
              m[a] = n - 1;
              lo = phi(m[0], m[1], m[2]);
              hi = -lo;
            } else {
              hi = phi(m[0], m[1], m[2]);
              m[a] = f - 1;
              lo = phi(m[0], m[1], m[2]);
            }
            out[i] -= factor_per_m * (hi - lo);
          }
        }
    });
  }
}

double maxDivergence_per_s(const MacGrid3& grid, WorkerPool* pool) {
  Array3 b;
  projectionRhs(grid, b, pool);
  double m = 0.0;
  for (std::size_t t = 0; t < b.size(); ++t) {
    const double v = std::fabs(b.data()[t]);
    if (!(v <= m)) m = v;
  }
  return m / (grid.dx_m * grid.dx_m);
}

void enforceSolidWalls(MacGrid3& grid) {
  for (int a = 0; a < 3; ++a) {
    if (grid.periodic(a)) continue;
    Array3& comp = grid.velocity_m_per_s[a];
    const std::array<int, 3> e = grid.faceExtents(a);
    for (int k = 0; k < e[2]; ++k)
      for (int j = 0; j < e[1]; ++j)
        for (int i = 0; i < e[0]; ++i) {
          const int m = a == 0 ? i : a == 1 ? j : k;
          if (grid.knownFace(a, m)) comp(i, j, k) = grid.knownFaceVelocity_m_per_s(a, m);
        }
  }
}

}  // namespace creaturelab::fluid3d
