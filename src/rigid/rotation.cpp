#include "rigid/rotation.hpp"

#include <cmath>

namespace creaturelab::rigid {

Quat quatMultiply(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

Quat quatConjugate(const Quat& q) { return {q[0], -q[1], -q[2], -q[3]}; }

Quat quatExp(const Vec3& r) {
  const double angle = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  if (angle == 0) return {1, 0, 0, 0};
  const double s = std::sin(0.5 * angle) / angle;
  return {std::cos(0.5 * angle), s * r[0], s * r[1], s * r[2]};
}

Vec3 quatLog(const Quat& q_in) {
  // The shorter of the two rotations q and -q describe.
  const double sign = q_in[0] < 0 ? -1.0 : 1.0;
  const double w = sign * q_in[0];
  const Vec3 v = {sign * q_in[1], sign * q_in[2], sign * q_in[3]};
  const double s = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (s == 0) return {0, 0, 0};
  const double scale = 2 * std::atan2(s, w) / s;
  return {scale * v[0], scale * v[1], scale * v[2]};
}

Vec3 quatDifference(const Quat& a, const Quat& b) { return quatLog(quatMultiply(quatConjugate(a), b)); }

Quat quatRotate(const Quat& a, const Vec3& r) {
  Quat q = quatMultiply(a, quatExp(r));
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& x : q) x /= n;
  return q;
}

}  // namespace creaturelab::rigid
