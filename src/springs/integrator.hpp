#pragma once
// Time integrators for the spring-mass System (thesis §4.1-4.2, Mehla 2005).
// Each integrator owns its scratch buffers (no allocation per step once sized) and sees the
// model only through System (§4.2.1: the solver is independent of the model).
#include <memory>
#include <optional>
#include <string_view>

#include "springs/system.hpp"

namespace creaturelab::springs {

enum class IntegratorKind {
  ExplicitEuler,    // Eq. 4.5: x += h v, v += h a, both from the start of the step. First order.
  SymplecticEuler,  // semi-implicit: v += h a(x, v), then x += h v_new. First order, symplectic.
  RK4,              // Eq. 4.16-4.19 on (x, v). Fourth order.
  ImplicitEuler,    // Baraff & Witkin 1998: one linearised backward-Euler step. First order.
};

// "euler", "symplectic_euler", "rk4", "implicit_euler"; std::nullopt for anything else.
std::optional<IntegratorKind> parseIntegrator(std::string_view name);
std::string_view integratorName(IntegratorKind kind);

// Per-step values travel explicitly (Box2D style): no global clock.
struct StepContext {
  double t_s;   // time at the start of the step, seconds
  double dt_s;  // step length, seconds
};

template <int D> class Integrator {
 public:
  virtual ~Integrator() = default;
  // Advances s from ctx.t_s to ctx.t_s + ctx.dt_s.
  virtual void step(const System<D>& system, State<D>& s, const StepContext& ctx) = 0;
};

template <int D> std::unique_ptr<Integrator<D>> makeIntegrator(IntegratorKind kind);

}  // namespace creaturelab::springs
