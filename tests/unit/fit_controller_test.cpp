// Controller-parameter fitting (fit/controller_fit.hpp) on a cheap kind whose metrics are closed
// forms: the optimum is found; the fit is bitwise the same for 1, 2 and 4 threads; an interrupted
// fit resumes from its record (in memory and through the HDF5 file) to the same result, reusing
// every recorded run; the target form solves a bounded least-squares problem; bad controller files
// are rejected before any run, and the shipped ones (experiments/fit/) load.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "fit/controller_fit.hpp"
#include "fit/controller_record.hpp"
#include "fit/controller_spec.hpp"
#include "kinds/kind.hpp"
#include "scratch_dir_test.hpp"

namespace creaturelab::fit {
namespace {

std::atomic<int> g_runs{0};

// distance = 1 - (a - 0.3)² - 2 (b - 0.6)² + 0.5 (a - 0.3)(b - 0.6): a maximum of 1 at (0.3, 0.6).
// speed = a + b, work = a² + b²: reaching speed 1 with least work gives a = b = 0.5.
class QuadraticKind : public kinds::SchemaKind {
 public:
  QuadraticKind() {
    params_ = {kinds::real("a", 0.7, "m", 0, 1, "first"), kinds::real("b", 0.2, "", 0, 1, "second"),
               kinds::integer("c", 1, 0, 5, "an integer"), kinds::real("fail_below_a", -1.0, "", -1, 1, "")};
    metrics_ = {{"distance_per_cycle_m", "m", ""}, {"mean_speed_m_per_s", "m/s", ""}, {"muscle_work_j", "J/m", ""}};
  }
  std::string name() const override { return "quadratic"; }
  std::string doc() const override { return "closed-form metrics for fit tests"; }
  kinds::Result run(const kinds::Params& p) const override {
    ++g_runs;
    kinds::ParamReader r(p);
    const double a = r.real("a"), b = r.real("b");
    if (a < r.real("fail_below_a")) throw kinds::RunFailure("a is too small");
    const double da = a - 0.3, db = b - 0.6;
    kinds::Result out;
    out.metrics["distance_per_cycle_m"] = {1 - da * da - 2 * db * db + 0.5 * da * db, "m"};
    out.metrics["mean_speed_m_per_s"] = {a + b, "m/s"};
    out.metrics["muscle_work_j"] = {a * a + b * b, "J/m"};
    out.timeseries["time_s"] = {{0.0, 1.0}, "s"};
    return out;
  }
};

kinds::Registry registry() {
  kinds::Registry r;
  r.add(std::make_unique<QuadraticKind>());
  return r;
}

const char* kMaximise = R"(
kind = "quadratic"
title = "cheap objective"
[params]
c = 2
[objective]
type = "maximise"
metric = "distance_per_cycle_m"
scale = 0.1
[solver]
max_iterations = 30
max_runs = 400
function_tolerance = 1e-12
gradient_tolerance = 1e-9
parameter_tolerance = 1e-10
[[tune]]
name = "a"
min = 0.0
max = 1.0
step = 0.01
[[tune]]
name = "b"
start = 0.25
min = 0.1
max = 0.9
step = 0.01
)";

ControllerSpec spec(const std::string& text = kMaximise) {
  static const kinds::Registry r = registry();
  return loadControllerSpecText(text, "cheap.toml", r);
}

const kinds::Kind& kind() {
  static const kinds::Registry r = registry();
  return *r.find("quadratic");
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectIdentical(const ControllerFitResult& a, const ControllerFitResult& b) {
  ASSERT_EQ(a.evaluations.size(), b.evaluations.size());
  for (std::size_t i = 0; i < a.evaluations.size(); ++i) {
    for (std::size_t j = 0; j < a.evaluations[i].x.size(); ++j)
      EXPECT_TRUE(sameBits(a.evaluations[i].x[j], b.evaluations[i].x[j])) << "evaluation " << i;
    EXPECT_TRUE(sameBits(a.evaluations[i].cost, b.evaluations[i].cost)) << "evaluation " << i;
  }
  ASSERT_EQ(a.history.size(), b.history.size());
  for (std::size_t i = 0; i < a.history.size(); ++i) {
    EXPECT_TRUE(sameBits(a.history[i].cost, b.history[i].cost)) << "iteration " << i;
    EXPECT_EQ(a.history[i].evaluations, b.history[i].evaluations);
  }
  for (std::size_t j = 0; j < a.x_fitted.size(); ++j) EXPECT_TRUE(sameBits(a.x_fitted[j], b.x_fitted[j]));
}

TEST(FitController, MaximiseFindsTheOptimumInsideTheBounds) {
  ControllerFitOptions o;
  o.jobs = 1;
  const ControllerFitResult r = fitController(spec(), kind(), o);
  EXPECT_NEAR(r.x_fitted[0], 0.3, 1e-4) << r.solver_report;
  EXPECT_NEAR(r.x_fitted[1], 0.6, 1e-4);
  EXPECT_GT(r.fitted.metrics.at("distance_per_cycle_m"), r.start.metrics.at("distance_per_cycle_m"));
  EXPECT_EQ(r.x_start[0], 0.7);  // the default value (start omitted), exactly: not x(z(0.7))
  EXPECT_EQ(r.x_start[1], 0.25);
  ASSERT_FALSE(r.history.empty());
  EXPECT_EQ(r.history.front().iteration, 0);
  EXPECT_EQ(r.new_runs, int(r.evaluations.size()));
}

TEST(FitController, IsBitwiseIdenticalForAnyThreadCount) {
  ControllerFitOptions o;
  o.jobs = 1;
  const ControllerFitResult one = fitController(spec(), kind(), o);
  for (int jobs : {2, 4}) {
    o.jobs = jobs;
    const ControllerFitResult many = fitController(spec(), kind(), o);
    SCOPED_TRACE("jobs " + std::to_string(jobs));
    expectIdentical(one, many);
  }
}

TEST(FitController, ResumesFromTheEvaluationsOfAnInterruptedFit) {
  const ControllerFitResult full = fitController(spec(), kind(), {});
  for (int stop : {1, 7, 23}) {
    SCOPED_TRACE("interrupted after " + std::to_string(stop) + " runs");
    ControllerFitOptions first;
    first.jobs = 2;
    first.stop_after_new_runs = stop;
    std::vector<Evaluation> record;
    first.on_batch = [&](const ControllerFitState& s) { record = *s.evaluations; };
    EXPECT_THROW(fitController(spec(), kind(), first), FitInterrupted);
    ASSERT_EQ(int(record.size()), stop);

    ControllerFitOptions again;
    again.recorded = record;
    const int before = g_runs;
    const ControllerFitResult resumed = fitController(spec(), kind(), again);
    expectIdentical(full, resumed);
    EXPECT_EQ(resumed.reused_runs, stop);
    EXPECT_EQ(resumed.new_runs, full.new_runs - stop);
    EXPECT_EQ(g_runs - before, full.new_runs - stop);
  }
}

// Failed runs (here a < 0.28 throws, just short of the optimum at 0.3) are evaluations that failed:
// the line search backs off from them, the record keeps the message, and the fit still ends at
// the optimum.
TEST(FitController, SurvivesFailingRuns) {
  std::string text = kMaximise;
  text.replace(text.find("c = 2"), 5, "c = 2\nfail_below_a = 0.28");
  const ControllerFitResult r = fitController(spec(text), kind(), {});
  EXPECT_NEAR(r.x_fitted[0], 0.3, 1e-3);
  int failed = 0;
  for (const auto& e : r.evaluations) failed += !e.ok;
  EXPECT_GT(failed, 0);
  for (const auto& e : r.evaluations) {
    if (!e.ok) {
      EXPECT_EQ(e.message, "a is too small");
    }
  }
}

TEST(FitController, TargetObjectiveIsBoundedLeastSquares) {
  const std::string text = R"(
kind = "quadratic"
[objective]
type = "target"
metric = "mean_speed_m_per_s"
target = 1.0
tolerance = 0.001
least = "muscle_work_j"
least_scale = 1.0
[solver]
max_iterations = 50
max_runs = 800
function_tolerance = 1e-12
gradient_tolerance = 1e-12
parameter_tolerance = 1e-12
[[tune]]
name = "a"
min = 0.05
max = 0.95
step = 0.01
[[tune]]
name = "b"
min = 0.05
max = 0.45
step = 0.01
)";
  // b is held at 0.45 by its bound, so a = 1 - 0.45 within the speed tolerance's pull.
  const ControllerFitResult r = fitController(spec(text), kind(), {});
  EXPECT_NEAR(r.x_fitted[1], 0.45, 1e-9) << r.solver_report;
  EXPECT_NEAR(r.x_fitted[0], 0.55, 2e-3);
  EXPECT_NEAR(r.fitted.metrics.at("mean_speed_m_per_s"), 1.0, 2e-3);
}

class FitRecordTest : public testing::ScratchDirTest {
 protected:
  FitRecordTest() : ScratchDirTest("fit_record") {}
};

// Through the HDF5 record, as `creaturelab fit controller --resume` does.
TEST_F(FitRecordTest, ResumesThroughTheHdf5Record) {
  const ControllerSpec s = spec();
  const ControllerFitResult full = fitController(s, kind(), {});
  ControllerFitOptions first;
  first.stop_after_new_runs = 12;
  first.on_batch = [&](const ControllerFitState& st) { writeControllerRecord(dir_.string(), s, st, {}); };
  EXPECT_THROW(fitController(s, kind(), first), FitInterrupted);

  ControllerFitOptions again;
  again.recorded = readControllerEvaluations(dir_.string(), s);
  ASSERT_EQ(again.recorded.size(), 12u);
  const ControllerFitResult resumed = fitController(s, kind(), again);
  expectIdentical(full, resumed);
  EXPECT_EQ(resumed.reused_runs, 12);
  writeControllerResult(dir_.string(), s, resumed, {}, {}, {});
  EXPECT_TRUE(std::filesystem::exists(file("params.toml")));

  // A record of another file is refused.
  std::string other = kMaximise;
  other.replace(other.find("step = 0.01"), 11, "step = 0.02");
  try {
    readControllerEvaluations(dir_.string(), spec(other));
    FAIL() << "expected FitError";
  } catch (const FitError& e) {
    EXPECT_NE(std::string(e.what()).find("SHA-256 differs"), std::string::npos) << e.what();
  }
}

// --- bad controller files: one message naming file, key and what was expected

std::string specError(const std::string& text, const kinds::Registry& r) {
  try {
    loadControllerSpecText(text, "bad.toml", r);
  } catch (const FitError& e) {
    return e.what();
  }
  return "";
}

std::string withTune(const std::string& tune, const std::string& params = "") {
  return "kind = \"jellyfish\"\n[params]\n" + params + "\n[objective]\nmetric = \"distance_per_cycle_m\"\n[[tune]]\n" +
         tune + "\n";
}

TEST(FitControllerBadInput, RejectsUnknownParametersBadBoundsAndBadMetrics) {
  const kinds::Registry r = kinds::defaultRegistry();
  std::string e = specError(withTune("name = \"stager\"\nmin = 0.1\nmax = 0.9\nstep = 0.05"), r);
  EXPECT_NE(e.find("unknown parameter 'stager' for kind 'jellyfish' (did you mean 'stagger'?)"), std::string::npos) << e;
  e = specError(withTune("name = \"stagger\"\nstart = 0.95\nmin = 0.1\nmax = 0.9\nstep = 0.05"), r);
  EXPECT_NE(e.find("bad.toml:8: tune[0]: the bounds [0.1, 0.9] exclude the start 0.95"), std::string::npos) << e;
  e = specError(withTune("name = \"stagger\"\nmin = 0.6\nmax = 0.9\nstep = 0.05"), r);  // default 0.5 outside
  EXPECT_NE(e.find("exclude the start 0.5"), std::string::npos) << e;
  e = specError(withTune("name = \"stagger\"\nmin = 0.1\nmax = 1.5\nstep = 0.05"), r);
  EXPECT_NE(e.find("leave the range of 'stagger'"), std::string::npos) << e;
  e = specError(withTune("name = \"cells\"\nmin = 10\nmax = 90\nstep = 5"), r);
  EXPECT_NE(e.find("only real parameters can be tuned"), std::string::npos) << e;
  e = specError(withTune("name = \"stagger\"\nmin = 0.1\nmax = 0.9\nstep = 0.5"), r);
  EXPECT_NE(e.find("tune[0].step: must be > 0 and at most a quarter"), std::string::npos) << e;
  e = specError(withTune("name = \"stagger\"\nmin = 0.1\nmax = 0.9\nstep = 0.05", "celss = 50"), r);
  EXPECT_NE(e.find("params.celss: unknown parameter 'celss' for kind 'jellyfish' (did you mean 'cells'?)"),
            std::string::npos)
      << e;
  e = specError(withTune("name = \"knot3_value\"\nmin = 0.6\nmax = 1.0\nstart = 0.8\nstep = 0.05"), r);
  EXPECT_NE(e.find("knot3_* is set but contraction_knots = 2"), std::string::npos) << e;
  e = specError("kind = \"jellyfish\"\n[objective]\nmetric = \"distance_per_cycle\"\n[[tune]]\nname = \"stagger\"\n"
                "min = 0.1\nmax = 0.9\nstep = 0.05\n",
                r);
  EXPECT_NE(e.find("'distance_per_cycle' is not a metric of kind 'jellyfish' (did you mean 'distance_per_cycle_m'?)"),
            std::string::npos)
      << e;
  e = specError("kind = \"jellyfish\"\n[objective]\nmetric = \"distance_per_cycle_m\"\n", r);
  EXPECT_NE(e.find("tune: missing"), std::string::npos) << e;
}

TEST(FitControllerSpec, ShippedFitFilesLoad) {
  // experiments/fit/ holds controller-fit files, which the runner's ShippedExperimentsLoadAndExpand
  // passes over (another format): each must load against the real kinds as `creaturelab fit
  // controller` loads it, start point included.
  const std::filesystem::path dir = std::filesystem::path(CREATURELAB_TEST_SOURCE_DIR) / "experiments" / "fit";
  const kinds::Registry r = kinds::defaultRegistry();
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".toml") continue;
    ++n;
    try {
      EXPECT_FALSE(loadControllerSpec(entry.path().string(), r).tuned.empty()) << entry.path();
    } catch (const FitError& err) {
      ADD_FAILURE() << err.what();
    }
  }
  EXPECT_GE(n, 2);
}

}  // namespace
}  // namespace creaturelab::fit
