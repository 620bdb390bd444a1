#pragma once
// The run folder on disk (DESIGN.md "Results (HDF5)"): one HDF5 file per point, written as
// NAME.h5.tmp and renamed when whole, and index.h5 with the sweep table, the checks and external
// links to every point. The HDF5 library here is not thread-safe: callers serialise these calls.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kinds/kind.hpp"
#include "runner/checks.hpp"
#include "runner/experiment.hpp"
#include "runner/table.hpp"

namespace creaturelab::runner {

// Attributes that record where a result came from; they may differ between two runs.
using Provenance = std::map<std::string, std::string>;
Provenance collectProvenance();
// Attribute names that are provenance (excluded from content digests).
const std::vector<std::string>& provenanceAttributeNames();

struct PointOutcome {
  bool ok = true;
  std::string message;  // why it failed
  kinds::Result result; // whole, or what was computed before the failure
  std::string started, finished;
  double wall_s = 0;
};

std::string pointFileName(int index);
// The resolved configuration of one point (kind + every parameter) and its SHA-256: resume
// only reuses a point file whose hash matches.
std::string pointConfigJson(const std::string& kind, const Point& point);
std::string pointConfigSha(const std::string& kind, const Point& point);

void writePointFile(const std::string& dir, const Experiment& experiment, const kinds::Kind& kind, const Point& point,
                    const PointOutcome& outcome, Provenance provenance);
// "" when the file is missing or unreadable.
std::string readPointConfigSha(const std::string& path);
// What index.h5 recorded of one point file (/integrity).
struct PointSeal {
  std::string config_sha256, content_sha256;
};

// Why `--resume` may not reuse the point file at `path` ("" when it may): its seal is broken, it
// cannot be read whole, or its content differs from what index.h5 recorded (`recorded`, may be
// null). Throws ExperimentError when it was made by another configuration (never recomputed over).
std::string pointFileDamage(const std::string& path, const std::string& kind, const Point& point,
                            const PointSeal* recorded);
// The table row of a point file; status "missing" when there is none. Throws ExperimentError when
// the file was made by another configuration (another run into the same folder): never mixed, or
// when it cannot be read whole (damaged after this run checked it).
Row readPointRow(const std::string& dir, const Point& point, const std::vector<std::string>& columns,
                 const kinds::Kind& kind);

void writeIndex(const std::string& dir, const Experiment& experiment, const kinds::Kind& kind, const Table& table,
                const std::vector<CheckOutcome>& checks, Provenance provenance);

struct StoredRun {
  std::string experiment_path, experiment_text;
  std::vector<std::string> overrides;
  Table table;
  std::map<int, PointSeal> seals;  // by point index; empty for an index older than /integrity
};
StoredRun readIndex(const std::string& dir);  // throws std::runtime_error naming the file

}  // namespace creaturelab::runner
