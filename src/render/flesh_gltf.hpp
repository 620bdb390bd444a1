#pragma once
// The flesh's skin (Lentine et al. 2010 §7, Figs. 7, 11, 13: the creatures "wrapped in flesh") as an
// animated .glb: one mesh, the frames as morph targets (render/mesh_export.hpp's GltfAnimation).
// Takes plain vertex arrays in the simulation's world (MuJoCo's: z up) and turns them into glTF's
// y-up frame, (x, y, z) -> (x, z, -y), a rotation, so the skin keeps its handedness. Bytes only.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "render/mesh_export.hpp"

namespace creaturelab::render {

class SkinAnimation {
 public:
  // Triangles counter-clockwise seen from outside, indices into each frame's vertices.
  explicit SkinAnimation(std::vector<std::array<std::int32_t, 3>> triangles, GltfLook look = skinLook());
  // Adds a frame at time t (s, increasing): xyz_m holds 3 coordinates (m, z up) per vertex. Throws
  // std::invalid_argument for a vertex count that differs from the first frame's, an index out of range,
  // or a time not after the last.
  void addFrame(double time_s, const std::vector<double>& xyz_m);
  int frames() const { return animation_.frames(); }
  // The .glb (GltfAnimation::glb). Throws std::invalid_argument without frames.
  std::vector<std::uint8_t> glb(const std::string& name) const { return animation_.glb(name); }

  // A flesh colour, matte.
  static GltfLook skinLook();

 private:
  std::vector<std::array<std::int32_t, 3>> triangles_;
  GltfAnimation animation_;
  std::size_t vertices_ = 0;
};

}  // namespace creaturelab::render
