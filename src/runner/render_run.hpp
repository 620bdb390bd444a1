#pragma once
// `creaturelab render`: a recorded jellyfish swim (a point file's /lagrangian/markers_m, /topology
// and /lagrangian/muscle_activation) becomes the 3-D jellyfish of Rudolf & Mould 2009 §3.4-3.5
// (render/), written as
//   OUT/render.h5 + render.xdmf   /render/... per frame (ParaView opens the .xdmf)
//   OUT/jellyfish.glb             glTF 2.0, one mesh with a morph target per frame, animated
//   OUT/obj/frame_NNNNNN.obj      a Wavefront OBJ per frame
//   OUT/figures/                  with figures: Figs. 7, 9, 10 as POV-Ray scenes and PNGs (povray, headless)
// Everything is made in OUT.tmp and renamed to OUT when whole: a failure leaves nothing behind.
//
// Rendering is a command, not an experiment kind: a kind runs a solver from parameters alone and
// does no I/O, while this reads a run that exists. The render settings have a kind-like schema
// (kinds/render_params.hpp: units, ranges, docs, `creaturelab list render`).
#include <string>
#include <vector>

namespace creaturelab::runner {

struct RenderRunOptions {
  std::string source;                  // a point file (.h5) or a run folder
  int point = 0;                       // the point, when source is a run folder
  std::string frames;                  // "A:B" or "A:B:STEP" (B exclusive, either may be empty); "" = all
  std::string out_dir;                 // default: <the point file's folder>/render_point_NNNNNN
  std::vector<std::string> overrides;  // render settings as key=value (kinds/render_params.hpp)
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

/// Throws ExperimentError (exit 2) for bad input, before anything is written: a run of another
/// kind, a point file without /lagrangian, frames outside the run, a degenerate outline in any
/// selected frame, unknown or out-of-range settings, an OUT that exists without force, figures
/// without povray. A later failure (disk full, povray failing) removes OUT.tmp and throws
/// std::runtime_error.
RenderReport renderRun(const RenderRunOptions& options);

}  // namespace creaturelab::runner
