// The fish kind's render hook: a recorded swim (/lagrangian/nodes_m; its first frame is the
// undeformed fish, fish_run.hpp) skinned on every frame with the NURBS surfaces of Tu 1996 ch. 7
// (fish/skin.hpp), drawn through render/'s exporters like the jellyfish; its figures are POV-Ray sea
// scenes of a few frames (render::povSeaScene).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "fish/fish_model.hpp"
#include "kinds/describe.hpp"
#include "kinds/fish.hpp"
#include "kinds/fish_render.hpp"
#include "kinds/render_hook.hpp"
#include "render/pov_scene.hpp"

namespace creaturelab::kinds {

render::TriangleMesh fishRenderMesh(const fish::SkinMesh& skin) {
  render::TriangleMesh out;
  for (const auto& p : skin.positions) out.positions.push_back({p.x(), p.z(), -p.y()});
  for (const auto& n : skin.normals) out.normals.push_back({n.x(), n.z(), -n.y()});
  for (const auto& t : skin.triangles) out.triangles.push_back({t[0], t[1], t[2]});
  const std::size_t body = 2 * std::size_t(skin.samples_around) * std::size_t(skin.samples_along);
  for (std::size_t v = 0; v < skin.positions.size(); ++v) out.parts.push_back(render::Part(v < body ? 0 : 1));
  return out;
}

render::GltfLook fishSkinLook() {
  render::GltfLook look;
  look.generator = "creaturelab fish (Tu 1996 NURBS skin)";
  look.material = "fish skin";
  look.base_colour = {0.35, 0.55, 0.7, 1.0};
  look.metallic = 0.1;
  look.roughness = 0.5;
  look.double_sided = true;  // the fins are sheets
  return look;
}

namespace {

using std::invalid_argument;

// The render settings: the skin's own (the fish kind's defaults) and the mesh's sampling.
struct FishRenderSettings {
  fish::SkinParams skin;
  std::int64_t skin_samples_around = 32;
  std::int64_t skin_samples_along = 64;
  std::int64_t pov_frames = 4;

  template <class V>
  void describe(V& v) {
    skin.describe(v);
    v.integer("skin_samples_around", skin_samples_around, 2, 1024, "mesh samples around each half body");
    v.integer("skin_samples_along", skin_samples_along, 2, 4096, "mesh samples along the body");
    v.integer("pov_frames", pov_frames, 1, 100, "--figures: POV-Ray sea scenes, evenly spaced over the recorded frames");
  }
};

// The recorded nodes, frame by frame, and the fish they move: the kind's topology with the first
// frame as its undeformed shape.
struct FishSwim {
  std::vector<double> time_s;
  std::vector<double> nodes_m;  // frames x kNodes x 3
  fish::FishModel model;
  fish::NodeMatrix frame(int k) const {
    fish::NodeMatrix x;
    for (int i = 0; i < fish::kNodes; ++i)
      for (int d = 0; d < 3; ++d) x(i, d) = nodes_m[(std::size_t(k) * fish::kNodes + i) * 3 + d];
    return x;
  }
};

FishSwim readFishSwim(const RecordedRun& run) {
  if (!run.has("lagrangian/nodes_m") || !run.has("lagrangian/time_s"))
    throw invalid_argument("has no /lagrangian/nodes_m and /lagrangian/time_s, the recorded fish to render "
                           "(task = stable_step records none)");
  const auto shape = run.shape("lagrangian/nodes_m");
  if (shape.size() != 3 || shape[0] == 0 || shape[1] != std::size_t(fish::kNodes) || shape[2] != 3)
    throw invalid_argument("/lagrangian/nodes_m must be (frames, " + std::to_string(fish::kNodes) +
                           ", 3) with at least one frame");
  FishSwim swim;
  swim.time_s = run.reals("lagrangian/time_s");
  if (swim.time_s.size() != shape[0])
    throw invalid_argument("/lagrangian/time_s has " + std::to_string(swim.time_s.size()) + " times for " +
                           std::to_string(shape[0]) + " frames of nodes");
  swim.nodes_m = run.reals("lagrangian/nodes_m");
  for (double v : swim.nodes_m)
    if (!std::isfinite(v)) throw invalid_argument("/lagrangian/nodes_m is not finite (did the fish blow up?)");
  swim.model = fish::buildFish(fish::FishGeometry{}, fish::UnitParams{});  // faces and topology
  swim.model.rest_positions_m = swim.frame(0);
  swim.model.body_length_m = run.attribute("body_length_m").value_or(-swim.model.rest_positions_m.col(0).minCoeff());
  return swim;
}

class FishRunRender : public RunRender {
 public:
  FishRunRender(FishSwim swim, const FishRenderSettings& s, Params settings)
      : swim_(std::move(swim)), settings_(std::move(settings)), skin_(swim_.model, s.skin),
        around_(int(s.skin_samples_around)), along_(int(s.skin_samples_along)), figure_count_(int(s.pov_frames)) {
    draw(0);
  }

  int frames() const override { return int(swim_.time_s.size()); }
  double timeS(int frame) const override { return swim_.time_s[frame]; }
  std::string check(int frame) const override {
    return frame >= 0 && frame < frames() ? "" : "no such frame (" + std::to_string(frames()) + " recorded)";
  }
  const render::TriangleMesh& render(int frame) override { return draw(frame); }
  const render::TriangleMesh& layout() const override { return mesh_; }
  const Params& settings() const override { return settings_; }
  std::vector<int> figureFrames() const override {
    const int n = std::min(figure_count_, frames());
    std::vector<int> out;
    for (int k = 0; k < n; ++k) out.push_back(n > 1 ? int(std::lround(double(k) * (frames() - 1) / (n - 1))) : frames() - 1);
    return out;
  }
  std::vector<render::PovFigure> figures() const override {
    std::vector<render::PovFigure> out;
    int index = 0;
    for (int k : figureFrames()) {
      const render::TriangleMesh& mesh = draw(k);
      render::Vec3 centre;
      const double nv = double(mesh.positions.size());
      for (const auto& p : mesh.positions) centre = {centre.x + p.x / nv, centre.y + p.y / nv, centre.z + p.z / nv};
      char name[32];
      std::snprintf(name, sizeof name, "fish_%03d", index++);
      out.push_back({name, 800, 600,
                     render::povSeaScene(mesh, centre, swim_.model.body_length_m, "t = " + std::to_string(timeS(k)) + " s"),
                     {}});
    }
    return out;
  }

 private:
  const render::TriangleMesh& draw(int frame) const {
    skin_.update(swim_.frame(frame));
    skin_.mesh(around_, along_, skin_mesh_);
    mesh_ = fishRenderMesh(skin_mesh_);
    return mesh_;
  }

  FishSwim swim_;  // before skin_, which keeps a reference to its model
  Params settings_;
  mutable fish::FishSkin skin_;
  mutable fish::SkinMesh skin_mesh_;
  mutable render::TriangleMesh mesh_;
  int around_, along_, figure_count_;
};

class FishRenderHook : public RenderHook {
 public:
  FishRenderHook() : settings_(schemaOf<FishRenderSettings>()) {}
  std::string name() const override { return "fish_render"; }
  std::string title() const override { return "the NURBS-skinned fish from a recorded swim (Tu 1996 ch. 7)"; }
  std::string meshName() const override { return "fish"; }
  render::GltfLook look() const override { return fishSkinLook(); }
  std::string partMeaning() const override { return "0 body, 1 fin"; }
  const std::vector<ParamSpec>& settings() const override { return settings_; }

  std::unique_ptr<RunRender> open(const RecordedRun& run, const Params& settings) const override {
    const FishRenderSettings s = readParams<FishRenderSettings>(settings);
    if (std::string e = s.skin.validate(); !e.empty()) throw invalid_argument("render settings: " + e);
    return std::make_unique<FishRunRender>(readFishSwim(run), s, settings);
  }

 private:
  std::vector<ParamSpec> settings_;
};

}  // namespace

const RenderHook* FishKind::renderHook() const {
  static const FishRenderHook hook;  // stateless after construction
  return &hook;
}

}  // namespace creaturelab::kinds
