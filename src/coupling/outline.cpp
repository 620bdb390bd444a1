#include "coupling/outline.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace creaturelab::coupling {
namespace {

constexpr double kPi = std::numbers::pi;

// A straight segment from a to b (x-z) in n = ceil(length / spacing) markers at the pieces' centres.
void segment(std::vector<OutlineMarker>& out, OutlineMarker base, double ax, double az, double bx, double bz,
             double spacing) {
  const double len = std::hypot(bx - ax, bz - az);
  const int n = std::max(1, int(std::ceil(len / spacing - 1e-12)));
  for (int k = 0; k < n; ++k) {
    const double s = (k + 0.5) / n;
    base.local_m = {ax + s * (bx - ax), 0.0, az + s * (bz - az)};
    base.length_m = len / n;
    out.push_back(base);
  }
}

// An arc of the ellipse (rx cos t, cz + rz sin t) for t in [t0, t1], by arc length approximately
// (n pieces of equal angle, each standing for its chord).
void arc(std::vector<OutlineMarker>& out, OutlineMarker base, double rx, double rz, double cz, double t0, double t1,
         double spacing) {
  const double approx = std::max(rx, rz) * std::abs(t1 - t0);
  const int n = std::max(3, int(std::ceil(approx / spacing - 1e-12)));
  for (int k = 0; k < n; ++k) {
    const double ta = t0 + (t1 - t0) * k / n, tb = t0 + (t1 - t0) * (k + 1) / n, tm = 0.5 * (ta + tb);
    base.local_m = {rx * std::cos(tm), 0.0, cz + rz * std::sin(tm)};
    base.length_m = std::hypot(rx * (std::cos(tb) - std::cos(ta)), rz * (std::sin(tb) - std::sin(ta)));
    out.push_back(base);
  }
}

void rectangle(std::vector<OutlineMarker>& out, const OutlineMarker& base, double sx, double sz, double spacing) {
  segment(out, base, -sx, -sz, sx, -sz, spacing);
  segment(out, base, sx, -sz, sx, sz, spacing);
  segment(out, base, sx, sz, -sx, sz, spacing);
  segment(out, base, -sx, sz, -sx, -sz, spacing);
}

}  // namespace

std::vector<OutlineMarker> outlineMarkers(const rigid::RigidModel& model, const rigid::RigidData& data,
                                          double spacing_m) {
  if (!(spacing_m > 0)) throw std::invalid_argument("marker spacing must be a positive length");
  std::vector<OutlineMarker> out;
  for (int g = 0; g < model.geoms(); ++g) {
    const int type = model.geomType(g);
    if (type == 0 || type == 1) continue;  // plane, height field: no volume
    const double* R = data.geomRotation(g);  // row-major; column 1 is the geom's y axis in world
    if (std::abs(std::abs(R[4]) - 1.0) > 1e-9)
      throw std::invalid_argument("geom " + std::to_string(g) + " of body '" + model.bodyName(model.geomBody(g)) +
                                  "' is not planar: its y axis is not along the world's y, so the x-z cut is not "
                                  "its outline");
    OutlineMarker base;
    base.geom = g;
    base.body = model.geomBody(g);
    const Vec3 s = model.geomSize(g);
    switch (type) {
      case 6: rectangle(out, base, s[0], s[2], spacing_m); break;                       // box
      case 2: arc(out, base, s[0], s[0], 0.0, 0.0, 2 * kPi, spacing_m); break;          // sphere
      case 4: arc(out, base, s[0], s[2], 0.0, 0.0, 2 * kPi, spacing_m); break;          // ellipsoid
      case 5: rectangle(out, base, s[0], s[1], spacing_m); break;                       // cylinder
      case 3:                                                                            // capsule
        segment(out, base, s[0], -s[1], s[0], s[1], spacing_m);
        arc(out, base, s[0], s[0], s[1], 0.0, kPi, spacing_m);
        segment(out, base, -s[0], s[1], -s[0], -s[1], spacing_m);
        arc(out, base, s[0], s[0], -s[1], kPi, 2 * kPi, spacing_m);
        break;
      default:
        throw std::invalid_argument("geom " + std::to_string(g) + " of body '" + model.bodyName(base.body) +
                                    "' has type " + std::to_string(type) +
                                    ", which has no outline for the fluid (box, sphere, ellipsoid, cylinder, capsule)");
    }
  }
  return out;
}

Vec3 markerWorld(const rigid::RigidData& data, const OutlineMarker& m) {
  const double* p = data.geomPosition(m.geom);
  const double* R = data.geomRotation(m.geom);
  const Vec3& x = m.local_m;
  return {R[0] * x[0] + R[1] * x[1] + R[2] * x[2] + p[0], R[3] * x[0] + R[4] * x[1] + R[5] * x[2] + p[1],
          R[6] * x[0] + R[7] * x[1] + R[8] * x[2] + p[2]};
}

}  // namespace creaturelab::coupling
