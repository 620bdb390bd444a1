// The spring network of the jellyfish slice (jellyfish/bell_model.hpp; Rudolf & Mould 2009,
// §3.2, Fig. 4 and the table of Fig. 12): geometry,
// symmetry, spring constants k = E t / L, tentacles at 1/100 of the bell's section, the muscle
// springs across the bell, and a rest shape in equilibrium.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "jellyfish/bell_model.hpp"
#include "springs/system.hpp"

namespace creaturelab::jellyfish {
namespace {

double distance(fluid::Vec2 a, fluid::Vec2 b) { return std::hypot(b.x - a.x, b.y - a.y); }

bool isTentacle(const BellModel& m, int marker) { return marker >= m.bell_markers; }

// Ramanujan's second approximation of an ellipse's perimeter (relative error ~ h^5 / 2^17 for
// h = ((a-b)/(a+b))^2; below 1e-12 here).
double ellipsePerimeter(double a, double b) {
  const double h = (a - b) * (a - b) / ((a + b) * (a + b));
  return M_PI * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
}

// Mirror symmetry x -> -x (§3.1: the organism is axially symmetric; the slice through the axis is
// mirror-symmetric), exactly, so that a symmetric start stays symmetric in the simulation: marker i
// of the bell mirrors marker segments - i, tentacle marker j of the left side mirrors marker j of
// the right side, for several resolutions.
TEST(JellyfishBell, MarkersAreExactlyMirrorSymmetric) {
  for (int segments : {8, 32, 64, 66}) {
    BellParams p = paperBell();
    p.segments = segments;
    const BellModel m = buildBell(p);
    const auto& x = m.rest_positions_m;
    ASSERT_EQ(m.bell_markers, segments + 1);
    for (int i = 0; i < m.bell_markers; ++i) {
      EXPECT_EQ(x[i].x, -x[segments - i].x) << "segments " << segments << " marker " << i;
      EXPECT_EQ(x[i].y, x[segments - i].y) << "segments " << segments << " marker " << i;
    }
    const std::size_t half = m.tentacle_markers.size() / 2;
    ASSERT_EQ(m.tentacle_markers.size(), 2 * half);
    for (std::size_t j = 0; j < half; ++j) {
      const fluid::Vec2 l = x[m.tentacle_markers[j]], r = x[m.tentacle_markers[half + j]];
      EXPECT_EQ(l.x, -r.x) << "tentacle marker " << j;
      EXPECT_EQ(l.y, r.y) << "tentacle marker " << j;
    }
    // Muscle springs join mirror images, so they are horizontal.
    for (const MuscleSpring& s : m.muscles) {
      EXPECT_EQ(s.b, segments - s.a);
      EXPECT_EQ(x[s.a].y, x[s.b].y);
    }
  }
}

// The bell's spring and bend constants are mirror-symmetric too: the bend at joint j and the bend
// at joint segments - j have the same rest angle (mirroring and reversing the chain each flip the
// sign of the signed turning angle) and stiffness.
TEST(JellyfishBell, SpringsAndBendsAreMirrorSymmetric) {
  const BellParams p = paperBell();
  const BellModel m = buildBell(p);
  const auto& net = m.network;
  for (int e = 0; e < p.segments; ++e) {
    ASSERT_EQ(net.spring_a[e], e);  // the bell's chain comes first, in order
    EXPECT_EQ(net.rest_length_m[e], net.rest_length_m[p.segments - 1 - e]) << "spring " << e;
    EXPECT_EQ(net.stiffness_n_per_m[e], net.stiffness_n_per_m[p.segments - 1 - e]) << "spring " << e;
  }
  for (int e = 0; e < p.segments - 1; ++e) {
    ASSERT_EQ(net.bend_j[e], e + 1);
    EXPECT_NEAR(net.rest_angle_rad[e], net.rest_angle_rad[p.segments - 2 - e], 1e-14) << "bend at joint " << e + 1;
    EXPECT_LT(net.rest_angle_rad[e], 0.0) << "the bell turns one way (clockwise, left aperture over the apex)";
  }
}

// Geometry (Fig. 12: diameter 40 mm, height 28 mm, thickness 4 mm; the markers are the
// subumbrella, semi-axes 16 mm and 24 mm): apex on the axis x = 0 at the top, aperture markers at
// y = 0, 32 mm apart, every bell marker on the subumbrellar half-ellipse.
TEST(JellyfishBell, ApexOnAxisApertureAtBaseMarkersOnTheEllipse) {
  const BellParams p = paperBell();
  const BellModel m = buildBell(p);
  const auto& x = m.rest_positions_m;
  const double a = 0.5 * p.diameter_m - p.thickness_m, b = p.height_m - p.thickness_m;
  EXPECT_EQ(m.apex, p.segments / 2);
  EXPECT_EQ(x[m.apex].x, 0.0);
  EXPECT_NEAR(x[m.apex].y, b, 1e-12);
  for (int i = 0; i < m.bell_markers; ++i) EXPECT_LE(x[i].y, x[m.apex].y) << "marker " << i << " above the apex";
  EXPECT_EQ(x[0].y, 0.0);
  EXPECT_EQ(x[m.bell_markers - 1].y, 0.0);
  EXPECT_NEAR(x[0].x, -a, 1e-15);
  EXPECT_NEAR(m.aperture_width_m, 2 * a, 1e-15);
  EXPECT_NEAR(m.aperture_width_m, 0.032, 1e-15);
  for (int i = 0; i < m.bell_markers; ++i) {
    // A marker interpolated on a 4096-chord polyline lies within its sagitta (~1e-9 m) of the ellipse.
    EXPECT_NEAR(std::pow(x[i].x / a, 2) + std::pow(x[i].y / b, 2), 1.0, 1e-6) << "marker " << i;
  }
  // Left to right: x increases along the chain.
  for (int i = 1; i < m.bell_markers; ++i) EXPECT_GT(x[i].x, x[i - 1].x);
}

// The markers are equally spaced in arc length, so the chain springs have (nearly) one length. The
// chords of equal arcs differ by the curvature, chord = arc (1 - arc^2 / (24 R^2)): with 2 mm arcs
// and radii of curvature between a^2/b = 10.7 mm and b^2/a = 36 mm that is 1.5e-3 to 1.3e-4, so
// the lengths agree to 2e-3 and their sum is half the ellipse's perimeter less at most 1.5e-3.
TEST(JellyfishBell, ChainSegmentsAreEqualInArcLength) {
  const BellParams p = paperBell();
  const BellModel m = buildBell(p);
  const auto& x = m.rest_positions_m;
  double shortest = 1, longest = 0, total = 0;
  for (int i = 0; i + 1 < m.bell_markers; ++i) {
    const double l = distance(x[i], x[i + 1]);
    shortest = std::min(shortest, l);
    longest = std::max(longest, l);
    total += l;
  }
  const double half_perimeter = 0.5 * ellipsePerimeter(0.016, 0.024);
  EXPECT_LT(longest / shortest - 1, 2e-3) << shortest << " .. " << longest;
  EXPECT_LT(total, half_perimeter);
  EXPECT_GT(total, half_perimeter * (1 - 1.5e-3));
  // The flesh's area in the slice is that arc length times the thickness.
  EXPECT_NEAR(m.bell_area_m2, total * p.thickness_m, 1e-3 * m.bell_area_m2);
}

// Constants from continuum properties (§3.2, per metre of depth, jellyfish_params.hpp): k = E t / L
// for each chain spring of the bell (λ = 1186 Pa, t = 4 mm); an angular spring B / L_joint at each
// joint (L_joint the mean of its two segments), so that the 32-segment chain keeps Fig. 12's
// 1.186 N·m/rad; the tentacles have "the same elastic modulus, but with a volume 1/100th" (§3.2,
// Fig. 12 area factor 1/100): k L = E t / 100 and B / 100; each muscle element carries its arc
// of the band, k ℓ = E_m s w and T_max w.
TEST(JellyfishBell, SpringConstantsFollowModulusThicknessOverLength) {
  const BellParams p = paperBell();
  const BellModel m = buildBell(p);
  const auto& net = m.network;
  int bell_springs = 0, tentacle_springs = 0;
  for (int e = 0; e < net.springCount(); ++e) {
    const double kl = net.stiffness_n_per_m[e] * net.rest_length_m[e];
    const bool tentacle = isTentacle(m, net.spring_a[e]) || isTentacle(m, net.spring_b[e]);
    const double expected = p.bell_modulus_pa * p.thickness_m * (tentacle ? p.tentacle_area_factor : 1.0);
    EXPECT_NEAR(kl, expected, 1e-14 * expected) << "spring " << e;
    EXPECT_NEAR(net.rest_length_m[e],
                distance(m.rest_positions_m[net.spring_a[e]], m.rest_positions_m[net.spring_b[e]]), 1e-18)
        << "spring " << e << " rest length is the drawn length";
    (tentacle ? tentacle_springs : bell_springs)++;
  }
  EXPECT_EQ(bell_springs, p.segments);
  EXPECT_EQ(tentacle_springs, static_cast<int>(m.tentacle_markers.size()));
  // Tentacle segments (2 mm) are about as long as the bell's (1.98 mm): their springs are ~1/100 as stiff.
  const double tentacle_k = net.stiffness_n_per_m[p.segments];
  EXPECT_NEAR(tentacle_k / net.stiffness_n_per_m[0], 0.01, 0.01 * 0.02);

  const auto& x = m.rest_positions_m;
  for (int e = 0; e < net.bendCount(); ++e) {
    const bool tentacle = isTentacle(m, net.bend_i[e]) || isTentacle(m, net.bend_k[e]);
    const double joint_m = 0.5 * (distance(x[net.bend_i[e]], x[net.bend_j[e]]) + distance(x[net.bend_j[e]], x[net.bend_k[e]]));
    const double expected = p.bending_rigidity_n_m * (tentacle ? p.tentacle_area_factor : 1.0);
    EXPECT_NEAR(net.bend_stiffness_nm_per_rad[e] * joint_m, expected, 1e-14 * expected) << "bend " << e;
    // Chords of the arc-equal markers differ from 1.983 mm by up to 0.16%.
    if (!tentacle) {
      EXPECT_NEAR(net.bend_stiffness_nm_per_rad[e], 1.186, 1.186 * 2e-3) << "Fig. 12 at 32 segments";
    }
  }

  // The band covers 0.875 of the half-arc: elements at markers 0..14 of 16, half weight at the ends.
  ASSERT_EQ(static_cast<int>(m.muscles.size()), 15);
  double band_m = 0;
  for (const MuscleSpring& s : m.muscles) {
    EXPECT_NEAR(s.stiffness_n_per_m * s.relaxed_length_m, p.muscle_modulus_pa * p.muscle_section_per_arc * s.arc_weight_m,
                1e-15);
    EXPECT_NEAR(s.tension_max_n_per_m, p.muscle_tension_n_per_m2 * s.arc_weight_m, 1e-18);
    EXPECT_NEAR(s.relaxed_length_m, distance(m.rest_positions_m[s.a], m.rest_positions_m[s.b]), 1e-18);
    band_m += s.arc_weight_m;
  }
  EXPECT_NEAR(band_m, p.muscle_band_fraction * m.apex * m.segment_m, 1e-15);
  EXPECT_NEAR(m.muscles[0].arc_weight_m, 0.5 * m.segment_m, 1e-18);
  EXPECT_NEAR(m.muscles.back().arc_weight_m, 0.5 * m.segment_m, 1e-15);
  // Fig. 4's aperture spring, a 0.1 mm layer every two segments across 32 mm: 1250 N/m, here
  // carried by the elements around the aperture (half of it by the half-weight aperture element).
  EXPECT_NEAR(m.muscles[0].stiffness_n_per_m, 0.25 * 1250.0, 1.0);
}

// The circumferential muscle (Fig. 4): elements across the bell between opposite points, at every
// marker of the band from the aperture toward the apex; the stagger's coordinate runs from 1 at
// the aperture to 0 at the apex, Spencer's delay order from 0 at the aperture (§3.1).
TEST(JellyfishBell, MusclesSpanTheBellFromApertureTowardApex) {
  const BellParams p = paperBell();
  const BellModel m = buildBell(p);
  for (int k = 0; k < static_cast<int>(m.muscles.size()); ++k) {
    const MuscleSpring& s = m.muscles[k];
    EXPECT_EQ(s.a, k);
    EXPECT_EQ(s.order_from_aperture, k);
    EXPECT_NEAR(s.aperture_position, 1.0 - double(s.a) / m.apex, 1e-15);
    EXPECT_GT(s.aperture_position, 0.0);
    EXPECT_LE(s.aperture_position, 1.0);
    if (k > 0) {
      EXPECT_LT(s.relaxed_length_m, m.muscles[k - 1].relaxed_length_m) << "muscles shorten toward the apex";
      EXPECT_LT(s.aperture_position, m.muscles[k - 1].aperture_position);
    }
  }
  EXPECT_EQ(m.muscles[0].aperture_position, 1.0);
  EXPECT_NEAR(m.muscles[0].relaxed_length_m, m.aperture_width_m, 1e-18);
}

// Topology: a chain of `segments` springs with a bend at each of its segments - 1 interior joints;
// each tentacle a chain of equal springs hanging straight down 20 mm from an aperture point, with
// bends along it and one where it leaves the bell; the network passes its own validation.
TEST(JellyfishBell, NetworkTopologyAndTentacles) {
  const BellParams p = paperBell();
  const BellModel m = buildBell(p);
  const auto& x = m.rest_positions_m;
  const int per_side = static_cast<int>(m.tentacle_markers.size()) / 2;
  EXPECT_EQ(per_side, 10);  // 20 mm in segments as long as the bell's 1.98 mm
  EXPECT_EQ(m.network.particleCount(), p.segments + 1 + 2 * per_side);
  EXPECT_EQ(static_cast<int>(x.size()), m.network.particleCount());
  EXPECT_EQ(m.network.springCount(), p.segments + 2 * per_side);
  EXPECT_EQ(m.network.bendCount(), (p.segments - 1) + 2 * (per_side - 1) + 2);
  EXPECT_EQ(m.network.validate(), "");
  for (int side = 0; side < 2; ++side) {
    const fluid::Vec2 root = x[side == 0 ? 0 : p.segments];
    const fluid::Vec2 tip = x[m.tentacle_markers[side * per_side + per_side - 1]];
    EXPECT_EQ(tip.x, root.x);
    EXPECT_NEAR(root.y - tip.y, p.tentacle_length_m, 1e-15);
  }
  BellParams bare = p;
  bare.tentacles = false;
  const BellModel b = buildBell(bare);
  EXPECT_TRUE(b.tentacle_markers.empty());
  EXPECT_EQ(b.network.particleCount(), p.segments + 1);
  EXPECT_EQ(b.network.springCount(), p.segments);
  EXPECT_EQ(b.network.bendCount(), p.segments - 1);
}

// Several tentacles a side: chains from the aperture and from bell markers a root spacing apart toward
// the apex, the left ones then their mirror images (marker k of the left half mirrors k of the right);
// each chain a bend where it leaves the bell. Roots that do not fit on the half bell are refused.
TEST(JellyfishBell, SeveralTentaclesPerSideHangFromSpacedRoots) {
  BellParams p = paperBell();
  p.tentacles_per_side = 3;
  p.tentacle_root_spacing_m = 4e-3;  // two segments of 1.98 mm
  const BellModel m = buildBell(p);
  const auto& x = m.rest_positions_m;
  ASSERT_EQ(m.tentacle_chains.size(), 6u);
  const int per_chain = 10;
  EXPECT_EQ(static_cast<int>(m.tentacle_markers.size()), 6 * per_chain);
  const int roots[6] = {0, 2, 4, p.segments, p.segments - 2, p.segments - 4};
  for (int c = 0; c < 6; ++c) {
    EXPECT_EQ(m.tentacle_chains[c].front(), roots[c]) << "chain " << c;
    EXPECT_EQ(static_cast<int>(m.tentacle_chains[c].size()), per_chain + 1);
    EXPECT_EQ(x[m.tentacle_chains[c].back()].x, x[roots[c]].x);
  }
  const std::size_t half = m.tentacle_markers.size() / 2;
  for (std::size_t j = 0; j < half; ++j) {
    EXPECT_EQ(x[m.tentacle_markers[j]].x, -x[m.tentacle_markers[half + j]].x);
    EXPECT_EQ(x[m.tentacle_markers[j]].y, x[m.tentacle_markers[half + j]].y);
  }
  EXPECT_EQ(m.network.bendCount(), (p.segments - 1) + 6 * (per_chain - 1) + 6);
  EXPECT_EQ(m.network.validate(), "");
  p.tentacles_per_side = 5;
  p.tentacle_root_spacing_m = 8e-3;  // the fifth root 16 segments in: the apex
  EXPECT_THROW((void)buildBell(p), std::invalid_argument);
}

// The bell as drawn is its rest shape: every spring at its rest length and every bend at its rest
// angle, so the network's elastic force and energy vanish there (up to round-off); a small
// deformation does give a force (the check is not vacuous).
TEST(JellyfishBell, RestShapeHasZeroElasticForce) {
  const BellModel m = buildBell(paperBell());
  const springs::System<2> system(m.network);
  springs::State<2> s = springs::zeroState<2>(m.network.particleCount());
  for (std::size_t i = 0; i < m.rest_positions_m.size(); ++i)
    s.x_m.col(static_cast<long>(i)) << m.rest_positions_m[i].x, m.rest_positions_m[i].y;
  springs::Points<2> f;
  system.conservativeForces(s, f);
  EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(system.elasticEnergy(s), 1e-24);
  s.x_m(0, m.apex) += 1e-4;
  system.conservativeForces(s, f);
  EXPECT_GT(f.cwiseAbs().maxCoeff(), 1e-2);
}

// Unusable parameters are refused with validate()'s words.
TEST(JellyfishBell, BuildRefusesBadParametersWithTheReason) {
  BellParams p = paperBell();
  p.segments = 31;
  try {
    (void)buildBell(p);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("segments must be even"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace creaturelab::jellyfish
