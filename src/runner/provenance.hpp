#pragma once
// Provenance of a run folder: index.h5's root attributes that say what built the binary, on which
// machine the run ran, when it started and how long it took. Like every provenance attribute they
// may differ between two runs and stay out of the content digests (provenanceAttributeNames).
#include <chrono>
#include <string>

namespace creaturelab::runner {

struct RunProvenance {
  std::string build_type;   // CMAKE_BUILD_TYPE of the binary ("unknown" when none was set)
  std::string cpu_model;    // /proc/cpuinfo "model name" ("unknown" where it has none)
  int cpu_cores = 0;        // std::thread::hardware_concurrency
  std::string started_utc;  // ISO 8601 UTC, when this invocation started the run
  std::chrono::steady_clock::time_point start;
};

// Taken when a run starts.
RunProvenance startRunProvenance();

// The first "model name" of a /proc/cpuinfo text; "unknown" when there is none.
std::string cpuModelFromCpuinfo(const std::string& cpuinfo);

// Adds build_type, cpu_model, cpu_cores (integer), started_utc and wall_s (seconds since p.start,
// a double) to the root of the whole index file `index_path`; the file is replaced atomically (a
// copy, written and renamed), so it stays whole if this fails.
void writeRunProvenance(const std::string& index_path, const RunProvenance& p);

}  // namespace creaturelab::runner
