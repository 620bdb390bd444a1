#include "runner/run.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <functional>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "core/text.hpp"
#include "runner/cost.hpp"
#include "runner/experiment.hpp"
#include "runner/folder_lock.hpp"
#include "runner/interrupt.hpp"
#include "runner/progress.hpp"
#include "runner/provenance.hpp"
#include "runner/store.hpp"
#include "runner/sweep_size.hpp"

namespace creaturelab::runner {
namespace fs = std::filesystem;

bool RunReport::checksPassed() const {
  for (const auto& c : checks)
    if (!c.counts()) return false;
  return true;
}

int RunReport::exitCode() const {
  if (failed > 0 || !write_error.empty()) return 3;
  return checksPassed() ? 0 : 1;
}

namespace {

std::string outputDir(const RunOptions& o, const Experiment& e) {
  if (!o.out_dir.empty()) return o.out_dir;
  if (!e.output.dir.empty()) return e.output.dir;
  return "results/runs/" + e.stem;
}

// The point index of a run file's name (point_NNNNNN...), -1 for index.h5 and other names.
int pointIndexOf(const std::string& name) {
  if (name.rfind("point_", 0) != 0 || name.size() < 12) return -1;
  int index = 0;
  for (size_t i = 6; i < 12; ++i) {
    if (name[i] < '0' || name[i] > '9') return -1;
    index = index * 10 + (name[i] - '0');
  }
  return index;
}

// A file the runner writes, by its exact name: index.h5, point_NNNNNN.h5, its .xdmf sidecar, its
// artifacts point_NNNNNN_<name> (renders), and the .tmp of each. --force removes these and only these.
bool isRunFile(const fs::path& p) {
  const std::string name = p.filename().string();
  if (name == "index.h5" || name == "index.h5.tmp") return true;
  if (pointIndexOf(name) < 0) return false;
  const std::string rest = name.substr(12);
  return rest == ".h5" || rest == ".h5.tmp" || rest == ".xdmf" || rest == ".xdmf.tmp" ||
         (rest.size() > 1 && rest[0] == '_');
}

// Before any work, on every rank (read-only): the folder must be creatable and writable.
void checkWritable(const std::string& dir) {
  fs::path probe = fs::absolute(dir);
  while (!fs::exists(probe)) probe = probe.parent_path();
  if (!fs::is_directory(probe)) throw ExperimentError("output folder " + dir + ": " + probe.string() + " is not a folder");
  if (access(probe.c_str(), W_OK) != 0) throw ExperimentError("output folder " + dir + ": " + probe.string() + " is not writable");
}

// Under the folder lock: an earlier run in the folder is only replaced or continued when asked.
void checkEarlierRun(const std::string& dir, const RunOptions& o) {
  bool has_run = false;
  for (const auto& entry : fs::directory_iterator(dir)) has_run |= isRunFile(entry.path());
  if (has_run && !o.resume && !o.force && o.slice_count == 1)
    throw ExperimentError("output folder " + dir +
                          " already holds a run: pass --resume to finish it, --force to replace it, or --out DIR");
}

// Removes the temporary files (*.tmp) this process may own: those of points in its share, and
// index.h5.tmp when it holds the folder alone. A crash or a kill leaves them; nothing reads them.
// Truncated first: a file HDF5 still holds open (a write that failed) frees its space only then;
// only a regular file with no other name is truncated, never a link's target (then unlinked).
int removeTemporaries(const std::string& dir, const std::function<bool(int)>& mine, bool whole_folder) {
  if (!fs::is_directory(dir)) return 0;
  int removed = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".tmp" || !isRunFile(entry.path())) continue;
    const int index = pointIndexOf(name);
    if (index < 0 ? !whole_folder : !mine(index)) continue;
    struct stat st {};
    if (::lstat(entry.path().c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink == 1) {
      if (const int fd = ::open(entry.path().c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC); fd >= 0) {
        if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink == 1)
          (void)!::ftruncate(fd, 0);  // best effort: the unlink below is what matters
        ::close(fd);
      }
    }
    if (::unlink(entry.path().c_str()) == 0) ++removed;
  }
  return removed;
}

// "no space left on device" when that is why a write failed (HDF5 reports errno 28 in its text).
std::string describeWriteError(const std::string& what) {
  if (what.find("errno = 28") != std::string::npos || what.find("No space left on device") != std::string::npos)
    return "no space left on device";
  return what;
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

// A point file that could not be written (disk full) on one MPI rank: the ranks end with exit 3.
struct PointWriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What a share of the run needs besides the options: the experiment, its points and the folder lock.
struct ShareContext {
  const RunOptions& o;
  const Experiment& e;
  const kinds::Kind& kind;
  const std::vector<Point>& points;
  const std::vector<std::string>& columns;
  const Cluster& cluster;
  const FolderLock& lock;  // held by rank 0; other ranks write under rank 0's lock
  const RunProvenance& run_provenance;  // index.h5's build, machine, start and wall time
};

RunReport runShare(const ShareContext& c, RunReport report);

}  // namespace

RunReport runExperiment(const RunOptions& o, const kinds::Registry& registry, const Cluster& cluster) {
  const RunProvenance run_provenance = startRunProvenance();
  const Experiment e = loadExperiment(o.experiment_path, o.overrides, registry);
  const kinds::Kind& kind = *registry.find(e.kind);
  sweepPointCount(e);  // before expanding: a count beyond the limit, never wrapped
  const std::vector<Point> points = expandPoints(e, kind);
  checkSelections(e, points);
  {
    // The points this process computes at once: --jobs (default the cores), at most its share.
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const size_t shares = size_t(o.slice_count) * size_t(cluster.size());
    const int share = int((points.size() + shares - 1) / shares);
    const CostLimits limits{o.allow_long, std::max(1, std::min(o.jobs > 0 ? o.jobs : cores, share)), memoryBudget()};
    checkCost(e, kind, points, limits);
  }
  const auto columns = sweepColumns(e);

  RunReport report;
  report.out_dir = outputDir(o, e);
  report.total = int(points.size());
  if (o.dry_run) return report;
  // Every rank checks (read-only), so a user error stops every rank here alike, before any
  // rank waits for another.
  checkWritable(report.out_dir);
  // Rank 0 alone takes the folder lock and looks at the folder under it (so two runs cannot both
  // find it free); it tells the other ranks whether to go on, so a refusal ends every rank alike.
  FolderLock lock;
  std::string refusal;
  if (cluster.rank() == 0) {
    try {
      fs::create_directories(report.out_dir);
      lock = FolderLock::acquire(report.out_dir,
                                 o.slice_count > 1 ? FolderLock::Mode::Shared : FolderLock::Mode::Exclusive);
      checkEarlierRun(report.out_dir, o);
      if (o.force) clearRun(report.out_dir);
      // Temporaries left by a crash or a kill: of the whole folder when this run holds it
      // alone, else (a --points share) only of this share's points.
      const int removed = removeTemporaries(
          report.out_dir, [&](int index) { return index % o.slice_count == o.slice_index; }, o.slice_count == 1);
      if (removed > 0) std::fprintf(stderr, "removed %d temporary file(s) left by an earlier run\n", removed);
    } catch (const std::exception& err) {
      refusal = err.what();
    }
  }
  if (cluster.broadcastFromRoot(refusal.empty() ? 1 : 0) == 0)
    throw ExperimentError(cluster.rank() == 0 ? refusal : "rank 0 refused the output folder " + report.out_dir);
  const ShareContext context{o, e, kind, points, columns, cluster, lock, run_provenance};
  if (cluster.size() == 1) return runShare(context, report);
  // Past this point an error on one rank would leave the others waiting: it ends them all.
  try {
    return runShare(context, report);
  } catch (const PointWriteError& err) {
    std::fprintf(stderr, "error (rank %d): %s\n", cluster.rank(), err.what());
    cluster.abort(3);  // points were computed and some written: not a user error
  } catch (const std::exception& err) {
    std::fprintf(stderr, "error (rank %d): %s\n", cluster.rank(), err.what());
    cluster.abort(2);
  }
}

namespace {

// The index is built from the point files alone, so it is the same whoever computed them. A
// point file of another configuration (a share run with other settings) is refused, never mixed.
void writeIndexFromFiles(const ShareContext& c, RunReport& report, const Provenance& provenance) {
  Table table{c.columns, {}, {}};
  for (const auto& m : c.kind.metrics()) table.metrics.push_back(m.name);
  report.failed = report.missing = 0;
  for (const auto& p : c.points) {
    table.rows.push_back(readPointRow(report.out_dir, p, c.columns, c.kind));
    if (table.rows.back().status == "failed") ++report.failed;
    if (table.rows.back().status == "missing") ++report.missing;
  }
  report.checks.clear();
  report.checks_evaluated = false;
  if (report.missing == 0) {
    report.checks = evaluateChecks(c.e.checks, table);
    report.checks_evaluated = true;
  }
  c.lock.lockIndex();  // shares finishing together take turns
  writeIndex(report.out_dir, c.e, c.kind, table, report.checks, provenance);
  writeRunProvenance(report.out_dir + "/index.h5", c.run_provenance);
  c.lock.unlockIndex();
}

RunReport runShare(const ShareContext& c, RunReport report) {
  const RunOptions& o = c.o;
  // This process's share: a --points slice and/or an MPI rank.
  const long long share_count = (long long)o.slice_count * c.cluster.size();
  const long long share_index = (long long)o.slice_index * c.cluster.size() + c.cluster.rank();
  const auto mine = [&](int index) { return index % share_count == share_index; };
  // The seals of the point files in the index of an earlier run into this folder: a file reused by
  // --resume must still hold the content recorded there. A damaged index is rewritten, not read.
  std::map<int, PointSeal> recorded;
  if (o.resume && fs::exists(report.out_dir + "/index.h5")) {
    try {
      recorded = readIndex(report.out_dir).seals;
    } catch (const std::exception& err) {
      std::fprintf(stderr, "resume: %s/index.h5 is not read (%s); it is written again\n", report.out_dir.c_str(),
                   err.what());
    }
  }
  std::vector<const Point*> todo;
  for (const auto& p : c.points) {
    const std::string path = report.out_dir + "/" + pointFileName(p.index);
    if (!mine(p.index)) {
      // Another share's point (--points): a file of another configuration means two shares of
      // different settings; refuse before running rather than mix them in one folder.
      if (o.slice_count > 1 && fs::exists(path)) {
        const std::string sha = readPointConfigSha(path);
        if (!sha.empty() && sha != pointConfigSha(c.e.kind, p))
          throw ExperimentError(path + " was made by a different configuration (another --points share with other "
                                       "settings?); use --force or another --out");
      }
      continue;
    }
    if (fs::exists(path)) {
      if (!o.resume && !o.force && o.slice_count == 1)
        throw ExperimentError(path + " exists: pass --resume or --force");
      const auto seal = recorded.find(p.index);
      const std::string damage = pointFileDamage(path, c.e.kind, p, seal == recorded.end() ? nullptr : &seal->second);
      if (damage.empty()) {
        ++report.skipped;
        continue;
      }
      // Removed now, so an index written before its recomputation (an interrupt) does not list it.
      std::fprintf(stderr, "resume: %s is damaged, recomputing it: %s\n", path.c_str(), damage.c_str());
      std::error_code ec;
      fs::remove(path, ec);
    }
    todo.push_back(&p);
  }

  const Provenance provenance = collectProvenance();
  int jobs = o.jobs > 0 ? o.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  jobs = std::min<int>(jobs, std::max<size_t>(1, todo.size()));
  if (report.skipped > 0)
    std::fprintf(stderr, "resume: %d point file(s) already complete, %zu to run\n", report.skipped, todo.size());
  Progress progress(int(todo.size()) + report.skipped, report.skipped, stderr, o.point_lines, o.progress_label);
  // SIGINT/SIGTERM only set a flag; this thread watches it while the workers run the points.
  const InterruptGuard interrupt_guard;
  std::mutex write_mutex;  // one point file written at a time; guards write_error
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  // A write error (disk full, folder removed) stops every worker; points already written stay.
  std::string write_error;
  std::mutex done_mutex;
  std::condition_variable done_cv;
  int workers_done = 0;
  std::atomic<int> written{0};
  auto worker = [&] {
    for (size_t i = next++; i < todo.size() && !stop; i = next++) {
      const Point& p = *todo[i];
      PointOutcome outcome = [&] {
        const SlotHold slot(o.core_slots);
        return runPoint(c.kind, p);
      }();
      std::lock_guard lock(write_mutex);
      if (stop) break;  // interrupted or a write failed while this point ran: it is not written
      try {
        writePointFile(report.out_dir, c.e, c.kind, p, outcome, provenance);
      } catch (const std::exception& err) {
        write_error = "cannot write " + report.out_dir + "/" + pointFileName(p.index) + ": " +
                      describeWriteError(err.what());
        stop = true;
        break;
      }
      ++written;
      progress.pointFinished(describePoint(p, c.columns) + (outcome.ok ? "" : ": " + outcome.message), outcome.ok,
                             outcome.wall_s);
    }
    std::lock_guard lock(done_mutex);
    ++workers_done;
    done_cv.notify_all();
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
  for (std::unique_lock lock(done_mutex); workers_done < jobs;) {
    done_cv.wait_for(lock, std::chrono::milliseconds(50));
    if (interrupted() && !stop) stop = true;
    if (stop && interrupted()) break;
  }
  if (const int signal = interrupted()) {
    // No point file is being written while this thread holds the write lock; the points still
    // computing are dropped (they were never written) when the process ends.
    std::lock_guard lock(write_mutex);
    removeTemporaries(report.out_dir, mine, o.slice_count == 1 && c.cluster.size() == 1);
    std::string index_note;
    if (c.cluster.rank() == 0) {
      try {
        writeIndexFromFiles(c, report, provenance);
        index_note = ", listed in " + report.out_dir + "/index.h5";
      } catch (const std::exception& err) {
        index_note = "; index.h5 not written: " + std::string(err.what());
      }
    }
    std::fprintf(stderr, "interrupted by %s: stopped before the remaining points; the point files written stay%s; "
                         "--resume finishes the run\n", signal == SIGINT ? "SIGINT" : "SIGTERM", index_note.c_str());
    std::fflush(stderr);
    endBySignal(signal);
  }
  for (auto& t : pool) t.join();
  if (!write_error.empty()) {
    removeTemporaries(report.out_dir, mine, o.slice_count == 1 && c.cluster.size() == 1);
    if (c.cluster.size() > 1) throw PointWriteError(write_error);
    progress.finish();
    report.ran = written;
    report.write_error = write_error;
    try {
      writeIndexFromFiles(c, report, provenance);
      report.write_error += "; the point files written before it stay, listed in " + report.out_dir + "/index.h5";
    } catch (const std::exception& err) {
      report.write_error += "; the point files written before it stay, but index.h5 could not be written: " +
                            describeWriteError(err.what());
    }
    report.write_error += "; free space and run again with --resume";
    return report;
  }
  progress.finish();
  report.ran = c.cluster.sumOnRoot(int(todo.size()));
  report.skipped = c.cluster.sumOnRoot(report.skipped);

  c.cluster.barrier();
  if (c.cluster.rank() != 0) return report;
  try {
    writeIndexFromFiles(c, report, provenance);
  } catch (const ExperimentError&) {
    throw;  // a point file of another configuration: a refusal (exit 2)
  } catch (const std::exception& err) {
    // Every point file is written; only the index is not (the disk filled): exit 3, not a crash.
    removeTemporaries(report.out_dir, mine, o.slice_count == 1 && c.cluster.size() == 1);
    report.write_error = "cannot write " + report.out_dir + "/index.h5: " + describeWriteError(err.what()) +
                         "; every point file is written; free space and run again with --resume to write the index";
  }
  return report;
}

}  // namespace

std::string describeExperiment(const std::string& path, const std::vector<std::string>& overrides,
                               const kinds::Registry& registry) {
  const Experiment e = loadExperiment(path, overrides, registry);
  const kinds::Kind& kind = *registry.find(e.kind);
  sweepPointCount(e);
  const auto points = expandPoints(e, kind);
  checkSelections(e, points);
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
