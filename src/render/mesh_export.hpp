#pragma once
// Files a user opens in standard tools, as bytes (the caller writes them; render/ does no I/O):
// - glTF 2.0 binary (.glb, Khronos glTF 2.0 spec): one mesh whose morph targets are the frames,
//   animated by a "weights" channel at the frames' times (LINEAR between neighbouring frames), so
//   Blender (File > Import > glTF) or any glTF viewer plays the swim. Metres, y up, like glTF.
//   Written with tinygltf (Debian's libtinygltf-dev).
// - Wavefront OBJ: one frame's vertices, normals and triangles.
#include <cstdint>
#include <string>
#include <vector>

#include "render/triangle_mesh.hpp"

namespace creaturelab::render {

/// Collects frames of one mesh layout (same triangles, same vertex count) for a .glb.
class GltfAnimation {
 public:
  /// Adds a frame at time t (seconds; frames in increasing time). Throws std::invalid_argument for a
  /// mesh whose triangles differ from the first frame's in count, or a time not after the last.
  void addFrame(double time_s, const TriangleMesh& mesh);
  int frames() const { return int(times_.size()); }
  /// The .glb: frame 0 is the base mesh; with more than one frame, frame k is morph target k and
  /// the animation's weights are 1 on target k at time t_k − t_0 (0 elsewhere).
  std::vector<std::uint8_t> glb(const std::string& name) const;

 private:
  std::vector<double> times_;
  std::vector<std::uint32_t> indices_;
  std::vector<std::vector<float>> positions_, normals_;  // per frame, vertices × 3
};

/// One frame as Wavefront OBJ text (1-based indices, "f a//a b//b c//c").
std::string objText(const TriangleMesh& mesh, const std::string& comment);

}  // namespace creaturelab::render
