#include "cli/commands.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <numeric>
#include <sstream>
#include <thread>
#include <toml++/toml.h>

#include "cli/render_commands.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "kinds/param_toml.hpp"
#include "kinds/render_hook.hpp"
#include "runner/checks.hpp"
#include "runner/compare.hpp"
#include "runner/experiment.hpp"
#include "runner/progress.hpp"
#include "runner/run_list.hpp"
#include "runner/store.hpp"
#include "runner/verify.hpp"

namespace creaturelab::cli {
namespace fs = std::filesystem;

namespace {

// A user error: printed as one message, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A count of the command line as a number 0..limit; false for anything else (signs, spaces,
// trailing characters, values that do not fit).
bool parseCount(const std::string& text, long long limit, long long& out) {
  if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos) return false;
  out = std::stoll(text);
  return out <= limit;
}

void parseSlice(const std::string& text, runner::RunOptions& o) {
  if (text.empty()) return;
  constexpr long long kMaxShares = 1000000;  // a sweep has at most a million points
  const auto slash = text.find('/');
  long long i = 0, n = 0;
  if (slash == std::string::npos || !parseCount(text.substr(0, slash), kMaxShares, i) ||
      !parseCount(text.substr(slash + 1), kMaxShares, n) || n < 1 || i >= n)
    throw UsageError("--points " + text + ": expected i/N with 0 <= i < N <= " + std::to_string(kMaxShares) +
                     ", e.g. --points 0/4");
  o.slice_index = int(i);
  o.slice_count = int(n);
}

// An override is one line "dotted.key=value": a value of several lines was cut at its first.
void checkOverrides(const std::vector<std::string>& overrides) {
  for (const auto& o : overrides)
    if (o.find_first_of("\n\r") != std::string::npos)
      throw UsageError("override '" + o.substr(0, o.find_first_of("\n\r")) +
                       "...': an override is one line (dotted.key=value); pass each as its own argument");
}

// A name from a file that becomes a folder under --out: one plain path component.
void checkPlainName(const std::string& name, const std::string& where) {
  if (name.empty() || name == "." || name == ".." || name.find_first_of("/\\") != std::string::npos ||
      name.find('\0') != std::string::npos)
    throw UsageError(where + ": name \"" + name + "\" is not a plain folder name (no '/', not '.' or '..')");
}

runner::Baseline loadBaseline(const std::string& path, double rtol, double atol, bool verify) {
  if (fs::is_directory(path)) {
    const runner::StoredRun stored = runner::readIndex(path);
    if (verify) runner::requireVerifiedRun(path, stored);
    runner::Baseline b{stored.experiment_path, stored.overrides, {{"default", {rtol, atol}}}, stored.table};
    return b;
  }
  std::ifstream in(path);
  if (!in) throw UsageError(path + ": no such baseline file or run folder");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(path + ": malformed JSON: " + e.what());
  }
  return runner::baselineFromJson(j, path);
}

}  // namespace

Commands::Commands(const runner::Cluster& cluster) : cluster_(cluster), registry_(kinds::defaultRegistry()) {}

int Commands::guard(const std::function<int()>& verb) const {
  // Under MPI every rank reads the same files and meets the same user error: rank 0 says it.
  try {
    return verb();
  } catch (const std::runtime_error& e) {
    if (primary()) std::fprintf(stderr, "error: %s\n", e.what());
  } catch (const std::bad_alloc&) {
    // Before the points run (expanding a huge sweep) or reading a damaged file's sizes: a message, not an abort.
    if (primary()) std::fprintf(stderr, "error: out of memory (a sweep or grid too large, or a damaged file?)\n");
  } catch (const std::exception& e) {
    // Anything else a damaged file can raise (JSON of the wrong shape, an index out of range).
    if (primary()) std::fprintf(stderr, "error: %s\n", e.what());
  } catch (...) {
    if (primary()) std::fprintf(stderr, "error: unknown exception\n");
  }
  return 2;
}

void Commands::printReport(const runner::RunReport& r) const {
  std::printf("%s: %d point(s), %d ran, %d reused, %d failed%s\n", r.out_dir.c_str(), r.total, r.ran, r.skipped,
              r.failed, r.missing ? (", " + std::to_string(r.missing) + " not yet run").c_str() : "");
  if (r.checks_evaluated && !r.checks.empty()) std::printf("%s", runner::formatCheckTable(r.checks).c_str());
  if (!r.checks_evaluated) std::printf("checks: not evaluated until every point has run (use --resume)\n");
}

int Commands::run(const RunArgs& args) const {
  runner::RunOptions o = args.options;
  parseSlice(args.slice, o);
  checkOverrides(o.overrides);
  const runner::RunReport report = runner::runExperiment(o, registry_, cluster_);
  if (!report.write_error.empty()) std::fprintf(stderr, "error: %s\n", report.write_error.c_str());
  if (o.dry_run) {
    std::printf("%s", runner::describeExperiment(o.experiment_path, o.overrides, registry_).c_str());
    std::printf("\nwould write %d point file(s) to %s\n", report.total, report.out_dir.c_str());
    return 0;
  }
  if (!primary()) return 0;
  printReport(report);
  return report.exitCode();
}

namespace {

void printSpecs(const std::vector<kinds::ParamSpec>& specs) {
  for (const auto& p : specs)
    std::printf("  %-26s %-8s default %-14s range %-34s %s\n", p.name.c_str(), p.unit.empty() ? "-" : p.unit.c_str(),
                kinds::describeValue(p.default_value).c_str(), kinds::describeRange(p).c_str(), p.doc.c_str());
}

}  // namespace

int Commands::list(const std::string& kind_name) const {
  if (kind_name == "render") {
    for (const auto& kind : registry_.all())
      if (const kinds::RenderHook* hook = kind->renderHook()) {
        std::printf("render: settings of `creaturelab render` on %s runs (key=value): %s\n", kind->name().c_str(),
                    hook->title().c_str());
        printSpecs(hook->settings());
      }
    return 0;
  }
  if (!kind_name.empty() && !registry_.find(kind_name))
    throw UsageError("unknown kind '" + kind_name + "' (`creaturelab list render` shows the render settings)");
  for (const auto& kind : registry_.all()) {
    if (!kind_name.empty() && kind->name() != kind_name) continue;
    std::printf("%s: %s\n", kind->name().c_str(), kind->doc().c_str());
    printSpecs(kind->params());
    std::printf("  metrics:\n");
    for (const auto& m : kind->metrics())
      std::printf("  %-26s %-8s %s\n", m.name.c_str(), m.unit.empty() ? "-" : m.unit.c_str(), m.doc.c_str());
    std::printf("\n");
  }
  return 0;
}

int Commands::show(const std::string& file, const std::vector<std::string>& overrides) const {
  checkOverrides(overrides);
  std::printf("%s", runner::describeExperiment(file, overrides, registry_).c_str());
  return 0;
}

int Commands::check(const std::string& run_dir, bool verify) const {
  const runner::StoredRun stored = runner::readIndex(run_dir);
  if (verify) runner::requireVerifiedRun(run_dir, stored);
  const auto e = runner::loadExperimentText(stored.experiment_text, stored.experiment_path, stored.overrides, registry_);
  const auto outcomes = runner::evaluateChecks(e.checks, stored.table);
  std::printf("%s", runner::formatCheckTable(outcomes).c_str());
  for (const auto& o : outcomes)
    if (!o.counts()) return 1;
  return 0;
}

int Commands::compare(const CompareArgs& args) const {
  const runner::StoredRun run = runner::readIndex(args.run);
  if (!args.no_verify) runner::requireVerifiedRun(args.run, run);
  const runner::Baseline baseline = loadBaseline(args.baseline, args.rtol, args.atol, !args.no_verify);
  const runner::Comparison c = runner::compareTables(run.table, baseline);
  std::printf("%s", runner::formatComparison(c, !args.all).c_str());
  std::printf("%s: %s\n", args.run.c_str(), c.passed() ? "within tolerance of the baseline" : "OUTSIDE the baseline");
  return c.passed() ? 0 : 1;
}

int Commands::baseline(const BaselineArgs& args) const {
  const runner::StoredRun run = runner::readIndex(args.run);
  runner::Baseline b{run.experiment_path, run.overrides, {{"default", {args.rtol, args.atol}}}, run.table};
  const std::string text = runner::baselineToJson(b).dump(2) + "\n";
  if (args.output.empty()) {
    std::fputs(text.c_str(), stdout);
  } else {
    if (fs::is_directory(args.output)) throw UsageError(args.output + ": is a folder; expected a file to write");
    io::writeFileAtomically(args.output, text);  // the old baseline stays whole if this fails
  }
  return 0;
}

int Commands::digest(const std::string& run_dir) const {
  if (fs::exists(run_dir) && !fs::is_directory(run_dir))
    throw UsageError(run_dir + ": is a file; expected a run folder (the --out of `creaturelab run`)");
  if (!fs::is_directory(run_dir)) throw UsageError(run_dir + ": no such run folder");
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(run_dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("point_", 0) == 0 && entry.path().extension() == ".h5") files.push_back(name);
  }
  std::sort(files.begin(), files.end());
  const std::vector<std::string>& skip = runner::provenanceAttributeNames();
  for (const auto& f : files) std::printf("%s  %s\n", io::contentDigest(run_dir + "/" + f, skip).c_str(), f.c_str());
  std::printf("%s  index.h5\n", io::contentDigest(run_dir + "/index.h5", skip).c_str());
  return 0;
}

// The list's [[render]] entries, after its experiments: `creaturelab render RUN --figures ...` on
// recorded swims (run = the run folder under the list's output root; frames, settings, figures).
namespace {

// The list's [[render]] entries, checked before any experiment runs: known keys, and a run that
// names one folder under the list's output root.
void checkRenderEntries(const toml::table& list, const std::string& file) {
  const auto* renders = list["render"].as_array();
  if (!renders) return;
  for (auto&& entry : *renders) {
    const auto* t = entry.as_table();
    if (!t || !(*t)["run"].is_string()) throw UsageError(file + ": each [[render]] needs run = \"<experiment stem>\"");
    for (auto&& [key, value] : *t)
      if (std::string problem = kinds::unknownKeyText(std::string(key.str()), {"run", "frames", "figures", "settings"});
          !problem.empty())
        throw UsageError(file + ": [[render]]: " + problem);
    checkPlainName((*t)["run"].value_or(std::string()), file + ": [[render]] run");
  }
}

}  // namespace

int Commands::reproduceRenders(const toml::table& list, const std::string& file, const std::string& out_root) const {
  const auto* renders = list["render"].as_array();
  if (!renders) return 0;
  checkRenderEntries(list, file);
  int code = 0;
  for (auto&& entry : *renders) {
    const auto* t = entry.as_table();
    runner::RenderRunOptions o;
    o.source = out_root + "/" + (*t)["run"].value_or(std::string());
    o.frames = (*t)["frames"].value_or(std::string());
    o.figures = (*t)["figures"].value_or(false);
    o.force = true;
    if (const auto* settings = (*t)["settings"].as_table())
      for (auto&& [key, value] : *settings) {
        std::ostringstream text;
        if (value.is_string()) text << *value.value<std::string>();
        else text << toml::json_formatter{value};
        o.overrides.push_back(std::string(key.str()) + "=" + text.str());
      }
    std::fprintf(stderr, "== render %s\n", o.source.c_str());
    try {
      code = std::max(code, render(o));
    } catch (const runner::ExperimentError& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      code = std::max(code, 2);
    }
  }
  return code;
}

int Commands::reproduce(const ReproduceArgs& args) const {
  toml::table list;
  if (fs::is_directory(args.list)) throw UsageError(args.list + ": is a folder; expected a TOML file listing experiments");
  try {
    list = toml::parse_file(args.list);
  } catch (const toml::parse_error& e) {
    throw UsageError(args.list + ": " + std::string(e.description()));
  }
  const auto* files = list["experiments"].as_array();
  if (!files)
    throw UsageError(args.list + ": expected experiments = [\"experiments/...toml\", {file = \"...\", set = [...]}, ...]");
  // Each entry: a path, or a table {file = "...", set = ["params.x=1", ...], name = "..."} whose
  // overrides make a quick version of a longer experiment; the run goes to OUT_ROOT/NAME
  // (default: the file's stem).
  std::vector<runner::RunOptions> planned;
  for (auto&& f : *files) {
    runner::RunOptions o;
    std::string name;
    if (const auto* path = f.as_string()) {
      o.experiment_path = path->get();
    } else if (const auto* t = f.as_table()) {
      for (auto&& [key, value] : *t)
        if (key != "file" && key != "set" && key != "name" && key != "minutes")
          throw UsageError(args.list + ": unknown key \"" + std::string(key.str()) +
                           "\" in an experiments entry; expected file, set, name, minutes");
      o.experiment_path = (*t)["file"].value_or(std::string());
      if (t->contains("name")) {
        if (!(*t)["name"].is_string()) throw UsageError(args.list + ": " + o.experiment_path + ": name is a string");
        name = (*t)["name"].value_or(std::string());
        checkPlainName(name, args.list + ": " + o.experiment_path);
      }
      if (const auto* set = (*t)["set"].as_array())
        for (auto&& v : *set) {
          if (!v.is_string()) throw UsageError(args.list + ": " + o.experiment_path + ": set holds strings \"key=value\"");
          o.overrides.push_back(v.value_or(std::string()));
        }
    } else {
      throw UsageError(args.list + ": an experiments entry is neither a path nor a table {file = \"...\"}");
    }
    if (o.experiment_path.empty())
      throw UsageError(args.list + ": an experiments entry names no file (a path, or {file = \"...\"})");
    if (name.empty()) name = fs::path(o.experiment_path).stem().string();
    checkPlainName(name, args.list + ": " + o.experiment_path);
    checkOverrides(o.overrides);
    o.out_dir = args.out_root + "/" + name;
    o.force = true;
    o.jobs = args.jobs;
    planned.push_back(std::move(o));
  }
  checkRenderEntries(list, args.list);
  // A list may say how long it takes (minutes = measured wall time of each entry): say so first,
  // and estimate the time left from it as the entries finish.
  std::vector<double> listed_s;
  for (auto&& f : *files) {
    const auto* t = f.as_table();
    listed_s.push_back(t ? (*t)["minutes"].value_or(0.0) * 60 : 0.0);
  }
  const double minutes = std::accumulate(listed_s.begin(), listed_s.end(), 0.0) / 60;
  if (minutes > 0 && primary())
    std::fprintf(stderr, "== %zu experiments from %s: about %.0f minutes on 2 cores (the sum of the times it lists)\n",
                 planned.size(), args.list.c_str(), minutes);
  // One line per experiment as it finishes (a status line on a terminal while it runs); the
  // check tables after every experiment and render. Experiments run side by side on the cores.
  runner::ListProgress progress(listed_s);
  const int jobs = args.jobs > 0 ? args.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  for (runner::RunOptions& o : planned) o.point_lines = false;
  std::vector<std::string> names;
  for (const runner::RunOptions& o : planned) names.push_back(fs::path(o.out_dir).filename().string());
  const std::vector<runner::ListEntryResult> results =
      runner::runList(std::move(planned), jobs, progress, registry_, cluster_);
  std::vector<runner::CheckOutcome> all;
  std::vector<std::string> unevaluated;
  int code = 0;
  for (size_t i = 0; i < results.size(); ++i) {
    const runner::ListEntryResult& result = results[i];
    if (result.error) std::rethrow_exception(result.error);  // the first in the list's order
    if (!result.ran || !primary()) continue;
    const runner::RunReport& r = result.report;
    if (!r.write_error.empty()) std::fprintf(stderr, "error: %s\n", r.write_error.c_str());
    if (!r.checks_evaluated) unevaluated.push_back(names[i]);
    for (auto c : r.checks) {
      c.name = names[i] + ": " + c.name;
      all.push_back(c);
    }
    code = std::max(code, r.exitCode());
  }
  if (primary()) code = std::max(code, reproduceRenders(list, args.list, args.out_root));
  if (primary()) {
    std::fflush(stderr);
    std::printf("\n== checks of every experiment\n%s", runner::formatCheckTable(all).c_str());
    for (const auto& name : unevaluated)
      std::printf("%s: checks not evaluated (not every point has run)\n", name.c_str());
  }
  return code;
}

}  // namespace creaturelab::cli
