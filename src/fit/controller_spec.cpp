#include "fit/controller_spec.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <toml++/toml.h>

#include "core/text.hpp"
#include "kinds/param_toml.hpp"

namespace creaturelab::fit {
namespace {

using core::formatNumber;
using kinds::ParamSpec;
using kinds::ParamType;
using Context = kinds::TomlContext<FitError>;

const ParamSpec& specFor(const kinds::Kind& kind, const std::string& name, const Context& ctx, const std::string& key,
                         const toml::node* node) {
  return kinds::specFor(kind, name, ctx, key, node, "creaturelab list " + kind.name());
}

double number(const toml::table& t, const std::string& name, double fallback, const Context& ctx,
              const std::string& key) {
  const toml::node* n = t.get(name);
  if (!n) return fallback;
  if (!n->is_number()) ctx.fail(key + "." + name, "expected a number", n);
  const double v = n->value<double>().value();
  if (!std::isfinite(v)) ctx.fail(key + "." + name, "expected a finite number", n);
  return v;
}

std::string metricName(const toml::table& t, const std::string& name, const kinds::Kind& kind, const Context& ctx,
                       const std::string& fallback) {
  const toml::node* n = t.get(name);
  if (!n) return fallback;
  if (!n->is_string()) ctx.fail("objective." + name, "expected a metric name", n);
  const std::string metric = n->value<std::string>().value();
  std::vector<std::string> names;
  for (const auto& m : kind.metrics()) names.push_back(m.name);
  if (std::find(names.begin(), names.end(), metric) == names.end())
    ctx.fail("objective." + name, "'" + metric + "' is not a metric of kind '" + kind.name() + "'" +
                                      core::didYouMean(metric, names),
             n);
  return metric;
}

ObjectiveSpec parseObjective(const toml::table* t, const kinds::Kind& kind, const Context& ctx) {
  ObjectiveSpec o;
  if (!t) ctx.fail("objective", "missing: add an [objective] table (type = \"maximise\" or \"target\")");
  kinds::checkKeys(*t, {"type", "metric", "scale", "target", "tolerance", "least", "least_scale"}, ctx, "objective");
  const std::string type = (*t)["type"].value_or(std::string("maximise"));
  if (type == "maximise" || type == "maximize") {
    o.type = ObjectiveType::maximise;
  } else if (type == "target") {
    o.type = ObjectiveType::target;
  } else {
    ctx.fail("objective.type", "'" + type + "' is not one of maximise | target", t->get("type"));
  }
  o.metric = metricName(*t, "metric", kind, ctx, "");
  if (o.metric.empty()) ctx.fail("objective.metric", "missing: name the metric, e.g. metric = \"distance_per_cycle_m\"");
  o.scale = number(*t, "scale", 1.0, ctx, "objective");
  if (!(o.scale > 0)) ctx.fail("objective.scale", "must be > 0", t->get("scale"));
  if (o.type == ObjectiveType::target) {
    if (!t->get("target")) ctx.fail("objective.target", "missing: a target objective needs target = <value>");
    o.target = number(*t, "target", 0.0, ctx, "objective");
    o.tolerance = number(*t, "tolerance", 1.0, ctx, "objective");
    if (!(o.tolerance > 0)) ctx.fail("objective.tolerance", "must be > 0", t->get("tolerance"));
    o.least = metricName(*t, "least", kind, ctx, "");
    o.least_scale = number(*t, "least_scale", 1.0, ctx, "objective");
    if (!(o.least_scale > 0)) ctx.fail("objective.least_scale", "must be > 0", t->get("least_scale"));
  } else {
    for (const char* k : {"target", "tolerance", "least", "least_scale"})
      if (t->get(k)) ctx.fail(std::string("objective.") + k, "only for type = \"target\"", t->get(k));
  }
  return o;
}

}  // namespace

kinds::Params ControllerSpec::paramsAt(const std::vector<double>& x) const {
  kinds::Params p = base;
  for (std::size_t i = 0; i < tuned.size(); ++i) p[tuned[i].name] = x[i];
  return p;
}

std::vector<double> ControllerSpec::start() const {
  std::vector<double> x;
  for (const auto& t : tuned) x.push_back(t.start);
  return x;
}

ControllerSpec loadControllerSpec(const std::string& path, const kinds::Registry& registry) {
  return loadControllerSpecText(Context{path}.readText("controller-fit"), path, registry);
}

ControllerSpec loadControllerSpecText(const std::string& text, const std::string& path,
                                      const kinds::Registry& registry) {
  const Context ctx{path};
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& err) {
    throw FitError(path + ":" + std::to_string(err.source().begin.line) + ": malformed TOML: " +
                   std::string(err.description()));
  }
  kinds::checkKeys(root, {"kind", "title", "description", "params", "objective", "solver", "tune"}, ctx, "");

  ControllerSpec s;
  s.path = path;
  s.stem = std::filesystem::path(path).stem().string();
  s.source_text = text;
  s.kind = root["kind"].value_or(std::string("jellyfish"));
  const kinds::Kind* kind = registry.find(s.kind);
  if (!kind)
    ctx.fail("kind", "unknown kind '" + s.kind + "'" + core::didYouMean(s.kind, registry.names()), root.get("kind"));
  s.title = root["title"].value_or(s.stem);

  // --- [params]: overrides of the kind's defaults
  kinds::Params given;
  if (const toml::node* p = root.get("params")) {
    const auto* t = p->as_table();
    if (!t) ctx.fail("params", "expected a table [params]", p);
    for (auto&& [k, v] : *t) {
      const std::string name(k.str()), key = "params." + name;
      given[name] = kinds::paramValue(specFor(*kind, name, ctx, key, &v), v, ctx, key);
      s.overrides.emplace_back(name, given[name]);
    }
  }
  s.base = kinds::withDefaults(*kind, given);

  // --- [[tune]]
  const toml::node* tn = root.get("tune");
  if (!tn) ctx.fail("tune", "missing: add one [[tune]] table per parameter to tune");
  const auto* arr = tn->as_array();
  if (!arr || !arr->is_array_of_tables() || arr->empty()) ctx.fail("tune", "expected [[tune]] tables", tn);
  int n = 0;
  for (auto&& item : *arr) {
    const auto& t = *item.as_table();
    const std::string key = "tune[" + std::to_string(n++) + "]";
    kinds::checkKeys(t, {"name", "start", "min", "max", "step"}, ctx, key);
    const auto name = t["name"].value<std::string>();
    if (!name) ctx.fail(key + ".name", "missing: the parameter to tune, e.g. name = \"stagger\"", &t);
    const ParamSpec& spec = specFor(*kind, *name, ctx, key + ".name", t.get("name"));
    if (spec.type != ParamType::Real)
      ctx.fail(key + ".name", "'" + *name + "' is " + kinds::typeName(spec.type) + "; only real parameters can be tuned",
               t.get("name"));
    for (const auto& other : s.tuned)
      if (other.name == *name) ctx.fail(key + ".name", "'" + *name + "' is tuned twice", t.get("name"));
    TunedParam p;
    p.name = *name;
    p.unit = spec.unit;
    for (const char* k : {"min", "max", "step"})
      if (!t.get(k)) ctx.fail(key + "." + k, "missing (tuned parameters need min, max and step)", &t);
    p.lower = number(t, "min", 0.0, ctx, key);
    p.upper = number(t, "max", 0.0, ctx, key);
    p.step = number(t, "step", 0.0, ctx, key);
    p.start = t.get("start") ? number(t, "start", 0.0, ctx, key) : std::get<double>(s.base.at(*name));
    const std::string range = "[" + formatNumber(p.lower) + ", " + formatNumber(p.upper) + "]";
    if (!(p.lower < p.upper)) ctx.fail(key, "min must be below max, got " + range, &t);
    if (p.lower < spec.min || p.upper > spec.max)
      ctx.fail(key, "bounds " + range + " leave the range of '" + p.name + "', " + kinds::describeRange(spec), &t);
    if (!(p.start > p.lower && p.start < p.upper))
      ctx.fail(key, "the bounds " + range + " exclude the start " + formatNumber(p.start) +
                        " (it must lie strictly inside)",
               t.get("start") ? t.get("start") : &t);
    if (!(p.step > 0 && p.step <= 0.25 * (p.upper - p.lower)))
      ctx.fail(key + ".step", "must be > 0 and at most a quarter of max - min (" +
                                  formatNumber(0.25 * (p.upper - p.lower)) + "), got " + formatNumber(p.step),
               t.get("step"));
    s.tuned.push_back(p);
  }

  s.objective = parseObjective(root["objective"].as_table(), *kind, ctx);
  if (const toml::node* sn = root.get("solver")) {
    const auto* t = sn->as_table();
    if (!t) ctx.fail("solver", "expected a table [solver]", sn);
    kinds::checkKeys(*t,
              {"max_iterations", "max_runs", "function_tolerance", "gradient_tolerance", "parameter_tolerance"}, ctx,
              "solver");
    auto& o = s.solver;
    o.max_iterations = static_cast<int>(number(*t, "max_iterations", o.max_iterations, ctx, "solver"));
    o.max_runs = static_cast<int>(number(*t, "max_runs", o.max_runs, ctx, "solver"));
    o.function_tolerance = number(*t, "function_tolerance", o.function_tolerance, ctx, "solver");
    o.gradient_tolerance = number(*t, "gradient_tolerance", o.gradient_tolerance, ctx, "solver");
    o.parameter_tolerance = number(*t, "parameter_tolerance", o.parameter_tolerance, ctx, "solver");
    if (o.max_iterations < 1) ctx.fail("solver.max_iterations", "must be >= 1", t->get("max_iterations"));
    if (o.max_runs < 2 * int(s.tuned.size()) + 1)
      ctx.fail("solver.max_runs", "must allow one gradient: at least 2 x tuned + 1 = " +
                                      std::to_string(2 * s.tuned.size() + 1),
               t->get("max_runs"));
    for (const char* k : {"function_tolerance", "gradient_tolerance", "parameter_tolerance"})
      if (!(number(*t, k, 1.0, ctx, "solver") > 0)) ctx.fail(std::string("solver.") + k, "must be > 0", t->get(k));
  }

  // The kind's own cross checks at the start (e.g. a knot used beyond contraction_knots).
  if (std::string err = kind->validate(s.paramsAt(s.start())); !err.empty())
    ctx.fail("", "the start parameters are not a valid " + s.kind + " run: " + err);
  return s;
}

}  // namespace creaturelab::fit
