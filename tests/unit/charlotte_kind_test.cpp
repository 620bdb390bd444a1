// The `charlotte` kind end to end on a small web: deterministic results (the third test),
// clear errors for bad targets, and the runner writing the renders beside the point file without
// their entering the HDF5 or its digest.
#include "scratch_dir_test.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <fstream>
#include <iterator>

#include "io/hdf5_digest.hpp"
#include "kinds/kind.hpp"
#include "runner/store.hpp"
#include "test_registry.hpp"

namespace {

using namespace creaturelab;
namespace fs = std::filesystem;

using creaturelab::testing::registry;

const kinds::Kind& charlotteKind() { return *registry().find("charlotte"); }

kinds::Params smallParams(kinds::Params overrides = {}) {
  kinds::Params p = {{"frame_scale", 0.35},        {"target_width_m", 0.3},
                     {"target_max_height_m", 0.2}, {"resettle_time_s", 0.04},
                     {"canvas_px", std::int64_t(240)},
                     {"emphasis", std::string("random_attachments")}};
  for (auto& [k, v] : overrides) p[k] = v;
  return kinds::withDefaults(charlotteKind(), p);
}

template <class T>
bool sameMap(const std::map<std::string, T>& a, const std::map<std::string, T>& b, bool (*eq)(const T&, const T&)) {
  if (a.size() != b.size()) return false;
  for (const auto& [k, v] : a)
    if (!b.count(k) || !eq(v, b.at(k))) return false;
  return true;
}

bool sameSeries(const kinds::Series& a, const kinds::Series& b) { return a.values == b.values && a.unit == b.unit; }
bool sameMetric(const kinds::Metric& a, const kinds::Metric& b) {
  return (a.value == b.value || (std::isnan(a.value) && std::isnan(b.value))) && a.unit == b.unit;
}
bool sameTracks(const kinds::Tracks& a, const kinds::Tracks& b) { return a.time_s == b.time_s && a.data == b.data; }
bool sameInts(const std::vector<std::int64_t>& a, const std::vector<std::int64_t>& b) { return a == b; }
bool sameBytes(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) { return a == b; }

}  // namespace

// The third test: runs are deterministic (bit for bit; the stored digest follows).
TEST(CharlotteKind, RunsAreDeterministic) {
  const kinds::Params p = smallParams();
  ASSERT_EQ(charlotteKind().validate(p), "");
  const kinds::Result a = charlotteKind().run(p), b = charlotteKind().run(p);
  EXPECT_TRUE(sameMap(a.timeseries, b.timeseries, sameSeries));
  EXPECT_TRUE(sameMap(a.metrics, b.metrics, sameMetric));
  EXPECT_TRUE(sameMap(a.lagrangian, b.lagrangian, sameTracks));
  EXPECT_TRUE(sameMap(a.topology, b.topology, sameInts));
  EXPECT_TRUE(sameMap(a.artifacts, b.artifacts, sameBytes));
  EXPECT_GT(a.metrics.at("segments_removed").value, 0);
  EXPECT_GT(a.metrics.at("attachments").value, 0);
  EXPECT_EQ(a.topology.at("removed_springs").size(), std::size_t(a.metrics.at("springs_removed").value));
  for (const char* name : {"web.png", "overlay.png", "cut.png", "result.png"}) EXPECT_TRUE(a.artifacts.count(name)) << name;
  // Every declared metric is returned, and nothing else.
  std::set<std::string> declared;
  for (const auto& m : charlotteKind().metrics()) declared.insert(m.name);
  for (const auto& [name, m] : a.metrics) EXPECT_TRUE(declared.count(name)) << name;
  EXPECT_EQ(a.metrics.size(), declared.size());
}

TEST(CharlotteKind, BadTargetsAreClearErrorsBeforeAnyWork) {
  EXPECT_EQ(charlotteKind().validate(smallParams({{"text", std::string("PIG!\xee\x80\x80")}})),
            "text \"PIG!\xee\x80\x80\": the font \"DejaVu Sans Bold\" has no glyph for '\xee\x80\x80' (character 5)");
  EXPECT_NE(charlotteKind().validate(smallParams({{"font", std::string("Nonexistent Grotesk")}})).find("is not installed"),
            std::string::npos);
  EXPECT_EQ(charlotteKind().validate(smallParams({{"target", std::string("image")},
                                              {"image_file", std::string("/nonexistent/emblem.pbm")}})),
            "image_file: /nonexistent/emblem.pbm: cannot be read (No such file or directory)");
  EXPECT_NE(charlotteKind().validate(smallParams({{"target", std::string("image")}})).find("no image file given"),
            std::string::npos);
  EXPECT_NE(charlotteKind().validate(smallParams({{"dilation_px", std::int64_t(4)}})).find("dilation_px is 4"),
            std::string::npos);
}

class CharlotteStore : public creaturelab::testing::ScratchDirTest {
 protected:
  CharlotteStore() : ScratchDirTest("creaturelab_charlotte_store") {}
};

// Result::artifacts land beside the point file as point_NNNNNN_<name>; the HDF5 (and its digest)
// does not see them.
TEST_F(CharlotteStore, ArtifactsAreWrittenBesideThePointAndStayOutOfTheDigest) {
  const runner::Experiment e = runner::loadExperimentText("kind = \"oscillator\"\n", "a.toml", {}, registry());
  const kinds::Kind& kind = *registry().find("oscillator");
  const auto points = runner::expandPoints(e, kind);
  runner::PointOutcome plain;
  plain.result.timeseries["time_s"] = {{0.0, 1.0}, "s"};
  runner::PointOutcome with = plain;
  with.result.artifacts["result.png"] = {1, 2, 3, 0, 255};
  with.result.artifacts["web.png"] = {};
  fs::create_directories(dir_ / "a");
  fs::create_directories(dir_ / "b");
  runner::writePointFile((dir_ / "a").string(), e, kind, points[0], plain, {});
  runner::writePointFile((dir_ / "b").string(), e, kind, points[0], with, {});
  std::ifstream in(dir_ / "b" / "point_000000_result.png", std::ios::binary);
  EXPECT_EQ(std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {}), (std::vector<std::uint8_t>{1, 2, 3, 0, 255}));
  EXPECT_TRUE(fs::exists(dir_ / "b" / "point_000000_web.png"));
  EXPECT_EQ(fs::file_size(dir_ / "b" / "point_000000_web.png"), 0u);
  for (const auto& entry : fs::directory_iterator(dir_ / "b")) EXPECT_NE(entry.path().extension(), ".tmp");
  const auto skip = runner::provenanceAttributeNames();
  EXPECT_EQ(io::contentDigest(dir_ / "a" / "point_000000.h5", skip), io::contentDigest(dir_ / "b" / "point_000000.h5", skip));
  // A name that is not a plain file name is refused.
  runner::PointOutcome bad = plain;
  bad.result.artifacts["../escape.png"] = {1};
  EXPECT_THROW(runner::writePointFile((dir_ / "a").string(), e, kind, points[0], bad, {}), std::runtime_error);
}
