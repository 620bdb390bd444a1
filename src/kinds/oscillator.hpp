#pragma once
#include <string>

#include "kinds/damped_oscillator.hpp"
#include "kinds/describe_kind.hpp"

namespace creaturelab::kinds {

// The oscillator kind's parameters: the body (its closed form's), the integrator and the span.
struct OscillatorParams {
  DampedOscillator body;
  std::string integrator = "rk4";
  RealOrAuto dt_s;  // "auto": half the integrator's stability limit (springs::autoStepS)
  double end_time_s = 10.0;

  template <class V>
  void describe(V& v) {
    body.describe(v);
    v.choice("integrator", integrator, {"euler", "symplectic_euler", "rk4", "implicit_euler"},
             "time integrator (thesis §4.2.1; rk4 is the thesis's choice, Eq. 4.16-4.19)");
    v.realOrAuto("dt_s", dt_s, "s", 1e-9, 10, "time step; \"auto\" = half the integrator's stability limit");
    v.real("end_time_s", end_time_s, "s", 1e-6, 1e5, "simulated time");
  }
  // Ranges, then: a fixed step no longer than the run.
  std::string validate() const;
};

// A damped mass on a spring, m x'' + c x' + k x = 0 (thesis Eq. 4.12), integrated by the spring-mass
// engine and stored beside its closed-form solution, so sweeps of integrator and dt show accuracy
// and stability.
class OscillatorKind : public DescribedKind<OscillatorParams> {
 public:
  OscillatorKind();
  std::string name() const override { return "oscillator"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
};

}  // namespace creaturelab::kinds
