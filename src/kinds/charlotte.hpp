#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// Charlotte's web (Mehla 2005 thesis ch. 6): a settled orb web with a text or an image inscribed by
// removing the spiral segments that match the dilated target, the three emphasis variants of
// Figs. 6.12-6.14, an image target (Fig. 6.16) and random gaps (Fig. 6.18); the web settles again
// afterwards. Renders (web, overlay, result) come back as Result::artifacts.
class CharlotteKind : public SchemaKind {
 public:
  CharlotteKind();
  std::string name() const override { return "charlotte"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
};

}  // namespace creaturelab::kinds
