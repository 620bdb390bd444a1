// The render hook (kinds/render_hook.hpp, kinds/jellyfish_render.cpp): which kinds' runs render, and
// the jellyfish's hook drawing a recorded swim read through a RecordedRun exactly as the renderer
// draws the same frames, refusing a recording without markers and settings out of range.
#include <gtest/gtest.h>

#include <algorithm>

#include <map>
#include <stdexcept>

#include "kinds/jellyfish_render_params.hpp"
#include "kinds/kind.hpp"
#include "kinds/render_hook.hpp"
#include "render_test_slice.hpp"

namespace creaturelab::kinds {
namespace {

// A recording held in memory, as the runner would read it from a point file.
struct MemoryRun : RecordedRun {
  std::map<std::string, std::vector<std::size_t>> shapes;
  std::map<std::string, std::vector<double>> real_data;
  std::map<std::string, std::vector<std::int64_t>> integer_data;
  std::map<std::string, double> attributes;

  bool has(const std::string& d) const override { return shapes.count(d) > 0; }
  std::vector<std::size_t> shape(const std::string& d) const override { return shapes.at(d); }
  std::vector<double> reals(const std::string& d) const override { return real_data.at(d); }
  std::vector<std::int64_t> integers(const std::string& d) const override { return integer_data.at(d); }
  std::optional<double> attribute(const std::string& name) const override {
    const auto it = attributes.find(name);
    return it == attributes.end() ? std::nullopt : std::optional<double>(it->second);
  }
};

// Two frames of the test bell (the second contracted), as a jellyfish run records them.
MemoryRun recordedSwim(const render::test::TestSlice& open, const render::test::TestSlice& closed) {
  MemoryRun run;
  const int markers = open.markers(), bell = open.topology.bell_markers;
  run.shapes["lagrangian/markers_m"] = {2, std::size_t(markers), 2};
  auto& xy = run.real_data["lagrangian/markers_m"];
  xy = open.xy;
  xy.insert(xy.end(), closed.xy.begin(), closed.xy.end());
  run.shapes["lagrangian/time_s"] = {2};
  run.real_data["lagrangian/time_s"] = {0.0, 0.1};
  run.shapes["topology/bell_markers"] = {1};
  run.integer_data["topology/bell_markers"] = {bell};
  run.shapes["topology/springs"] = {std::size_t(2 * (bell - 1))};
  auto& springs = run.integer_data["topology/springs"];
  for (int k = 0; k + 1 < bell; ++k) springs.insert(springs.end(), {k, k + 1});
  run.attributes["bell_thickness_m"] = 0.003;
  return run;
}

Params defaults(const RenderHook& hook) {
  Params p;
  for (const auto& spec : hook.settings()) p[spec.name] = spec.default_value;
  p["rings"] = std::int64_t(12);
  p["segments"] = std::int64_t(16);
  return p;
}

TEST(RenderHook, TheJellyfishsAndTheFishsRunsRender) {
  const Registry registry = defaultRegistry();
  std::vector<std::string> rendering;
  for (const auto& kind : registry.all())
    if (kind->renderHook()) rendering.push_back(kind->name());
  std::sort(rendering.begin(), rendering.end());
  EXPECT_EQ(rendering, (std::vector<std::string>{"fish", "jellyfish"}));
  EXPECT_EQ(registry.find("jellyfish")->renderHook()->name(), "jellyfish_render");
  EXPECT_EQ(registry.find("fish")->renderHook()->name(), "fish_render");
}

TEST(RenderHook, JellyfishDrawsTheRecordedFramesAsItsRenderer) {
  const auto open = render::test::testSlice(32, 0), closed = render::test::testSlice(32, 0, 0.016, 0.024, 0.3);
  const MemoryRun run = recordedSwim(open, closed);
  const RenderHook& hook = *defaultRegistry().find("jellyfish")->renderHook();
  const Params settings = defaults(hook);
  auto drawn = hook.open(run, settings);
  ASSERT_EQ(drawn->frames(), 2);
  EXPECT_EQ(drawn->timeS(1), 0.1);
  EXPECT_EQ(drawn->check(1), "");
  EXPECT_EQ(std::get<double>(drawn->settings().at("thickness_m")), 0.003);  // "auto": the run's bell
  render::JellyfishRenderer direct(renderParams(settings, 0.003), open.topology, open.markers());
  const render::TriangleMesh& want = direct.render(closed.frame(0.1));
  const render::TriangleMesh& got = drawn->render(1);
  ASSERT_EQ(got.positions.size(), want.positions.size());
  for (std::size_t v = 0; v < want.positions.size(); ++v) {
    EXPECT_EQ(got.positions[v].x, want.positions[v].x);
    EXPECT_EQ(got.positions[v].y, want.positions[v].y);
    EXPECT_EQ(got.positions[v].z, want.positions[v].z);
  }
  EXPECT_EQ(got.triangles, drawn->layout().triangles);
}

TEST(RenderHook, JellyfishRefusesARecordingWithoutMarkersAndSettingsOutOfRange) {
  const RenderHook& hook = *defaultRegistry().find("jellyfish")->renderHook();
  try {
    hook.open(MemoryRun{}, defaults(hook));
    FAIL() << "a recording without markers was drawn";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/lagrangian/markers_m"), std::string::npos) << e.what();
  }
  const auto slice = render::test::testSlice(32, 0);
  Params bad = defaults(hook);
  bad["rings"] = std::int64_t(2);  // below the renderer's 3
  try {
    hook.open(recordedSwim(slice, slice), bad);
    FAIL() << "rings = 2 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("render settings"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace creaturelab::kinds
