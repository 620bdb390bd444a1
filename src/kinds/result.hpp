#pragma once
// What one sweep point returns: named time series, scalar metrics and Lagrangian tracks.
// Kinds fill it; the runner writes it (DESIGN.md "Results (HDF5)").
#include <cstdint>
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

// Cell-centred scalar fields on a uniform 2D grid (frames × ny × nx) or 3D grid (frames × nz × ny × nx)
// at output times, row-major (x fastest).
struct Field {
  std::vector<double> data;
  std::string unit;
};

struct FieldFrames {
  std::vector<double> time_s;  // one per frame
  int nx = 0, ny = 0;
  int nz = 0;                            // 0: 2D frames; > 0: cells along z of a 3D grid
  double dx_m = 0, dy_m = 0, dz_m = 0;   // cell size
  double origin_x_m = 0, origin_y_m = 0, origin_z_m = 0;  // lowest corner of the domain
  std::map<std::string, Field> fields;   // each frames × ny × nx, or frames × nz × ny × nx
  int frames() const { return int(time_s.size()); }
};

struct Result {
  std::map<std::string, Series> timeseries;  // includes "time_s"; all the same length
  std::map<std::string, Metric> metrics;
  std::map<std::string, Tracks> lagrangian;
  FieldFrames fields;  // empty unless the kind has a grid
  // Integer tables that describe the model rather than its motion (which particles a spring
  // joins, its strand type, ...): /topology/<name>.
  std::map<std::string, std::vector<std::int64_t>> topology;
  // Files written beside the point file as <run dir>/point_NNNNNN_<name> (renders, e.g. "result.png"):
  // file name -> bytes. Kinds do no I/O; the runner writes these. Not part of the HDF5 (nor its digest).
  std::map<std::string, std::vector<std::uint8_t>> artifacts;
};

}  // namespace creaturelab::kinds
