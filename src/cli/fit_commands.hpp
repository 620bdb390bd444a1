#pragma once
// `creaturelab fit spline DATA` and `creaturelab fit controller FILE`. Each returns the
// exit code; user errors are thrown as std::runtime_error (Commands::guard prints them, exit 2).
#include <optional>
#include <string>

#include "kinds/kind.hpp"

namespace creaturelab::cli {

struct FitSplineArgs {
  std::string data;          // CSV, point file (.h5) or run folder
  std::string out;           // "" = results/runs/fit/<data stem>_spline
  std::optional<int> knots;  // evenly spaced knots (unset: 4, or as many as --phases)
  std::string phases;        // "0,0.3": knot phases
  std::optional<double> period_s;  // unset: the point's contraction_hz attribute, else detected
  double phase_origin_s = 0;
  double from_s = -1e300;    // drop samples before this time
  double lower = 0.56, upper = 1.0;
  std::string loss = "none";
  double loss_scale = 0.01;
  std::string start_values;  // "1,0.56": one per knot
  std::string dataset = "timeseries/diameter_ratio";
  std::string time_dataset = "timeseries/time_s";
  std::string weight_dataset;
  int point = 0;
  bool force = false;  // replace an existing output folder
};

struct FitControllerArgs {
  std::string file;
  std::string out;  // "" = results/runs/fit/<file stem>
  int jobs = 0;
  bool resume = false;
  bool force = false;
};

int fitSpline(const FitSplineArgs& args);
int fitController(const FitControllerArgs& args, const kinds::Registry& registry);

}  // namespace creaturelab::cli
