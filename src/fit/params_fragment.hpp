#pragma once
// `[params]` fragments that `creaturelab run` accepts as they are: append one to an experiment
// file that has no [params] table of its own (or copy its lines into that table).
#include <string>
#include <utility>
#include <vector>

#include "kinds/params.hpp"

namespace creaturelab::fit {

/// A TOML literal that parses back to exactly `v` and stays a float ("1.0", not "1").
std::string tomlFloat(double v);
/// A TOML literal of a parameter value (floats as tomlFloat, strings quoted).
std::string tomlValue(const kinds::Value& v);

/// "# comment lines\n[params]\nname = value\n..." in the given order.
std::string paramsFragment(const std::vector<std::pair<std::string, kinds::Value>>& params,
                           const std::string& comment);

/// The jellyfish kind's curve parameters: contraction_knots = K, knotN_phase/value/tangent.
std::vector<std::pair<std::string, kinds::Value>> knotParams(const std::vector<double>& phases,
                                                             const std::vector<double>& values,
                                                             const std::vector<double>& tangents);

}  // namespace creaturelab::fit
