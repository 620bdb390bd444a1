#pragma once
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// An orb web built strand by strand (Mehla 2005 thesis §5.2) and settled under gravity and drag,
// optionally swaying in the thesis's wind (§5.3.9, Fig. 5.45).
class WebKind : public Kind {
 public:
  WebKind();
  std::string name() const override { return "web"; }
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
