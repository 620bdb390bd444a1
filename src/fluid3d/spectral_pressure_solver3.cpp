#include "fluid3d/spectral_pressure_solver3.hpp"

#include <cmath>
#include <numbers>

namespace creaturelab::fluid3d {

EigenBasis1 eigenBasis(int n, const AxisBoundary3& sides) {
  const double pi = std::numbers::pi;
  EigenBasis1 e;
  e.n = n;
  e.basis.assign(static_cast<std::size_t>(n) * n, 0.0);
  e.eigenvalue.assign(n, 0.0);
  const bool low_solid = sides.low != BoundaryType3::open, high_solid = sides.high != BoundaryType3::open;
  for (int m = 0; m < n; ++m) {
    double theta = 0.0;
    for (int j = 0; j < n; ++j) {
      const double x = j + 0.5;
      double phi = 0.0;
      if (sides.periodic()) {
        const int f = (m + 1) / 2;  // frequency: m = 0 → 0, 1, 2 → 1, 3, 4 → 2, ...
        theta = 2.0 * pi * f / n;
        phi = (m == 0) ? 1.0 : (m % 2 == 1) ? std::cos(theta * j) : std::sin(theta * j);
        if (n % 2 == 0 && m == n - 1) phi = (j % 2 == 0) ? 1.0 : -1.0;  // f = n/2: (−1)^j
      } else if (low_solid && high_solid) {
        theta = pi * m / n;
        phi = std::cos(theta * x);
      } else if (!low_solid && !high_solid) {
        theta = pi * (m + 1) / n;
        phi = std::sin(theta * x);
      } else {
        theta = pi * (m + 0.5) / n;
        phi = low_solid ? std::cos(theta * x) : std::sin(theta * x);
      }
      e.basis[static_cast<std::size_t>(j) * n + m] = phi;
    }
    const double s = std::sin(0.5 * theta);
    e.eigenvalue[m] = 4.0 * s * s;
    double norm2 = 0.0;
    for (int j = 0; j < n; ++j) norm2 += e.basis[static_cast<std::size_t>(j) * n + m] * e.basis[static_cast<std::size_t>(j) * n + m];
    const double scale = 1.0 / std::sqrt(norm2);
    for (int j = 0; j < n; ++j) e.basis[static_cast<std::size_t>(j) * n + m] *= scale;
  }
  return e;
}

void SpectralPressureSolver3::prepare(const std::array<int, 3>& cells, const Boundaries3& sides) {
  bool same = ready_ && cells == cells_;
  for (int a = 0; a < 3; ++a)
    same = same && sides.axis[a].low == sides_.axis[a].low && sides.axis[a].high == sides_.axis[a].high;
  if (same) return;
  for (int a = 0; a < 3; ++a) {
    bases_[a] = eigenBasis(cells[a], sides.axis[a]);
    fast_[a] = allow_fast_ && FastTransform1::applies(cells[a], sides.axis[a])
                   ? std::make_unique<FastTransform1>(cells[a], sides.axis[a])
                   : nullptr;
  }
  cells_ = cells, sides_ = sides, ready_ = true;
  t1_ = Array3(cells[0], cells[1], cells[2]);
  t2_ = Array3(cells[0], cells[1], cells[2]);
}

void SpectralPressureSolver3::transform(int a, bool forward, const Array3& in, Array3& out) {
  const EigenBasis1& e = bases_[a];
  const int n = e.n, nx = in.nx(), ny = in.ny(), nz = in.nz();
  // coefficient(out index o, in index t): forward φ_o(t) = basis[t n + o]; inverse φ_t(o) = basis[o n + t].
  auto coefficient = [&](int o, int t) {
    return forward ? e.basis[static_cast<std::size_t>(t) * n + o] : e.basis[static_cast<std::size_t>(o) * n + t];
  };
  if (fast_[a]) {
    const FastTransform1& f = *fast_[a];
    // Lines along axis a: gathered, transformed, scattered (threads share the other two indices).
    const long stride = a == 0 ? 1 : a == 1 ? nx : static_cast<long>(nx) * ny;
    const int outer = a == 2 ? ny : nz;     // the index the threads split
    const int inner = a == 0 ? ny : nx;     // the other one
    forSlabs(workers_, outer, [&](int o0, int o1) {
      std::vector<double> src(n), dst(n), work(4 * n);
      for (int o = o0; o < o1; ++o)
        for (int l = 0; l < inner; ++l) {
          const long base = a == 0 ? in.index(0, l, o) : a == 1 ? in.index(l, 0, o) : in.index(l, o, 0);
          for (int t = 0; t < n; ++t) src[t] = in.data()[base + t * stride];
          if (forward)
            f.forward(src.data(), dst.data(), work.data());
          else
            f.inverse(src.data(), dst.data(), work.data());
          for (int t = 0; t < n; ++t) out.data()[base + t * stride] = dst[t];
        }
    });
    return;
  }
  if (a == 0) {
    forSlabs(workers_, nz, [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < ny; ++j) {
          const double* src = in.row(j, k);
          double* dst = out.row(j, k);
          for (int o = 0; o < nx; ++o) {
            double s = 0.0;
            for (int t = 0; t < nx; ++t) s += coefficient(o, t) * src[t];
            dst[o] = s;
          }
        }
    });
  } else if (a == 1) {
    forSlabs(workers_, nz, [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int o = 0; o < ny; ++o) {
          double* dst = out.row(o, k);
          for (int i = 0; i < nx; ++i) dst[i] = 0.0;
          for (int t = 0; t < ny; ++t) {
            const double c = coefficient(o, t);
            const double* src = in.row(t, k);
            for (int i = 0; i < nx; ++i) dst[i] += c * src[i];
          }
        }
    });
  } else {
    const std::size_t slab = in.slabSize();
    forSlabs(workers_, nz, [&](int o0, int o1) {
      for (int o = o0; o < o1; ++o) {
        double* dst = out.data() + o * slab;
        for (std::size_t m = 0; m < slab; ++m) dst[m] = 0.0;
        for (int t = 0; t < nz; ++t) {
          const double c = coefficient(o, t);
          const double* src = in.data() + t * slab;
          for (std::size_t m = 0; m < slab; ++m) dst[m] += c * src[m];
        }
      }
    });
  }
}

SolveReport3 SpectralPressureSolver3::solve(const std::array<int, 3>& cells, const Boundaries3& sides, const Array3& b,
                                            Array3& q) {
  prepare(cells, sides);
  if (!q.sameShape(b)) q = Array3(cells[0], cells[1], cells[2]);
  transform(0, true, b, t1_);
  transform(1, true, t1_, t2_);
  transform(2, true, t2_, t1_);
  const std::vector<double>&lx = bases_[0].eigenvalue, &ly = bases_[1].eigenvalue, &lz = bases_[2].eigenvalue;
  forSlabs(workers_, cells[2], [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < cells[1]; ++j) {
        double* row = t1_.row(j, k);
        for (int i = 0; i < cells[0]; ++i) {
          const double lambda = lx[i] + ly[j] + lz[k];
          row[i] = lambda > 0.0 ? row[i] / lambda : 0.0;  // the constant mode of a closed box: mean zero
        }
      }
  });
  transform(2, false, t1_, t2_);
  transform(1, false, t2_, t1_);
  transform(0, false, t1_, q);
  return {};
}

}  // namespace creaturelab::fluid3d
