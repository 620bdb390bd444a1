#include <cmath>
#include <stdexcept>

// Debian's libtinygltf is a shared library built with its defaults: include the header as is.
#include <tiny_gltf.h>

#include "fish/export.hpp"
#include "render/gltf_blocks.hpp"

namespace creaturelab::fish {

std::vector<std::uint8_t> exportGlb(const std::vector<SkinFrame>& frames) {
  if (frames.empty()) throw std::invalid_argument("glTF export: no frames");
  const SkinMesh& first = frames[0].mesh;
  for (const auto& f : frames)
    if (f.mesh.positions.size() != first.positions.size() || f.mesh.triangles != first.triangles)
      throw std::invalid_argument("glTF export: the frames do not share one mesh");

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "creaturelab fish (Tu 1996 NURBS skin)";
  model.buffers.resize(1);

  auto flat = [](const std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3d>* minus) {
    std::vector<float> out;
    out.reserve(v.size() * 3);
    for (size_t i = 0; i < v.size(); ++i)
      for (int d = 0; d < 3; ++d) out.push_back(float(v[i][d] - (minus ? (*minus)[i][d] : 0.0)));
    return out;
  };
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.attributes["POSITION"] = render::addFloatAccessor(model, flat(first.positions, nullptr), 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  prim.attributes["NORMAL"] = render::addFloatAccessor(model, flat(first.normals, nullptr), 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  std::vector<std::uint32_t> indices;
  for (const auto& t : first.triangles)
    for (int v : t) indices.push_back(std::uint32_t(v));
  prim.indices = render::addIndexAccessor(model, indices);
  // Morph target k + 1 holds frame k + 1 minus frame 0 (glTF 2.0 §3.7.2.2: targets are displacements).
  const int targets = int(frames.size()) - 1;
  for (int k = 1; k <= targets; ++k) {
    std::map<std::string, int> t;
    t["POSITION"] = render::addFloatAccessor(model, flat(frames[k].mesh.positions, &first.positions), 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    t["NORMAL"] = render::addFloatAccessor(model, flat(frames[k].mesh.normals, &first.normals), 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    prim.targets.push_back(t);
  }
  tinygltf::Material mat;
  mat.name = "fish skin";
  mat.doubleSided = true;  // the fins are sheets
  mat.pbrMetallicRoughness.baseColorFactor = {0.35, 0.55, 0.7, 1.0};
  mat.pbrMetallicRoughness.metallicFactor = 0.1;
  mat.pbrMetallicRoughness.roughnessFactor = 0.5;
  model.materials.push_back(mat);
  prim.material = 0;

  tinygltf::Mesh mesh;
  mesh.name = "fish";
  mesh.primitives.push_back(prim);
  mesh.weights.assign(targets, 0.0);
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = "fish";
  // Our z is up; glTF's y is up: rotate -90 degrees about x (quaternion x, y, z, w).
  node.rotation = {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  if (targets > 0) {
    std::vector<float> times, weights;
    for (size_t k = 0; k < frames.size(); ++k) {
      times.push_back(float(frames[k].time_s - frames[0].time_s));
      for (int t = 1; t <= targets; ++t) weights.push_back(int(k) == t ? 1.0f : 0.0f);
    }
    render::addMorphAnimation(model, times, weights, "swim");
  }

  return render::glbBytes(model, "glTF export");
}

}  // namespace creaturelab::fish
