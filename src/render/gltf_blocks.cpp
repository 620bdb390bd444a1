#include "render/gltf_blocks.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace creaturelab::render {
namespace {

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

}  // namespace

int addFloatAccessor(tinygltf::Model& model, const std::vector<float>& values, int components, int target,
                     bool with_bounds) {
  tinygltf::Accessor a;
  a.bufferView = addView(model, values.data(), values.size() * sizeof(float), target);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.type = components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_SCALAR;
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

int addIndexAccessor(tinygltf::Model& model, const std::vector<std::uint32_t>& indices) {
  tinygltf::Accessor a;
  a.bufferView = addView(model, indices.data(), indices.size() * sizeof(std::uint32_t),
                         TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  a.type = TINYGLTF_TYPE_SCALAR;
  a.count = indices.size();
  model.accessors.push_back(a);
  return int(model.accessors.size()) - 1;
}

void addMorphAnimation(tinygltf::Model& model, const std::vector<float>& times_s, const std::vector<float>& weights,
                       const std::string& name) {
  tinygltf::AnimationSampler sampler;
  sampler.input = addFloatAccessor(model, times_s, 1, 0, true);
  sampler.output = addFloatAccessor(model, weights, 1, 0, false);
  sampler.interpolation = "LINEAR";
  tinygltf::AnimationChannel channel;
  channel.sampler = 0;
  channel.target_node = 0;
  channel.target_path = "weights";
  tinygltf::Animation animation;
  animation.name = name;
  animation.samplers.push_back(sampler);
  animation.channels.push_back(channel);
  model.animations.push_back(animation);
}

std::vector<std::uint8_t> glbBytes(tinygltf::Model& model, const std::string& what) {
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true))
    throw std::runtime_error(what + ": tinygltf could not write the .glb");
  const std::string bytes = out.str();
  return {bytes.begin(), bytes.end()};
}

}  // namespace creaturelab::render
