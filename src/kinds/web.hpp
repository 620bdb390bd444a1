#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// An orb web built strand by strand (Mehla 2005 thesis §5.2) and settled under gravity and drag,
// optionally swaying in the thesis's wind (§5.3.9, Fig. 5.45).
class WebKind : public SchemaKind {
 public:
  WebKind();
  std::string name() const override { return "web"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
