#include "springs/rk4.hpp"

namespace creaturelab::springs {

// The k_i of Eq. 4.16-4.19 are not stored: their weighted sum is accumulated as each stage is
// evaluated, so the step needs five buffers instead of eight.
template <int D> void RungeKutta4<D>::step(const System<D>& system, State<D>& s, const StepContext& ctx) {
  const double h = ctx.dt_s, t = ctx.t_s;
  const Points<D>& x0 = s.x_m;
  const Points<D>& v0 = s.v_m_per_s;

  // k1 = h f(x0, t0)  (Eq. 4.16)
  system.accelerations(s, t, acc_);
  sum_dx_ = v0;
  sum_dv_ = acc_;

  // k2 = h f(x0 + k1/2, t0 + h/2)  (Eq. 4.17)
  stage_.x_m = x0 + (0.5 * h) * v0;
  stage_.v_m_per_s = v0 + (0.5 * h) * acc_;
  system.accelerations(stage_, t + 0.5 * h, acc_);
  sum_dx_ += 2.0 * stage_.v_m_per_s;
  sum_dv_ += 2.0 * acc_;

  // k3 = h f(x0 + k2/2, t0 + h/2)  (Eq. 4.18)
  stage_.x_m = x0 + (0.5 * h) * stage_.v_m_per_s;
  stage_.v_m_per_s = v0 + (0.5 * h) * acc_;
  system.accelerations(stage_, t + 0.5 * h, acc_);
  sum_dx_ += 2.0 * stage_.v_m_per_s;
  sum_dv_ += 2.0 * acc_;

  // k4 = h f(x0 + k3, t0 + h)  (Eq. 4.19)
  stage_.x_m = x0 + h * stage_.v_m_per_s;
  stage_.v_m_per_s = v0 + h * acc_;
  system.accelerations(stage_, t + h, acc_);
  sum_dx_ += stage_.v_m_per_s;
  sum_dv_ += acc_;

  // x(t0 + h) = x0 + k1/6 + k2/3 + k3/3 + k4/6  (Eq. 4.19)
  s.x_m += (h / 6.0) * sum_dx_;
  s.v_m_per_s += (h / 6.0) * sum_dv_;
}

template class RungeKutta4<2>;
template class RungeKutta4<3>;

}  // namespace creaturelab::springs
