#pragma once
// Exporters of the skinned fish: glTF 2.0 binary (.glb) animation, Wavefront OBJ frames and
// POV-Ray scenes. They return bytes or text and write no file (the runner writes artifacts), so
// that the lead can later factor them with the render module's (issue 14).
#include <cstdint>
#include <string>
#include <vector>

#include "fish/skin.hpp"

namespace creaturelab::fish {

// One frame of the skin: its mesh and its time.
struct SkinFrame {
  double time_s = 0;
  SkinMesh mesh;
};

// A .glb with one mesh whose morph targets are the frames (positions and normals relative to the
// first), animated by a "weights" channel that moves from one frame to the next (LINEAR: vertices
// interpolate between frames). All frames must share the triangles. Throws std::invalid_argument
// on an empty or inconsistent sequence, std::runtime_error if tinygltf fails to write.
std::vector<std::uint8_t> exportGlb(const std::vector<SkinFrame>& frames);

// One frame as OBJ text: v, vn, and f a//a b//b c//c (1-based).
std::string exportObj(const SkinMesh& mesh, const std::string& comment);

// A POV-Ray scene of one frame: the skin as a mesh2 with normals, a camera looking at the fish from
// above and to its left, two lights and a sea-blue background. centre_m: where the camera looks.
std::string exportPov(const SkinMesh& mesh, const Eigen::Vector3d& centre_m, double body_length_m,
                      const std::string& comment);

}  // namespace creaturelab::fish
