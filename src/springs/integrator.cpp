#include "springs/integrator.hpp"

#include "springs/explicit_euler.hpp"
#include "springs/implicit_euler.hpp"
#include "springs/rk4.hpp"
#include "springs/symplectic_euler.hpp"

namespace creaturelab::springs {

std::optional<IntegratorKind> parseIntegrator(std::string_view name) {
  if (name == "euler") return IntegratorKind::ExplicitEuler;
  if (name == "symplectic_euler") return IntegratorKind::SymplecticEuler;
  if (name == "rk4") return IntegratorKind::RK4;
  if (name == "implicit_euler") return IntegratorKind::ImplicitEuler;
  return std::nullopt;
}

std::string_view integratorName(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::ExplicitEuler: return "euler";
    case IntegratorKind::SymplecticEuler: return "symplectic_euler";
    case IntegratorKind::RK4: return "rk4";
    case IntegratorKind::ImplicitEuler: return "implicit_euler";
  }
  return "unknown";
}

template <int D> std::unique_ptr<Integrator<D>> makeIntegrator(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::ExplicitEuler: return std::make_unique<ExplicitEuler<D>>();
    case IntegratorKind::SymplecticEuler: return std::make_unique<SymplecticEuler<D>>();
    case IntegratorKind::RK4: return std::make_unique<RungeKutta4<D>>();
    case IntegratorKind::ImplicitEuler: return std::make_unique<ImplicitEuler<D>>();
  }
  return nullptr;
}

template std::unique_ptr<Integrator<2>> makeIntegrator<2>(IntegratorKind);
template std::unique_ptr<Integrator<3>> makeIntegrator<3>(IntegratorKind);

}  // namespace creaturelab::springs
