#pragma once
// Explicit (forward) Euler, thesis Eq. 4.5 applied to Eq. 4.3-4.4: x += h v, v += h a(x, v),
// both derivatives taken at the start of the step. First order; on an undamped oscillator its
// amplification |1 + i omega h| > 1, so it is stable only with damping (stability.hpp).
#include "springs/integrator.hpp"

namespace creaturelab::springs {

template <int D> class ExplicitEuler final : public Integrator<D> {
 public:
  void step(const System<D>& system, State<D>& s, const StepContext& ctx) override;

 private:
  Points<D> force_;  // newtons, scratch reused every step
};

extern template class ExplicitEuler<2>;
extern template class ExplicitEuler<3>;

}  // namespace creaturelab::springs
