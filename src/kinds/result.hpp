#pragma once
// What one sweep point returns: named time series, scalar metrics and Lagrangian tracks.
// Kinds fill it; the runner writes it (DESIGN.md "Results (HDF5)").
#include <map>
#include <string>
#include <vector>

namespace creaturelab::kinds {

struct Series {
  std::vector<double> values;
  std::string unit;
};

struct Metric {
  double value = 0;
  std::string unit;
};

// Positions of markers or particles: frames × points × dim, row-major.
struct Tracks {
  std::vector<double> time_s;  // one per frame
  std::vector<double> data;
  int points = 0;
  int dim = 0;
  std::string unit = "m";
  int frames() const { return time_s.empty() ? 0 : int(time_s.size()); }
};

struct Result {
  std::map<std::string, Series> timeseries;  // includes "time_s"; all the same length
  std::map<std::string, Metric> metrics;
  std::map<std::string, Tracks> lagrangian;
};

}  // namespace creaturelab::kinds
