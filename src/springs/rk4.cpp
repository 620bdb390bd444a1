#include "springs/rk4.hpp"

namespace creaturelab::springs {

namespace {

// The per-coordinate updates between stages, on one block of coordinates. __restrict: the arrays are
// distinct buffers, so each loop vectorises. Each line is the whole-array form's arithmetic for one
// coordinate (e.g. x0 + (h/2) v0), so the step is the same bit for bit as with whole-array passes.

// After k1: sums = (v0, a1); next stage = (x0 + c v0, v0 + c a1).
void firstStage(int m, const double* __restrict a, const double* __restrict x0, const double* __restrict v0,
                double* __restrict xs, double* __restrict vs, double* __restrict sdx, double* __restrict sdv, double c) {
  for (int i = 0; i < m; ++i) {
    sdx[i] = v0[i];
    sdv[i] = a[i];
    xs[i] = x0[i] + c * v0[i];
    vs[i] = v0[i] + c * a[i];
  }
}

// After k2 or k3, evaluated at stage velocity vs: sums += 2 (vs, a); next stage = (x0 + c vs, v0 + c a).
void middleStage(int m, const double* __restrict a, const double* __restrict x0, const double* __restrict v0,
                 double* __restrict xs, double* __restrict vs, double* __restrict sdx, double* __restrict sdv,
                 double c) {
  for (int i = 0; i < m; ++i) {
    sdx[i] += 2.0 * vs[i];
    sdv[i] += 2.0 * a[i];
    xs[i] = x0[i] + c * vs[i];
    vs[i] = v0[i] + c * a[i];
  }
}

// After k4: sums += (vs, a); x0 += c sum_dx, v0 += c sum_dv with c = h/6.
void lastStage(int m, const double* __restrict a, const double* __restrict vs, double* __restrict sdx,
               double* __restrict sdv, double* __restrict x0, double* __restrict v0, double c) {
  for (int i = 0; i < m; ++i) {
    sdx[i] += vs[i];
    sdv[i] += a[i];
    x0[i] += c * sdx[i];
    v0[i] += c * sdv[i];
  }
}

}  // namespace

// The k_i of Eq. 4.16-4.19 are not stored: their weighted sum is accumulated as each stage is
// evaluated, so the step needs five buffers instead of eight. Each stage is one force evaluation
// followed by one sweep over the coordinates (System::accelerationsInBlocks), which adds the stage's
// derivative to the sums and writes the next stage's state in the same pass.
template <int D> void RungeKutta4<D>::step(const System<D>& system, State<D>& s, const StepContext& ctx) {
  const double h = ctx.dt_s, t = ctx.t_s, half = 0.5 * h;
  const int n = system.particleCount();
  stage_.x_m.resize(D, n);
  stage_.v_m_per_s.resize(D, n);
  sum_dx_.resize(D, n);
  sum_dv_.resize(D, n);
  double* x0 = s.x_m.data();
  double* v0 = s.v_m_per_s.data();
  double* xs = stage_.x_m.data();
  double* vs = stage_.v_m_per_s.data();
  double* sdx = sum_dx_.data();
  double* sdv = sum_dv_.data();

  // k1 = h f(x0, t0)  (Eq. 4.16); the k2 stage is (x0 + h/2 v0, v0 + h/2 a1).
  system.accelerationsInBlocks(s, t, forces_, [=](int i, int m, const double* a) {
    firstStage(m, a, x0 + i, v0 + i, xs + i, vs + i, sdx + i, sdv + i, half);
  });
  // k2 = h f(x0 + k1/2, t0 + h/2)  (Eq. 4.17); the k3 stage is (x0 + h/2 v2, v0 + h/2 a2).
  system.accelerationsInBlocks(stage_, t + half, forces_, [=](int i, int m, const double* a) {
    middleStage(m, a, x0 + i, v0 + i, xs + i, vs + i, sdx + i, sdv + i, half);
  });
  // k3 = h f(x0 + k2/2, t0 + h/2)  (Eq. 4.18); the k4 stage is (x0 + h v3, v0 + h a3).
  system.accelerationsInBlocks(stage_, t + half, forces_, [=](int i, int m, const double* a) {
    middleStage(m, a, x0 + i, v0 + i, xs + i, vs + i, sdx + i, sdv + i, h);
  });
  // k4 = h f(x0 + k3, t0 + h)  (Eq. 4.19), then x(t0 + h) = x0 + k1/6 + k2/3 + k3/3 + k4/6 (Eq. 4.19).
  // s changes only here, after the last force evaluation has read the stage.
  system.accelerationsInBlocks(stage_, t + h, forces_, [=](int i, int m, const double* a) {
    lastStage(m, a, vs + i, sdx + i, sdv + i, x0 + i, v0 + i, h / 6.0);
  });
}

template class RungeKutta4<2>;
template class RungeKutta4<3>;

}  // namespace creaturelab::springs
