#include "core/text.hpp"

#include <algorithm>
#include <charconv>
#include <ctime>
#include <limits>
#include <numeric>
#include <system_error>

namespace creaturelab::core {

// Two-row dynamic programme: row[j] = distance between a[0..i) and b[0..j).
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous(b.size() + 1);
  std::vector<std::size_t> current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates) {
  const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  const std::string* best = nullptr;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = editDistance(word, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = &candidate;
    }
  }
  return (best != nullptr && best_distance <= limit) ? *best : std::string();
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& known) {
  std::string near = closestMatch(word, known);
  if (near.empty() && word.size() >= 3)
    for (const auto& k : known)
      if (k.rfind(word, 0) == 0) {
        near = k;
        break;
      }
  return near.empty() ? "" : " (did you mean '" + near + "'?)";
}

std::string formatNumber(double value) {
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (error != std::errc()) return "?";  // cannot happen: 64 characters hold any double
  return std::string(buffer, end);
}

std::string isoTimeUtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  const std::size_t length = std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return std::string(buffer, length);
}

}  // namespace creaturelab::core
