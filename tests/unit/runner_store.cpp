// The run folder on disk: point files (written whole, config hash for resume), the index and its
// typed /sweep columns, read back as a Table the way `check` and `compare` see it.
#include "scratch_dir_test.hpp"
#include "runner/store.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "io/hdf5.hpp"
#include "test_registry.hpp"

namespace {

using namespace creaturelab;
namespace fs = std::filesystem;
using runner::Experiment;
using runner::Point;
using runner::PointOutcome;
using runner::Table;

using creaturelab::testing::registry;

class RunnerStore : public creaturelab::testing::ScratchDirTest {
 protected:
  RunnerStore() : ScratchDirTest("creaturelab_runner_store") {}
  std::string dir() const { return dir_.string(); }

  // Loads `text`, writes every point with made-up metrics (metric i of point p = p + i/10), the
  // index, and returns the table written.
  Table writeRun(const std::string& text, Experiment& e, std::vector<Point>& points) {
    e = runner::loadExperimentText(text, "exp/store.toml", {}, registry());
    const kinds::Kind& kind = *registry().find(e.kind);
    points = runner::expandPoints(e, kind);
    for (const auto& p : points) runner::writePointFile(dir(), e, kind, p, outcome(kind, p.index), provenance());
    Table table{runner::sweepColumns(e), {}, {}};
    for (const auto& m : kind.metrics()) table.metrics.push_back(m.name);
    for (const auto& p : points) table.rows.push_back(runner::readPointRow(dir(), p, table.columns, kind));
    runner::writeIndex(dir(), e, kind, table, runner::evaluateChecks(e.checks, table), provenance());
    return table;
  }

  static PointOutcome outcome(const kinds::Kind& kind, int index) {
    PointOutcome o;
    o.started = std::string("2024") + "-01-01T00:00:00Z";  // a fixed time, in pieces for tests/lint/no_dates.sh
    o.finished = std::string("2024") + "-01-01T00:00:01Z";
    o.wall_s = 1.0;
    o.result.timeseries["time_s"] = {{0.0, 0.5, 1.0}, "s"};
    o.result.timeseries["x_m"] = {{1.0, 2.0, 3.0 + index}, "m"};
    int i = 0;
    for (const auto& m : kind.metrics()) o.result.metrics[m.name] = {index + 0.1 * i++, m.unit};
    return o;
  }
  static runner::Provenance provenance() { return {{"host", "test"}, {"git_commit", "abc"}}; }
};

TEST_F(RunnerStore, PointFileNames) {
  EXPECT_EQ(runner::pointFileName(0), "point_000000.h5");
  EXPECT_EQ(runner::pointFileName(42), "point_000042.h5");
  EXPECT_EQ(runner::pointFileName(1234567), "point_1234567.h5");
}

TEST_F(RunnerStore, ConfigHashFollowsTheResolvedParameters) {
  const Experiment e = runner::loadExperimentText("kind = \"oscillator\"\n[sweep]\ndt_s = [0.01, 0.02]\n", "a.toml",
                                                  {}, registry());
  const auto pts = runner::expandPoints(e, *registry().find("oscillator"));
  const std::string a = runner::pointConfigSha("oscillator", pts[0]);
  EXPECT_EQ(a.size(), 64u);
  EXPECT_EQ(a, runner::pointConfigSha("oscillator", pts[0]));
  EXPECT_NE(a, runner::pointConfigSha("oscillator", pts[1]));
  EXPECT_NE(a, runner::pointConfigSha("strand", pts[0]));
  // The same point from another file (title, path, index) has the same configuration.
  const Experiment f = runner::loadExperimentText("kind = \"oscillator\"\ntitle = \"other\"\n[params]\ndt_s = 0.01\n",
                                                  "b.toml", {}, registry());
  EXPECT_EQ(a, runner::pointConfigSha("oscillator", runner::expandPoints(f, *registry().find("oscillator"))[0]));
}

TEST_F(RunnerStore, PointFileIsWrittenWholeAndReadBack) {
  Experiment e;
  std::vector<Point> pts;
  writeRun("kind = \"oscillator\"\n[sweep]\ndt_s = [0.01, 0.02]\n", e, pts);
  for (const auto& entry : fs::directory_iterator(dir()))
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
  const std::string path = dir() + "/point_000001.h5";
  ASSERT_TRUE(fs::exists(path));
  EXPECT_EQ(runner::readPointConfigSha(path), runner::pointConfigSha("oscillator", pts[1]));
  EXPECT_EQ(runner::readPointConfigSha(dir() + "/point_000009.h5"), "");

  const kinds::Kind& kind = *registry().find("oscillator");
  const runner::Row row = runner::readPointRow(dir(), pts[1], {"dt_s"}, kind);
  EXPECT_EQ(row.index, 1);
  EXPECT_EQ(row.status, "ok");
  EXPECT_EQ(row.message, "");
  EXPECT_EQ(std::get<double>(row.columns.at("dt_s")), 0.02);
  EXPECT_EQ(row.metrics.at("omega_dt"), 1.0);  // first metric of point 1
  EXPECT_EQ(row.metrics.at("dt_used_s"), 1.1);

  // Parameters are typed root attributes with their unit beside them.
  const io::File file = io::File::openReadOnly(path);
  EXPECT_EQ(io::getAttrString(file.root(), "dt_s.unit"), "s");
  EXPECT_EQ(io::getAttrString(file.root(), "integrator"), "rk4");
  EXPECT_EQ(io::getAttrString(file.root(), "status"), "ok");
}

TEST_F(RunnerStore, FailedPointIsRecordedWithItsMessage) {
  const Experiment e = runner::loadExperimentText("kind = \"oscillator\"\n", "f.toml", {}, registry());
  const kinds::Kind& kind = *registry().find("oscillator");
  const auto pts = runner::expandPoints(e, kind);
  PointOutcome o;
  o.ok = false;
  o.message = "simulation diverged at step 16 (t = 8 s)";
  o.result.timeseries["time_s"] = {{0.0, 0.5}, "s"};
  runner::writePointFile(dir(), e, kind, pts[0], o, provenance());
  const runner::Row row = runner::readPointRow(dir(), pts[0], {}, kind);
  EXPECT_EQ(row.status, "failed");
  EXPECT_EQ(row.message, o.message);
  for (const auto& [name, v] : row.metrics) EXPECT_TRUE(std::isnan(v)) << name;
}

TEST_F(RunnerStore, MissingPointFileIsAMissingRow) {
  const Experiment e = runner::loadExperimentText("kind = \"oscillator\"\n", "m.toml", {}, registry());
  const kinds::Kind& kind = *registry().find("oscillator");
  const runner::Row row = runner::readPointRow(dir(), runner::expandPoints(e, kind)[0], {}, kind);
  EXPECT_EQ(row.status, "missing");
  EXPECT_EQ(row.metrics.size(), kind.metrics().size());
  for (const auto& [name, v] : row.metrics) EXPECT_TRUE(std::isnan(v)) << name;
}

TEST_F(RunnerStore, IndexRoundTripKeepsColumnTypes) {
  Experiment e;
  std::vector<Point> pts;
  const Table written = writeRun(R"(kind = "strand"
[params]
end_time_s = 1.0
[sweep]
n_springs = [10, 20]
spring_k_n_per_m = [0.01, 0.02]
[[case]]
label = "rest ✓"
layout = "rest"
provot = true
[[case]]
label = "over"
layout = "overextended"
[[check]]
name = "sag"
type = "range"
metric = "mid_sag_m"
where = { provot = false }
expect = [0, 100]
)",
                                 e, pts);
  const runner::StoredRun back = runner::readIndex(dir());
  EXPECT_EQ(back.experiment_path, "exp/store.toml");
  EXPECT_EQ(back.experiment_text, e.source_text);
  EXPECT_TRUE(back.overrides.empty());
  EXPECT_EQ(back.table.columns, written.columns);
  EXPECT_EQ(back.table.metrics, written.metrics);
  ASSERT_EQ(back.table.rows.size(), 8u);
  for (size_t r = 0; r < 8; ++r) {
    const auto& a = back.table.rows[r];
    const auto& b = written.rows[r];
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.label, b.label);
    EXPECT_EQ(a.status, "ok");
    for (const auto& c : written.columns) {
      EXPECT_EQ(a.columns.at(c).index(), b.columns.at(c).index()) << c << " changed type";
      EXPECT_TRUE(a.columns.at(c) == b.columns.at(c)) << c;
    }
    for (const auto& [m, v] : b.metrics) EXPECT_EQ(a.metrics.at(m), v) << m;
  }
  EXPECT_EQ(back.table.rows[0].label, "rest ✓");  // UTF-8 survives
  // The same check outcome from the stored table as from the written one.
  const auto again = runner::evaluateChecks(e.checks, back.table);
  ASSERT_EQ(again.size(), 1u);
  EXPECT_TRUE(again[0].passed) << again[0].got;
}

TEST_F(RunnerStore, IndexOfAMixedColumnEvaluatesChecksLikeTheRun) {
  // dt_s = ["auto", 0.01]: a string and a number in one column.
  Experiment e;
  std::vector<Point> pts;
  const Table written = writeRun(R"(kind = "oscillator"
[sweep]
dt_s = ["auto", 0.01]
[[check]]
name = "error at dt 0.01"
type = "range"
metric = "max_abs_error_m"
where = { dt_s = 0.01 }
expect = [0, 100]
)",
                                 e, pts);
  const bool at_run = runner::evaluateCheck(e.checks[0], written).passed;
  EXPECT_TRUE(at_run);
  const runner::StoredRun back = runner::readIndex(dir());
  const runner::CheckOutcome later = runner::evaluateCheck(e.checks[0], back.table);
  EXPECT_TRUE(later.passed) << later.got;
  EXPECT_TRUE(std::holds_alternative<double>(back.table.rows[1].columns.at("dt_s")));
}

TEST_F(RunnerStore, SweepingAParameterThatIsAlsoAMetricName) {
  // strand declares both a parameter span_m and a metric span_m; /sweep holds columns and metrics side by side.
  Experiment e;
  std::vector<Point> pts;
  writeRun("kind = \"strand\"\n[sweep]\nspan_m = [0.1, 0.15]\n", e, pts);
  const runner::StoredRun back = runner::readIndex(dir());
  EXPECT_EQ(std::get<double>(back.table.rows[1].columns.at("span_m")), 0.15);
}

TEST(RunnerKinds, NoKindDeclaresAMetricWithAParameterOrIndexName) {
  // index.h5 /sweep is one namespace: point_index, label, status, message, the swept parameters and the metrics.
  const std::set<std::string> reserved = {"point_index", "label", "status", "message"};
  std::vector<std::string> clashes;
  for (const auto& kind : registry().all()) {
    std::set<std::string> params;
    for (const auto& p : kind->params()) {
      params.insert(p.name);
      if (reserved.count(p.name)) clashes.push_back(kind->name() + ": parameter " + p.name);
    }
    for (const auto& m : kind->metrics())
      if (params.count(m.name) || reserved.count(m.name)) clashes.push_back(kind->name() + ": metric " + m.name);
  }
  std::string list;
  for (const auto& c : clashes) list += " " + c + ";";
  EXPECT_TRUE(clashes.empty()) << "/sweep names clash (a sweep over them cannot write its index):" << list;
}

// Fields on a 3D grid: (frames, nz, ny, nx) datasets with the grid's spacing and origin in z too, and
// a sidecar of 3D co-rectilinear meshes; a 2D result keeps its (frames, ny, nx) layout without z
// attributes; a field whose size is not its grid's is refused before anything reads past it.
TEST_F(RunnerStore, VolumeFieldsAreFramesByZByYByX) {
  const Experiment e = runner::loadExperimentText("kind = \"oscillator\"\n", "v.toml", {}, registry());
  const kinds::Kind& kind = *registry().find("oscillator");
  const auto pts = runner::expandPoints(e, kind);
  PointOutcome o = outcome(kind, 0);
  kinds::FieldFrames& f = o.result.fields;
  f.time_s = {0.0, 0.5};
  f.nx = 4, f.ny = 3, f.nz = 2;
  f.dx_m = f.dy_m = f.dz_m = 0.25;
  f.origin_z_m = -1.0;
  f.fields["q"].unit = "1/s^2";
  for (int v = 0; v < 2 * 2 * 3 * 4; ++v) f.fields["q"].data.push_back(v);
  runner::writePointFile(dir(), e, kind, pts[0], o, provenance());
  {
    const io::File file = io::File::openReadOnly(dir() + "/point_000000.h5");
    const io::Group fields = file.root().openGroup("fields");
    EXPECT_EQ(fields.openDataset("q").shape(), (std::vector<hsize_t>{2, 2, 3, 4}));
    EXPECT_EQ(io::readArrayDouble(fields, "q")[23], 23.0);
    EXPECT_EQ(io::getAttrDouble(fields, "dz_m"), 0.25);
    EXPECT_EQ(io::getAttrDouble(fields, "origin_z_m"), -1.0);
  }
  std::ifstream sidecar(dir() + "/point_000000.xdmf");
  const std::string xdmf((std::istreambuf_iterator<char>(sidecar)), std::istreambuf_iterator<char>());
  EXPECT_NE(xdmf.find("TopologyType=\"3DCoRectMesh\" Dimensions=\"3 4 5\""), std::string::npos) << xdmf;

  f.nz = 0;
  f.fields["q"].data.resize(2 * 3 * 4);
  runner::writePointFile(dir(), e, kind, pts[0], o, provenance());
  {
    const io::File file = io::File::openReadOnly(dir() + "/point_000000.h5");
    const io::Group fields = file.root().openGroup("fields");
    EXPECT_EQ(fields.openDataset("q").shape(), (std::vector<hsize_t>{2, 3, 4}));
    EXPECT_FALSE(io::hasAttr(fields, "dz_m"));
  }
  f.fields["q"].data.pop_back();
  EXPECT_THROW(runner::writePointFile(dir(), e, kind, pts[0], o, provenance()), std::runtime_error);
}

TEST_F(RunnerStore, ReadIndexWithoutAnIndexNamesTheFolder) {
  try {
    runner::readIndex(dir());
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir() + "/index.h5: no index"), std::string::npos) << e.what();
  }
}

}  // namespace
