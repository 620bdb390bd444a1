#include "kinds/param_toml.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/text.hpp"

namespace creaturelab::kinds {

std::string tomlErrorText(const std::string& file, const std::string& key, const std::string& msg,
                          const toml::node* node) {
  std::string text = file;
  if (node && node->source().begin.line > 0) text.append(":").append(std::to_string(node->source().begin.line));
  text.append(": ");
  if (!key.empty()) text.append(key).append(": ");
  return text.append(msg);
}

std::string readWholeFile(const std::string& path, const std::string& what, std::string& text) {
  if (!std::filesystem::is_regular_file(path)) return "no such " + what + " file";
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) return "cannot read the file";
  text = buffer.str();
  return "";
}

std::string unknownKeyText(const std::string& key, const std::vector<std::string>& known) {
  if (std::find(known.begin(), known.end(), key) != known.end()) return "";
  return "unknown key '" + key + "'" + core::didYouMean(key, known);
}

std::optional<Value> scalarValue(const toml::node& node) {
  if (auto v = node.as_integer()) return Value(std::int64_t(v->get()));
  if (auto v = node.as_floating_point()) return Value(v->get());
  if (auto v = node.as_boolean()) return Value(v->get());
  if (auto v = node.as_string()) return Value(v->get());
  return std::nullopt;
}

std::string coerceValue(const ParamSpec& spec, Value& value) {
  if (auto i = std::get_if<std::int64_t>(&value);
      i && (spec.type == ParamType::Real || spec.type == ParamType::RealOrAuto))
    value = double(*i);
  // Below 2^53 (about 9e15) a whole double is exactly the integer that was written.
  if (auto d = std::get_if<double>(&value);
      d && spec.type == ParamType::Integer && std::floor(*d) == *d && std::fabs(*d) < 9e15)
    value = std::int64_t(*d);
  const std::string expected = checkValue(spec, value);
  if (expected.empty()) return "";
  return "got " + describeValue(value) + ", expected " + expected + " (" + spec.doc + ")";
}

const ParamSpec* findParam(const Kind& kind, const std::string& name, std::string& problem) {
  std::vector<std::string> names;
  for (const auto& s : kind.params()) {
    if (s.name == name) return &s;
    names.push_back(s.name);
  }
  problem = "unknown parameter '" + name + "' for kind '" + kind.name() + "'" + core::didYouMean(name, names);
  return nullptr;
}

}  // namespace creaturelab::kinds
