// The variations of Rudolf & Mould 2009 §3.5, Eq. 2 (render/variation.hpp), each alone against the
// unvaried surface: ridges 0 at full expansion and (1.51 - 1.36) ϑ at full contraction on the
// exumbrella only; noise c = α_unstr d_i Q_P(2 d_i, 8 d_j, 0.01 t), deterministic by seed and
// attenuated toward the apex; the structural pattern; bitwise-identical meshes for one seed.
#include "render/jellyfish_renderer.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "render_test_slice.hpp"

namespace creaturelab::render {
namespace {

using test::noVariation;
using test::testSlice;

// The displacement of every vertex from the unvaried mesh `base`, along base's wall normal.
struct Displacement {
  std::vector<double> along;  // signed distance along the wall normal
  std::vector<double> off;    // distance off that normal
};

Displacement displacement(const TriangleMesh& base, const TriangleMesh& varied, const MeshLayout& m) {
  Displacement d;
  d.along.assign(base.positions.size(), 0.0);
  d.off.assign(base.positions.size(), 0.0);
  for (int i = 0; i < m.rings - 1; ++i)
    for (int j = 0; j < m.segments; ++j)
      for (int v : {m.exumbrellaRing(i) + j, m.subumbrellaRing(i) + j}) {
        const Vec3 wall = base.normals[m.exumbrellaRing(i) + j] - base.normals[m.subumbrellaRing(i) + j];
        const Vec3 n = (1.0 / norm(wall)) * wall, delta = varied.positions[v] - base.positions[v];
        d.along[v] = dot(delta, n);
        d.off[v] = norm(delta - d.along[v] * n);
      }
  return d;
}

RenderParams only(bool structural, bool ridges, bool noise) {
  RenderParams p = noVariation();
  p.segments = 64;  // a multiple of 4 f: sin(8 σ_j) reaches ±1 on the grid
  p.structural = structural;
  p.ridges = ridges;
  p.noise = noise;
  return p;
}

TEST(RenderVariation, RidgesFollowTheMuscleOnTheExumbrellaOnly) {
  auto s = testSlice(32, 0);
  const double theta = 0.004;
  JellyfishRenderer plain(only(false, false, false), s.topology, s.markers());
  JellyfishRenderer ridged(only(false, true, false), s.topology, s.markers());
  const MeshLayout& m = plain.layout();
  for (double a : {0.0, 0.5, 1.0}) {
    s.activation.assign(s.activation.size(), a);
    const TriangleMesh base = plain.render(s.frame());
    const TriangleMesh& varied = ridged.render(s.frame());
    const Displacement d = displacement(base, varied, m);
    for (int i = 0; i < m.rings - 1; ++i) {
      double high = -1, low = 1;
      for (int j = 0; j < m.segments; ++j) {
        // The subumbrella does not move at all.
        EXPECT_EQ(std::memcmp(&varied.positions[m.subumbrellaRing(i) + j], &base.positions[m.subumbrellaRing(i) + j],
                              sizeof(Vec3)), 0);
        const int v = m.exumbrellaRing(i) + j;
        EXPECT_LT(d.off[v], 1e-15);
        high = std::max(high, d.along[v]);
        low = std::min(low, d.along[v]);
      }
      const double expected = (1.51 - 1.36) * theta * ridged.slice().contraction[i];
      EXPECT_NEAR(high, expected, 1e-15) << a << " ring " << i;  // (1 + sin) / 2 = 1 on the crests
      EXPECT_NEAR(low, 0.0, 1e-15) << a << " ring " << i;        // and 0 in the troughs
      if (ridged.slice().latitude[i] > 0.3) {
        EXPECT_EQ(ridged.slice().contraction[i], a);  // inside the band
      }
    }
  }
}

TEST(RenderVariation, NoiseIsEquationTwo) {
  const auto s = testSlice(32, 0);
  JellyfishRenderer plain(only(false, false, false), s.topology, s.markers());
  JellyfishRenderer noisy(only(false, false, true), s.topology, s.markers());
  const MeshLayout& m = plain.layout();
  const double t = 3.7;
  const TriangleMesh base = plain.render(s.frame(t));
  const TriangleMesh& varied = noisy.render(s.frame(t));
  const Displacement d = displacement(base, varied, m);
  const Variation reference(only(false, false, true), m);
  const double alpha = 2.25 * 0.004;
  double largest_near_apex = 0, largest = 0;
  for (int i = 0; i < m.rings - 1; ++i) {
    const double d_i = noisy.slice().latitude[i];
    for (int j = 0; j < m.segments; ++j) {
      const double c = reference.unstructured(d_i, double(j) / m.segments, t);
      // Both surfaces of the wall move by c along its normal: the thickness stays.
      EXPECT_NEAR(d.along[m.exumbrellaRing(i) + j], c, 1e-15);
      EXPECT_NEAR(d.along[m.subumbrellaRing(i) + j], c, 1e-15);
      // The attenuation: |c| <= α_unstr d_i |Q_P| with |Q_P| about 1 at most.
      EXPECT_LE(std::abs(c), 1.05 * alpha * d_i);
      (d_i < 0.1 ? largest_near_apex : largest) = std::max(d_i < 0.1 ? largest_near_apex : largest, std::abs(c));
    }
  }
  EXPECT_LT(largest_near_apex, 0.1 * 1.05 * alpha);
  EXPECT_GT(largest, 0.1 * alpha);
  // The apexes (d = 0) do not move, and the noise closes around the bell (period 8 in 8 d_j).
  EXPECT_EQ(std::memcmp(&varied.positions[m.exumbrellaPole()], &base.positions[m.exumbrellaPole()], sizeof(Vec3)), 0);
  EXPECT_EQ(reference.unstructured(0.6, 1.0, t), reference.unstructured(0.6, 0.0, t));
}

TEST(RenderVariation, NoiseIsDeterministicBySeed) {
  const auto s = testSlice(32, 8);
  RenderParams p;  // every variation on
  JellyfishRenderer a(p, s.topology, s.markers()), b(p, s.topology, s.markers());
  p.noise_seed = 2;
  JellyfishRenderer c(p, s.topology, s.markers());
  const TriangleMesh& ma = a.render(s.frame(1.0));
  const TriangleMesh& mb = b.render(s.frame(1.0));
  const TriangleMesh& mc = c.render(s.frame(1.0));
  const std::size_t bytes = ma.positions.size() * sizeof(Vec3);
  EXPECT_EQ(std::memcmp(ma.positions.data(), mb.positions.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(ma.normals.data(), mb.normals.data(), bytes), 0);
  EXPECT_NE(std::memcmp(ma.positions.data(), mc.positions.data(), bytes), 0);
  // A renderer used for other frames first gives bitwise the same frame again.
  a.render(s.frame(2.0));
  EXPECT_EQ(std::memcmp(a.render(s.frame(1.0)).positions.data(), mb.positions.data(), bytes), 0);
}

TEST(RenderVariation, StructuralPattern) {
  const auto s = testSlice(32, 0);
  RenderParams p = only(true, false, false);
  p.structural_apex_taper = 0;
  JellyfishRenderer plain(only(false, false, false), s.topology, s.markers());
  JellyfishRenderer shaped(p, s.topology, s.markers());
  const MeshLayout& m = plain.layout();
  const TriangleMesh base = plain.render(s.frame());
  const Displacement d = displacement(base, shaped.render(s.frame()), m);
  for (int j = 0; j < m.segments; ++j) {
    const double expected = 0.375 * 0.004 * std::abs(std::sin(8 * 2 * M_PI * j / m.segments));
    EXPECT_NEAR(d.along[m.exumbrellaRing(10) + j], expected, 1e-15);
    EXPECT_NEAR(d.along[m.subumbrellaRing(10) + j], expected, 1e-15);
  }
  // With the taper, the pattern fades in from the apex.
  JellyfishRenderer tapered(only(true, false, false), s.topology, s.markers());
  const Displacement t = displacement(base, tapered.render(s.frame()), m);
  const int near_apex = m.rings - 3;  // d = 2/63
  const double d_i = tapered.slice().latitude[near_apex], x = d_i / 0.2;
  EXPECT_NEAR(t.along[m.exumbrellaRing(near_apex) + 2], 0.375 * 0.004 * x * x * (3 - 2 * x) * std::abs(std::sin(8 * 2 * M_PI * 2 / 64)), 1e-15);
}

}  // namespace
}  // namespace creaturelab::render
