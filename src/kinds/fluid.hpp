#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// The incompressible fluid alone (Rudolf & Mould 2009 §3.2, Eq. 1; Stam 1999 stable fluids on a
// MAC grid): decaying Taylor-Green vortices for convergence, a vortex pair meeting a wall, ...
class FluidKind : public SchemaKind {
 public:
  FluidKind();
  std::string name() const override { return "fluid"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
