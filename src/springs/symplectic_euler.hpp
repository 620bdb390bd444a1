#pragma once
// Symplectic (semi-implicit) Euler: v += h a(x, v), then x += h v_new. Same cost as explicit
// Euler, first order, but symplectic: on an undamped oscillator it keeps a modified energy
// exactly, so energy error stays bounded for ever, and it is stable up to omega h = 2.
#include "springs/integrator.hpp"

namespace creaturelab::springs {

template <int D> class SymplecticEuler final : public Integrator<D> {
 public:
  void step(const System<D>& system, State<D>& s, const StepContext& ctx) override;

 private:
  Points<D> force_;  // newtons, scratch reused every step
};

extern template class SymplecticEuler<2>;
extern template class SymplecticEuler<3>;

}  // namespace creaturelab::springs
