#pragma once
// A kind whose parameters are one described struct P (describe.hpp): its schema is P's description
// with P's in-class defaults, and its validation is P's member validate() (ranges from the
// description, then the cross-field rules), so run() reads `readParams<P>(params)` and no names.
#include <string>

#include "kinds/describe.hpp"
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

template <class P>
class DescribedKind : public SchemaKind {
 public:
  std::string validate(const Params& params) const override { return readParams<P>(params).validate(); }

 protected:
  DescribedKind() { params_ = schemaOf<P>(); }
};

}  // namespace creaturelab::kinds
