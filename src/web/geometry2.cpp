#include "web/geometry2.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace creaturelab::web {
namespace {

// Sign of the turn a -> b -> c: +1 left, -1 right, 0 collinear.
int orientation(const Point2& a, const Point2& b, const Point2& c) {
  const double v = cross2(b - a, c - a);
  return (v > 0) - (v < 0);
}

// q lies on segment [a, b], given that a, b, q are collinear.
bool onSegment(const Point2& a, const Point2& b, const Point2& q) {
  return q.x() <= std::max(a.x(), b.x()) && q.x() >= std::min(a.x(), b.x()) && q.y() <= std::max(a.y(), b.y()) &&
         q.y() >= std::min(a.y(), b.y());
}

}  // namespace

bool segmentsIntersect(const Point2& p1, const Point2& p2, const Point2& q1, const Point2& q2) {
  const int o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
  const int o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && onSegment(p1, p2, q1)) || (o2 == 0 && onSegment(p1, p2, q2)) ||
         (o3 == 0 && onSegment(q1, q2, p1)) || (o4 == 0 && onSegment(q1, q2, p2));
}

std::optional<std::pair<int, int>> firstSelfIntersection(const std::vector<Point2>& polygon) {
  const int n = static_cast<int>(polygon.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) continue;
      if (segmentsIntersect(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n])) return {{i, j}};
    }
  return std::nullopt;
}

bool pointInPolygon(const Point2& p, const std::vector<Point2>& polygon) {
  bool inside = false;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

double distanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

Point2 leastSquaresIntersection(const std::vector<Point2>& a, const std::vector<Point2>& b) {
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  Point2 rhs = Point2::Zero(), mean = Point2::Zero();
  for (size_t i = 0; i < a.size(); ++i) {
    const Point2 u = (b[i] - a[i]).normalized();
    const Eigen::Matrix2d proj = Eigen::Matrix2d::Identity() - u * u.transpose();
    m += proj;
    rhs += proj * a[i];
    mean += 0.5 * (a[i] + b[i]);
  }
  if (!a.empty()) mean /= static_cast<double>(a.size());
  // det(m) = 0 exactly for parallel lines; relative test against the scale of m (trace = number of lines).
  if (a.size() < 2 || std::fabs(m.determinant()) <= 1e-9 * m.trace() * m.trace()) return mean;
  return m.inverse() * rhs;
}

}  // namespace creaturelab::web
