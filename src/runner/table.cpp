#include "runner/table.hpp"

#include <cmath>
#include <limits>

namespace creaturelab::runner {

double numericValue(const kinds::Value& v) {
  if (auto d = std::get_if<double>(&v)) return *d;
  if (auto i = std::get_if<std::int64_t>(&v)) return double(*i);
  if (auto b = std::get_if<bool>(&v)) return *b ? 1.0 : 0.0;
  return std::numeric_limits<double>::quiet_NaN();
}

bool sameValue(const kinds::Value& a, const kinds::Value& b) {
  const bool a_text = std::holds_alternative<std::string>(a), b_text = std::holds_alternative<std::string>(b);
  if (a_text || b_text) return a_text && b_text && std::get<std::string>(a) == std::get<std::string>(b);
  const double x = numericValue(a), y = numericValue(b);
  return std::fabs(x - y) <= 1e-12 * std::max(std::fabs(x), std::fabs(y));
}

}  // namespace creaturelab::runner
