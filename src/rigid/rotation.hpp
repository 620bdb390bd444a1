#pragma once
// Unit quaternions in MuJoCo's convention (w, x, y, z), for ball joints: a ball joint's
// qpos is the quaternion of its body relative to the parent, its three qvel are the angular
// velocity in the body's own frame, and MuJoCo integrates q <- q * exp(h omega). A rotation by
// the vector r (axis times angle, body frame) is therefore q * exp(r); log inverts exp.
#include <array>

#include "rigid/rigid_model.hpp"

namespace creaturelab::rigid {

using Quat = std::array<double, 4>;

Quat quatMultiply(const Quat& a, const Quat& b);
Quat quatConjugate(const Quat& q);
// exp of the rotation vector r (rad): the unit quaternion of a rotation by |r| about r.
Quat quatExp(const Vec3& r);
// The rotation vector (rad, |r| <= pi) of a unit quaternion: quatExp(quatLog(q)) = +-q.
Vec3 quatLog(const Quat& q);
// The rotation (body frame of a) that carries a to b: log(conj(a) * b).
Vec3 quatDifference(const Quat& a, const Quat& b);
// a rotated by the body-frame rotation vector r, renormalised: a * exp(r).
Quat quatRotate(const Quat& a, const Vec3& r);

}  // namespace creaturelab::rigid
