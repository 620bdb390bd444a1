#include "kinds/params.hpp"

#include <cmath>
#include <stdexcept>

#include "core/text.hpp"

namespace creaturelab::kinds {

ParamSpec real(std::string name, double def, std::string unit, double min, double max, std::string doc) {
  return {std::move(name), ParamType::Real, def, std::move(unit), std::move(doc), min, max, {}};
}

ParamSpec integer(std::string name, std::int64_t def, std::int64_t min, std::int64_t max, std::string doc) {
  return {std::move(name), ParamType::Integer, def, "", std::move(doc), double(min), double(max), {}};
}

ParamSpec boolean(std::string name, bool def, std::string doc) {
  return {std::move(name), ParamType::Boolean, def, "", std::move(doc), 0, 1, {}};
}

ParamSpec choice(std::string name, std::string def, std::vector<std::string> choices, std::string doc) {
  return {std::move(name), ParamType::Choice, std::move(def), "", std::move(doc), 0, 0, std::move(choices)};
}

ParamSpec realOrAuto(std::string name, std::string unit, double min, double max, std::string doc) {
  return {std::move(name), ParamType::RealOrAuto, std::string("auto"), std::move(unit), std::move(doc), min, max, {}};
}

ParamSpec text(std::string name, std::string def, std::string unit, std::string doc) {
  return {std::move(name), ParamType::Text, std::move(def), std::move(unit), std::move(doc), 0, 0, {}};
}

std::string typeName(ParamType type) {
  switch (type) {
    case ParamType::Real: return "a number";
    case ParamType::Integer: return "an integer";
    case ParamType::Boolean: return "true or false";
    case ParamType::Choice: return "one of the listed strings";
    case ParamType::RealOrAuto: return "a number or \"auto\"";
    case ParamType::Text: return "a string";
  }
  return "?";
}

std::string describeValue(const Value& v) {
  if (auto d = std::get_if<double>(&v)) return core::formatNumber(*d);
  if (auto i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (auto b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  return "\"" + std::get<std::string>(v) + "\"";
}

std::string describeRange(const ParamSpec& spec) {
  switch (spec.type) {
    case ParamType::Boolean: return "true | false";
    case ParamType::Text: return "text";
    case ParamType::Choice: {
      std::string out;
      for (const auto& c : spec.choices) out += (out.empty() ? "\"" : " | \"") + c + "\"";
      return out;
    }
    default: {
      std::string lo = std::isinf(spec.min) ? "-inf" : core::formatNumber(spec.min);
      std::string hi = std::isinf(spec.max) ? "inf" : core::formatNumber(spec.max);
      return "[" + lo + ", " + hi + "]" + (spec.type == ParamType::RealOrAuto ? " or \"auto\"" : "");
    }
  }
}

namespace {
std::string checkNumber(const ParamSpec& spec, double x) {
  if (!std::isfinite(x)) return "a finite number";
  if (x < spec.min || x > spec.max) return "a value in " + describeRange(spec);
  return "";
}
}  // namespace

std::string checkValue(const ParamSpec& spec, const Value& v) {
  switch (spec.type) {
    case ParamType::Real:
      if (auto d = std::get_if<double>(&v)) return checkNumber(spec, *d);
      return typeName(spec.type);
    case ParamType::Integer:
      if (auto i = std::get_if<std::int64_t>(&v)) return checkNumber(spec, double(*i));
      return typeName(spec.type);
    case ParamType::Boolean:
      return std::holds_alternative<bool>(v) ? "" : typeName(spec.type);
    case ParamType::Choice: {
      auto s = std::get_if<std::string>(&v);
      if (s)
        for (const auto& c : spec.choices)
          if (c == *s) return "";
      return "one of " + describeRange(spec);
    }
    case ParamType::RealOrAuto:
      if (auto d = std::get_if<double>(&v)) return checkNumber(spec, *d);
      if (auto s = std::get_if<std::string>(&v); s && *s == "auto") return "";
      return typeName(spec.type) + " in " + describeRange(spec);
    case ParamType::Text:
      return std::holds_alternative<std::string>(v) ? "" : typeName(spec.type);
  }
  return "a valid value";
}

const Value& ParamReader::at(const std::string& name) const {
  auto it = params_.find(name);
  if (it == params_.end()) throw std::logic_error("parameter '" + name + "' is not declared by this kind");
  return it->second;
}

double ParamReader::real(const std::string& name) const {
  const Value& v = at(name);
  if (auto d = std::get_if<double>(&v)) return *d;
  throw std::logic_error("parameter '" + name + "' is not a number");
}

std::int64_t ParamReader::integer(const std::string& name) const {
  const Value& v = at(name);
  if (auto i = std::get_if<std::int64_t>(&v)) return *i;
  throw std::logic_error("parameter '" + name + "' is not an integer");
}

bool ParamReader::boolean(const std::string& name) const {
  const Value& v = at(name);
  if (auto b = std::get_if<bool>(&v)) return *b;
  throw std::logic_error("parameter '" + name + "' is not a boolean");
}

const std::string& ParamReader::text(const std::string& name) const {
  const Value& v = at(name);
  if (auto s = std::get_if<std::string>(&v)) return *s;
  throw std::logic_error("parameter '" + name + "' is not a string");
}

bool ParamReader::isAuto(const std::string& name) const {
  auto s = std::get_if<std::string>(&at(name));
  return s && *s == "auto";
}

}  // namespace creaturelab::kinds
