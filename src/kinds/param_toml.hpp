#pragma once
// A kind's parameters as written in a TOML file. Experiment files (runner/experiment.cpp) and
// controller-fit files (fit/controller_spec.cpp) both carry a [params] table checked against a
// kind; reading it here keeps one mistake one message in both formats.
//
// Errors name the file, the line when toml++ knows it, the key and what was expected:
//   "exp.toml:4: params.dt: unknown parameter 'dt' for kind 'strand' (did you mean 'dt_s'?); ..."
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// "<file>[:<line>]: [<key>: ]<msg>".
std::string tomlErrorText(const std::string& file, const std::string& key, const std::string& msg,
                          const toml::node* node);

// Reads the whole file into `text`; "" when it did, else the problem in words ("no such <what>
// file", "cannot read the file").
std::string readWholeFile(const std::string& path, const std::string& what, std::string& text);

// "" when `key` is one of `known`, else "unknown key '<key>'" with a close match.
std::string unknownKeyText(const std::string& key, const std::vector<std::string>& known);

// The file being read. Error is the format's own user-error type (runner::ExperimentError,
// fit::FitError), which the CLI and the tests tell apart, so it is a parameter, not a base class.
template <class Error>
struct TomlContext {
  std::string file;

  [[noreturn]] void fail(const std::string& key, const std::string& msg, const toml::node* node = nullptr) const {
    throw Error(tomlErrorText(file, key, msg, node));
  }

  // The file's text; `what` names the format in the error ("no such experiment file").
  std::string readText(const std::string& what) const {
    std::string text;
    if (std::string problem = readWholeFile(file, what, text); !problem.empty()) fail("", problem);
    return text;
  }
};

// Every key of `table` must be one of `known`; `prefix` is the table's key in errors.
template <class Error>
void checkKeys(const toml::table& table, const std::vector<std::string>& known, const TomlContext<Error>& ctx,
               const std::string& prefix) {
  for (auto&& [k, v] : table)
    if (std::string problem = unknownKeyText(std::string(k.str()), known); !problem.empty())
      ctx.fail(prefix, problem, &v);
}

// An integer, float, boolean or string; nullopt for tables, arrays and dates.
std::optional<Value> scalarValue(const toml::node& node);

// Converts `value` to the spec's type where nothing is lost (an integer literal is a fine real, a
// whole real a fine integer), then checks type and range: "" when acceptable, else
// "got <value>, expected <what> (<doc>)".
std::string coerceValue(const ParamSpec& spec, Value& value);

template <class Error>
Value coerce(const ParamSpec& spec, Value value, const TomlContext<Error>& ctx, const std::string& key,
             const toml::node* node) {
  if (std::string problem = coerceValue(spec, value); !problem.empty()) ctx.fail(key, problem, node);
  return value;
}

// A scalar node as a value of the parameter `spec`.
template <class Error>
Value paramValue(const ParamSpec& spec, const toml::node& node, const TomlContext<Error>& ctx, const std::string& key) {
  const std::optional<Value> value = scalarValue(node);
  if (!value) ctx.fail(key, "expected " + typeName(spec.type), &node);
  return coerce(spec, *value, ctx, key, &node);
}

// The parameter `name` of `kind`, else nullptr and `problem` says so, with a close match.
const ParamSpec* findParam(const Kind& kind, const std::string& name, std::string& problem);

// The parameter `name` of `kind`; an unknown name fails, pointing at `list_command`, which shows
// every parameter (`creaturelab list` or `creaturelab list <kind>`).
template <class Error>
const ParamSpec& specFor(const Kind& kind, const std::string& name, const TomlContext<Error>& ctx,
                         const std::string& key, const toml::node* node, const std::string& list_command) {
  std::string problem;
  if (const ParamSpec* spec = findParam(kind, name, problem)) return *spec;
  ctx.fail(key, problem + "; `" + list_command + "` shows every parameter", node);
}

}  // namespace creaturelab::kinds
