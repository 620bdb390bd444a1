#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// A planar creature driven by the controller of Lentine et al. 2010 in the project's 2-D fluid,
// two-way coupled (Lentine et al. 2010 §4, §6, §7; issue 16): kind `control`'s
// controller with the fluid force (Eq. 10) instead of the simple wind.
class ControlFluidKind : public SchemaKind {
 public:
  ControlFluidKind();
  std::string name() const override { return "control_fluid"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
