// The render's files (render/mesh_export.hpp, render/pov_scene.hpp, io/xdmf.hpp): the .glb reloads
// with tinygltf with the same vertex count, bounds, morph targets and animation; OBJ, XDMF and
// POV-Ray text carry the mesh.
#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <sstream>

#include "io/xdmf.hpp"
#include "render/jellyfish_renderer.hpp"
#include "render/mesh_export.hpp"
#include "render/pov_scene.hpp"
#include "render_test_slice.hpp"

namespace creaturelab::render {
namespace {

using test::testSlice;

std::vector<TriangleMesh> threeFrames() {
  auto s = testSlice(32, 8);
  RenderParams p;
  p.rings = 20;
  p.segments = 32;
  p.tentacles = 4;
  JellyfishRenderer r(p, s.topology, s.markers());
  std::vector<TriangleMesh> out;
  for (int k = 0; k < 3; ++k) {
    s.activation.assign(s.activation.size(), 0.4 * k);
    for (std::size_t m = 1; m < s.xy.size(); m += 2) s.xy[m] += 0.001;  // swimming up
    out.push_back(r.render(s.frame(0.04 * k)));
  }
  return out;
}

TEST(RenderExport, GlbRoundTrip) {
  const auto frames = threeFrames();
  GltfAnimation animation;
  for (int k = 0; k < 3; ++k) animation.addFrame(0.04 * k + 1.0, frames[k]);
  const auto bytes = animation.glb("jellyfish");
  ASSERT_GT(bytes.size(), 12u);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "glTF");

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()))) << err;
  EXPECT_EQ(model.asset.version, "2.0");
  ASSERT_EQ(model.meshes.size(), 1u);
  const auto& primitive = model.meshes[0].primitives.at(0);
  const auto& positions = model.accessors.at(primitive.attributes.at("POSITION"));
  EXPECT_EQ(positions.count, frames[0].positions.size());
  EXPECT_EQ(model.accessors.at(primitive.indices).count, 3 * frames[0].triangles.size());
  const Bounds b = boundsOf(frames[0]);
  ASSERT_EQ(positions.minValues.size(), 3u);
  ASSERT_EQ(positions.maxValues.size(), 3u);
  const double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
  for (int c = 0; c < 3; ++c) {  // float32 in the file
    EXPECT_NEAR(positions.minValues[c], lo[c], 1e-8);
    EXPECT_NEAR(positions.maxValues[c], hi[c], 1e-8);
  }
  // One morph target per frame after the first, and frame k's bounds from its target's deltas.
  ASSERT_EQ(primitive.targets.size(), 2u);
  const auto& target = model.accessors.at(primitive.targets[1].at("POSITION"));
  const auto& view = model.bufferViews.at(target.bufferView);
  const float* base = reinterpret_cast<const float*>(model.buffers[0].data.data() +
                                                     model.bufferViews.at(positions.bufferView).byteOffset);
  const float* delta = reinterpret_cast<const float*>(model.buffers[0].data.data() + view.byteOffset);
  Bounds last;
  for (std::size_t v = 0; v < target.count; ++v)
    last.add({base[3 * v] + delta[3 * v], base[3 * v + 1] + delta[3 * v + 1], base[3 * v + 2] + delta[3 * v + 2]});
  const Bounds expected = boundsOf(frames[2]);
  EXPECT_NEAR(last.hi.y, expected.hi.y, 1e-7);
  EXPECT_NEAR(last.lo.x, expected.lo.x, 1e-7);
  // The animation plays the frames at their times, from 0.
  ASSERT_EQ(model.animations.size(), 1u);
  const auto& sampler = model.animations[0].samplers.at(0);
  const auto& input = model.accessors.at(sampler.input);
  EXPECT_EQ(input.count, 3u);
  EXPECT_NEAR(input.maxValues.at(0), 0.08, 1e-7);
  EXPECT_EQ(model.accessors.at(sampler.output).count, 6u);  // 3 keys x 2 targets
  EXPECT_EQ(model.animations[0].channels.at(0).target_path, "weights");
}

TEST(RenderExport, GlbRefusesMismatchedFrames) {
  const auto frames = threeFrames();
  GltfAnimation animation;
  animation.addFrame(0, frames[0]);
  EXPECT_THROW(animation.addFrame(0, frames[1]), std::invalid_argument);  // not after the last
  TriangleMesh fewer = frames[1];
  fewer.triangles.pop_back();
  EXPECT_THROW(animation.addFrame(1, fewer), std::invalid_argument);
  GltfAnimation single;
  single.addFrame(0, frames[0]);
  tinygltf::Model model;
  std::string err, warn;
  const auto bytes = single.glb("one");
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size())));
  EXPECT_TRUE(model.animations.empty());
}

TEST(RenderExport, GlbCarriesTheLook) {
  GltfLook look;
  look.material = "fish skin";
  look.base_colour = {0.35, 0.55, 0.7, 1.0};
  look.double_sided = true;
  GltfAnimation animation(look);
  animation.addFrame(0, threeFrames()[0]);
  const auto bytes = animation.glb("fish");
  tinygltf::Model model;
  std::string err, warn;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size())));
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].name, "fish skin");
  EXPECT_TRUE(model.materials[0].doubleSided);
  EXPECT_EQ(model.materials[0].pbrMetallicRoughness.baseColorFactor[2], 0.7);
  EXPECT_EQ(model.nodes.at(0).name, "fish");
}

TEST(RenderExport, ObjXdmfPov) {
  const TriangleMesh mesh = threeFrames()[0];
  const std::string obj = objText(mesh, "jellyfish", "a test");
  std::istringstream lines(obj);
  std::size_t v = 0, vn = 0, f = 0;
  for (std::string line; std::getline(lines, line);) {
    v += line.rfind("v ", 0) == 0;
    vn += line.rfind("vn ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(v, mesh.positions.size());
  EXPECT_EQ(vn, mesh.positions.size());
  EXPECT_EQ(f, mesh.triangles.size());
  EXPECT_NE(obj.find("f 1//1 "), std::string::npos);  // 1-based
  EXPECT_EQ(obj.rfind("# a test\no jellyfish\n", 0), 0u);

  io::XdmfTriangleMesh x{"render.h5", "/render", {0.0, 0.04}, long(mesh.positions.size()), long(mesh.triangles.size()),
                         "positions_m", {"normals"}, {"part"}};
  const std::string xdmf = io::xdmfMeshText(x);
  EXPECT_NE(xdmf.find("TopologyType=\"Triangle\" NumberOfElements=\"" + std::to_string(mesh.triangles.size())),
            std::string::npos);
  EXPECT_NE(xdmf.find("render.h5:/render/positions_m"), std::string::npos);
  EXPECT_NE(xdmf.find("<Time Value=\"0.040000000000000001\" />"), std::string::npos);

  const std::string pov = povMeshInclude(mesh, "Jf");
  EXPECT_EQ(pov.rfind("#declare Jf = mesh2 {", 0), 0u);
  EXPECT_NE(pov.find("vertex_vectors { " + std::to_string(mesh.positions.size()) + ","), std::string::npos);
  EXPECT_NE(pov.find("face_indices { " + std::to_string(mesh.triangles.size()) + ","), std::string::npos);
  const std::string scene = povGalleryScene({{"jf.inc", "Jf", "frame", boundsOf(mesh), {}}}, PovView{}, "test");
  EXPECT_NE(scene.find("orthographic"), std::string::npos);
  EXPECT_NE(scene.find("#include \"jf.inc\""), std::string::npos);

  // The sea scene: the mesh inline, POV-Ray's left-handed frame (z changes sign), the camera above.
  TriangleMesh one;
  one.positions = {{0, 0, 0.5}, {1, 0, 0}, {0, 1, 0}};
  one.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  one.triangles = {{0, 1, 2}};
  const std::string sea = povSeaScene(one, {0, 0, 0}, 1.0, "a test");
  EXPECT_EQ(sea.rfind("// a test\n", 0), 0u);
  EXPECT_NE(sea.find("vertex_vectors { 3,\n    <0, 0, -0.5>,"), std::string::npos) << sea;
  EXPECT_NE(sea.find("camera { perspective location <0.2, 1, 0.55> look_at"), std::string::npos) << sea;
  EXPECT_NE(sea.find("face_indices { 1,\n    <0, 1, 2>"), std::string::npos) << sea;
}

}  // namespace
}  // namespace creaturelab::render
