#include "render/mesh_export.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace creaturelab::render {
namespace {

std::vector<float> toFloats(const std::vector<Vec3>& v) {
  std::vector<float> out;
  out.reserve(3 * v.size());
  for (const Vec3& p : v) out.insert(out.end(), {float(p.x), float(p.y), float(p.z)});
  return out;
}

// Appends `bytes` to the model's single buffer (4-byte aligned) as a new buffer view.
int addView(tinygltf::Model& model, const void* bytes, std::size_t size, int target) {
  auto& data = model.buffers[0].data;
  data.resize((data.size() + 3) / 4 * 4, 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = size;
  view.target = target;
  const auto* p = static_cast<const std::uint8_t*>(bytes);
  data.insert(data.end(), p, p + size);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

// A float accessor (VEC3 or SCALAR) over its own view; with_bounds adds min/max (required for
// POSITION and for an animation's input).
int addFloats(tinygltf::Model& model, const std::vector<float>& values, int type, int target, bool with_bounds) {
  const int components = type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
  tinygltf::Accessor a;
  a.bufferView = addView(model, values.data(), values.size() * sizeof(float), target);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.type = type;
  a.count = values.size() / components;
  if (with_bounds) {
    a.minValues.assign(components, std::numeric_limits<double>::infinity());
    a.maxValues.assign(components, -std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < values.size(); ++k) {
      a.minValues[k % components] = std::min(a.minValues[k % components], double(values[k]));
      a.maxValues[k % components] = std::max(a.maxValues[k % components], double(values[k]));
    }
  }
  model.accessors.push_back(a);
  return int(model.accessors.size()) - 1;
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
  model.asset.generator = "creaturelab render (Rudolf & Mould 2009 jellyfish)";
  model.buffers.resize(1);

  tinygltf::Material material;
  material.name = "mesoglea";
  material.pbrMetallicRoughness.baseColorFactor = {0.85, 0.88, 0.95, 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.55;
  model.materials.push_back(material);

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = 0;
  {
    tinygltf::Accessor a;
    a.bufferView = addView(model, indices_.data(), indices_.size() * sizeof(std::uint32_t),
                           TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = indices_.size();
    model.accessors.push_back(a);
    primitive.indices = int(model.accessors.size()) - 1;
  }
  primitive.attributes["POSITION"] =
      addFloats(model, positions_[0], TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  primitive.attributes["NORMAL"] = addFloats(model, normals_[0], TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, false);

  tinygltf::Mesh mesh;
  mesh.name = name;
  const int frames = int(times_.size());
  if (frames > 1) {
    for (int k = 0; k < frames; ++k) {
      std::map<std::string, int> target;
      target["POSITION"] = addFloats(model, difference(positions_[k], positions_[0]), TINYGLTF_TYPE_VEC3,
                                     TINYGLTF_TARGET_ARRAY_BUFFER, true);
      target["NORMAL"] = addFloats(model, difference(normals_[k], normals_[0]), TINYGLTF_TYPE_VEC3,
                                   TINYGLTF_TARGET_ARRAY_BUFFER, false);
      primitive.targets.push_back(target);
    }
    mesh.weights.assign(frames, 0.0);
  }
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

  if (frames > 1) {
    // Weights: one-hot on target k at t_k, so a viewer blends neighbouring frames linearly.
    std::vector<float> times, weights(std::size_t(frames) * frames, 0.0f);
    for (int k = 0; k < frames; ++k) {
      times.push_back(float(times_[k] - times_[0]));
      weights[std::size_t(k) * frames + k] = 1.0f;
    }
    tinygltf::AnimationSampler sampler;
    sampler.input = addFloats(model, times, TINYGLTF_TYPE_SCALAR, 0, true);
    sampler.output = addFloats(model, weights, TINYGLTF_TYPE_SCALAR, 0, false);
    sampler.interpolation = "LINEAR";
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    tinygltf::Animation animation;
    animation.name = "swim";
    animation.samplers.push_back(sampler);
    animation.channels.push_back(channel);
    model.animations.push_back(animation);
  }

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true)) throw std::runtime_error("tinygltf could not write the .glb");
  const std::string bytes = out.str();
  return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
}

std::string objText(const TriangleMesh& mesh, const std::string& comment) {
  std::string out = "# " + comment + "\no jellyfish\n";
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
