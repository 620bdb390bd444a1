#pragma once
// Parameter schema of an experiment kind: name, unit, default, allowed range, one-line doc.
// The runner turns experiment files into `Params`; a kind reads them through `ParamReader`.
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace creaturelab::kinds {

using Value = std::variant<double, std::int64_t, bool, std::string>;
using Params = std::map<std::string, Value>;  // every declared parameter, resolved

enum class ParamType { Real, Integer, Boolean, Choice, RealOrAuto, Text };

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Real;
  Value default_value;
  std::string unit;  // "" for dimensionless
  std::string doc;   // one line, cites the paper where the default comes from
  double min = -std::numeric_limits<double>::infinity();  // inclusive, numbers only
  double max = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;  // Choice only
};

ParamSpec real(std::string name, double def, std::string unit, double min, double max, std::string doc);
ParamSpec integer(std::string name, std::int64_t def, std::int64_t min, std::int64_t max, std::string doc);
ParamSpec boolean(std::string name, bool def, std::string doc);
ParamSpec choice(std::string name, std::string def, std::vector<std::string> choices, std::string doc);
// A positive real or the string "auto" (e.g. dt_s = "auto" picks a stable step).
ParamSpec realOrAuto(std::string name, std::string unit, double min, double max, std::string doc);
// Free text the kind parses itself (its validate() reports what is wrong with it).
ParamSpec text(std::string name, std::string def, std::string unit, std::string doc);

std::string typeName(ParamType type);
std::string describeValue(const Value& v);  // "0.5", "true", "\"rk4\""
std::string describeRange(const ParamSpec& spec);  // "[0, 10]", one of "a" | "b", ...

// Checks type and range; "" if `v` is acceptable for `spec`, else what was expected.
std::string checkValue(const ParamSpec& spec, const Value& v);

// Typed access for kinds. Throws std::logic_error on a programming error (wrong type asked).
class ParamReader {
 public:
  explicit ParamReader(const Params& params) : params_(params) {}
  double real(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  bool isAuto(const std::string& name) const;

 private:
  const Value& at(const std::string& name) const;
  const Params& params_;
};

}  // namespace creaturelab::kinds
