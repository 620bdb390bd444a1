#include "fit/profile.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/text.hpp"
#include "jellyfish/contraction_curve.hpp"

namespace creaturelab::fit {

Profile dropBefore(const Profile& profile, double from_s) {
  Profile out;
  out.source = profile.source;
  for (int i = 0; i < profile.size(); ++i) {
    if (!(profile.time_s[i] >= from_s)) continue;
    out.time_s.push_back(profile.time_s[i]);
    out.value.push_back(profile.value[i]);
    if (!profile.weight.empty()) out.weight.push_back(profile.weight[i]);
  }
  return out;
}

std::string checkSamples(const Profile& p) {
  const std::string where = p.source.empty() ? "the profile" : p.source;
  if (p.value.size() != p.time_s.size())
    return where + ": " + std::to_string(p.time_s.size()) + " times but " + std::to_string(p.value.size()) + " values";
  if (!p.weight.empty() && p.weight.size() != p.time_s.size())
    return where + ": " + std::to_string(p.time_s.size()) + " samples but " + std::to_string(p.weight.size()) +
           " weights";
  if (p.time_s.empty()) return where + ": no samples";
  for (int i = 0; i < p.size(); ++i) {
    if (!std::isfinite(p.time_s[i]) || !std::isfinite(p.value[i]) || !std::isfinite(p.weightAt(i)))
      return where + ": sample " + std::to_string(i) + " is not finite (time " + core::formatNumber(p.time_s[i]) +
             ", value " + core::formatNumber(p.value[i]) + "); remove NaN rows";
    if (p.weightAt(i) < 0) return where + ": sample " + std::to_string(i) + " has a negative weight";
    if (i > 0 && !(p.time_s[i] > p.time_s[i - 1]))
      return where + ": time does not increase at sample " + std::to_string(i) + " (" +
             core::formatNumber(p.time_s[i - 1]) + " s then " + core::formatNumber(p.time_s[i]) + " s)";
  }
  return "";
}

std::string checkCoverage(const Profile& p, double period_s, double phase_origin_s,
                          const std::vector<double>& knot_phases) {
  const std::string where = p.source.empty() ? "the profile" : p.source;
  const int knots = static_cast<int>(knot_phases.size());
  if (!(std::isfinite(period_s) && period_s > 0)) return "the period must be > 0, got " + core::formatNumber(period_s);
  int used = 0;
  for (int i = 0; i < p.size(); ++i) used += p.weightAt(i) > 0;
  if (used < 4 * knots)
    return where + ": too few samples: " + std::to_string(used) + " of positive weight, but " +
           std::to_string(knots) + " knot(s) need at least 4 per knot segment (" + std::to_string(4 * knots) + ")";
  const double span = p.time_s.back() - p.time_s.front();
  // A relative slack of 1e-9 accepts samples that cover exactly one period up to rounding.
  if (span < period_s * (1 - 1e-9))
    return where + ": the samples cover " + core::formatNumber(span) + " s, less than one period (" +
           core::formatNumber(period_s) + " s); give more data or the right --period";
  // Distinct phases per segment, rounded to 1e-12 so that two periods sampled alike count once.
  std::vector<std::set<long long>> phases(knots);
  for (int i = 0; i < p.size(); ++i) {
    if (!(p.weightAt(i) > 0)) continue;
    const double phase = jellyfish::wrapPhase((p.time_s[i] - phase_origin_s) / period_s);
    phases[jellyfish::segmentOf(knot_phases, phase)].insert(std::llround(phase * 1e12));
  }
  for (int k = 0; k < knots; ++k) {
    if (phases[k].size() >= 4) continue;
    const double end = knot_phases[(k + 1) % knots] + (k + 1 == knots ? 1.0 : 0.0);
    return where + ": too few samples between knot phases " + core::formatNumber(knot_phases[k]) + " and " +
           core::formatNumber(end) + ": " + std::to_string(phases[k].size()) +
           " distinct phase(s), at least 4 needed; use fewer knots or denser data";
  }
  return "";
}

}  // namespace creaturelab::fit
