// `base = "<path>"` in experiment files (runner/experiment.hpp, docs/experiments.md): tables merge
// key by key, [[case]] and [[check]] lists replace, inherit or clear; bases chain, paths are relative
// to the naming file; missing bases and cycles name the chain; the stored text is the merged document.
#include "runner/experiment.hpp"
#include "test_registry.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace creaturelab;
using runner::Experiment;
using runner::ExperimentError;
namespace fs = std::filesystem;

using creaturelab::testing::registry;

double realValue(const kinds::Value& v) { return std::get<double>(v); }

// A scratch folder of experiment files, removed after the test; paths in errors are relative to it
// (the test runs with it as the working folder, as a user runs from the source folder).
class ExperimentBase : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("creaturelab_base_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    old_ = fs::current_path();
    fs::current_path(dir_);
  }
  void TearDown() override {
    fs::current_path(old_);
    fs::remove_all(dir_);
  }
  static void write(const std::string& path, const std::string& text) {
    if (fs::path(path).has_parent_path()) fs::create_directories(fs::path(path).parent_path());
    std::ofstream(path) << text;
  }
  static Experiment load(const std::string& path, const std::vector<std::string>& overrides = {}) {
    return runner::loadExperiment(path, overrides, registry());
  }
  static std::string errorOf(const std::string& path, const std::vector<std::string>& overrides = {}) {
    try {
      load(path, overrides);
    } catch (const ExperimentError& err) {
      return err.what();
    }
    ADD_FAILURE() << "no ExperimentError for " << path;
    return "";
  }

 private:
  fs::path dir_, old_;
};

// A claim file with params, a sweep, two cases and two checks.
const char* kClaim = R"(kind = "oscillator"
title = "claim"
description = "the claim's text"
[params]
dt_s = 0.01
end_time_s = 2.0
integrator = "rk4"
[sweep]
stiffness_n_per_m = [1.0, 2.0]
[output]
lagrangian = false
[[case]]
label = "soft"
damping_ns_per_m = 0.0
[[case]]
label = "damped"
damping_ns_per_m = 0.1
[[check]]
name = "first"
type = "range"
metric = "max_abs_error_m"
expect = [0, 1]
[[check]]
name = "second"
type = "range"
metric = "max_abs_error_m"
expect = [0, 2]
)";

TEST_F(ExperimentBase, TablesMergeKeyByKeyAndScalarsOverride) {
  write("claims/claim.toml", kClaim);
  write("study.toml", R"(base = "claims/claim.toml"
title = "study"
[params]
dt_s = 0.005
[sweep]
x0_m = [0.1, 0.2, 0.3]
[output]
dir = "somewhere"
)");
  const Experiment e = load("study.toml");
  EXPECT_EQ(e.kind, "oscillator");  // inherited
  EXPECT_EQ(e.title, "study");      // overridden
  EXPECT_EQ(e.stem, "study");       // the file's own stem
  EXPECT_EQ(e.path, "study.toml");
  ASSERT_EQ(e.params.size(), 3u);
  EXPECT_EQ(realValue(e.params.at("dt_s")), 0.005);       // the study's
  EXPECT_EQ(realValue(e.params.at("end_time_s")), 2.0);   // the claim's
  EXPECT_EQ(std::get<std::string>(e.params.at("integrator")), "rk4");
  ASSERT_EQ(e.axes.size(), 2u);  // the claim's axis and the study's
  EXPECT_EQ(e.axes[0].name, "stiffness_n_per_m");  // toml++ orders a table's keys
  EXPECT_EQ(e.axes[1].name, "x0_m");
  EXPECT_EQ(e.axes[1].values.size(), 3u);
  EXPECT_EQ(e.output.dir, "somewhere");
  EXPECT_FALSE(e.output.lagrangian);  // nested table merged, not replaced
  EXPECT_EQ(e.cases.size(), 2u);      // inherited
  EXPECT_EQ(e.checks.size(), 2u);
}

TEST_F(ExperimentBase, ASweepAxisOfTheFileReplacesTheBasesValues) {
  write("claim.toml", kClaim);
  write("study.toml", "base = \"claim.toml\"\n[sweep]\nstiffness_n_per_m = [3.0]\n");
  const Experiment e = load("study.toml");
  ASSERT_EQ(e.axes.size(), 1u);
  ASSERT_EQ(e.axes[0].values.size(), 1u);
  EXPECT_EQ(realValue(e.axes[0].values[0]), 3.0);
}

TEST_F(ExperimentBase, CaseAndCheckListsReplaceInheritOrClear) {
  write("claim.toml", kClaim);
  write("replace.toml", R"(base = "claim.toml"
[[case]]
label = "stiff"
damping_ns_per_m = 0.5
[[check]]
name = "own"
type = "range"
metric = "max_abs_error_m"
expect = [0, 3]
)");
  const Experiment r = load("replace.toml");
  ASSERT_EQ(r.cases.size(), 1u);
  EXPECT_EQ(r.cases[0].label, "stiff");
  ASSERT_EQ(r.checks.size(), 1u);
  EXPECT_EQ(r.checks[0].name, "own");

  write("clear.toml", "base = \"claim.toml\"\ncase = []\ncheck = []\n");
  const Experiment c = load("clear.toml");
  EXPECT_TRUE(c.cases.empty());
  EXPECT_TRUE(c.checks.empty());
  EXPECT_EQ(runner::expandPoints(c, *registry().find("oscillator")).size(), 2u);  // the sweep alone

  write("inherit.toml", "base = \"claim.toml\"\n[params]\ndt_s = 0.02\n");
  const Experiment i = load("inherit.toml");
  ASSERT_EQ(i.cases.size(), 2u);
  EXPECT_EQ(i.cases[1].label, "damped");
  ASSERT_EQ(i.checks.size(), 2u);
  EXPECT_EQ(i.checks[1].name, "second");
}

TEST_F(ExperimentBase, EmptyListsInAFileWithoutBaseMeanNone) {
  write("plain.toml", "kind = \"oscillator\"\ncase = []\ncheck = []\n");
  write("none.toml", "kind = \"oscillator\"\n");
  const Experiment e = load("plain.toml");
  EXPECT_TRUE(e.cases.empty());
  EXPECT_TRUE(e.checks.empty());
  EXPECT_EQ(e.resolved_json, runner::loadExperimentText("kind = \"oscillator\"\n", "plain.toml", {}, registry())
                                 .resolved_json);
}

TEST_F(ExperimentBase, BasesChainAndPathsAreRelativeToTheNamingFile) {
  // studies/osc/grid.toml -> ../../claims/osc/mid.toml -> root/claim.toml
  write("root/claim.toml", kClaim);
  write("claims/osc/mid.toml", "base = \"../../root/claim.toml\"\ntitle = \"mid\"\n[params]\nend_time_s = 3.0\n");
  write("studies/osc/grid.toml", "base = \"../../claims/osc/mid.toml\"\n[params]\ndt_s = 0.002\n");
  const Experiment e = load("studies/osc/grid.toml");
  EXPECT_EQ(e.title, "mid");
  EXPECT_EQ(realValue(e.params.at("dt_s")), 0.002);
  EXPECT_EQ(realValue(e.params.at("end_time_s")), 3.0);
  EXPECT_EQ(std::get<std::string>(e.params.at("integrator")), "rk4");
  EXPECT_EQ(e.cases.size(), 2u);
  EXPECT_EQ(e.stem, "grid");
  // The same chain from another working folder: paths follow the files, not the caller.
  fs::current_path("studies");
  EXPECT_EQ(load("osc/grid.toml").resolved_json, e.resolved_json);
  fs::current_path("..");
}

TEST_F(ExperimentBase, AMissingBaseNamesTheChain) {
  write("a.toml", "base = \"b.toml\"\n");
  write("b.toml", "base = \"sub/missing.toml\"\nkind = \"oscillator\"\n");
  const std::string m = errorOf("a.toml");
  EXPECT_NE(m.find("a.toml -> b.toml -> sub/missing.toml: base file not found"), std::string::npos) << m;
}

TEST_F(ExperimentBase, ACycleNamesTheChain) {
  write("studies/jellyfish/grid.toml", "base = \"../../experiments/jellyfish/fig5.toml\"\n");
  write("experiments/jellyfish/fig5.toml", "base = \"../../studies/jellyfish/grid.toml\"\nkind = \"oscillator\"\n");
  const std::string m = errorOf("studies/jellyfish/grid.toml");
  EXPECT_NE(m.find("studies/jellyfish/grid.toml -> experiments/jellyfish/fig5.toml -> studies/jellyfish/grid.toml: "
                   "base cycle"),
            std::string::npos)
      << m;
  write("self.toml", "base = \"./self.toml\"\nkind = \"oscillator\"\n");
  const std::string s = errorOf("self.toml");
  EXPECT_NE(s.find("self.toml -> self.toml: base cycle"), std::string::npos) << s;
}

TEST_F(ExperimentBase, ABaseThatIsNotAStringIsRefused) {
  write("a.toml", "base = 3\nkind = \"oscillator\"\n");
  const std::string m = errorOf("a.toml");
  EXPECT_NE(m.find("a.toml:1: base: expected the path of another experiment file"), std::string::npos) << m;
  write("b.toml", "base = \"a.toml\"\n");
  const std::string chained = errorOf("b.toml");
  EXPECT_NE(chained.find("b.toml -> a.toml:1: base: expected"), std::string::npos) << chained;
  write("c.toml", "base = \"\"\nkind = \"oscillator\"\n");
  EXPECT_NE(errorOf("c.toml").find("c.toml:1: base: expected"), std::string::npos);
}

TEST_F(ExperimentBase, ErrorsInABasesKeysNameTheBaseFile) {
  write("claim.toml", "kind = \"oscillator\"\n[params]\ndt_s = 0.01\nintegratr = \"rk4\"\n");
  write("study.toml", "base = \"claim.toml\"\n[params]\ndt_s = 0.02\n");
  const std::string m = errorOf("study.toml");
  EXPECT_EQ(m.rfind("claim.toml:4: params.integratr: unknown parameter", 0), 0u) << m;
  write("bad_check.toml", "kind = \"oscillator\"\n[[check]]\nname = \"x\"\ntype = \"range\"\nmetric = \"nope\"\n"
                          "expect = [0, 1]\n");
  write("study2.toml", "base = \"bad_check.toml\"\n");
  const std::string c = errorOf("study2.toml");
  EXPECT_EQ(c.rfind("bad_check.toml:", 0), 0u) << c;
  EXPECT_NE(c.find("'nope' is not a metric"), std::string::npos) << c;
  // A malformed base names the chain, the base, its line and column.
  write("broken.toml", "kind = \"oscillator\"\n[params\n");
  write("study3.toml", "base = \"broken.toml\"\n");
  const std::string b = errorOf("study3.toml");
  EXPECT_EQ(b.rfind("study3.toml -> broken.toml: broken.toml:2:", 0), 0u) << b;
  EXPECT_NE(b.find("malformed TOML"), std::string::npos) << b;
}

TEST_F(ExperimentBase, OverridesApplyAfterTheMerge) {
  write("claim.toml", kClaim);
  write("study.toml", "base = \"claim.toml\"\n[params]\ndt_s = 0.005\n");
  const Experiment e = load("study.toml", {"params.dt_s=0.001", "params.end_time_s=1.5", "sweep.stiffness_n_per_m=[4]"});
  EXPECT_EQ(realValue(e.params.at("dt_s")), 0.001);
  EXPECT_EQ(realValue(e.params.at("end_time_s")), 1.5);
  EXPECT_EQ(std::get<std::string>(e.params.at("integrator")), "rk4");
  ASSERT_EQ(e.axes.size(), 1u);
  EXPECT_EQ(realValue(e.axes[0].values.at(0)), 4.0);
  const std::string m = errorOf("study.toml", {"base=\"other.toml\""});
  EXPECT_NE(m.find("base: cannot be set by an override"), std::string::npos) << m;
}

TEST_F(ExperimentBase, TheStoredTextIsTheMergedDocumentAndLoadsToTheSameExperiment) {
  write("claims/claim.toml", kClaim);
  write("studies/study.toml", R"(base = "../claims/claim.toml"
title = "study of 0.1 and 1e-8"
case = []
[params]
dt_s = 0.1
x0_m = 1e-8
[sweep]
damping_ns_per_m = [0.05, 0.3]
)");
  const std::vector<std::string> overrides = {"params.end_time_s=0.7"};
  const Experiment e = load("studies/study.toml", overrides);
  EXPECT_EQ(e.source_text.find("base"), std::string::npos) << e.source_text;
  EXPECT_NE(e.source_text.find("study of 0.1"), std::string::npos) << e.source_text;
  // `creaturelab check RUN` loads the stored text under the stored path and overrides, with no
  // base file in reach (another working folder).
  fs::current_path(fs::temp_directory_path());
  const Experiment back = runner::loadExperimentText(e.source_text, e.path, overrides, registry());
  EXPECT_EQ(back.resolved_json, e.resolved_json);
  EXPECT_EQ(back.source_text, e.source_text);
  EXPECT_EQ(back.checks.size(), e.checks.size());
  EXPECT_EQ(back.stem, "study");
  EXPECT_EQ(realValue(back.params.at("x0_m")), 1e-8);
  EXPECT_EQ(realValue(back.params.at("end_time_s")), 0.7);
}

TEST_F(ExperimentBase, AFileWithoutBaseKeepsItsTextAsRead) {
  write("claim.toml", kClaim);
  const Experiment e = load("claim.toml");
  EXPECT_EQ(e.source_text, kClaim);
  // Resolved the same whether read alone or as the base of an empty study.
  write("study.toml", "base = \"claim.toml\"\n");
  const Experiment s = load("study.toml");
  EXPECT_EQ(s.resolved_json, e.resolved_json);
  EXPECT_EQ(s.checks.size(), 2u);
}

}  // namespace

namespace {

// Every shipped study's stored text (the merged document) loads to the same experiment: what
// `creaturelab check RUN` reads back from a study's run folder.
TEST(ExperimentBaseShipped, EveryStudysMergedTextLoadsToTheSameExperiment) {
  const fs::path root = fs::path(CREATURELAB_TEST_SOURCE_DIR);
  int merged = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root / "studies")) {
    if (entry.path().extension() != ".toml") continue;
    const std::string path = entry.path().string();
    try {
      const Experiment e = runner::loadExperiment(path, {}, registry());
      const Experiment back = runner::loadExperimentText(e.source_text, e.path, {}, registry());
      EXPECT_EQ(back.resolved_json, e.resolved_json) << path;
      ASSERT_EQ(back.checks.size(), e.checks.size()) << path;
      for (size_t i = 0; i < e.checks.size(); ++i) {
        EXPECT_EQ(back.checks[i].name, e.checks[i].name) << path;
        EXPECT_EQ(back.checks[i].where, e.checks[i].where) << path;
        EXPECT_EQ(back.checks[i].expect_lo, e.checks[i].expect_lo) << path;
        EXPECT_EQ(back.checks[i].expect_hi, e.checks[i].expect_hi) << path;
        EXPECT_EQ(back.checks[i].known_deviation, e.checks[i].known_deviation) << path;
      }
      std::stringstream raw;
      raw << std::ifstream(path).rdbuf();
      if (raw.str() != e.source_text) ++merged;  // a file with a base stores its merged document
    } catch (const ExperimentError& err) {
      ADD_FAILURE() << err.what();
    }
  }
  EXPECT_GE(merged, 1);
}

}  // namespace
