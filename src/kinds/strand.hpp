#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// A single web strand (Mehla 2005 thesis §5.1, Figs. 5.1-5.2): a chain of masses between two pinned
// anchors under gravity and air drag, laid at rest length, over-extended, or constrained by Provot.
class StrandKind : public SchemaKind {
 public:
  StrandKind();
  std::string name() const override { return "strand"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
