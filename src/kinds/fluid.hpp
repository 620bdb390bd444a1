#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// The incompressible fluid alone (Rudolf & Mould 2009 §3.2, Eq. 1; Stam 1999 stable fluids on a
// MAC grid): decaying Taylor-Green vortices for convergence, a vortex pair meeting a wall, ...
class FluidKind : public Kind {
 public:
  FluidKind();
  std::string name() const override { return "fluid"; }
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
