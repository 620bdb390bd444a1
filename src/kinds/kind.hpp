#pragma once
// An experiment kind: the only place that knows both a solver and the harness (DESIGN.md).
// It declares its parameters and metrics and turns a resolved parameter set into a Result.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinds/params.hpp"
#include "kinds/result.hpp"

namespace creaturelab::kinds {

class RenderHook;  // kinds/render_hook.hpp

struct MetricSpec {
  std::string name;
  std::string unit;
  std::string doc;
};

// Thrown by a run that cannot finish (divergence, NaN): the point is recorded as failed with
// this message and whatever was computed before the failure; the other points still run.
class RunFailure : public std::runtime_error {
 public:
  explicit RunFailure(const std::string& message, Result partial = {})
      : std::runtime_error(message), partial_(std::move(partial)) {}
  const Result& partial() const { return partial_; }

 private:
  Result partial_;
};

// What one point will cost, estimated from its parameters before it runs (cheaply: no stepping), so
// the runner can refuse a point that would run for hours, or not fit in memory, before any work
// starts. 0 = not known.
struct CostEstimate {
  double steps = 0;         // time steps the solver will take
  double memory_bytes = 0;  // peak memory of the point while it runs, its recorded Result included
  std::string detail;       // how: e.g. "dt = 1.25e-07 s (auto for euler) x 8 substeps over 15 s"
};

class Kind {
 public:
  virtual ~Kind() = default;
  virtual std::string name() const = 0;
  virtual std::string doc() const = 0;
  virtual const std::vector<ParamSpec>& params() const = 0;
  virtual const std::vector<MetricSpec>& metrics() const = 0;
  // Checks that need several parameters together; "" when the set is consistent.
  virtual std::string validate(const Params& params) const { (void)params; return ""; }
  virtual Result run(const Params& params) const = 0;
  // See CostEstimate; a kind that cannot tell returns {}. Never throws: a point that cannot run
  // says so in validate() or run().
  virtual CostEstimate estimateCost(const Params& params) const { (void)params; return {}; }
  // Whether and how `creaturelab render` draws a recorded run of this kind (kinds/render_hook.hpp);
  // nullptr (the default): its runs do not render.
  virtual const RenderHook* renderHook() const { return nullptr; }
};

// A kind whose schema is fixed when it is constructed: the constructor fills params_ and metrics_.
class SchemaKind : public Kind {
 public:
  const std::vector<ParamSpec>& params() const override { return params_; }
  const std::vector<MetricSpec>& metrics() const override { return metrics_; }

 protected:
  std::vector<ParamSpec> params_;
  std::vector<MetricSpec> metrics_;
};

class Registry {
 public:
  void add(std::unique_ptr<Kind> kind) { kinds_.push_back(std::move(kind)); }
  const Kind* find(const std::string& name) const {
    for (const auto& k : kinds_)
      if (k->name() == name) return k.get();
    return nullptr;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& k : kinds_) out.push_back(k->name());
    return out;
  }
  const std::vector<std::unique_ptr<Kind>>& all() const { return kinds_; }

 private:
  std::vector<std::unique_ptr<Kind>> kinds_;
};

// Every kind this build knows.
Registry defaultRegistry();

// Fills every declared parameter missing from `params` with its default.
Params withDefaults(const Kind& kind, Params params);

}  // namespace creaturelab::kinds
