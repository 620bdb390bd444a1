#pragma once
// Classical fourth-order Runge-Kutta, thesis Eq. 4.16-4.19, on the first-order system
// (x, v)' = (v, a(x, v, t)) (Eq. 4.3-4.4); the thesis' own integrator. Four force evaluations per
// step; stable on an undamped oscillator up to omega h = 2 sqrt(2).
#include "springs/integrator.hpp"

namespace creaturelab::springs {

template <int D> class RungeKutta4 final : public Integrator<D> {
 public:
  void step(const System<D>& system, State<D>& s, const StepContext& ctx) override;

 private:
  State<D> stage_;      // the state at which the next derivative is evaluated
  Points<D> forces_;    // System::accelerationsInBlocks' scratch (the raw forces)
  Points<D> sum_dx_;    // k1 + 2 k2 + 2 k3 + k4 for x (velocities)
  Points<D> sum_dv_;    // the same for v (accelerations)
};

extern template class RungeKutta4<2>;
extern template class RungeKutta4<3>;

}  // namespace creaturelab::springs
