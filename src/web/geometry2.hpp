#pragma once
// Small plane-geometry helpers for the web construction (frame checks, hub, spiral free zone).
// Points are Eigen::Vector2d in metres.
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace creaturelab::web {

using Point2 = Eigen::Vector2d;

// z component of the cross product a x b.
inline double cross2(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

// True when the closed segments [p1, p2] and [q1, q2] share at least one point (touching counts).
bool segmentsIntersect(const Point2& p1, const Point2& p2, const Point2& q1, const Point2& q2);

// Pair (i, j), i < j, of two non-adjacent edges of the closed polygon that intersect; edge i joins
// vertex i to vertex i+1 (mod n). std::nullopt for a simple polygon.
std::optional<std::pair<int, int>> firstSelfIntersection(const std::vector<Point2>& polygon);

// Even-odd rule; points on the boundary may go either way.
bool pointInPolygon(const Point2& p, const std::vector<Point2>& polygon);

// Distance from p to the closed segment [a, b].
double distanceToSegment(const Point2& p, const Point2& a, const Point2& b);

// The point nearest (least squares) to every line i, line i passing through a[i] and b[i]:
//   minimise sum_i |(I - u_i u_i^T)(x - a_i)|^2,  u_i = (b_i - a_i)/|b_i - a_i|,
// i.e. solve sum_i (I - u_i u_i^T) x = sum_i (I - u_i u_i^T) a_i. With one line, or with every line
// parallel, the system is singular: the mean of the midpoints is returned instead.
Point2 leastSquaresIntersection(const std::vector<Point2>& a, const std::vector<Point2>& b);

}  // namespace creaturelab::web
