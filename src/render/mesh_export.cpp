#include "render/mesh_export.hpp"

#include "render/gltf_blocks.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace creaturelab::render {
namespace {

std::vector<float> toFloats(const std::vector<Vec3>& v) {
  std::vector<float> out;
  out.reserve(3 * v.size());
  for (const Vec3& p : v) out.insert(out.end(), {float(p.x), float(p.y), float(p.z)});
  return out;
}

std::vector<float> difference(const std::vector<float>& a, const std::vector<float>& base) {
  std::vector<float> out(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) out[k] = a[k] - base[k];
  return out;
}

}  // namespace

void GltfAnimation::addFrame(double time_s, const TriangleMesh& mesh) {
  if (times_.empty()) {
    for (const auto& t : mesh.triangles)
      for (auto v : t) indices_.push_back(std::uint32_t(v));
  } else {
    if (mesh.triangles.size() * 3 != indices_.size() || 3 * mesh.positions.size() != positions_[0].size())
      throw std::invalid_argument("every frame of a glTF animation must have the first frame's vertices and triangles");
    if (!(time_s > times_.back())) throw std::invalid_argument("glTF frames must come in increasing time");
  }
  times_.push_back(time_s);
  positions_.push_back(toFloats(mesh.positions));
  normals_.push_back(toFloats(mesh.normals));
}

std::vector<std::uint8_t> GltfAnimation::glb(const std::string& name) const {
  if (times_.empty()) throw std::invalid_argument("a glTF file needs at least one frame");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = look_.generator;
  model.buffers.resize(1);

  tinygltf::Material material;
  material.name = look_.material;
  material.doubleSided = look_.double_sided;
  material.pbrMetallicRoughness.baseColorFactor.assign(look_.base_colour.begin(), look_.base_colour.end());
  material.pbrMetallicRoughness.metallicFactor = look_.metallic;
  material.pbrMetallicRoughness.roughnessFactor = look_.roughness;
  model.materials.push_back(material);

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = 0;
  primitive.indices = addIndexAccessor(model, indices_);
  primitive.attributes["POSITION"] =
      addFloatAccessor(model, positions_[0], 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  primitive.attributes["NORMAL"] = addFloatAccessor(model, normals_[0], 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);

  tinygltf::Mesh mesh;
  mesh.name = name;
  const int targets = int(times_.size()) - 1;
  for (int k = 1; k <= targets; ++k) {
    std::map<std::string, int> target;
    target["POSITION"] = addFloatAccessor(model, difference(positions_[k], positions_[0]), 3,
                                          TINYGLTF_TARGET_ARRAY_BUFFER, true);
    target["NORMAL"] = addFloatAccessor(model, difference(normals_[k], normals_[0]), 3,
                                        TINYGLTF_TARGET_ARRAY_BUFFER, false);
    primitive.targets.push_back(target);
  }
  mesh.weights.assign(targets, 0.0);
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = name;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.name = name;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  if (targets > 0) {
    // Weights: one-hot on frame k's target at t_k, so a viewer blends neighbouring frames linearly.
    std::vector<float> times, weights(std::size_t(targets + 1) * targets, 0.0f);
    for (int k = 0; k <= targets; ++k) {
      times.push_back(float(times_[k] - times_[0]));
      if (k > 0) weights[std::size_t(k) * targets + (k - 1)] = 1.0f;
    }
    addMorphAnimation(model, times, weights, "swim");
  }

  return glbBytes(model, "glTF export");
}

std::string objText(const TriangleMesh& mesh, const std::string& object, const std::string& comment) {
  std::string out = "# " + comment + "\no " + object + "\n";
  out.reserve(64 * (2 * mesh.positions.size() + mesh.triangles.size()));
  char line[160];
  for (const Vec3& p : mesh.positions) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    out += line;
  }
  for (const Vec3& n : mesh.normals) {
    std::snprintf(line, sizeof line, "vn %.6f %.6f %.6f\n", n.x, n.y, n.z);
    out += line;
  }
  for (const auto& t : mesh.triangles) {
    std::snprintf(line, sizeof line, "f %d//%d %d//%d %d//%d\n", t[0] + 1, t[0] + 1, t[1] + 1, t[1] + 1, t[2] + 1,
                  t[2] + 1);
    out += line;
  }
  return out;
}

}  // namespace creaturelab::render
