// The flesh's skin as an animated .glb (render/flesh_gltf.hpp): a flesh on a skeleton that MuJoCo
// spins is recorded, exported and read back with tinygltf: vertex, triangle and frame counts match,
// the base mesh is the first frame turned to glTF's y up, and base + the last morph target is the
// last frame. About 0.05 s of CPU.
#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "control_models.hpp"
#include "flesh/flesh.hpp"
#include "flesh_models.hpp"
#include "render/flesh_gltf.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::flesh {
namespace {

class FleshExportTest : public testing::ScratchDirTest {
 protected:
  FleshExportTest() : ScratchDirTest("flesh_export") {}
};

std::vector<double> coordinates(const Eigen::Matrix3Xd& x) { return {x.data(), x.data() + x.size()}; }

const float* floats(const tinygltf::Model& model, int accessor) {
  const auto& view = model.bufferViews.at(model.accessors.at(accessor).bufferView);
  return reinterpret_cast<const float*>(model.buffers.at(view.buffer).data.data() + view.byteOffset +
                                        model.accessors.at(accessor).byteOffset);
}

TEST_F(FleshExportTest, SkinGlbReadsBackWithItsFrames) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("spinner.xml"), testing::spinnerXml()));
  FleshParams p;
  p.slices = 8;
  Flesh flesh(model, p);
  rigid::RigidData skeleton(model);
  skeleton.qvel()[0] = 2 * std::numbers::pi;
  flesh.placeOnSkeleton(skeleton);

  std::vector<std::array<std::int32_t, 3>> triangles;
  for (const auto& t : flesh.mesh().triangles) triangles.push_back({t[0], t[1], t[2]});
  render::SkinAnimation skin(triangles);
  const int frames = 5, steps_per_frame = 10;
  const std::vector<double> first = coordinates(flesh.positions_m());
  skin.addFrame(0.0, first);
  for (int k = 1; k < frames; ++k) {
    for (int s = 0; s < steps_per_frame; ++s) {
      flesh.step(skeleton, model.timestep_s());
      skeleton.step();
      std::fill(skeleton.appliedForces(), skeleton.appliedForces() + model.dofs(), 0.0);
    }
    skin.addFrame(k * steps_per_frame * model.timestep_s(), coordinates(flesh.positions_m()));
  }
  const std::vector<double> last = coordinates(flesh.positions_m());
  EXPECT_EQ(skin.frames(), frames);

  const auto bytes = skin.glb("flesh");
  tinygltf::Model gltf;
  std::string err, warn;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromMemory(&gltf, &err, &warn, bytes.data(), unsigned(bytes.size())))
      << err;
  ASSERT_EQ(gltf.meshes.size(), 1u);
  const auto& primitive = gltf.meshes[0].primitives.at(0);
  const int position = primitive.attributes.at("POSITION");
  const int n = flesh.vertices();
  EXPECT_EQ(gltf.accessors.at(position).count, std::size_t(n));
  EXPECT_EQ(gltf.accessors.at(primitive.indices).count, 3 * flesh.mesh().triangles.size());
  ASSERT_EQ(primitive.targets.size(), std::size_t(frames - 1));
  ASSERT_EQ(gltf.animations.size(), 1u);
  EXPECT_EQ(gltf.accessors.at(gltf.animations[0].samplers.at(0).input).count, std::size_t(frames));

  // glTF's y up: (x, y, z) of the simulation -> (x, z, -y); float32 in the file.
  const float* base = floats(gltf, position);
  const float* delta = floats(gltf, primitive.targets.back().at("POSITION"));
  double base_error = 0, last_error = 0;
  for (int i = 0; i < n; ++i) {
    const double want_base[3] = {first[3 * i], first[3 * i + 2], -first[3 * i + 1]};
    const double want_last[3] = {last[3 * i], last[3 * i + 2], -last[3 * i + 1]};
    for (int c = 0; c < 3; ++c) {
      base_error = std::max(base_error, std::abs(base[3 * i + c] - want_base[c]));
      last_error = std::max(last_error, std::abs(base[3 * i + c] + delta[3 * i + c] - want_last[c]));
    }
  }
  EXPECT_LT(base_error, 1e-7);
  EXPECT_LT(last_error, 1e-6);
  EXPECT_GT(std::abs(last[0] - first[0]) + std::abs(last[1] - first[1]), 0.01);  // the skin did move
}

TEST_F(FleshExportTest, MismatchedFramesAreErrors) {
  render::SkinAnimation skin({{0, 1, 2}});
  EXPECT_THROW(skin.addFrame(0.0, {0, 0, 0, 1, 0, 0}), std::invalid_argument);  // vertex 2 missing
  skin.addFrame(0.0, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  EXPECT_THROW(skin.addFrame(0.1, {0, 0, 0, 1, 0, 0}), std::invalid_argument);
  EXPECT_THROW(skin.addFrame(0.0, {0, 0, 0, 1, 0, 0, 0, 1, 0}), std::invalid_argument);  // not after the last
  EXPECT_THROW(render::SkinAnimation({{0, 1, 2}}).glb("empty"), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::flesh
