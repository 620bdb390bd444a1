#pragma once
// `creaturelab render`: a recorded run becomes a 3-D animation through its kind's render hook
// (Kind::renderHook(), kinds/render_hook.hpp; the jellyfish's: Rudolf & Mould 2009 §3.4-3.5),
// written as
//   OUT/render.h5 + render.xdmf   /render/... per frame (ParaView opens the .xdmf)
//   OUT/NAME.glb                  glTF 2.0, one mesh with a morph target per later frame, animated
//   OUT/obj/frame_NNNNNN.obj      a Wavefront OBJ per frame
//   OUT/figures/                  with figures: the paper's figures as POV-Ray scenes and PNGs (povray, headless)
// Everything is made in OUT.tmp and renamed to OUT when whole: a failure leaves nothing behind.
//
// Rendering is a command, not an experiment: it reads a run that exists. The hook reads the point
// file through the runner and does no I/O; its settings have a kind-like schema (units, ranges,
// docs, `creaturelab list render`).
#include <string>
#include <vector>

namespace creaturelab::runner {

struct RenderRunOptions {
  std::string source;                  // a point file (.h5) or a run folder
  int point = 0;                       // the point, when source is a run folder
  std::string frames;                  // "A:B" or "A:B:STEP" (B exclusive, either may be empty); "" = all
  std::string out_dir;                 // default: <the point file's folder>/render_point_NNNNNN
  std::vector<std::string> overrides;  // render settings as key=value (the hook's settings())
  bool force = false;                  // replace an existing OUT
  bool figures = false;                // also Figs. 7, 9, 10 (needs povray)
  bool obj = true, glb = true;
  double figure_scale = 1.0;           // multiplies the figures' pixel sizes
};

struct RenderReport {
  std::string out_dir, point_file;
  int frames = 0, vertices = 0, triangles = 0;
  double render_ms_per_frame = 0;      // CPU time of the mesh alone (slice, discs, variation, normals)
  std::vector<std::string> files;      // written, relative to out_dir
};

/// Throws ExperimentError (exit 2) for bad input, before anything is written: a run of a kind
/// without a render hook, a point file without /lagrangian, frames outside the run, a degenerate outline in any
/// selected frame, unknown or out-of-range settings, an OUT that exists without force, figures
/// without povray. A later failure (disk full, povray failing) removes OUT.tmp and throws
/// std::runtime_error.
RenderReport renderRun(const RenderRunOptions& options);

}  // namespace creaturelab::runner
