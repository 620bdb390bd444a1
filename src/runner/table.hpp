#pragma once
// The sweep table of a run: a row per point with its swept values and metrics (index.h5 /sweep).
#include <map>
#include <string>
#include <vector>

#include "kinds/params.hpp"

namespace creaturelab::runner {

struct Row {
  int index = 0;
  std::string label;
  std::string status = "missing";  // ok | failed | missing
  std::string message;             // why a point failed
  std::map<std::string, kinds::Value> columns;
  std::map<std::string, double> metrics;  // NaN where a failed point has none
  // The point file's seal, recorded in index.h5 /integrity so `check` and `compare` can tell a
  // damaged or swapped file: its configuration fingerprint and content digest ("" when missing).
  std::string config_sha256, content_sha256;
};

struct Table {
  std::vector<std::string> columns;  // swept parameter names
  std::vector<std::string> metrics;  // the kind's declared metrics
  std::vector<Row> rows;
};

// Numeric values compare by value whatever their stored type; strings and booleans exactly.
bool sameValue(const kinds::Value& a, const kinds::Value& b);
// Number for sorting and ranges; NaN for strings.
double numericValue(const kinds::Value& v);

}  // namespace creaturelab::runner
