#pragma once
// `creaturelab render` through the kind (Kind::renderHook()): a kind whose recorded runs can be drawn
// in 3-D says how. The runner opens the point file, answers the hook's reads (RecordedRun) and
// writes every file (render.h5, .glb, OBJ, POV-Ray scenes and their PNGs); the hook turns what was
// read into meshes and scene text, and does no I/O.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kinds/params.hpp"
#include "render/mesh_export.hpp"
#include "render/pov_scene.hpp"
#include "render/triangle_mesh.hpp"

namespace creaturelab::kinds {

// A recorded run as a render hook reads it: datasets by path in the point file (e.g.
// "lagrangian/markers_m"), attributes of its root by name. The runner throws for a dataset that
// is not there; has() asks first.
class RecordedRun {
 public:
  virtual ~RecordedRun() = default;
  virtual bool has(const std::string& dataset) const = 0;
  virtual std::vector<std::size_t> shape(const std::string& dataset) const = 0;
  virtual std::vector<double> reals(const std::string& dataset) const = 0;  // flattened, row-major
  virtual std::vector<std::int64_t> integers(const std::string& dataset) const = 0;
  virtual std::optional<double> attribute(const std::string& name) const = 0;  // a number, if present
};

// A recorded run made ready to draw with resolved settings. Every frame has the same triangles.
class RunRender {
 public:
  virtual ~RunRender() = default;
  virtual int frames() const = 0;
  virtual double timeS(int frame) const = 0;
  // "" when the frame can be drawn, else why not (nothing is drawn).
  virtual std::string check(int frame) const = 0;
  // The frame's mesh; throws for a frame check() refuses. Valid until the next call.
  virtual const render::TriangleMesh& render(int frame) = 0;
  // The mesh's triangles and parts, fixed by the settings (positions: the last frame drawn).
  virtual const render::TriangleMesh& layout() const = 0;
  // The settings as the render used them (a value the run decides, like "auto", resolved).
  virtual const Params& settings() const = 0;
  // The paper's figures as POV-Ray scenes, and the frames they draw (checked before drawing).
  virtual std::vector<int> figureFrames() const = 0;
  virtual std::vector<render::PovFigure> figures() const = 0;
};

class RenderHook {
 public:
  virtual ~RenderHook() = default;
  virtual std::string name() const = 0;         // the render file's kind, e.g. "jellyfish_render"
  virtual std::string title() const = 0;        // the render file's title
  virtual std::string meshName() const = 0;     // the .glb's name and its mesh's, the OBJ's object
  virtual render::GltfLook look() const = 0;    // the .glb's material
  virtual std::string partMeaning() const = 0;  // what each value of TriangleMesh::parts means
  // The render.* settings: name, unit, default, range, doc (`creaturelab list render`).
  virtual const std::vector<ParamSpec>& settings() const = 0;
  // Throws std::invalid_argument for a recording the hook cannot draw or settings it refuses.
  virtual std::unique_ptr<RunRender> open(const RecordedRun& run, const Params& settings) const = 0;
};

}  // namespace creaturelab::kinds
