#include "kinds/flyer_measures.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "kinds/control_params.hpp"

namespace creaturelab::kinds {
namespace {
std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}
}  // namespace

std::vector<control::StrokeFollow> parseStrokeSense(const std::string& text,
                                                    const std::vector<std::string>& controlled) {
  const auto entries = splitList(text, ',');
  if (entries.empty()) return {};
  std::vector<control::StrokeFollow> out(controlled.size());
  for (const auto& e : entries) {
    const auto eq = e.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument("stroke_sense: '" + e + "' is not 'controlled_joint = [+|-]inboard_joint'");
    const std::string joint = trimmed(e.substr(0, eq));
    std::string follow = trimmed(e.substr(eq + 1));
    double sign = 1.0;
    if (!follow.empty() && (follow[0] == '-' || follow[0] == '+')) {
      sign = follow[0] == '-' ? -1.0 : 1.0;
      follow = trimmed(follow.substr(1));
    }
    std::size_t k = 0;
    while (k < controlled.size() && controlled[k] != joint) ++k;
    if (k == controlled.size() || follow.empty())
      throw std::invalid_argument("stroke_sense: '" + e + "': the left side must be a controlled joint, the right an inboard joint");
    out[k] = {follow, sign};
  }
  return out;
}

int framesPerCycle(double period_s, double frame_s) {
  const double n = period_s / frame_s;
  if (n < 1 || std::abs(n - std::round(n)) > 1e-6)
    throw std::invalid_argument("flap_period_s: " + std::to_string(period_s) + " s is not a whole number of frames of " +
                                std::to_string(frame_s) + " s");
  return int(std::round(n));
}

double lastCyclesMean(const std::vector<double>& v, int frames_per_cycle, int cycles) {
  const long n = long(frames_per_cycle) * cycles;
  if (n < 1 || n > long(v.size())) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0;
  for (long k = long(v.size()) - n; k < long(v.size()); ++k) sum += v[k];
  return sum / double(n);
}

double lastCyclesStandardError(const std::vector<double>& v, int frames_per_cycle, int cycles) {
  const long n = long(frames_per_cycle) * cycles;
  if (cycles < 2 || frames_per_cycle < 1 || n > long(v.size())) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> means;
  for (long k = long(v.size()) - n; k < long(v.size()); k += frames_per_cycle) {
    double sum = 0;
    for (long j = k; j < k + frames_per_cycle; ++j) sum += v[j];
    means.push_back(sum / double(frames_per_cycle));
  }
  double mean = 0, squares = 0;
  for (double m : means) mean += m / double(cycles);
  for (double m : means) squares += (m - mean) * (m - mean);
  return std::sqrt(squares / double(cycles - 1) / double(cycles));
}

}  // namespace creaturelab::kinds
