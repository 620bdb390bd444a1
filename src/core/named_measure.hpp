#pragma once
// What a run measures, named and with its unit, as the kinds write it to the point file.
#include <string>
#include <vector>

namespace creaturelab::core {

// One value per recorded frame (or step).
struct NamedSeries {
  std::string name;
  std::string unit;  // "" for dimensionless
  std::vector<double> values;
};

// One scalar measure.
struct NamedValue {
  std::string name;
  std::string unit;  // "" for dimensionless
  double value = 0;
};

}  // namespace creaturelab::core
