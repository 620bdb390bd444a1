#include "springs/symplectic_euler.hpp"

namespace creaturelab::springs {

template <int D> void SymplecticEuler<D>::step(const System<D>& system, State<D>& s, const StepContext& ctx) {
  const double h = ctx.dt_s;
  double* x = s.x_m.data();
  double* v = s.v_m_per_s.data();
  system.accelerationsThen(s, ctx.t_s, force_, [=](int i, double a) {
    v[i] += h * a;     // velocity first ...
    x[i] += h * v[i];  // ... then position with the new velocity
  });
}

template class SymplecticEuler<2>;
template class SymplecticEuler<3>;

}  // namespace creaturelab::springs
