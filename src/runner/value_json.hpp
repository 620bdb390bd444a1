#pragma once
// Parameter values as JSON (provenance, baselines, resolved configurations).
#include <nlohmann/json.hpp>

#include "kinds/params.hpp"

namespace creaturelab::runner {

inline nlohmann::json toJson(const kinds::Value& v) {
  return std::visit([](const auto& x) { return nlohmann::json(x); }, v);
}

inline nlohmann::json toJson(const kinds::Params& params) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [k, v] : params) out[k] = toJson(v);
  return out;
}

// JSON scalar -> Value; integers stay integers. Returns false for arrays/objects/null.
inline bool fromJson(const nlohmann::json& j, kinds::Value& out) {
  if (j.is_boolean()) out = j.get<bool>();
  else if (j.is_number_integer()) out = j.get<std::int64_t>();
  else if (j.is_number()) out = j.get<double>();
  else if (j.is_string()) out = j.get<std::string>();
  else return false;
  return true;
}

}  // namespace creaturelab::runner
