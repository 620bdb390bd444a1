#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// Tu's artificial fish (X. Tu, Artificial Animals for Computer Animation, 1996; docs/fish-spec.md):
// a 23-node spring-mass body in water, stepped semi-implicitly, driven by swim and turn motor
// controllers through a schedule, optionally skinned with NURBS surfaces and exported.
class FishKind : public SchemaKind {
 public:
  FishKind();
  std::string name() const override { return "fish"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
