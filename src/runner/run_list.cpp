#include "runner/run_list.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>

#include "runner/core_slots.hpp"
#include "runner/interrupt.hpp"

namespace creaturelab::runner {
namespace fs = std::filesystem;

namespace {

// The problems of a finished entry, for its progress line ("" when none).
std::string problemsOf(const RunReport& r) {
  std::string problems;
  if (r.failed > 0) problems = std::to_string(r.failed) + " FAILED";
  if (r.missing > 0) problems += (problems.empty() ? "" : ", ") + std::to_string(r.missing) + " not run";
  return problems;
}

}  // namespace

std::vector<ListEntryResult> runList(std::vector<RunOptions> entries, int jobs, ListProgress& progress,
                                     const kinds::Registry& registry, const Cluster& cluster) {
  const int lanes = cluster.size() == 1 ? std::clamp<int>(jobs, 1, std::max<int>(1, int(entries.size()))) : 1;
  CoreSlots slots(std::max(1, jobs));
  std::vector<ListEntryResult> results(entries.size());
  std::mutex progress_mutex;
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  // While entries run side by side, a signal between two of them is kept for the next to act on.
  const InterruptGuard list_guard;
  auto lane = [&] {
    for (size_t i = next++; i < entries.size() && !stop; i = next++) {
      RunOptions& o = entries[i];
      const std::string name = fs::path(o.out_dir).filename().string();
      if (lanes > 1) o.core_slots = &slots;
      {
        const std::lock_guard lock(progress_mutex);
        o.progress_label = progress.label(name);
      }
      ListEntryResult& result = results[i];
      result.ran = true;
      const auto t0 = std::chrono::steady_clock::now();
      try {
        result.report = runExperiment(o, registry, cluster);
      } catch (...) {
        result.error = std::current_exception();
        stop = true;
        continue;
      }
      result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (cluster.rank() != 0) continue;
      const std::lock_guard lock(progress_mutex);
      progress.experimentFinished(name, result.report.total, problemsOf(result.report), result.wall_s);
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < lanes; ++k) pool.emplace_back(lane);
  lane();
  for (auto& t : pool) t.join();
  if (const int signal = interrupted()) endBySignal(signal);  // after the last entry, before what follows
  return results;
}

}  // namespace creaturelab::runner
