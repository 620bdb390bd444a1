#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <cmath>

// Debian's libtinygltf is a shared library built with its defaults: include the header as is.
#include <tiny_gltf.h>

#include "fish/export.hpp"

namespace creaturelab::fish {
namespace {

// Appends floats to the buffer as a new view + accessor; returns the accessor index.
int addAccessor(tinygltf::Model& model, const std::vector<float>& values, int components, int target,
                bool with_bounds) {
  auto& buffer = model.buffers[0].data;
  while (buffer.size() % 4) buffer.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = values.size() * sizeof(float);
  if (target) view.target = target;
  const size_t at = buffer.size();
  buffer.resize(at + view.byteLength);
  std::memcpy(buffer.data() + at, values.data(), view.byteLength);
  model.bufferViews.push_back(view);

  tinygltf::Accessor acc;
  acc.bufferView = int(model.bufferViews.size()) - 1;
  acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  acc.count = values.size() / components;
  acc.type = components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_SCALAR;
  if (with_bounds) {
    acc.minValues.assign(components, std::numeric_limits<double>::infinity());
    acc.maxValues.assign(components, -std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < values.size(); ++i) {
      acc.minValues[i % components] = std::min(acc.minValues[i % components], double(values[i]));
      acc.maxValues[i % components] = std::max(acc.maxValues[i % components], double(values[i]));
    }
  }
  model.accessors.push_back(acc);
  return int(model.accessors.size()) - 1;
}

}  // namespace

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
  prim.attributes["POSITION"] = addAccessor(model, flat(first.positions, nullptr), 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  prim.attributes["NORMAL"] = addAccessor(model, flat(first.normals, nullptr), 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  {
    auto& buffer = model.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = first.triangles.size() * 3 * sizeof(std::uint32_t);
    view.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
    for (const auto& t : first.triangles)
      for (int v : t) {
        const std::uint32_t i = std::uint32_t(v);
        const auto* b = reinterpret_cast<const std::uint8_t*>(&i);
        buffer.insert(buffer.end(), b, b + 4);
      }
    model.bufferViews.push_back(view);
    tinygltf::Accessor acc;
    acc.bufferView = int(model.bufferViews.size()) - 1;
    acc.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    acc.count = first.triangles.size() * 3;
    acc.type = TINYGLTF_TYPE_SCALAR;
    model.accessors.push_back(acc);
    prim.indices = int(model.accessors.size()) - 1;
  }
  // Morph target k + 1 holds frame k + 1 minus frame 0 (glTF 2.0 §3.7.2.2: targets are displacements).
  const int targets = int(frames.size()) - 1;
  for (int k = 1; k <= targets; ++k) {
    std::map<std::string, int> t;
    t["POSITION"] = addAccessor(model, flat(frames[k].mesh.positions, &first.positions), 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    t["NORMAL"] = addAccessor(model, flat(frames[k].mesh.normals, &first.normals), 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
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
    tinygltf::AnimationSampler sampler;
    sampler.input = addAccessor(model, times, 1, 0, true);
    sampler.output = addAccessor(model, weights, 1, 0, false);
    sampler.interpolation = "LINEAR";
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    tinygltf::Animation anim;
    anim.name = "swim";
    anim.samplers.push_back(sampler);
    anim.channels.push_back(channel);
    model.animations.push_back(anim);
  }

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true)) throw std::runtime_error("glTF export: tinygltf could not write the model");
  const std::string bytes = out.str();
  return {bytes.begin(), bytes.end()};
}

}  // namespace creaturelab::fish
