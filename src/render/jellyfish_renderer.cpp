#include "render/jellyfish_renderer.hpp"

namespace creaturelab::render {

JellyfishRenderer::JellyfishRenderer(const RenderParams& params, SliceTopology topology, int markers)
    : params_(params),
      slice_model_(params, std::move(topology), markers),
      discs_(params, !slice_model_.topology().left_tentacle.empty()),
      variation_(params, discs_.layout()) {
  discs_.initialise(mesh_);
}

const TriangleMesh& JellyfishRenderer::render(const SliceFrame& frame) {
  if (std::string problem = slice_model_.check(frame); !problem.empty()) throw OutlineError(problem);
  // 1. the 2-D render model
  slice_model_.build(frame, slice_);
  // 2. discs: the umbrella, and each tentacle's centreline (moved by its noise) and tube
  discs_.umbrella(slice_, mesh_);
  for (int k = 0; k < discs_.layout().tentacles; ++k) {
    discs_.centreline(slice_, k, line_);
    variation_.tentacle(k, frame.time_s, line_);
    discs_.tube(line_, k, mesh_);
  }
  // 3. variation along the unvaried surface's normals
  if (variation_.umbrellaVaries()) {
    computeNormals(mesh_);
    variation_.umbrella(slice_, frame.time_s, mesh_);
  }
  // 4. the final normals
  computeNormals(mesh_);
  return mesh_;
}

}  // namespace creaturelab::render
