// Properties of the built web (Mehla 2005 §5.2): determinism, strand types,
// pinning, spring lengths, counts, the hub's free zone, spokes and the frame's inward force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "web/build.hpp"
#include "web/measure.hpp"

namespace web = creaturelab::web;

namespace {

const web::WebModel& defaultWeb() {
  static const web::WebModel m = web::build(web::WebParams{});
  return m;
}

double laidLength(const web::WebModel& m, int s) {
  return (m.state.x_m.col(m.network.spring_a[s]) - m.state.x_m.col(m.network.spring_b[s])).norm();
}

// Bitwise equality of everything build() returns.
bool identical(const web::WebModel& a, const web::WebModel& b) {
  const auto &na = a.network, &nb = b.network;
  if (na.particleCount() != nb.particleCount() || na.springCount() != nb.springCount()) return false;
  return na.mass_kg == nb.mass_kg && na.pinned == nb.pinned && na.spring_a == nb.spring_a && na.spring_b == nb.spring_b &&
         na.rest_length_m == nb.rest_length_m && na.stiffness_n_per_m == nb.stiffness_n_per_m &&
         na.damping_ns_per_m == nb.damping_ns_per_m && na.gravity_m_per_s2 == nb.gravity_m_per_s2 &&
         na.drag_ns_per_m == nb.drag_ns_per_m && a.state.x_m == b.state.x_m && a.state.v_m_per_s == b.state.v_m_per_s &&
         a.spring_type == b.spring_type && a.external_force_n == b.external_force_n && a.hub_particles == b.hub_particles &&
         a.spokes == b.spokes && a.inner_frame_particles == b.inner_frame_particles;
}

int firstSpringOf(const web::WebModel& m, web::StrandType t) {
  const auto it = std::find(m.spring_type.begin(), m.spring_type.end(), t);
  return static_cast<int>(it - m.spring_type.begin());
}

}  // namespace

TEST(WebBuild, NetworkIsValidAndAtRestInThePlane) {
  const auto& m = defaultWeb();
  EXPECT_EQ(m.network.validate(), "");
  EXPECT_EQ(m.state.x_m.cols(), m.network.particleCount());
  EXPECT_EQ(m.state.x_m.row(2).cwiseAbs().maxCoeff(), 0.0);  // laid in z = 0
  EXPECT_EQ(m.state.v_m_per_s.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(m.network.gravity_m_per_s2, creaturelab::springs::Vec<3>(0, -9.81, 0));
  EXPECT_EQ(m.network.drag_ns_per_m, 1e-8);
  EXPECT_TRUE((m.network.mass_kg.array() == 1e-8).all());
}

TEST(WebBuild, TwoBuildsAreIdentical) {
  const auto a = web::build(web::WebParams{});
  EXPECT_TRUE(identical(a, defaultWeb()));
}

TEST(WebBuild, SeedsChangeOnlyTheRandomChoices) {
  web::WebParams p;
  p.seed = 2;
  const auto other = web::build(p);
  const auto& base = defaultWeb();
  EXPECT_FALSE(identical(base, other));
  // Frame, primary spokes and hub are laid before the first random choice: the same, spring for spring.
  const int first_random = firstSpringOf(base, web::StrandType::secondary_spoke);
  ASSERT_EQ(first_random, firstSpringOf(other, web::StrandType::secondary_spoke));
  for (int s = 0; s < first_random; ++s) {
    ASSERT_EQ(base.network.spring_a[s], other.network.spring_a[s]);
    ASSERT_EQ(base.network.spring_b[s], other.network.spring_b[s]);
    ASSERT_EQ(base.network.rest_length_m[s], other.network.rest_length_m[s]);
    ASSERT_EQ(base.state.x_m.col(base.network.spring_a[s]), other.state.x_m.col(other.network.spring_a[s]));
  }
  EXPECT_EQ(base.hub_particles.front(), other.hub_particles.front());
  // Without randomness (closest hub mass, no spiral jitter) the seed has no effect at all.
  web::WebParams q;
  q.hub_attach_choices = 1;
  q.spiral_jitter = 0;
  const auto q1 = web::build(q);
  q.seed = 12345;
  EXPECT_TRUE(identical(q1, web::build(q)));
}

TEST(WebBuild, EverySpringHasATypeAndEveryTypeOccurs) {
  const auto& m = defaultWeb();
  ASSERT_EQ(m.spring_type.size(), static_cast<size_t>(m.network.springCount()));
  std::set<web::StrandType> seen(m.spring_type.begin(), m.spring_type.end());
  EXPECT_EQ(seen.size(), static_cast<size_t>(web::kStrandTypeCount));
  for (auto t : web::kAllStrandTypes) EXPECT_FALSE(web::strandTypeName(t).empty());
  EXPECT_EQ(web::strandTypeName(web::StrandType::secondary_spoke), "secondary_spoke");
}

TEST(WebBuild, OnlyTheAttachmentParticlesArePinned) {
  const auto& m = defaultWeb();
  const web::WebParams p;
  ASSERT_EQ(m.attachment_particles.size(), p.attachment_points_m.size());
  for (size_t i = 0; i < m.attachment_particles.size(); ++i) {
    const int a = m.attachment_particles[i];
    EXPECT_EQ(m.network.pinned[a], 1);
    EXPECT_EQ(m.state.x_m.col(a).head<2>(), p.attachment_points_m[i]);
  }
  EXPECT_EQ(std::count(m.network.pinned.begin(), m.network.pinned.end(), 1),
            static_cast<long>(m.attachment_particles.size()));
  // Each anchor has exactly one spring, an outer-frame one.
  for (int a : m.attachment_particles) {
    int n = 0;
    for (int s = 0; s < m.network.springCount(); ++s)
      if (m.network.spring_a[s] == a || m.network.spring_b[s] == a) {
        ++n;
        EXPECT_EQ(m.spring_type[s], web::StrandType::outer_frame);
      }
    EXPECT_EQ(n, 1);
  }
}

TEST(WebBuild, NoSpringOfZeroLengthAndNoneLaidCompressed) {
  const auto& m = defaultWeb();
  double shortest = INFINITY;
  for (int s = 0; s < m.network.springCount(); ++s) {
    const double len = laidLength(m, s);
    shortest = std::min(shortest, len);
    EXPECT_GE(len, m.network.rest_length_m[s] * (1 - 1e-12)) << "spring " << s << " laid compressed";
    EXPECT_NE(m.network.spring_a[s], m.network.spring_b[s]);
  }
  EXPECT_GT(shortest, 1e-3);  // 1 mm: no strand joins two nearly coincident masses
}

TEST(WebBuild, SpringsKeepTheirTypesOverExtension) {
  // web_params.hpp: every spring of a type starts at placement / rest - 1.
  const auto& m = defaultWeb();
  const web::WebParams p;
  for (int s = 0; s < m.network.springCount(); ++s) {
    double ratio = 0;
    switch (m.spring_type[s]) {
      case web::StrandType::outer_frame: ratio = p.outer_frame_placement_m / p.outer_frame_rest_length_m; break;
      case web::StrandType::inner_frame: ratio = p.frame_placement_m / p.frame_rest_length_m; break;
      case web::StrandType::spiral: ratio = p.spiral_placement_m / p.spiral_rest_length_m; break;
      default: ratio = p.spoke_placement_m / p.spoke_rest_length_m;
    }
    ASSERT_NEAR(laidLength(m, s) / m.network.rest_length_m[s], ratio, 1e-9 * ratio) << "spring " << s;
  }
  web::WebParams q;
  q.overextension = 1.5;
  const auto o = web::build(q);
  for (int s = 0; s < o.network.springCount(); s += 97) EXPECT_NEAR(laidLength(o, s) / o.network.rest_length_m[s], 2.5, 1e-9);
}

TEST(WebBuild, CountsAreConsistent) {
  const auto& m = defaultWeb();
  const auto& c = m.counts;
  EXPECT_EQ(c.particles, m.network.particleCount());
  EXPECT_EQ(c.springs, m.network.springCount());
  EXPECT_EQ(c.spokes, static_cast<int>(m.spokes.size()));
  EXPECT_EQ(c.spiral_springs, std::count(m.spring_type.begin(), m.spring_type.end(), web::StrandType::spiral));
  EXPECT_GE(c.spiral_springs, c.spiral_segments);
  EXPECT_GT(c.spiral_segments, 0);
  const int secondary_radii = c.spokes - 2 * c.primary_spokes;
  EXPECT_GT(secondary_radii, 0);
  double rest = 0, laid = 0;
  for (int s = 0; s < m.network.springCount(); ++s) rest += m.network.rest_length_m[s], laid += laidLength(m, s);
  EXPECT_NEAR(c.silk_length_m, rest, 1e-9 * rest);
  EXPECT_NEAR(c.silk_laid_length_m, laid, 1e-9 * laid);
  EXPECT_NEAR(c.web_mass_kg, 1e-8 * c.particles, 1e-20 * c.particles);
  // A connected web: a spring network of P particles needs at least P - 1 springs.
  EXPECT_GE(c.springs, c.particles - 1);
}

TEST(WebBuild, SpiralStopsShortOfTheHub) {
  // Thesis §5.2: the spiral ends "a little distance away from the hub", here spiral_free_masses masses
  // short of the hub end of each radius (web_params.hpp).
  const auto& m = defaultWeb();
  const web::WebParams p;
  std::set<int> on_spiral;
  double nearest = INFINITY;
  for (int s = 0; s < m.network.springCount(); ++s) {
    if (m.spring_type[s] != web::StrandType::spiral) continue;
    for (int q : {m.network.spring_a[s], m.network.spring_b[s]}) {
      on_spiral.insert(q);
      nearest = std::min(nearest, (m.state.x_m.col(q).head<2>() - m.hub_centre_m).norm());
    }
  }
  double zone = 0;  // the free zone: the disc through the farthest hub-end mass left free
  int touched_next = 0;
  for (const auto& r : m.spokes) {
    const int size = static_cast<int>(r.size());
    for (int i = std::max(0, size - p.spiral_free_masses); i < size; ++i) {
      EXPECT_FALSE(on_spiral.count(r[i])) << "hub-end mass " << size - i << " of a radius is on the spiral";
      zone = std::max(zone, (m.state.x_m.col(r[i]).head<2>() - m.hub_centre_m).norm());
    }
    if (size - p.spiral_free_masses - 1 >= 1) touched_next += on_spiral.count(r[size - p.spiral_free_masses - 1]);
  }
  EXPECT_GE(nearest, zone);
  // ...but the spiral reaches the first mass outside the zone on most radii.
  EXPECT_GT(touched_next, static_cast<int>(m.spokes.size()) / 2);
  EXPECT_NEAR(zone, p.hub_radius_m + p.spiral_free_masses * p.spoke_placement_m, 2 * p.spoke_placement_m);
}

TEST(WebBuild, SpokesRunFromTheFrameToTheHub) {
  const auto& m = defaultWeb();
  std::set<int> frame(m.inner_frame_particles.begin(), m.inner_frame_particles.end());
  std::set<int> hub(m.hub_particles.begin(), m.hub_particles.end());
  std::set<std::pair<int, int>> spoke_springs;
  for (int s = 0; s < m.network.springCount(); ++s)
    if (m.spring_type[s] == web::StrandType::primary_spoke || m.spring_type[s] == web::StrandType::secondary_spoke)
      spoke_springs.insert(std::minmax(m.network.spring_a[s], m.network.spring_b[s]));
  double previous_angle = -INFINITY;
  for (const auto& r : m.spokes) {
    ASSERT_GE(r.size(), 2u);
    EXPECT_TRUE(frame.count(r.front()));
    EXPECT_TRUE(hub.count(r.back()));
    for (size_t i = 0; i + 1 < r.size(); ++i) EXPECT_TRUE(spoke_springs.count(std::minmax(r[i], r[i + 1])));
    const Eigen::Vector2d d = m.state.x_m.col(r.front()).head<2>() - m.hub_centre_m;
    const double angle = std::atan2(d.y(), d.x());
    EXPECT_GE(angle, previous_angle);  // in order of angle about the hub
    previous_angle = angle;
  }
  EXPECT_GE(m.hub_particles.size(), 4u);  // at least two primary spokes, two arms each
  EXPECT_GE(m.counts.primary_spokes, 2);
}

TEST(WebBuild, InwardForceActsOnTheInnerFrameOnly) {
  const auto& m = defaultWeb();
  const web::WebParams p;
  std::set<int> frame(m.inner_frame_particles.begin(), m.inner_frame_particles.end());
  double total = 0, perimeter = 0;
  const int n = static_cast<int>(m.inner_frame_particles.size());
  for (int i = 0; i < n; ++i)
    perimeter += (m.state.x_m.col(m.inner_frame_particles[(i + 1) % n]) - m.state.x_m.col(m.inner_frame_particles[i])).norm();
  for (int q = 0; q < m.network.particleCount(); ++q) {
    const Eigen::Vector3d f = m.external_force_n.col(q);
    if (!frame.count(q)) {
      EXPECT_EQ(f.norm(), 0.0);
      continue;
    }
    total += f.norm();
    const Eigen::Vector2d inward = (m.centre_m - m.state.x_m.col(q).head<2>()).normalized();
    EXPECT_NEAR(f.head<2>().normalized().dot(inward), 1.0, 1e-12);
    EXPECT_EQ(f.z(), 0.0);
  }
  EXPECT_NEAR(total, p.inner_frame_inward_force_n_per_m * perimeter, 1e-12 * total);
}

TEST(WebBuild, HubSagOfTheLaidWebIsZero) {
  const auto& m = defaultWeb();
  EXPECT_EQ(web::hubSagM(m, m.state), 0.0);
  EXPECT_GT(web::meanStrain(m, m.state, web::StrandType::primary_spoke), 1.0);  // laid 7 mm over 3 mm rest
}
