#pragma once
// A measured contraction profile: samples (time, value, weight) of the normalised bell diameter
// or muscle length over one or more periods, and the checks a profile must pass before it is
// fitted ("Bad input"). Pure data and checks: the readers are in profile_io.hpp.
#include <string>
#include <vector>

namespace creaturelab::fit {

struct Profile {
  std::vector<double> time_s;
  std::vector<double> value;   // normalised diameter or rest-length factor (dimensionless)
  std::vector<double> weight;  // one per sample, >= 0 (0 drops the sample); empty = all 1
  std::string source;          // where it came from, for messages ("data.csv", "run/point_000000.h5:/timeseries/x")

  int size() const { return static_cast<int>(time_s.size()); }
  double weightAt(int i) const { return weight.empty() ? 1.0 : weight[i]; }
};

/// Samples with time >= from_s (drops a warm-up transient).
Profile dropBefore(const Profile& profile, double from_s);

/// "" if the samples are usable at all: the same number of times, values and weights; every number
/// finite (the first NaN is named by its sample index); times strictly increasing; weights >= 0.
std::string checkSamples(const Profile& profile);

/// "" if the profile can determine a periodic cubic Hermite curve with knots at `knot_phases`
/// (strictly increasing, in [0, 1)) when its time t is at phase (t - phase_origin_s) / period_s:
/// the samples span at least one period, and each knot segment holds at least 4 samples of
/// positive weight at distinct phases (then each segment's cubic, and so every knot value and
/// tangent, is determined by the data alone). Call checkSamples first.
std::string checkCoverage(const Profile& profile, double period_s, double phase_origin_s,
                          const std::vector<double>& knot_phases);

}  // namespace creaturelab::fit
