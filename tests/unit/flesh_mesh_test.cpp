// The flesh's mesh (flesh/flesh_mesh.hpp): closed and outward-oriented shells, one per geom, their
// mass against the analytic shell, anchors that give back the rest shape, refinement to a maximum
// edge, vertex areas summing to the surface; parameter validation. Each TEST well under 0.1 s.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "control_models.hpp"
#include "flesh/flesh.hpp"
#include "flesh_models.hpp"
#include "render/triangle_mesh.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::flesh {
namespace {

render::TriangleMesh asRenderMesh(const FleshMesh& m, const Eigen::Matrix3Xd& x) {
  render::TriangleMesh out;
  for (int i = 0; i < m.vertices(); ++i) out.positions.push_back({x(0, i), x(1, i), x(2, i)});
  for (const auto& t : m.triangles) out.triangles.push_back({t[0], t[1], t[2]});
  return out;
}

class FleshMeshTest : public testing::ScratchDirTest {
 protected:
  FleshMeshTest() : ScratchDirTest("flesh_mesh") {}
  rigid::RigidModel load(const std::string& xml) {
    return rigid::RigidModel::load(testing::writeText(file("model.xml"), xml));
  }
};

TEST_F(FleshMeshTest, ShellsAreClosedOutwardAndOnePerGeom) {
  const auto model = load(testing::freeCreatureXml(0.1, 2.0));
  const FleshMesh m = buildFleshMesh(model, FleshParams{});
  const render::TriangleMesh r = asRenderMesh(m, m.rest_m);
  EXPECT_EQ(render::checkClosedOriented(r), "");
  EXPECT_EQ(render::componentCount(r), 2);          // the sphere's and the capsule's
  EXPECT_EQ(render::eulerCharacteristic(r), 2 * 2);  // two spheres topologically
  EXPECT_GT(render::signedVolume(r), 0);              // counter-clockwise seen from outside
  EXPECT_EQ(int(m.body.size()), m.vertices());
  for (int i = 0; i < m.vertices(); ++i) EXPECT_TRUE(m.body[i] == 1 || m.body[i] == 2);
}

// Mass = density x shell volume 4/3 pi ((r + t)^3 - r^3); the tessellated sphere is inscribed, so its
// mass falls short by O(1/slices^2): under 4% at 16 slices, and 4 times closer at 32.
TEST_F(FleshMeshTest, MassIsTheShellsAndConvergesWithSlices) {
  const double r = 0.1;
  const auto model = load(testing::heldSphereXml(r));
  FleshParams p;
  p.thickness_m = 0.01;
  const double exact = p.density_kg_per_m3 * 4.0 / 3 * std::numbers::pi * (std::pow(r + p.thickness_m, 3) - r * r * r);
  auto error = [&](int slices) {
    p.slices = slices;
    return std::abs(buildFleshMesh(model, p).mass_kg.sum() / exact - 1);
  };
  const double e16 = error(16), e32 = error(32);
  EXPECT_LT(e16, 0.04);
  EXPECT_NEAR(e16 / e32, 4.0, 0.6);
}

// The anchors, carried by the bodies at the reference configuration, are the rest shape; the vertex
// areas sum to the flesh's surface.
TEST_F(FleshMeshTest, AnchorsGiveTheRestShapeAndAreasSumToTheSurface) {
  const auto model = load(testing::freeCreatureXml(0.1, 2.0));
  Flesh flesh(model);
  rigid::RigidData data(model);
  data.reset();
  flesh.placeOnSkeleton(data);
  EXPECT_LT((flesh.positions_m() - flesh.mesh().rest_m).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_EQ(flesh.velocities_m_per_s().cwiseAbs().maxCoeff(), 0.0);
  Eigen::VectorXd area;
  flesh.vertexAreas(area);
  double surface = 0;
  const auto& x = flesh.positions_m();
  for (const auto& t : flesh.mesh().triangles)
    surface += 0.5 * (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).norm();
  EXPECT_NEAR(area.sum(), surface, 1e-12 * surface);
  EXPECT_TRUE((area.array() > 0).all());
}

// Longest-edge bisection: a box (8 vertices) and a sphere with a capsule refined to 40 mm and 20 mm
// edges stay closed and outward, with no edge longer, and the mass barely moves (midpoints stay on
// the flat triangles).
TEST_F(FleshMeshTest, MaxEdgeRefinesAndStaysClosed) {
  for (const std::string& xml : {testing::boxXml(), testing::freeCreatureXml(0.1, 2.0)})
    for (const double max_edge : {0.04, 0.02}) {
      const auto model = load(xml);
      FleshParams p;
      p.max_edge_m = max_edge;
      const FleshMesh coarse = buildFleshMesh(model, FleshParams{}), fine = buildFleshMesh(model, p);
      double longest = 0;
      for (const auto& e : fine.edges)
        longest = std::max(longest, (fine.rest_m.col(e[0]) - fine.rest_m.col(e[1])).norm());
      EXPECT_LE(longest, max_edge);
      EXPECT_GT(fine.vertices(), coarse.vertices());
      const render::TriangleMesh r = asRenderMesh(fine, fine.rest_m);
      EXPECT_EQ(render::checkClosedOriented(r), "");
      EXPECT_GT(render::signedVolume(r), 0);
      EXPECT_NEAR(fine.mass_kg.sum(), coarse.mass_kg.sum(), 0.1 * coarse.mass_kg.sum());
    }
}

TEST_F(FleshMeshTest, BadParametersAreNamed) {
  const auto model = load(testing::heldSphereXml(0.1));
  auto message = [&](auto change) {
    FleshParams p;
    change(p);
    try {
      Flesh flesh(model, p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([](FleshParams& p) { p.thickness_m = 0; }).find("thickness_m"), std::string::npos);
  EXPECT_NE(message([](FleshParams& p) { p.slices = 2; }).find("slices"), std::string::npos);
  EXPECT_NE(message([](FleshParams& p) { p.density_kg_per_m3 = -1; }).find("density"), std::string::npos);
  EXPECT_NE(message([](FleshParams& p) { p.youngs_modulus_pa = NAN; }).find("youngs_modulus_pa"), std::string::npos);
  EXPECT_NE(message([](FleshParams& p) { p.binding_hz = 0; }).find("binding_hz"), std::string::npos);
  EXPECT_NE(message([](FleshParams& p) { p.binding_damping_ratio = -0.1; }).find("binding_damping_ratio"),
            std::string::npos);
  EXPECT_NE(message([](FleshParams& p) { p.cg_tolerance = 1; }).find("cg_tolerance"), std::string::npos);
  EXPECT_EQ(FleshParams{}.validate(), "");
}

TEST_F(FleshMeshTest, AModelWithoutMovingGeomsIsAnError) {
  const auto model = load("<mujoco><worldbody><geom type=\"sphere\" size=\"0.1\"/></worldbody></mujoco>");
  EXPECT_THROW(Flesh flesh(model), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::flesh
