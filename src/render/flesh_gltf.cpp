#include "render/flesh_gltf.hpp"

#include <stdexcept>
#include <utility>

#include "render/triangle_mesh.hpp"

namespace creaturelab::render {

GltfLook SkinAnimation::skinLook() {
  GltfLook look;
  look.material = "flesh";
  look.base_colour = {0.8, 0.45, 0.4, 1.0};
  look.roughness = 0.7;
  return look;
}

SkinAnimation::SkinAnimation(std::vector<std::array<std::int32_t, 3>> triangles, GltfLook look)
    : triangles_(std::move(triangles)), animation_(std::move(look)) {}

void SkinAnimation::addFrame(double time_s, const std::vector<double>& xyz_m) {
  if (xyz_m.size() % 3 != 0) throw std::invalid_argument("a skin frame needs 3 coordinates per vertex");
  const std::size_t n = xyz_m.size() / 3;
  if (animation_.frames() == 0) {
    for (const auto& t : triangles_)
      for (std::int32_t v : t)
        if (v < 0 || std::size_t(v) >= n)
          throw std::invalid_argument("a skin triangle names vertex " + std::to_string(v) + " of " + std::to_string(n));
    vertices_ = n;
  } else if (n != vertices_) {
    throw std::invalid_argument("every skin frame must have the first frame's " + std::to_string(vertices_) +
                                " vertices, not " + std::to_string(n));
  }
  TriangleMesh mesh;
  mesh.positions.resize(n);
  for (std::size_t i = 0; i < n; ++i) mesh.positions[i] = {xyz_m[3 * i], xyz_m[3 * i + 2], -xyz_m[3 * i + 1]};
  mesh.triangles = triangles_;
  computeNormals(mesh);
  animation_.addFrame(time_s, mesh);
}

}  // namespace creaturelab::render
