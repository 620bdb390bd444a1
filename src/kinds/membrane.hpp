#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// The immersed-boundary membrane test (ib/membrane_body.hpp; Peskin 2002): an elliptical ring of
// zero-rest-length springs in a box of fluid relaxes to the circle of the same area; the
// enclosed area it loses is the coupling's leakage (Rudolf & Mould 2009 §3.2, "a minimal amount
// of leakage across solid boundaries").
class MembraneKind : public SchemaKind {
 public:
  MembraneKind();
  std::string name() const override { return "membrane"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
};

}  // namespace creaturelab::kinds
