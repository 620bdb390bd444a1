#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// A creature driven by the gradient-descent controller of Lentine et al. 2010 under gravity and
// simple wind (Lentine et al. 2010 §2-3, §5, §7; issue 15): an MJCF model,
// controlled joints with their objectives, kinematic joints held.
class ControlKind : public SchemaKind {
 public:
  ControlKind();
  std::string name() const override { return "control"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
