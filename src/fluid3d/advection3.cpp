#include "fluid3d/advection3.hpp"

#include "fluid3d/upwind_advection3.hpp"

namespace creaturelab::fluid3d {
namespace advection3_detail {

using Point = std::array<double, 3>;

// Velocity in cells per second at p (cell units).
Point cellVelocity(const std::array<PaddedComponent3, 3>& v, const Point& p, double per_dx) {
  return {v[0].sample(p) * per_dx, v[1].sample(p) * per_dx, v[2].sample(p) * per_dx};
}

// Velocity in cells per second at component a's sample m: its own value, and the other components
// averaged over the four samples around it (the trilinear sample there, weights ½ · ½).
Point faceVelocity(const std::array<PaddedComponent3, 3>& v, int a, const int (&m)[3], double per_dx) {
  Point u{};
  for (int b = 0; b < 3; ++b) {
    if (b == a) {
      u[b] = v[b].at(m[0], m[1], m[2]) * per_dx;
      continue;
    }
    // b's samples at b-index m_b and m_b + 1, a-index m_a − 1 and m_a.
    int q[3] = {m[0], m[1], m[2]};
    double s = 0.0;
    for (int db = 0; db < 2; ++db)
      for (int da = 0; da < 2; ++da) {
        q[b] = m[b] + db, q[a] = m[a] - 1 + da;
        s += v[b].at(q[0], q[1], q[2]);
      }
    u[b] = 0.25 * s * per_dx;
  }
  return u;
}

// The midpoint (RK2) trace from p over `dt` (negative: backwards), u0 the velocity at p.
Point trace(const std::array<PaddedComponent3, 3>& v, const Point& p, const Point& u0, double dt, double per_dx) {
  const Point mid{p[0] + 0.5 * dt * u0[0], p[1] + 0.5 * dt * u0[1], p[2] + 0.5 * dt * u0[2]};
  const Point u1 = cellVelocity(v, mid, per_dx);
  return {p[0] + dt * u1[0], p[1] + dt * u1[1], p[2] + dt * u1[2]};
}

// Calls f(a, i, j, k, position in cell units, output slot) for every sample, slab-parallel.
template <class F>
void forEachSample(const MacGrid3& grid, FaceField3& out, WorkerPool* pool, F f) {
  for (int a = 0; a < 3; ++a) {
    const std::array<int, 3> e = grid.faceExtents(a);
    out[a].resize(e[0], e[1], e[2]);
    forSlabs(pool, e[2], [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < e[1]; ++j)
          for (int i = 0; i < e[0]; ++i) {
            const int m[3] = {i, j, k};
            double& slot = out[a](i, j, k);
            if (grid.knownFace(a, m[a])) {
              slot = grid.knownFaceVelocity_m_per_s(a, m[a]);
              continue;
            }
            Point p{i + 0.5, j + 0.5, k + 0.5};
            p[a] -= 0.5;
            f(a, i, j, k, p, slot);
          }
    });
  }
}

}  // namespace advection3_detail

void AdvectionSolver3::padAll(const MacGrid3& grid, const FaceField3& field, std::array<PaddedComponent3, 3>& padded) {
  for (int a = 0; a < 3; ++a) padded[a].fill(a, grid, field[a], workers_);
}

void SemiLagrangianAdvection3::advect(const MacGrid3& grid, double dt_s, FaceField3& out) {
  using namespace advection3_detail;
  padAll(grid, grid.velocity_m_per_s, velocity_);
  const double per_dx = 1.0 / grid.dx_m;
  forEachSample(grid, out, workers_, [&](int a, int i, int j, int k, const Point& p, double& slot) {
    const Point u0 = faceVelocity(velocity_, a, {i, j, k}, per_dx);
    slot = velocity_[a].sample(trace(velocity_, p, u0, -dt_s, per_dx));
  });
}

void MacCormackAdvection3::advect(const MacGrid3& grid, double dt_s, FaceField3& out) {
  using namespace advection3_detail;
  padAll(grid, grid.velocity_m_per_s, velocity_);
  const double per_dx = 1.0 / grid.dx_m;
  for (int a = 0; a < 3; ++a) {
    const std::array<int, 3> e = grid.faceExtents(a);
    lo_[a].resize(e[0], e[1], e[2]);
    hi_[a].resize(e[0], e[1], e[2]);
    for (int d = 0; d < 3; ++d) ahead_[d][a].resize(e[0], e[1], e[2]);
  }
  // Forward: φ̂ and the range of its stencil; the forward trace's end is kept for the backward pass.
  forEachSample(grid, out, workers_, [&](int a, int i, int j, int k, const Point& p, double& slot) {
    const Point u0 = faceVelocity(velocity_, a, {i, j, k}, per_dx);
    slot = velocity_[a].sample(trace(velocity_, p, u0, -dt_s, per_dx), lo_[a](i, j, k), hi_[a](i, j, k));
    const Point ahead = trace(velocity_, p, u0, dt_s, per_dx);
    for (int d = 0; d < 3; ++d) ahead_[d][a](i, j, k) = ahead[d];
  });
  padAll(grid, out, forward_);
  // Backward: φ̃ = φ̂ at the forward trace's end; correct and clamp.
  forEachSample(grid, out, workers_, [&](int a, int i, int j, int k, const Point&, double& slot) {
    const double back = forward_[a].sample({ahead_[0][a](i, j, k), ahead_[1][a](i, j, k), ahead_[2][a](i, j, k)});
    const double corrected = slot + 0.5 * (grid.velocity_m_per_s[a](i, j, k) - back);
    const double lo = lo_[a](i, j, k), hi = hi_[a](i, j, k);
    slot = corrected < lo ? lo : corrected > hi ? hi : corrected;
  });
}

std::unique_ptr<AdvectionSolver3> makeAdvectionSolver(AdvectionScheme3 scheme) {
  if (scheme == AdvectionScheme3::semi_lagrangian) return std::make_unique<SemiLagrangianAdvection3>();
  if (scheme == AdvectionScheme3::upwind2_rk2) return std::make_unique<Upwind2Rk2Advection3>();
  return std::make_unique<MacCormackAdvection3>();
}

}  // namespace creaturelab::fluid3d
