#include "render/creature_gltf.hpp"

#include <tiny_gltf.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "render/geom_mesh.hpp"
#include "render/gltf_blocks.hpp"

namespace creaturelab::render {
namespace {

std::vector<float> floats(const std::vector<Vec3>& v) {
  std::vector<float> out;
  for (const Vec3& p : v) out.insert(out.end(), {float(p.x), float(p.y), float(p.z)});
  return out;
}

// An accessor of VEC4 floats (addFloatAccessor writes scalars; the view is the same).
int addVec4Accessor(tinygltf::Model& model, const std::vector<float>& values) {
  const int a = addFloatAccessor(model, values, 1, 0, false);
  model.accessors[a].type = TINYGLTF_TYPE_VEC4;
  model.accessors[a].count = values.size() / 4;
  return a;
}

int addMeshOf(tinygltf::Model& model, const CreatureGeom& g, int index) {
  const TriangleMesh m = geomMesh(g.mujoco_type, g.size_m);
  std::vector<std::uint32_t> indices;
  for (const auto& t : m.triangles) indices.insert(indices.end(), {std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = 0;
  primitive.indices = addIndexAccessor(model, indices);
  primitive.attributes["POSITION"] = addFloatAccessor(model, floats(m.positions), 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  primitive.attributes["NORMAL"] = addFloatAccessor(model, floats(m.normals), 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  tinygltf::Mesh mesh;
  mesh.name = "geom_" + std::to_string(index);
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
  return int(model.meshes.size()) - 1;
}

}  // namespace

std::array<double, 4> quaternionOf(const double* r) {
  const double trace = r[0] + r[4] + r[8];
  std::array<double, 4> q{};
  if (trace > 0) {
    const double s = 2.0 * std::sqrt(1.0 + trace);
    q = {0.25 * s, (r[7] - r[5]) / s, (r[2] - r[6]) / s, (r[3] - r[1]) / s};
  } else if (r[0] > r[4] && r[0] > r[8]) {
    const double s = 2.0 * std::sqrt(1.0 + r[0] - r[4] - r[8]);
    q = {(r[7] - r[5]) / s, 0.25 * s, (r[1] + r[3]) / s, (r[2] + r[6]) / s};
  } else if (r[4] > r[8]) {
    const double s = 2.0 * std::sqrt(1.0 + r[4] - r[0] - r[8]);
    q = {(r[2] - r[6]) / s, (r[1] + r[3]) / s, 0.25 * s, (r[5] + r[7]) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + r[8] - r[0] - r[4]);
    q = {(r[3] - r[1]) / s, (r[2] + r[6]) / s, (r[5] + r[7]) / s, 0.25 * s};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= n;
  return q;
}

GltfLook CreatureAnimation::boneLook() {
  GltfLook look;
  look.material = "geom";
  look.base_colour = {0.6, 0.6, 0.62, 1.0};
  look.roughness = 0.6;
  return look;
}

CreatureAnimation::CreatureAnimation(std::vector<CreatureGeom> geoms, GltfLook look)
    : geoms_(std::move(geoms)), look_(std::move(look)) {
  if (geoms_.empty()) throw std::invalid_argument("a creature .glb needs at least one geom");
  for (const CreatureGeom& g : geoms_) geomMesh(g.mujoco_type, g.size_m, 3);  // throws what it cannot draw
}

void CreatureAnimation::addFrame(double time_s, const std::vector<double>& position_m, const std::vector<double>& rotation) {
  const std::size_t n = geoms_.size();
  if (position_m.size() != 3 * n || rotation.size() != 9 * n)
    throw std::invalid_argument("a creature frame needs 3 position and 9 rotation values for each of its " +
                                std::to_string(n) + " geoms");
  if (!times_.empty() && !(time_s > times_.back()))
    throw std::invalid_argument("creature frame times must increase (" + std::to_string(time_s) + " s after " +
                                std::to_string(times_.back()) + " s)");
  for (std::size_t g = 0; g < n; ++g) {
    const double* r = &rotation[9 * g];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double rtr = r[a] * r[b] + r[3 + a] * r[3 + b] + r[6 + a] * r[6 + b];
        if (!(std::fabs(rtr - (a == b ? 1.0 : 0.0)) <= 1e-6))
          throw std::invalid_argument("geom " + std::to_string(g) + "'s rotation at t = " + std::to_string(time_s) +
                                      " s is not a rotation matrix");
      }
    std::array<double, 4> q = quaternionOf(r);
    if (!times_.empty()) {  // the sign nearer the last frame's, so that slerp takes the short way
      const float* last = &rotations_[rotations_.size() - 4 * n + 4 * g];
      if (last[3] * q[0] + last[0] * q[1] + last[1] * q[2] + last[2] * q[3] < 0)
        for (double& c : q) c = -c;
    }
    translations_.insert(translations_.end(), {float(position_m[3 * g]), float(position_m[3 * g + 1]), float(position_m[3 * g + 2])});
    rotations_.insert(rotations_.end(), {float(q[1]), float(q[2]), float(q[3]), float(q[0])});
  }
  times_.push_back(time_s);
}

std::vector<std::uint8_t> CreatureAnimation::glb(const std::string& name) const {
  if (times_.empty()) throw std::invalid_argument("a creature .glb needs at least one frame");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = look_.generator;
  model.buffers.resize(1);
  tinygltf::Material material;
  material.name = look_.material;
  material.pbrMetallicRoughness.baseColorFactor.assign(look_.base_colour.begin(), look_.base_colour.end());
  material.pbrMetallicRoughness.metallicFactor = look_.metallic;
  material.pbrMetallicRoughness.roughnessFactor = look_.roughness;
  model.materials.push_back(material);

  const std::size_t n = geoms_.size(), frames = times_.size();
  tinygltf::Node root;
  root.name = name;
  root.rotation = {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};  // -90 deg about x: z up -> y up
  model.nodes.push_back(root);
  for (std::size_t g = 0; g < n; ++g) {
    tinygltf::Node node;
    node.name = "geom_" + std::to_string(g);
    node.mesh = addMeshOf(model, geoms_[g], int(g));
    node.translation.assign(translations_.begin() + 3 * g, translations_.begin() + 3 * g + 3);
    node.rotation.assign(rotations_.begin() + 4 * g, rotations_.begin() + 4 * g + 4);
    model.nodes.push_back(node);
    model.nodes[0].children.push_back(int(g) + 1);
  }
  tinygltf::Scene scene;
  scene.name = name;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  if (frames > 1) {
    std::vector<float> times;
    for (double t : times_) times.push_back(float(t - times_[0]));
    const int input = addFloatAccessor(model, times, 1, 0, true);
    tinygltf::Animation animation;
    animation.name = "motion";
    for (std::size_t g = 0; g < n; ++g) {
      std::vector<float> translation, rotation;
      for (std::size_t f = 0; f < frames; ++f) {
        translation.insert(translation.end(), translations_.begin() + 3 * (f * n + g), translations_.begin() + 3 * (f * n + g) + 3);
        rotation.insert(rotation.end(), rotations_.begin() + 4 * (f * n + g), rotations_.begin() + 4 * (f * n + g) + 4);
      }
      for (const auto& [path, output] : {std::pair{std::string("translation"), addFloatAccessor(model, translation, 3, 0, false)},
                                         std::pair{std::string("rotation"), addVec4Accessor(model, rotation)}}) {
        tinygltf::AnimationSampler sampler;
        sampler.input = input;
        sampler.output = output;
        sampler.interpolation = "LINEAR";
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel channel;
        channel.sampler = int(animation.samplers.size()) - 1;
        channel.target_node = int(g) + 1;
        channel.target_path = path;
        animation.channels.push_back(channel);
      }
    }
    model.animations.push_back(animation);
  }
  return glbBytes(model, "creature glTF export");
}

}  // namespace creaturelab::render
