#pragma once
// Reading a measured contraction profile (file I/O; the fit itself does none).
//
// CSV: a header row, then one sample per row: time in s, the normalised value, and optionally a
//      weight (>= 0). Comma-separated; blank lines and lines starting with '#' are skipped.
//        time_s,value
//        0.00,1.000
//        0.04,0.987
// HDF5: a point file of a run (or a run folder and a point index): one timeseries against
//      /timeseries/time_s, by default the jellyfish's /timeseries/diameter_ratio.
// Errors (FitError) name the file and the line or dataset: a missing header, a row with the
// wrong number of columns, a field that is not a number, a NaN.
#include <optional>
#include <string>

#include "fit/fit_error.hpp"
#include "fit/profile.hpp"

namespace creaturelab::fit {

Profile readProfileCsv(const std::string& path);

struct Hdf5ProfileSource {
  std::string value_dataset = "timeseries/diameter_ratio";
  std::string time_dataset = "timeseries/time_s";
  std::string weight_dataset;  // "" = all 1
  int point = 0;               // when the path is a run folder: point_NNNNNN.h5
};

struct Hdf5Profile {
  Profile profile;
  std::string file;                      // the point file read
  std::optional<double> contraction_hz;  // the point's contraction_hz attribute, when it has one
};

Hdf5Profile readProfileHdf5(const std::string& path, const Hdf5ProfileSource& source);

}  // namespace creaturelab::fit
