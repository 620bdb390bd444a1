// What a web run measures (web/web_run.hpp) and the thesis's wind (web/wind_gen.hpp, Mehla 2005
// Fig. 5.45) on the default web as laid, without stepping it.
#include <gtest/gtest.h>

#include <cmath>

#include "web/build.hpp"
#include "web/measure.hpp"
#include "web/web_run.hpp"
#include "web/wind_gen.hpp"

namespace web = creaturelab::web;

namespace {

const web::WebModel& laidWeb() {
  static const web::WebModel m = web::build(web::WebParams{});
  return m;
}

}  // namespace

// windgen: z = -WIND sin(degree) with degree counted in degrees from 0; x = y = -r z with one
// random factor r in [-3, 3] held for 50 calls.
TEST(WebWind, WindgenFollowsFigure545) {
  web::WindGen g{2.0, 7};
  g.next();
  EXPECT_EQ(g.z, 0.0);
  double r = 0;
  for (int deg = 1; deg < 50; ++deg) {
    g.next();
    EXPECT_NEAR(g.z, -2.0 * std::sin(deg * M_PI / 180.0), 1e-15);
    EXPECT_EQ(g.x, g.y);
    if (deg == 1) r = -g.x / g.z;
    EXPECT_NEAR(-g.x / g.z, r, 1e-12);
  }
  EXPECT_GE(r, -3.0);
  EXPECT_LE(r, 3.0);
  g.next();  // call 50 draws a new factor
  EXPECT_NE(-g.x / g.z, r);
}

// The force is zero before the first call, then windgen's vector times a weight that is 1 at the
// hub and grows as exp(distance / (50 web radii)), so at most e^(1/50) on the web.
TEST(WebWind, ForceIsWindgenWeightedByDistanceToTheHub) {
  const web::WebModel& m = laidWeb();
  web::WebWind wind(m, m.state, {1.0, 3});
  EXPECT_EQ(wind.force_n().cwiseAbs().maxCoeff(), 0.0);
  wind.next();
  wind.next();
  web::WindGen g{1.0, 3};
  g.next();
  g.next();
  const Eigen::Vector3d w(g.x, g.y, g.z);
  for (int i = 0; i < wind.force_n().cols(); ++i) {
    const double weight = wind.force_n().col(i).norm() / w.norm();
    EXPECT_GE(weight, 1.0 - 1e-12);
    EXPECT_LE(weight, std::exp(1.0 / 50) + 1e-12);
    EXPECT_NEAR(wind.force_n().col(i).dot(w) / (wind.force_n().col(i).norm() * w.norm()), 1.0, 1e-12);
  }
}

// A web held as laid: no sag, no displacement, positions every k-th frame only.
TEST(WebRunRecorder, AWebAtRestSwaysByNothing) {
  const web::WebModel& m = laidWeb();
  web::WebRunRecorder rec(m, web::hubPositionM(m, m.state), 3);
  EXPECT_TRUE(std::isnan(rec.hubRmsDisplacement_m()));
  for (int f = 0; f < 7; ++f) rec.record(f, 0.02 * f, m.state);
  EXPECT_EQ(rec.hubRmsDisplacement_m(), 0.0);
  EXPECT_EQ(rec.hubSag_m(), std::vector<double>(7, 0.0));
  EXPECT_EQ(rec.positions().time_s, (std::vector<double>{0.0, 0.06, 0.12}));
  EXPECT_EQ(rec.positions().data.size(), 3 * m.state.x_m.size());
}

// The hub lowered by 1 cm in every recorded frame: the sag and the rms displacement are 1 cm.
TEST(WebRunRecorder, HubSagAndDisplacementOfAMovedHub) {
  const web::WebModel& m = laidWeb();
  auto s = m.state;
  for (int h : m.hub_particles) s.x_m(1, h) -= 0.01;
  web::WebRunRecorder rec(m, web::hubPositionM(m, m.state), 1);
  rec.record(0, 0.0, s);
  rec.record(1, 0.02, s);
  EXPECT_NEAR(rec.hubSag_m()[1], 0.01, 1e-12);
  EXPECT_NEAR(rec.hubRmsDisplacement_m(), 0.01, 1e-12);
}

// The measures of the laid web, taken as its own statics: its counts, no sag, the solve and step passed through.
TEST(WebMeasures, OfTheLaidWeb) {
  const web::WebModel& m = laidWeb();
  const creaturelab::springs::EquilibriumResult eq{true, 4, 0, 0};
  const auto measures = web::webMeasures(m, m.network, {m.state, m.state, eq, std::nullopt, 0.001, 0.0});
  auto value = [&](const std::string& name) {
    for (const auto& v : measures)
      if (v.name == name) return v.value;
    ADD_FAILURE() << name << " missing";
    return std::nan("");
  };
  EXPECT_EQ(value("particles"), m.counts.particles);
  EXPECT_EQ(value("hub_sag_m"), 0.0);
  EXPECT_EQ(value("static_iterations"), 4.0);
  EXPECT_TRUE(std::isnan(value("settling_time_s")));
  EXPECT_EQ(value("dt_used_s"), 0.001);
  EXPECT_GT(value("spiral_coverage"), 0.0);
  EXPECT_EQ(web::webTopology(m).at("spring_a").size(), std::size_t(m.network.springCount()));
}
