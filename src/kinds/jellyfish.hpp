#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// A 2-D jellyfish bell swimming in sea water, coupled by the immersed boundary method
// (Rudolf & Mould 2009 §3.1–3.3, Figs. 4, 5, 11, 12).
class JellyfishKind : public SchemaKind {
 public:
  JellyfishKind();
  std::string name() const override { return "jellyfish"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
  // Defined in kinds/jellyfish_render.cpp: a recorded swim drawn in 3-D (Rudolf & Mould 2009 §3.4-3.5).
  const RenderHook* renderHook() const override;

  // The largest number of Hermite knots the schema declares (knot0_* .. knot{N-1}_*).
  static constexpr int kMaxKnots = 6;
};

}  // namespace creaturelab::kinds
