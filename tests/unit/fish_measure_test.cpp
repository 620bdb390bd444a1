// What the experiments measure on a record (fish_measure.hpp), on hand-made centre-of-mass tracks:
// a turn from a swimming start (direction of travel before the first non-swim item against the
// run's last window) and the settled drift and heading change of a straight swim.
#include <gtest/gtest.h>

#include <cmath>

#include "fish/fish_measure.hpp"

namespace creaturelab::fish {
namespace {

// A record of a centre of mass at (x(t), y(t)), one frame every 0.1 s.
template <class Path>
FishRecord track(double end_s, Path path) {
  FishRecord rec;
  for (int f = 0; f * 0.1 <= end_s + 1e-9; ++f) {
    const double t = f * 0.1;
    const auto [x, y] = path(t);
    rec.time_s.push_back(t);
    rec.com_m.insert(rec.com_m.end(), {x, y, 0.0});
    rec.heading_rad.push_back(0.0);
  }
  return rec;
}

TEST(FishMeasure, TravelTurnIsTheChangeOfDirectionAndPathOverItsAngle) {
  // Straight along +x at 1 m/s for 10 s, a quarter circle of radius 2 m to the left over the 5 s
  // item (pi m of path), then straight along +y.
  const double v = M_PI / 5;  // path speed on the arc
  const FishRecord rec = track(25, [&](double t) -> std::pair<double, double> {
    if (t <= 10) return {t, 0.0};
    if (t <= 15) return {10 + 2 * std::sin(v * (t - 10) / 2), 2 - 2 * std::cos(v * (t - 10) / 2)};
    return {12.0, 2 + (t - 15)};
  });
  const auto schedule = parseSchedule("swim 10; left 5; swim 10");
  const TravelTurn m = measureTravelTurn(rec, schedule, 2.0);
  ASSERT_TRUE(m.found);
  EXPECT_NEAR(m.heading_change_deg, 90.0, 1e-9);
  EXPECT_NEAR(m.path_m, M_PI, 2e-3);  // a polygon of 50 chords
  EXPECT_NEAR(m.radius_m, 2.0, 2e-3);
  // no full window before the item, or after it: not measured
  EXPECT_FALSE(measureTravelTurn(rec, schedule, 11.0).found);
  EXPECT_FALSE(measureTravelTurn(track(25, [](double t) { return std::pair{t, 0.0}; }), parseSchedule("swim 25"), 2.0).found);
}

TEST(FishMeasure, SettledDriftIgnoresTheStartButSeesACurve) {
  // The start turns the path by 0.1 rad in its first 5 s, then it runs straight on that heading:
  // large whole-run drift, zero settled drift and turn.
  const FishRecord straight = track(60, [](double t) {
    return t < 5 ? std::pair{t, 0.0} : std::pair{5 + (t - 5) * std::cos(0.1), (t - 5) * std::sin(0.1)};
  });
  const SwimMeasures a = measureSwim(straight, 1.0, 10.0, 5.0);
  EXPECT_GT(a.lateral_drift_fraction, 0.08);
  EXPECT_NEAR(a.settled_lateral_drift_fraction, 0.0, 1e-12);
  EXPECT_NEAR(a.settled_heading_change_deg, 0.0, 1e-9);
  // A slow left circle: its settled direction turns.
  const FishRecord circle = track(60, [](double t) { return std::pair{100 * std::sin(t / 100), 100 - 100 * std::cos(t / 100)}; });
  const SwimMeasures b = measureSwim(circle, 1.0, 10.0, 5.0);
  EXPECT_NEAR(b.settled_heading_change_deg, (55.0 - 10.0) / 100 * 180 / M_PI, 1e-9);
  EXPECT_GT(b.settled_lateral_drift_fraction, 0.1);
  // no window given: not measured
  EXPECT_TRUE(std::isnan(measureSwim(circle, 1.0, 10.0).settled_heading_change_deg));
}

}  // namespace
}  // namespace creaturelab::fish
