#include "runner/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <set>
#include <toml++/toml.h>

#include "core/text.hpp"
#include "kinds/param_toml.hpp"
#include "runner/value_json.hpp"

namespace creaturelab::runner {
namespace {

using kinds::ParamSpec;
using Context = kinds::TomlContext<ExperimentError>;

const ParamSpec& specFor(const kinds::Kind& kind, const std::string& name, const Context& ctx, const std::string& key,
                         const toml::node* node) {
  return kinds::specFor(kind, name, ctx, key, node, "creaturelab list");
}

// "start:stop:step", inclusive of stop up to rounding; values are start + i*step rounded to 12
// significant digits so 0.1 steps print as 0.3, not 0.30000000000000004.
std::vector<Value> expandRange(const std::string& text, const ParamSpec& spec, const Context& ctx,
                               const std::string& key, const toml::node* node) {
  double a = 0, b = 0, step = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf:%lf:%lf%c", &a, &b, &step, &tail) != 3)
    ctx.fail(key, "range \"" + text + "\" is not start:stop:step", node);
  if (!(step > 0) || b < a) ctx.fail(key, "range \"" + text + "\" is empty (needs step > 0 and stop >= start)", node);
  const long n = long(std::floor((b - a) / step + 1e-9)) + 1;
  if (n > 100000) ctx.fail(key, "range \"" + text + "\" has " + std::to_string(n) + " values; at most 100000", node);
  std::vector<Value> values;
  for (long i = 0; i < n; ++i) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.12g", a + double(i) * step);
    values.push_back(kinds::coerce(spec, Value(std::strtod(buf, nullptr)), ctx, key, node));
  }
  return values;
}

void applyOverride(toml::table& root, const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ExperimentError("override '" + text + "': expected dotted.key=value, e.g. params.dt_s=0.001");
  const std::string path = text.substr(0, eq), rhs = text.substr(eq + 1);
  toml::table holder;
  try {
    holder = toml::parse("v = " + rhs);
  } catch (const toml::parse_error&) {
    holder.insert_or_assign("v", rhs);  // bare words: params.integrator=rk4
  }
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  toml::table* t = &root;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    auto* next = (*t)[parts[i]].as_table();
    if (!next) {
      if ((*t).contains(parts[i]))
        throw ExperimentError("override '" + text + "': '" + parts[i] + "' is not a table");
      t->insert_or_assign(parts[i], toml::table{});
      next = (*t)[parts[i]].as_table();
    }
    t = next;
  }
  t->insert_or_assign(parts.back(), *holder.get("v"));
}

std::string expectText(const toml::node* node) {
  if (!node) return "";
  std::ostringstream s;
  s << toml::json_formatter{*node};
  // One line, single spaces: errors are one line each.
  std::string text;
  for (char ch : s.str()) {
    if (ch == '\n') ch = ' ';
    if (ch == ' ' && (text.empty() || text.back() == ' ' || text.back() == '[')) continue;
    if (ch == ']' && !text.empty() && text.back() == ' ') text.pop_back();
    text += ch;
  }
  return text;
}

Where parseWhere(const toml::node* node, const Context& ctx, const std::string& key) {
  Where where;
  if (!node) return where;
  auto* t = node->as_table();
  if (!t) ctx.fail(key, "expected a table such as { layout = \"overextended\" }", node);
  for (auto&& [k, v] : *t) {
    auto value = kinds::scalarValue(v);
    if (!value) ctx.fail(key + "." + std::string(k.str()), "expected a number, string or boolean", &v);
    where.emplace_back(std::string(k.str()), *value);
  }
  return where;
}

CheckSpec parseCheck(const toml::table& t, int n, const kinds::Kind& kind, const Context& ctx) {
  const std::string key = "check[" + std::to_string(n) + "]";
  static const std::vector<std::string> known = {"name",      "type",        "metric",           "axis",
                                                 "expect",    "direction",   "strict",           "where",
                                                 "numerator", "denominator", "numerator_metric", "denominator_metric",
                                                 "numerator_base", "denominator_base", "base_relation", "known_deviation",
                                                 "relative_to", "relative_metric", "uncertainty", "samples"};
  kinds::checkKeys(t, known, ctx, key);
  CheckSpec c;
  c.name = t["name"].value_or(std::string());
  c.type = t["type"].value_or(std::string());
  c.metric = t["metric"].value_or(std::string());
  c.axis = t["axis"].value_or(std::string());
  c.direction = t["direction"].value_or(std::string("increasing"));
  c.strict = t["strict"].value_or(true);
  c.known_deviation = t["known_deviation"].value_or(std::string());
  if (t.contains("known_deviation") && (!t["known_deviation"].is_string() || c.known_deviation.empty()))
    ctx.fail(key + ".known_deviation", "expected a non-empty string: why the model does not reproduce this claim",
             t.get("known_deviation"));
  c.relative_metric = t["relative_metric"].value_or(std::string());
  c.numerator_metric = t["numerator_metric"].value_or(c.metric);
  c.denominator_metric = t["denominator_metric"].value_or(c.metric);
  if (c.name.empty()) ctx.fail(key, "needs a name", &t);
  static const std::vector<std::string> types = {"argmax", "argmin", "range", "ratio",
                                                 "difference", "monotonic", "order"};
  if (std::find(types.begin(), types.end(), c.type) == types.end())
    ctx.fail(key + ".type",
             "'" + c.type + "' is not one of argmax | argmin | range | ratio | difference | monotonic | order" +
                 core::didYouMean(c.type, types),
             t.get("type"));
  std::vector<std::string> metric_names;
  for (const auto& m : kind.metrics()) metric_names.push_back(m.name);
  for (const auto& [field, name] : {std::pair{"metric", c.metric}, std::pair{"numerator_metric", c.numerator_metric},
                                    std::pair{"denominator_metric", c.denominator_metric},
                                    std::pair{"relative_metric", c.relative_metric.empty() ? c.metric : c.relative_metric}})
    if (std::find(metric_names.begin(), metric_names.end(), name) == metric_names.end())
      ctx.fail(key + "." + field, "'" + name + "' is not a metric of kind '" + kind.name() + "'" +
                                      core::didYouMean(name, metric_names), t.get(field));
  const bool needs_axis = c.type == "argmax" || c.type == "argmin" || c.type == "monotonic" || c.type == "order";
  if (needs_axis && c.axis.empty()) ctx.fail(key, "a " + c.type + " check needs an axis", &t);
  if (c.type == "monotonic" && c.direction != "increasing" && c.direction != "decreasing")
    ctx.fail(key + ".direction", "expected \"increasing\" or \"decreasing\"", t.get("direction"));
  if (c.type != "monotonic") {
    const toml::node* e = t.get("expect");
    if (!e) ctx.fail(key, "needs expect = [low, high]", &t);
    if (auto s = e->as_string()) {
      if (c.type != "argmax" && c.type != "argmin") ctx.fail(key + ".expect", "expected [low, high]", e);
      c.expect_choice = s->get();
    } else if (auto a = e->as_array(); a && a->size() == 2 && (*a)[0].is_number() && (*a)[1].is_number()) {
      c.expect_lo = (*a)[0].value<double>().value();
      c.expect_hi = (*a)[1].value<double>().value();
      if (c.expect_hi < c.expect_lo) ctx.fail(key + ".expect", "low is above high", e);
    } else {
      ctx.fail(key + ".expect", "expected [low, high], got " + expectText(e), e);
    }
  }
  c.where = parseWhere(t.get("where"), ctx, key + ".where");
  c.numerator = parseWhere(t.get("numerator"), ctx, key + ".numerator");
  c.denominator = parseWhere(t.get("denominator"), ctx, key + ".denominator");
  c.numerator_base = parseWhere(t.get("numerator_base"), ctx, key + ".numerator_base");
  c.denominator_base = parseWhere(t.get("denominator_base"), ctx, key + ".denominator_base");
  if (t.contains("base_relation")) {
    const std::string relation = t["base_relation"].value_or(std::string());
    if (relation != "ratio" && relation != "difference")
      ctx.fail(key + ".base_relation", "expected \"ratio\" or \"difference\"", t.get("base_relation"));
    if (c.numerator_base.empty() && c.denominator_base.empty())
      ctx.fail(key + ".base_relation", "belongs to a check with numerator_base or denominator_base",
               t.get("base_relation"));
    c.base_difference = relation == "difference";
  }
  if ((c.type == "ratio" || c.type == "difference") && (c.numerator.empty() || c.denominator.empty()))
    ctx.fail(key, "a " + c.type + " check needs numerator = {...} and denominator = {...} point selections", &t);
  c.relative_to = parseWhere(t.get("relative_to"), ctx, key + ".relative_to");
  if (!c.relative_to.empty() || !c.relative_metric.empty()) {
    if (c.type != "argmax" && c.type != "argmin")
      ctx.fail(key, "relative_to and relative_metric belong to argmax and argmin checks", &t);
    if (c.relative_to.empty() || c.relative_metric.empty())
      ctx.fail(key, "relative_to = {...} and relative_metric go together", &t);
    if (c.expect_choice) ctx.fail(key + ".expect", "a relative argmax/argmin expects [low, high]", t.get("expect"));
  }
  if (t.contains("uncertainty")) {
    c.uncertainty = t["uncertainty"].value_or(std::string());
    const toml::node* u = t.get("uncertainty");
    if (c.type != "range" && c.type != "ratio" && c.type != "difference")
      ctx.fail(key + ".uncertainty", "belongs to range, ratio and difference checks", u);
    if (std::find(metric_names.begin(), metric_names.end(), c.uncertainty) == metric_names.end())
      ctx.fail(key + ".uncertainty", "expected the name of the metric holding " + c.metric + "'s standard error; '" +
                                         c.uncertainty + "' is not a metric of kind '" + kind.name() + "'" +
                                         core::didYouMean(c.uncertainty, metric_names), u);
    if (c.numerator_metric != c.metric || c.denominator_metric != c.metric || !c.numerator_base.empty() ||
        !c.denominator_base.empty())
      ctx.fail(key + ".uncertainty", "is one metric's standard error: not with numerator_metric, denominator_metric "
                                     "or a *_base selection", u);
    if (!t.contains("samples"))
      ctx.fail(key, "uncertainty needs samples = \"<parameter>\": the integer parameter counting the samples "
                    "behind each point's standard error (its degrees of freedom)", &t);
  }
  if (t.contains("samples")) {
    c.samples = t["samples"].value_or(std::string());
    const toml::node* s = t.get("samples");
    if (!t.contains("uncertainty")) ctx.fail(key + ".samples", "belongs to a check with uncertainty", s);
    const auto& params = kind.params();
    auto spec = std::find_if(params.begin(), params.end(), [&](const kinds::ParamSpec& p) { return p.name == c.samples; });
    if (spec == params.end() || spec->type != kinds::ParamType::Integer) {
      std::vector<std::string> integers;
      for (const auto& p : params)
        if (p.type == kinds::ParamType::Integer) integers.push_back(p.name);
      ctx.fail(key + ".samples", "expected the name of an integer parameter of kind '" + kind.name() +
                                     "' counting each point's samples; '" + c.samples + "' is not one" +
                                     core::didYouMean(c.samples, integers),
               s);
    }
  }
  return c;
}

// The context naming the file a node came from: a base file's keys are reported in that file.
// Nodes an override made carry no source and belong to `ctx`'s file.
Context contextOf(const toml::node& node, const Context& ctx) {
  const auto& file = node.source().path;
  return file && !file->empty() ? Context{*file} : ctx;
}

toml::table parseToml(const std::string& text, const std::string& path, const std::string& prefix) {
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& err) {
    throw ExperimentError(prefix + path + ":" + std::to_string(err.source().begin.line) + ":" +
                          std::to_string(err.source().begin.column) + ": malformed TOML: " +
                          std::string(err.description()));
  }
}

// Tables merge key by key, recursively; any other value of `over` (a scalar, a list, the [[case]]
// and [[check]] lists as a whole) replaces the base's. Nodes are moved, so they keep their source.
void mergeInto(toml::table& base, toml::table&& over) {
  for (auto&& [k, v] : over) {
    toml::table* into = base[k].as_table();
    if (into && v.is_table()) mergeInto(*into, std::move(*v.as_table()));
    else base.insert_or_assign(k, std::move(v));
  }
}

// The files read so far, first the one given: "a.toml -> b.toml" in errors, canonical paths for cycles.
struct BaseChain {
  std::vector<std::string> shown;
  std::vector<std::filesystem::path> canonical;
  std::string text() const {
    std::string t;
    for (const auto& s : shown) t += (t.empty() ? "" : " -> ") + s;
    return t;
  }
};

std::filesystem::path canonicalOf(const std::string& path) {
  std::error_code ec;
  auto p = std::filesystem::weakly_canonical(path, ec);
  return ec ? std::filesystem::absolute(path).lexically_normal() : p;
}

// `root` (read from chain.shown.back()) merged over its base chain, without `base` keys.
toml::table withBases(toml::table root, BaseChain& chain) {
  const toml::node* b = root.get("base");
  if (!b) return root;
  const std::string& path = chain.shown.back();
  if (!b->is_string() || b->as_string()->get().empty())
    throw ExperimentError(kinds::tomlErrorText(
        chain.text(), "base", "expected the path of another experiment file, relative to this one, e.g. base = "
                              "\"../../experiments/jellyfish/fig5_frequency.toml\"", b));
  const std::string shown =
      (std::filesystem::path(path).parent_path() / b->as_string()->get()).lexically_normal().string();
  const std::filesystem::path canonical = canonicalOf(shown);
  const bool cycle = std::find(chain.canonical.begin(), chain.canonical.end(), canonical) != chain.canonical.end();
  chain.shown.push_back(shown);
  chain.canonical.push_back(canonical);
  if (cycle) throw ExperimentError(chain.text() + ": base cycle");
  std::string text;
  if (!kinds::readWholeFile(shown, "experiment", text).empty())
    throw ExperimentError(chain.text() + ": base file not found");
  toml::table merged = withBases(parseToml(text, shown, chain.text() + ": "), chain);
  root.erase("base");
  mergeInto(merged, std::move(root));
  return merged;
}

nlohmann::json resolvedJson(const Experiment& e) {
  nlohmann::json j;
  j["kind"] = e.kind;
  j["title"] = e.title;
  j["params"] = toJson(e.params);
  j["sweep"] = nlohmann::json::array();
  for (const auto& a : e.axes) {
    nlohmann::json values = nlohmann::json::array();
    for (const auto& v : a.values) values.push_back(toJson(v));
    j["sweep"].push_back({{"name", a.name}, {"values", values}});
  }
  j["cases"] = nlohmann::json::array();
  for (const auto& c : e.cases) j["cases"].push_back({{"label", c.label}, {"values", toJson(c.values)}});
  return j;
}

}  // namespace

Experiment loadExperiment(const std::string& path, const std::vector<std::string>& overrides,
                          const kinds::Registry& registry) {
  if (std::filesystem::is_directory(path))
    throw ExperimentError(path + ": is a folder; expected an experiment file (e.g. experiments/web/sag.toml)");
  return loadExperimentText(Context{path}.readText("experiment"), path, overrides, registry);
}

Experiment loadExperimentText(const std::string& text, const std::string& path,
                              const std::vector<std::string>& overrides, const kinds::Registry& registry) {
  const Context ctx{path};
  toml::table root = parseToml(text, path, "");
  // A file with a base keeps the merged document: a run folder re-checks itself without the base.
  std::string source_text = text;
  if (root.contains("base")) {
    BaseChain chain{{path}, {canonicalOf(path)}};
    root = withBases(std::move(root), chain);
    std::ostringstream merged;
    merged << toml::toml_formatter{root} << "\n";
    source_text = merged.str();
  }
  for (const auto& o : overrides) applyOverride(root, o);
  if (root.contains("base")) ctx.fail("base", "cannot be set by an override: name the base in the file");

  static const std::vector<std::string> top = {"kind", "title", "description", "params", "sweep", "case", "check", "output"};
  for (auto&& [k, v] : root)
    if (std::string problem = kinds::unknownKeyText(std::string(k.str()), top); !problem.empty())
      contextOf(v, ctx).fail("", problem, &v);

  Experiment e;
  e.path = path;
  e.source_text = source_text;
  e.overrides = overrides;
  e.stem = std::filesystem::path(path).stem().string();
  auto kind_name = root["kind"].value<std::string>();
  if (!kind_name) ctx.fail("kind", "missing: every experiment names its kind, e.g. kind = \"strand\"");
  e.kind = *kind_name;
  const kinds::Kind* kind = registry.find(e.kind);
  if (!kind)
    contextOf(*root.get("kind"), ctx)
        .fail("kind", "unknown kind '" + e.kind + "'" + core::didYouMean(e.kind, registry.names()), root.get("kind"));
  e.title = root["title"].value_or(e.stem);

  if (const toml::node* p = root.get("params")) {
    auto* t = p->as_table();
    if (!t) contextOf(*p, ctx).fail("params", "expected a table [params]", p);
    for (auto&& [k, v] : *t) {
      const std::string name(k.str()), key = "params." + name;
      const Context at = contextOf(v, ctx);
      e.params[name] = kinds::paramValue(specFor(*kind, name, at, key, &v), v, at, key);
    }
  }

  if (const toml::node* s = root.get("sweep")) {
    auto* t = s->as_table();
    if (!t) contextOf(*s, ctx).fail("sweep", "expected a table [sweep]", s);
    for (auto&& [k, v] : *t) {
      const std::string name(k.str()), key = "sweep." + name;
      const Context at = contextOf(v, ctx);
      const ParamSpec& spec = specFor(*kind, name, at, key, &v);
      SweepAxis axis{name, {}};
      if (auto str = v.as_string(); str && std::count(str->get().begin(), str->get().end(), ':') == 2) {
        axis.values = expandRange(str->get(), spec, at, key, &v);
      } else if (auto arr = v.as_array()) {
        for (auto&& item : *arr) {
          auto value = kinds::scalarValue(item);
          if (!value) at.fail(key, "list items must be numbers, strings or booleans", &item);
          axis.values.push_back(kinds::coerce(spec, *value, at, key, &item));
        }
      } else {
        at.fail(key, "expected a list [a, b, ...] or a range \"start:stop:step\"", &v);
      }
      if (axis.values.empty()) at.fail(key, "empty sweep axis", &v);
      e.axes.push_back(std::move(axis));
    }
  }

  // An empty list (case = [], check = []) is none: it clears a base's list.
  if (const toml::node* c = root.get("case")) {
    auto* arr = c->as_array();
    if (!arr || (!arr->empty() && !arr->is_array_of_tables()))
      contextOf(*c, ctx).fail("case", "expected [[case]] tables", c);
    int n = 0;
    for (auto&& item : *arr) {
      Case cs;
      const Context at = contextOf(item, ctx);
      const std::string key = "case[" + std::to_string(n++) + "]";
      for (auto&& [k, v] : *item.as_table()) {
        const std::string name(k.str());
        if (name == "label") {
          cs.label = v.value_or(std::string());
          continue;
        }
        for (const auto& a : e.axes)
          if (a.name == name) at.fail(key + "." + name, "is also a [sweep] axis; set it in one place", &v);
        const std::string item_key = key + "." + name;
        cs.values[name] = kinds::paramValue(specFor(*kind, name, at, item_key, &v), v, at, item_key);
        cs.keys.push_back(name);
      }
      if (cs.label.empty()) cs.label = "case " + std::to_string(n - 1);
      // A label names one case: checks select by it and the index lists it per row.
      for (size_t other = 0; other < e.cases.size(); ++other)
        if (e.cases[other].label == cs.label)
          at.fail(key + ".label", "\"" + cs.label + "\" is already the label of case[" + std::to_string(other) +
                                      "]; each [[case]] needs its own label", item.as_table()->get("label"));
      e.cases.push_back(std::move(cs));
    }
  }

  if (const toml::node* c = root.get("check")) {
    auto* arr = c->as_array();
    if (!arr || (!arr->empty() && !arr->is_array_of_tables()))
      contextOf(*c, ctx).fail("check", "expected [[check]] tables", c);
    int n = 0;
    for (auto&& item : *arr) e.checks.push_back(parseCheck(*item.as_table(), n++, *kind, contextOf(item, ctx)));
  }

  if (const toml::node* o = root.get("output")) {
    auto* t = o->as_table();
    if (!t) contextOf(*o, ctx).fail("output", "expected a table [output]", o);
    static const std::vector<std::string> known = {"dir", "lagrangian"};
    for (auto&& [k, v] : *t)
      if (std::string problem = kinds::unknownKeyText(std::string(k.str()), known); !problem.empty())
        contextOf(v, ctx).fail("output", problem, &v);
    e.output.dir = (*t)["dir"].value_or(std::string());
    e.output.lagrangian = (*t)["lagrangian"].value_or(true);
  }

  // Check axes and selections name columns that exist.
  const auto columns = sweepColumns(e);
  for (const auto& chk : e.checks) {
    const std::string key = "check '" + chk.name + "'";
    if (!chk.axis.empty() && std::find(columns.begin(), columns.end(), chk.axis) == columns.end())
      ctx.fail(key, "axis '" + chk.axis + "' is not swept" + core::didYouMean(chk.axis, columns));
    for (const Where* w : {&chk.where, &chk.numerator, &chk.denominator, &chk.numerator_base, &chk.denominator_base,
                           &chk.relative_to})
      for (const auto& [k, v] : *w)
        if (k != "label" && std::find(columns.begin(), columns.end(), k) == columns.end())
          ctx.fail(key, "selection key '" + k + "' is not a swept column" + core::didYouMean(k, columns));
  }

  e.resolved_json = resolvedJson(e).dump();
  return e;
}

std::vector<std::string> sweepColumns(const Experiment& experiment) {
  std::vector<std::string> cols;
  for (const auto& c : experiment.cases)
    for (const auto& k : c.keys)
      if (std::find(cols.begin(), cols.end(), k) == cols.end()) cols.push_back(k);
  for (const auto& a : experiment.axes) cols.push_back(a.name);
  // The checks' sample counts, so that a check can be judged again from the table alone.
  for (const auto& c : experiment.checks)
    if (!c.samples.empty() && std::find(cols.begin(), cols.end(), c.samples) == cols.end()) cols.push_back(c.samples);
  return cols;
}

std::vector<Point> expandPoints(const Experiment& experiment, const kinds::Kind& kind) {
  std::vector<Case> cases = experiment.cases;
  if (cases.empty()) cases.push_back(Case{});
  size_t grid = 1;
  for (const auto& a : experiment.axes) grid *= a.values.size();
  if (grid * cases.size() > 1000000) throw ExperimentError(experiment.path + ": sweep has over a million points");

  std::vector<Point> points;
  for (const auto& cs : cases) {
    for (size_t g = 0; g < grid; ++g) {
      Point p;
      p.index = int(points.size());
      p.label = cs.label;
      p.params = experiment.params;
      for (const auto& [k, v] : cs.values) p.params[k] = v;
      size_t rem = g;
      for (size_t a = experiment.axes.size(); a-- > 0;) {
        const auto& axis = experiment.axes[a];
        p.params[axis.name] = axis.values[rem % axis.values.size()];
        rem /= axis.values.size();
      }
      p.params = kinds::withDefaults(kind, std::move(p.params));
      if (std::string err = kind.validate(p.params); !err.empty())
        throw ExperimentError(experiment.path + ": point " + std::to_string(p.index) +
                              (p.label.empty() ? "" : " (" + p.label + ")") + ": " + err);
      points.push_back(std::move(p));
    }
  }
  return points;
}

}  // namespace creaturelab::runner
