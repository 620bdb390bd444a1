#pragma once
// Files a user opens in standard tools, as bytes (the caller writes them; render/ does no I/O), for
// every creature that renders (the jellyfish's recorded swims, the fish's skin):
// - glTF 2.0 binary (.glb, Khronos glTF 2.0 spec): one mesh whose morph targets are the frames,
//   animated by a "weights" channel at the frames' times (LINEAR between neighbouring frames), so
//   Blender (File > Import > glTF) or any glTF viewer plays the swim. Metres, y up, like glTF.
//   Written with tinygltf (Debian's libtinygltf-dev).
// - Wavefront OBJ: one frame's vertices, normals and triangles.
// POV-Ray scenes are in render/pov_scene.hpp.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "render/triangle_mesh.hpp"

namespace creaturelab::render {

/// How a creature looks in its .glb: the material (glTF 2.0 §3.9 metallic-roughness) and the
/// generator the file names.
struct GltfLook {
  std::string generator = "creaturelab";
  std::string material = "surface";
  std::array<double, 4> base_colour = {0.8, 0.8, 0.8, 1.0};  // linear RGBA
  double metallic = 0.0, roughness = 0.5;
  bool double_sided = false;  // true for open sheets (fins) seen from both sides
};

/// Collects frames of one mesh layout (same triangles, same vertex count) for a .glb.
class GltfAnimation {
 public:
  explicit GltfAnimation(GltfLook look = {}) : look_(std::move(look)) {}
  /// Adds a frame at time t (seconds; frames in increasing time). Throws std::invalid_argument for a
  /// mesh whose triangles differ from the first frame's in count, or a time not after the last.
  void addFrame(double time_s, const TriangleMesh& mesh);
  int frames() const { return int(times_.size()); }
  /// The .glb: frame 0 is the base mesh; frame k > 0 is morph target k − 1 (its displacement from
  /// frame 0, glTF 2.0 §3.7.2.2), and the animation's weights at time t_k − t_0 are 1 on that target
  /// and 0 elsewhere (all 0 at frame 0). Throws std::invalid_argument without frames.
  std::vector<std::uint8_t> glb(const std::string& name) const;

 private:
  GltfLook look_;
  std::vector<double> times_;
  std::vector<std::uint32_t> indices_;
  std::vector<std::vector<float>> positions_, normals_;  // per frame, vertices × 3
};

/// One frame as Wavefront OBJ text: the comment, "o object", v, vn, and f a//a b//b c//c (1-based).
std::string objText(const TriangleMesh& mesh, const std::string& object, const std::string& comment);

}  // namespace creaturelab::render
