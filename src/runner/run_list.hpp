#pragma once
// The experiments of a list (`creaturelab reproduce`), run side by side: at most `jobs` at once on
// one process, sharing `jobs` core slots (core_slots.hpp), so one experiment's idle cores go to the
// next; over MPI ranks one at a time, every rank in each. Each point's result does not depend on
// what runs beside it.
#include <exception>
#include <vector>

#include "kinds/kind.hpp"
#include "runner/cluster.hpp"
#include "runner/progress.hpp"
#include "runner/run.hpp"

namespace creaturelab::runner {

struct ListEntryResult {
  RunReport report;
  double wall_s = 0;
  bool ran = false;              // false: not started (an earlier entry's error stopped the list)
  std::exception_ptr error;      // an error the entry threw (ExperimentError: a user error)
};

// Runs `entries` (each with its out_dir and jobs set) from the first; an entry that throws stops the
// entries not yet started. `progress` gets one line per finished entry (on rank 0). The results come
// in the list's order.
std::vector<ListEntryResult> runList(std::vector<RunOptions> entries, int jobs, ListProgress& progress,
                                     const kinds::Registry& registry, const Cluster& cluster);

}  // namespace creaturelab::runner
