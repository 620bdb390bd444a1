// A recorded swim rendered frame by frame (Rudolf & Mould 2009 §3.4-3.5): the jellyfish kind runs
// two cycles on the paper's 100² grid, recording markers, topology and muscle activation as a run
// does; every frame becomes a closed, manifold mesh with outward normals (positive volume, Euler
// characteristic 2 per piece: the umbrella and each tentacle), with every variation on.
#include <gtest/gtest.h>

#include <cmath>

#include "kinds/jellyfish.hpp"
#include "render/jellyfish_renderer.hpp"

namespace creaturelab::render {
namespace {

struct Swim {
  kinds::Result result;
  SliceTopology topology;
};

const Swim& swim() {
  static const Swim s = [] {
    const kinds::JellyfishKind kind;
    // The Hermite curve holds full activation over part of the cycle, so a 25 Hz frame sees it (the
    // default pulse peaks between frames); twice the step it was written on keeps it cheap.
    kinds::Params p = kinds::withDefaults(kind, {{"cells", std::int64_t(100)},
                                                 {"duration_s", 1.0 / 0.7},
                                                 {"frame_rate_hz", 25.0},
                                                 {"activation_shape", kinds::Value(std::string("hermite"))},
                                                 {"dt_s", 0.00125},
                                                 // the setting this test was written on, pinned
                                                 {"force_stage", kinds::Value(std::string("before_advection"))},
                                                 {"box_aspect", 1.5},
                                                 {"start_y_fraction", 0.2},
                                                 // the force at the step's end, the viscous solve to 1e-10
                                                 {"implicit_theta", 1.0},
                                                 {"viscosity_tolerance", 1e-10}});
    Swim out;
    out.result = kind.run(p);
    const auto& t = out.result.topology;
    out.topology = sliceTopology(int(t.at("bell_markers")[0]), t.at("springs"), t.at("muscles"),
                                 out.result.lagrangian.at("markers_m").points);
    return out;
  }();
  return s;
}

TEST(RenderSwim, EveryFrameIsClosedManifoldAndOutward) {
  const Swim& s = swim();
  const kinds::Tracks& markers = s.result.lagrangian.at("markers_m");
  const kinds::Tracks& activation = s.result.lagrangian.at("muscle_activation");
  ASSERT_EQ(activation.points, int(s.topology.muscle_markers.size()));
  ASSERT_EQ(s.topology.left_tentacle.size(), s.topology.right_tentacle.size());
  ASSERT_GT(s.topology.left_tentacle.size(), 2u);
  EXPECT_EQ(s.topology.validate(markers.points), "");
  ASSERT_EQ(markers.frames(), 72);
  RenderParams params;  // every variation on, 64 x 128 with 16 tentacles
  JellyfishRenderer renderer(params, s.topology, markers.points);
  const int tentacles = params.tentacles;
  double most_contracted = 0;
  for (int k = 0; k < markers.frames(); ++k) {
    const SliceFrame frame{markers.time_s[k],
                           std::span<const double>(markers.data).subspan(std::size_t(k) * markers.points * 2,
                                                                         std::size_t(markers.points) * 2),
                           std::span<const double>(activation.data).subspan(std::size_t(k) * activation.points,
                                                                            std::size_t(activation.points))};
    ASSERT_EQ(renderer.check(frame), "") << "frame " << k;
    const TriangleMesh& mesh = renderer.render(frame);
    ASSERT_EQ(checkClosedOriented(mesh), "") << "frame " << k;
    EXPECT_EQ(eulerCharacteristic(mesh), 2 * (1 + tentacles)) << "frame " << k;
    EXPECT_EQ(componentCount(mesh), 1 + tentacles) << "frame " << k;
    EXPECT_GT(signedVolume(mesh), 0.0) << "frame " << k;
    for (const Vec3& n : mesh.normals) ASSERT_NEAR(norm(n), 1.0, 1e-12) << "frame " << k;
    most_contracted = std::max(most_contracted, renderer.slice().contraction[0]);
  }
  // The swim reaches full activation, so the ridges reach (1.51 - 1.36) ϑ at the margin.
  EXPECT_GT(most_contracted, 0.99);
}

}  // namespace
}  // namespace creaturelab::render
