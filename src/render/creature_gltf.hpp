#pragma once
// A 3-D creature's rigid geoms as an animated .glb (Khronos glTF 2.0: §3.5 nodes, §3.11 animations),
// from what a run records (control/fluid_run3.hpp): each geom's MuJoCo type and size, and its world
// pose per frame. One node per geom carries its mesh (render/geom_mesh.hpp, in the geom's frame) and
// is animated by translation and rotation channels (LINEAR / quaternion slerp between frames), under
// a root node that turns MuJoCo's z up into glTF's y up, (x, y, z) -> (x, z, -y). Bytes only.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "render/mesh_export.hpp"

namespace creaturelab::render {

struct CreatureGeom {
  int mujoco_type = 6;                // MuJoCo's geom type (render/geom_mesh.hpp's GeomShape)
  std::array<double, 3> size_m{};     // MuJoCo's geom_size
};

class CreatureAnimation {
 public:
  // Throws std::invalid_argument for no geoms, or a geom geomMesh cannot draw (its message).
  explicit CreatureAnimation(std::vector<CreatureGeom> geoms, GltfLook look = boneLook());
  // Adds a frame at time t (s, increasing): per geom its world position (3 values, m) and rotation
  // (9 values, row-major, columns the geom's axes: MuJoCo's geom_xmat). Throws std::invalid_argument
  // for sizes that do not match the geoms, a time not after the last, or a rotation that is not one
  // (|R^T R - I| > 1e-6).
  void addFrame(double time_s, const std::vector<double>& position_m, const std::vector<double>& rotation);
  int frames() const { return int(times_.size()); }
  int geoms() const { return int(geoms_.size()); }
  // The .glb; throws std::invalid_argument without frames.
  std::vector<std::uint8_t> glb(const std::string& name) const;

  // A bone grey, matte.
  static GltfLook boneLook();

 private:
  std::vector<CreatureGeom> geoms_;
  GltfLook look_;
  std::vector<double> times_;
  std::vector<float> translations_, rotations_;  // per frame and geom: x, y, z; x, y, z, w
};

// The unit quaternion (w, x, y, z) of a rotation matrix (row-major); Shepperd's method, picking the
// largest of w, x, y, z to divide by.
std::array<double, 4> quaternionOf(const double* rotation);

}  // namespace creaturelab::render
