#include "fit/params_fragment.hpp"

#include <sstream>

#include "core/text.hpp"

namespace creaturelab::fit {

std::string tomlFloat(double v) {
  std::string s = core::formatNumber(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // "3" -> "3.0"; nan/inf stay
  return s;
}

std::string tomlValue(const kinds::Value& v) {
  if (const double* d = std::get_if<double>(&v)) return tomlFloat(*d);
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  std::string out = "\"";
  for (char c : std::get<std::string>(v)) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string paramsFragment(const std::vector<std::pair<std::string, kinds::Value>>& params,
                           const std::string& comment) {
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << "\n";
  out << "[params]\n";
  for (const auto& [name, value] : params) out << name << " = " << tomlValue(value) << "\n";
  return out.str();
}

std::vector<std::pair<std::string, kinds::Value>> knotParams(const std::vector<double>& phases,
                                                             const std::vector<double>& values,
                                                             const std::vector<double>& tangents) {
  std::vector<std::pair<std::string, kinds::Value>> out;
  out.emplace_back("contraction_knots", kinds::Value(std::int64_t(phases.size())));
  for (std::size_t k = 0; k < phases.size(); ++k) {
    const std::string p = "knot" + std::to_string(k) + "_";
    out.emplace_back(p + "phase", kinds::Value(phases[k]));
    out.emplace_back(p + "value", kinds::Value(values[k]));
    out.emplace_back(p + "tangent", kinds::Value(tangents[k]));
  }
  return out;
}

}  // namespace creaturelab::fit
