#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// A damped mass on a spring, m x'' + c x' + k x = 0 (thesis Eq. 4.12), integrated by the spring-mass
// engine and stored beside its closed-form solution, so sweeps of integrator and dt show accuracy
// and stability.
class OscillatorKind : public SchemaKind {
 public:
  OscillatorKind();
  std::string name() const override { return "oscillator"; }
  std::string doc() const override;
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;
};

}  // namespace creaturelab::kinds
