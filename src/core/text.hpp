#pragma once
// Small text helpers for messages and provenance: "did you mean" suggestions,
// round-trip number formatting, UTC timestamps.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace creaturelab::core {

// Levenshtein distance (insertions, deletions, substitutions each cost 1), on bytes.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate closest to `word` by editDistance, if that distance is at most
// max(2, word.size() / 3); otherwise "". Ties go to the earlier candidate.
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates);

// " (did you mean '<name>'?)" for the closestMatch of `word` among `known`, else for the first
// known name that starts with `word` (3 characters or more): units are spelled out in names, so
// "spring_k" is a prefix of "spring_k_n_per_m". "" when neither finds one.
std::string didYouMean(const std::string& word, const std::vector<std::string>& known);

// Shortest text that parses back to exactly `value` (std::to_chars), e.g. "0.1", "1e-07",
// "3", "nan", "inf", "-inf".
std::string formatNumber(double value);

// Current UTC time as ISO 8601 with seconds: "YYYY-MM-DDThh:mm:ssZ".
std::string isoTimeUtcNow();

}  // namespace creaturelab::core
