#pragma once
// The kinds as the program registers them, for the tests that load experiments (one per program).
#include "kinds/kind.hpp"

namespace creaturelab::testing {

inline const kinds::Registry& registry() {
  static const kinds::Registry r = kinds::defaultRegistry();
  return r;
}

}  // namespace creaturelab::testing
