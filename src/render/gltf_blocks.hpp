#pragma once
// Building blocks of the morph-target glTF 2.0 exports (Khronos glTF 2.0 spec §3.6 buffers,
// §3.7.2.2 morph targets, §3.11 animations) for render/mesh_export's .glb writer: one buffer, each
// accessor over its own 4-byte aligned view. Bytes only, no files.
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace creaturelab::render {

/// Appends `values` (floats, `components` = 1 or 3 per element) as a view and an accessor (SCALAR
/// or VEC3); `target` is the view's target (0: none); with_bounds adds min/max (required for
/// POSITION and an animation's input). Returns the accessor's index.
int addFloatAccessor(tinygltf::Model& model, const std::vector<float>& values, int components, int target,
                     bool with_bounds);

/// Appends triangle indices (unsigned int) as an element-array view and accessor; returns its index.
int addIndexAccessor(tinygltf::Model& model, const std::vector<std::uint32_t>& indices);

/// Animates node 0's morph weights: at times[k] the weights are weights[k * targets ...] (LINEAR
/// between keys, so a viewer blends neighbouring frames).
void addMorphAnimation(tinygltf::Model& model, const std::vector<float>& times_s, const std::vector<float>& weights,
                       const std::string& name);

/// The model as a binary glTF (.glb). Throws std::runtime_error naming `what` if tinygltf fails.
std::vector<std::uint8_t> glbBytes(tinygltf::Model& model, const std::string& what);

}  // namespace creaturelab::render
