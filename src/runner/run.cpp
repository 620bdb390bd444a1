#include "runner/run.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <thread>

#include "core/text.hpp"
#include "runner/experiment.hpp"
#include "runner/progress.hpp"
#include "runner/store.hpp"

namespace creaturelab::runner {
namespace fs = std::filesystem;

bool RunReport::checksPassed() const {
  for (const auto& c : checks)
    if (!c.counts()) return false;
  return true;
}

int RunReport::exitCode() const {
  if (failed > 0) return 3;
  return checksPassed() ? 0 : 1;
}

namespace {

std::string outputDir(const RunOptions& o, const Experiment& e) {
  if (!o.out_dir.empty()) return o.out_dir;
  if (!e.output.dir.empty()) return e.output.dir;
  return "results/runs/" + e.stem;
}

bool isRunFile(const fs::path& p) {
  const std::string name = p.filename().string();
  // point_NNNNNN.h5, its .tmp, its .xdmf sidecar and its artifacts point_NNNNNN_<name> (renders).
  const bool point = name.rfind("point_", 0) == 0;
  const bool artifact = point && name.size() > 13 && name[12] == '_';
  return name == "index.h5" || artifact ||
         (point && (p.extension() == ".h5" || p.extension() == ".tmp" || p.extension() == ".xdmf"));
}

// Before any work: the folder must be writable, and an earlier run in it is only replaced or
// continued when asked.
void prepareOutputDir(const std::string& dir, const RunOptions& o) {
  fs::path probe = fs::absolute(dir);
  while (!fs::exists(probe)) probe = probe.parent_path();
  if (!fs::is_directory(probe)) throw ExperimentError("output folder " + dir + ": " + probe.string() + " is not a folder");
  if (access(probe.c_str(), W_OK) != 0) throw ExperimentError("output folder " + dir + ": " + probe.string() + " is not writable");
  if (!fs::exists(dir)) return;
  bool has_run = false;
  for (const auto& entry : fs::directory_iterator(dir)) has_run |= isRunFile(entry.path());
  if (has_run && !o.resume && !o.force && o.slice_count == 1)
    throw ExperimentError("output folder " + dir +
                          " already holds a run: pass --resume to finish it, --force to replace it, or --out DIR");
}

void clearRun(const std::string& dir) {
  if (!fs::exists(dir)) return;
  for (const auto& entry : fs::directory_iterator(dir))
    if (isRunFile(entry.path())) fs::remove(entry.path());
}

std::string describePoint(const Point& p, const std::vector<std::string>& columns) {
  std::string s = "point " + std::to_string(p.index);
  std::string detail = p.label;
  for (const auto& c : columns) detail += (detail.empty() ? "" : ", ") + c + "=" + kinds::describeValue(p.params.at(c));
  return detail.empty() ? s : s + " (" + detail + ")";
}

PointOutcome runPoint(const kinds::Kind& kind, const Point& point) {
  PointOutcome out;
  out.started = core::isoTimeUtcNow();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    out.result = kind.run(point.params);
  } catch (const kinds::RunFailure& e) {
    out.ok = false;
    out.message = e.what();
    out.result = e.partial();
  } catch (const std::exception& e) {
    out.ok = false;
    out.message = std::string("internal error: ") + e.what();
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.finished = core::isoTimeUtcNow();
  return out;
}

RunReport runShare(const RunOptions& o, const Experiment& e, const kinds::Kind& kind, const std::vector<Point>& points,
                   const std::vector<std::string>& columns, RunReport report, const Cluster& cluster);

}  // namespace

RunReport runExperiment(const RunOptions& o, const kinds::Registry& registry, const Cluster& cluster) {
  const Experiment e = loadExperiment(o.experiment_path, o.overrides, registry);
  const kinds::Kind& kind = *registry.find(e.kind);
  const std::vector<Point> points = expandPoints(e, kind);
  const auto columns = sweepColumns(e);

  RunReport report;
  report.out_dir = outputDir(o, e);
  report.total = int(points.size());
  if (o.dry_run) return report;
  // Every rank checks (read-only), so a user error stops every rank here alike, before any
  // rank waits for another.
  prepareOutputDir(report.out_dir, o);
  if (cluster.rank() == 0) {
    if (o.force) clearRun(report.out_dir);
    fs::create_directories(report.out_dir);
  }
  cluster.barrier();
  if (cluster.size() == 1) return runShare(o, e, kind, points, columns, report, cluster);
  // Past this point an error on one rank would leave the others waiting: it ends them all.
  try {
    return runShare(o, e, kind, points, columns, report, cluster);
  } catch (const std::exception& err) {
    std::fprintf(stderr, "error (rank %d): %s\n", cluster.rank(), err.what());
    cluster.abort(2);
  }
}

namespace {

RunReport runShare(const RunOptions& o, const Experiment& e, const kinds::Kind& kind, const std::vector<Point>& points,
                   const std::vector<std::string>& columns, RunReport report, const Cluster& cluster) {
  // This process's share: a --points slice and/or an MPI rank.
  const int share_count = o.slice_count * cluster.size();
  const int share_index = o.slice_index * cluster.size() + cluster.rank();
  std::vector<const Point*> todo;
  for (const auto& p : points) {
    if (p.index % share_count != share_index) continue;
    const std::string path = report.out_dir + "/" + pointFileName(p.index);
    if (fs::exists(path)) {
      if (!o.resume && !o.force && o.slice_count == 1)
        throw ExperimentError(path + " exists: pass --resume or --force");
      const std::string sha = readPointConfigSha(path);
      if (sha == pointConfigSha(e.kind, p)) {
        ++report.skipped;
        continue;
      }
      if (!sha.empty())
        throw ExperimentError(path + " was made by a different configuration; use --force or another --out");
    }
    todo.push_back(&p);
  }

  const Provenance provenance = collectProvenance();
  int jobs = o.jobs > 0 ? o.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  jobs = std::min<int>(jobs, std::max<size_t>(1, todo.size()));
  if (report.skipped > 0)
    std::fprintf(stderr, "resume: %d point file(s) already complete, %zu to run\n", report.skipped, todo.size());
  Progress progress(int(todo.size()) + report.skipped, report.skipped);
  std::mutex write_mutex;  // one point file written at a time; guards write_error
  std::atomic<size_t> next{0};
  std::atomic<int> failed{0};
  // A write error (disk full, folder removed) stops every worker; points already written stay.
  std::exception_ptr write_error;
  auto worker = [&] {
    for (size_t i = next++; i < todo.size(); i = next++) {
      const Point& p = *todo[i];
      PointOutcome outcome = runPoint(kind, p);
      try {
        std::lock_guard lock(write_mutex);
        if (write_error) return;
        writePointFile(report.out_dir, e, kind, p, outcome, provenance);
      } catch (...) {
        write_error = std::current_exception();
        next = todo.size();
        return;
      }
      if (!outcome.ok) ++failed;
      progress.pointFinished(describePoint(p, columns) + (outcome.ok ? "" : ": " + outcome.message), outcome.ok,
                             outcome.wall_s);
    }
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (write_error) std::rethrow_exception(write_error);
  progress.finish();
  report.ran = cluster.sumOnRoot(int(todo.size()));
  report.skipped = cluster.sumOnRoot(report.skipped);

  cluster.barrier();
  if (cluster.rank() != 0) return report;

  // The index is built from the point files alone, so it is the same whoever computed them.
  Table table{columns, {}, {}};
  for (const auto& m : kind.metrics()) table.metrics.push_back(m.name);
  for (const auto& p : points) {
    table.rows.push_back(readPointRow(report.out_dir, p, columns, kind));
    if (table.rows.back().status == "failed") ++report.failed;
    if (table.rows.back().status == "missing") ++report.missing;
  }
  if (report.missing == 0) {
    report.checks = evaluateChecks(e.checks, table);
    report.checks_evaluated = true;
  }
  writeIndex(report.out_dir, e, kind, table, report.checks, provenance);
  return report;
}

}  // namespace

std::string describeExperiment(const std::string& path, const std::vector<std::string>& overrides,
                               const kinds::Registry& registry) {
  const Experiment e = loadExperiment(path, overrides, registry);
  const kinds::Kind& kind = *registry.find(e.kind);
  const auto points = expandPoints(e, kind);
  const auto columns = sweepColumns(e);
  std::ostringstream s;
  s << e.title << "\nkind: " << e.kind << " — " << kind.doc() << "\n\nparameters (resolved; * = set by the file):\n";
  const kinds::Params base = kinds::withDefaults(kind, e.params);
  for (const auto& spec : kind.params()) {
    const bool swept = std::find(columns.begin(), columns.end(), spec.name) != columns.end();
    s << "  " << (e.params.count(spec.name) ? "* " : "  ") << spec.name << " = "
      << (swept ? std::string("(swept)") : kinds::describeValue(base.at(spec.name)))
      << (spec.unit.empty() ? "" : " " + spec.unit) << "\n";
  }
  s << "\nsweep: " << points.size() << " point(s)\n";
  for (const auto& p : points) s << "  " << describePoint(p, columns) << "\n";
  s << "\nchecks: " << e.checks.size() << "\n";
  for (const auto& c : e.checks) s << "  " << c.name << " (" << c.type << " of " << c.metric << ")\n";
  return s.str();
}

}  // namespace creaturelab::runner
