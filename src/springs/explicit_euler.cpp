#include "springs/explicit_euler.hpp"

namespace creaturelab::springs {

template <int D> void ExplicitEuler<D>::step(const System<D>& system, State<D>& s, const StepContext& ctx) {
  const double h = ctx.dt_s;
  double* x = s.x_m.data();
  double* v = s.v_m_per_s.data();
  system.accelerationsThen(s, ctx.t_s, force_, [=](int i, double a) {
    x[i] += h * v[i];  // Eq. 4.5 on x' = v (Eq. 4.3), with the old velocity
    v[i] += h * a;     // Eq. 4.5 on v' = f/m (Eq. 4.4)
  });
}

template class ExplicitEuler<2>;
template class ExplicitEuler<3>;

}  // namespace creaturelab::springs
