#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// A damped mass on a spring, m x'' + c x' + k x = 0 (thesis Eq. 4.12), integrated by the spring-mass
// engine and stored beside its closed-form solution, so sweeps of integrator and dt show accuracy
// and stability.
class OscillatorKind : public Kind {
 public:
  OscillatorKind();
  std::string name() const override { return "oscillator"; }
  std::string doc() const override;
  const std::vector<ParamSpec>& params() const override { return params_; }
  const std::vector<MetricSpec>& metrics() const override { return metrics_; }
  std::string validate(const Params& params) const override;
  Result run(const Params& params) const override;

 private:
  std::vector<ParamSpec> params_;
  std::vector<MetricSpec> metrics_;
};

}  // namespace creaturelab::kinds
