// The jellyfish kind's render hook: a recorded swim (/lagrangian/markers_m, /topology and
// /lagrangian/muscle_activation) becomes the 3-D jellyfish of Rudolf & Mould 2009 §3.4-3.5
// (render/jellyfish_renderer.hpp) and its Figs. 7, 9, 10 (render/jellyfish_figures.hpp).
#include <stdexcept>

#include "kinds/jellyfish.hpp"
#include "kinds/render_hook.hpp"
#include "kinds/jellyfish_render_params.hpp"
#include "render/jellyfish_figures.hpp"
#include "render/jellyfish_renderer.hpp"

namespace creaturelab::kinds {
namespace {

using std::invalid_argument;

render::SliceRecording readSwim(const RecordedRun& run) {
  render::SliceRecording swim;
  if (!run.has("lagrangian/markers_m") || !run.has("lagrangian/time_s"))
    throw invalid_argument("has no /lagrangian/markers_m and /lagrangian/time_s, the recorded bell to render");
  const auto shape = run.shape("lagrangian/markers_m");
  if (shape.size() != 3 || shape[2] != 2 || shape[0] == 0)
    throw invalid_argument("/lagrangian/markers_m must be (frames, markers, 2) with at least one frame");
  swim.markers = int(shape[1]);
  swim.markers_xy = run.reals("lagrangian/markers_m");
  swim.time_s = run.reals("lagrangian/time_s");
  if (swim.time_s.size() != shape[0])
    throw invalid_argument("/lagrangian/time_s has " + std::to_string(swim.time_s.size()) + " times for " +
                           std::to_string(shape[0]) + " frames of markers");
  for (const char* name : {"topology/bell_markers", "topology/springs"})
    if (!run.has(name)) throw invalid_argument("has no /" + std::string(name));
  const auto bell = run.integers("topology/bell_markers");
  const auto springs = run.integers("topology/springs");
  const auto muscles = run.has("topology/muscles") ? run.integers("topology/muscles") : std::vector<std::int64_t>{};
  swim.topology = render::sliceTopology(bell.empty() ? 0 : int(bell[0]), springs, muscles, swim.markers);
  swim.muscles = int(swim.topology.muscle_markers.size());
  // The muscle state the ridges follow; runs recorded before it was stored have none (no ridges).
  if (run.has("lagrangian/muscle_activation")) {
    const auto a = run.shape("lagrangian/muscle_activation");
    if (a.size() != 3 || a[0] != shape[0] || int(a[1]) != swim.muscles || a[2] != 1)
      throw invalid_argument("/lagrangian/muscle_activation must be (frames, muscles, 1) like /topology/muscles");
    swim.activation = run.reals("lagrangian/muscle_activation");
  }
  if (std::string e = swim.topology.validate(swim.markers); !e.empty()) throw invalid_argument(e);
  swim.contraction_hz = run.attribute("contraction_hz").value_or(0.0);
  return swim;
}

class JellyfishRunRender : public RunRender {
 public:
  JellyfishRunRender(render::SliceRecording swim, Params settings, const render::RenderParams& params)
      : swim_(std::move(swim)), settings_(std::move(settings)), renderer_(params, swim_.topology, swim_.markers) {}

  int frames() const override { return swim_.frames(); }
  double timeS(int frame) const override { return swim_.time_s[frame]; }
  std::string check(int frame) const override { return renderer_.check(swim_.frame(frame)); }
  const render::TriangleMesh& render(int frame) override { return renderer_.render(swim_.frame(frame)); }
  const render::TriangleMesh& layout() const override { return renderer_.mesh(); }
  const Params& settings() const override { return settings_; }
  std::vector<int> figureFrames() const override { return render::jellyfishFigureFrames(swim_); }
  std::vector<render::PovFigure> figures() const override {
    return render::jellyfishFigures(swim_, renderer_.params());
  }

 private:
  render::SliceRecording swim_;
  Params settings_;
  render::JellyfishRenderer renderer_;
};

class JellyfishRenderHook : public RenderHook {
 public:
  std::string name() const override { return "jellyfish_render"; }
  std::string title() const override { return "3-D jellyfish from a recorded swim (Rudolf & Mould 2009 §3.4-3.5)"; }
  std::string meshName() const override { return "jellyfish"; }
  render::GltfLook look() const override {
    return {.generator = "creaturelab render (Rudolf & Mould 2009 jellyfish)", .material = "mesoglea",
            .base_colour = {0.85, 0.88, 0.95, 1.0}, .metallic = 0.0, .roughness = 0.55};
  }
  std::string partMeaning() const override { return "0 exumbrella, 1 subumbrella, 2 tentacle"; }
  const std::vector<ParamSpec>& settings() const override { return renderParamSpecs(); }

  std::unique_ptr<RunRender> open(const RecordedRun& run, const Params& settings) const override {
    render::SliceRecording swim = readSwim(run);
    // thickness_m = "auto": the recorded bell's (the jellyfish kind's default when the run has none).
    const render::RenderParams params = renderParams(settings, run.attribute("bell_thickness_m").value_or(0.004));
    if (std::string e = params.validate(); !e.empty()) throw invalid_argument("render settings: " + e);
    Params resolved = settings;
    resolved["thickness_m"] = params.thickness.apex_m;
    return std::make_unique<JellyfishRunRender>(std::move(swim), std::move(resolved), params);
  }
};

}  // namespace

const RenderHook* JellyfishKind::renderHook() const {
  static const JellyfishRenderHook hook;  // stateless
  return &hook;
}

}  // namespace creaturelab::kinds
