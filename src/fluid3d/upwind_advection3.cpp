#include "fluid3d/upwind_advection3.hpp"

#include <cmath>

namespace creaturelab::fluid3d {

void GhostedComponent3::fill(int a, const MacGrid3& grid, const Array3& values) {
  const int e[3] = {values.nx(), values.ny(), values.nz()};
  data_.resize(e[0] + 2 * kGhost, e[1] + 2 * kGhost, e[2] + 2 * kGhost);
  ex_ = e[0] + 2 * kGhost, ey_ = e[1] + 2 * kGhost;
  for (int k = 0; k < e[2]; ++k)
    for (int j = 0; j < e[1]; ++j)
      for (int i = 0; i < e[0]; ++i) ref(i, j, k) = values(i, j, k);
  // Axis by axis over the full (ghosted) range of the other two: later axes overwrite the corners
  // that earlier ones filled from not yet filled ghosts.
  for (int d = 0; d < 3; ++d) {
    const int E = e[d];
    const AxisBoundary3& b = grid.boundaries.axis[d];
    const int o1 = (d + 1) % 3, o2 = (d + 2) % 3;
    // ghost index g takes offset + factor · value at source index.
    struct Rule {
      int ghost, source;
      double factor, offset = 0.0;
    };
    Rule rules[4];
    if (b.periodic()) {
      rules[0] = {-1, E - 1, 1.0}, rules[1] = {-2, E - 2, 1.0}, rules[2] = {E, 0, 1.0}, rules[3] = {E + 1, 1, 1.0};
    } else if (d != a) {
      auto mirror = [](BoundaryType3 t) { return t == BoundaryType3::no_slip || t == BoundaryType3::inflow ? -1.0 : 1.0; };
      const double lo = mirror(b.low), hi = mirror(b.high);
      rules[0] = {-1, 0, lo}, rules[1] = {-2, 1, lo}, rules[2] = {E, E - 1, hi}, rules[3] = {E + 1, E - 2, hi};
    } else {
      const bool lo_open = b.low == BoundaryType3::open, hi_open = b.high == BoundaryType3::open;
      const double lo_wall = 2.0 * b.normalVelocity_m_per_s(false), hi_wall = 2.0 * b.normalVelocity_m_per_s(true);
      rules[0] = lo_open ? Rule{-1, 0, 1.0} : Rule{-1, 1, -1.0, lo_wall};
      rules[1] = lo_open ? Rule{-2, 0, 1.0} : Rule{-2, 2, -1.0, lo_wall};
      rules[2] = hi_open ? Rule{E, E - 1, 1.0} : Rule{E, E - 2, -1.0, hi_wall};
      rules[3] = hi_open ? Rule{E + 1, E - 1, 1.0} : Rule{E + 1, E - 3, -1.0, hi_wall};
    }
    for (int p2 = -kGhost; p2 < e[o2] + kGhost; ++p2)
      for (int p1 = -kGhost; p1 < e[o1] + kGhost; ++p1)
        for (const Rule& r : rules) {
          int g[3], s[3];
          g[d] = r.ghost, s[d] = r.source;
          g[o1] = s[o1] = p1;
          g[o2] = s[o2] = p2;
          ref(g[0], g[1], g[2]) = r.offset + r.factor * at(s[0], s[1], s[2]);
        }
  }
}

namespace upwind3_detail {

// Flux of component a through the high control-volume face of sample m in direction b (cell
// units: velocity × value); see the header.
double frommFlux(const std::array<GhostedComponent3, 3>& q, int a, int b, const int (&m)[3]) {
  int p[3] = {m[0], m[1], m[2]};
  auto value = [&](int c, int shift_b, int shift_a) {
    p[0] = m[0], p[1] = m[1], p[2] = m[2];
    p[b] += shift_b;
    p[a] += shift_a;
    return q[c].at(p[0], p[1], p[2]);
  };
  const double advecting =
      b == a ? 0.5 * (value(a, 0, 0) + value(a, 1, 0)) : 0.5 * (value(b, 1, -1) + value(b, 1, 0));
  const double qm1 = value(a, -1, 0), q0 = value(a, 0, 0), q1 = value(a, 1, 0), q2 = value(a, 2, 0);
  const double from_low = q0 + 0.25 * (q1 - qm1);
  const double from_high = q1 - 0.25 * (q2 - q0);
  return 0.5 * (advecting * (from_low + from_high) - std::fabs(advecting) * (from_high - from_low));
}

}  // namespace upwind3_detail

void Upwind2Rk2Advection3::stage(const MacGrid3& grid, const std::array<GhostedComponent3, 3>& state, double c,
                                 bool corrector, FaceField3& out) {
  using namespace upwind3_detail;
  for (int a = 0; a < 3; ++a) {
    const std::array<int, 3> e = grid.faceExtents(a);
    out[a].resize(e[0], e[1], e[2]);
    forSlabs(workers_, e[2], [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < e[1]; ++j)
          for (int i = 0; i < e[0]; ++i) {
            const int m[3] = {i, j, k};
            if (grid.knownFace(a, m[a])) {
              out[a](i, j, k) = grid.knownFaceVelocity_m_per_s(a, m[a]);
              continue;
            }
            double divergence = 0.0;
            for (int b = 0; b < 3; ++b) {
              int low[3] = {i, j, k};
              low[b] -= 1;
              divergence += frommFlux(state, a, b, m) - frommFlux(state, a, b, low);
            }
            const double stepped = state[a].at(i, j, k) - c * divergence;
            out[a](i, j, k) = corrector ? 0.5 * (grid.velocity_m_per_s[a](i, j, k) + stepped) : stepped;
          }
    });
  }
}

void Upwind2Rk2Advection3::advect(const MacGrid3& grid, double dt_s, FaceField3& out) {
  const double c = dt_s / grid.dx_m;
  for (int a = 0; a < 3; ++a) ghosted_[a].fill(a, grid, grid.velocity_m_per_s[a]);
  stage(grid, ghosted_, c, false, predictor_);
  for (int a = 0; a < 3; ++a) ghosted_[a].fill(a, grid, predictor_[a]);
  stage(grid, ghosted_, c, true, out);
}

}  // namespace creaturelab::fluid3d
