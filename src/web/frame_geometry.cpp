#include "web/frame_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "web/web_params.hpp"

namespace creaturelab::web {

namespace {
constexpr double kDuplicateM = 1e-3;      // anchors closer than this are the same point
constexpr double kCollinearSine = 1e-3;   // |sin(turning angle)| below this: a straight corner
}  // namespace

Point2 frameCentre(const std::vector<Point2>& pts) {
  Point2 lo = pts.front(), hi = pts.front();
  for (const auto& p : pts) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return 0.5 * (lo + hi);
}

std::vector<Point2> innerFramePoints(const std::vector<Point2>& pts, const Point2& c, double move_outer_m) {
  std::vector<Point2> inner;
  inner.reserve(pts.size());
  for (const auto& p : pts) inner.push_back(p + move_outer_m * (c - p).normalized());
  return inner;
}

std::string validateFrameGeometry(const WebParams& prm) {
  const auto& pts = prm.attachment_points_m;
  const int n = static_cast<int>(pts.size());
  std::ostringstream m;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((pts[i] - pts[j]).norm() < kDuplicateM) {
        m << "attachment points " << i << " and " << j << " are the same point (closer than 1 mm); remove one";
        return m.str();
      }
  for (int i = 0; i < n; ++i) {
    const Point2 a = pts[i], b = pts[(i + 1) % n], c = pts[(i + 2) % n];
    const Point2 u = b - a, v = c - b;
    if (std::fabs(cross2(u, v)) <= kCollinearSine * u.norm() * v.norm()) {
      m << "attachment points " << i << ", " << (i + 1) % n << " and " << (i + 2) % n
        << " are collinear; move one of them off the line (a frame corner needs a bend)";
      return m.str();
    }
  }
  if (const auto cross = firstSelfIntersection(pts)) {
    m << "the frame crosses itself: the side from attachment point " << cross->first << " to "
      << (cross->first + 1) % n << " meets the side from " << cross->second << " to " << (cross->second + 1) % n
      << "; list the points in order around the frame";
    return m.str();
  }
  const Point2 c = frameCentre(pts);
  if (!pointInPolygon(c, pts)) {
    m << "the centre of the attachment points' bounding box (" << c.x() << ", " << c.y()
      << ") m lies outside the frame; the web is built around it (thesis Fig. 5.3)";
    return m.str();
  }
  for (int i = 0; i < n; ++i) {
    const double d = (pts[i] - c).norm();
    if (prm.move_outer_m > 0.5 * d) {
      m << "move_outer_m (" << prm.move_outer_m << " m) is more than half the distance from attachment point " << i
        << " to the centre (" << d << " m); the inner frame would collapse";
      return m.str();
    }
  }
  const auto inner = innerFramePoints(pts, c, prm.move_outer_m);
  if (const auto cross = firstSelfIntersection(inner)) {
    m << "the inner frame crosses itself (sides " << cross->first << " and " << cross->second
      << "); use a smaller move_outer_m or a rounder frame";
    return m.str();
  }
  if (!pointInPolygon(c, inner)) {
    m << "the centre (" << c.x() << ", " << c.y() << ") m lies outside the inner frame; use a smaller move_outer_m";
    return m.str();
  }
  double to_frame = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const Point2 a = inner[i], b = inner[(i + 1) % n];
    const double len = (b - a).norm();
    if (len < 2 * prm.frame_placement_m) {
      m << "inner-frame side " << i << " (from attachment point " << i << " to " << (i + 1) % n << ") is " << len
        << " m long, shorter than two frame placements (" << 2 * prm.frame_placement_m
        << " m); it needs a middle mass for its primary spoke (thesis Fig. 5.10)";
      return m.str();
    }
    to_frame = std::min(to_frame, distanceToSegment(c, a, b));
  }
  // The spiral's free zone: the hub ring plus spiral_free_masses spoke placements, and one more
  // placement for the spiral to start on.
  const double free_zone_m = prm.hub_radius_m + (prm.spiral_free_masses + 1) * prm.spoke_placement_m;
  if (free_zone_m >= to_frame) {
    m << "the spiral's free zone (hub_radius_m + spiral_free_masses + 1 spoke placements = " << free_zone_m
      << " m) reaches the inner frame (" << to_frame << " m from the centre); no spiral would fit";
    return m.str();
  }
  return "";
}

}  // namespace creaturelab::web
