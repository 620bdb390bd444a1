#pragma once
// A user error found before fitting (bad data, bad options, a bad controller file): the CLI
// prints its message and exits with code 2, having written nothing.
#include <stdexcept>

namespace creaturelab::fit {

class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace creaturelab::fit
