#pragma once
// `creaturelab run`: load, expand, validate, schedule the points (threads, MPI ranks), write the
// point files and the index, evaluate the checks.
#include <optional>
#include <string>
#include <vector>

#include "kinds/kind.hpp"
#include "runner/checks.hpp"
#include "runner/cluster.hpp"
#include "runner/core_slots.hpp"

namespace creaturelab::runner {

struct RunOptions {
  std::string experiment_path;
  std::vector<std::string> overrides;
  std::string out_dir;  // "" = the experiment's [output] dir, else results/runs/<stem>
  int jobs = 0;         // 0 = the cores
  bool resume = false;  // skip points whose file exists with the same configuration
  bool force = false;   // replace an existing run in out_dir
  bool dry_run = false; // print the plan only
  int slice_index = 0, slice_count = 1;  // --points i/N: run points with index % N == i
  bool allow_long = false;  // run points estimated to take very many steps or much memory
  // Progress on stderr: a line per finished point; false (a run of a list) only a status line on a
  // terminal, after progress_label.
  bool point_lines = true;
  std::string progress_label;
  // Shared with experiments running beside this one (a list): each point computes while holding a
  // slot. Null: the run's --jobs workers compute at will.
  CoreSlots* core_slots = nullptr;
};

struct RunReport {
  std::string out_dir;
  int total = 0, ran = 0, skipped = 0, failed = 0, missing = 0;
  std::vector<CheckOutcome> checks;
  bool checks_evaluated = false;
  // A point file could not be written (disk full, folder gone): the run stopped there; the points
  // written before stay, listed in the index. The message names the file.
  std::string write_error;
  bool checksPassed() const;
  // 0: all good; 1: a check failed; 3: a point failed (ran but could not finish) or could not be
  // written.
  int exitCode() const;
};

// Throws ExperimentError for user errors (nothing is written then).
// With several MPI ranks, rank r runs the points with index % size == r and rank 0 writes the index.
RunReport runExperiment(const RunOptions& options, const kinds::Registry& registry, const Cluster& cluster);

// Prints the resolved parameters and the expanded sweep (`creaturelab show`).
std::string describeExperiment(const std::string& path, const std::vector<std::string>& overrides,
                               const kinds::Registry& registry);

}  // namespace creaturelab::runner
