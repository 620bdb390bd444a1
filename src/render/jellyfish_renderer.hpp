#pragma once
// The jellyfish's render pipeline (Rudolf & Mould 2009 §3.4-3.5): a recorded 2-D slice becomes a
// closed, oriented 3-D triangle mesh with normals. Per frame, in order:
//   1. slice      the 2-D render model: exumbrella by thickness, cubic splines, resampling (§3.4)
//   2. discs      each opposing pair revolved into a ring; rings stitched; tentacles (§3.5, Fig. 7)
//   3. variation  structural, compression ridges, Perlin noise along the normals (§3.5, Eq. 2)
//   4. normals    area-weighted vertex normals of the final surface
// Deterministic (the same inputs and seed give bitwise the same mesh), no I/O, nothing printed.
// The mesh's triangles are fixed by the parameters; only positions and normals change.
#include <stdexcept>

#include "render/disc_extrapolation.hpp"
#include "render/slice_model2.hpp"
#include "render/variation.hpp"

namespace creaturelab::render {

/// A frame whose outline cannot be rendered (SliceModel2::check's message).
struct OutlineError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class JellyfishRenderer {
 public:
  /// `markers`: markers per frame. Throws std::invalid_argument for unusable parameters or topology.
  JellyfishRenderer(const RenderParams& params, SliceTopology topology, int markers);

  /// "" when the frame can be rendered, else why not (no rendering is done).
  std::string check(const SliceFrame& frame) const { return slice_model_.check(frame); }

  /// Renders one frame; throws OutlineError for a frame check() refuses. The reference stays
  /// valid until the next call.
  const TriangleMesh& render(const SliceFrame& frame);

  const TriangleMesh& mesh() const { return mesh_; }
  const Slice2& slice() const { return slice_; }  // the last frame's 2-D model
  const MeshLayout& layout() const { return discs_.layout(); }
  const RenderParams& params() const { return params_; }

 private:
  RenderParams params_;
  SliceModel2 slice_model_;
  DiscExtrapolation discs_;
  Variation variation_;
  Slice2 slice_;
  Centreline line_;
  TriangleMesh mesh_;
};

}  // namespace creaturelab::render
