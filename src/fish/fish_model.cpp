#include "fish/fish_model.hpp"

#include <cmath>
#include <stdexcept>

namespace creaturelab::fish {
namespace {

// Ring r (0..4) node k (0 upper-left, 1 lower-left, 2 lower-right, 3 upper-right) is node 1 + 4r + k.
int ringNode(int ring, int k) { return 1 + 4 * ring + (k & 3); }
constexpr int kSnout = 0, kDorsalTip = 21, kVentralTip = 22;

std::string positive(const char* name, double v) {
  return std::isfinite(v) && v > 0 ? "" : std::string(name) + " must be positive (got " + std::to_string(v) + ")";
}

}  // namespace

std::string UnitParams::validate() const {
  for (auto [name, v] : {std::pair{"stiffness_cross_n_per_m", stiffness_cross_n_per_m},
                         {"stiffness_other_n_per_m", stiffness_other_n_per_m},
                         {"stiffness_muscle_n_per_m", stiffness_muscle_n_per_m}, {"mass_unit_kg", mass_unit_kg}})
    if (auto m = positive(name, v); !m.empty()) return m;
  if (!(damping_ns_per_m >= 0) || !std::isfinite(damping_ns_per_m))
    return "damping_ns_per_m must be >= 0 (got " + std::to_string(damping_ns_per_m) + ")";
  for (int i = 0; i < 7; ++i)
    if (!(mass_units[i] > 0) || !std::isfinite(mass_units[i]))
      return "mass of node class " + std::to_string(i) + " must be positive (got " + std::to_string(mass_units[i]) + ")";
  return "";
}

std::string FishGeometry::validate() const {
  const FishGeometry& g = *this;
  for (auto [name, v] : {std::pair{"body_length_m", g.body_length_m}, {"tail_half_height", g.tail_half_height}})
    if (auto m = positive(name, v); !m.empty()) return m;
  double prev = 0;
  for (int r = 0; r < 5; ++r) {
    if (!(g.ring_station[r] > prev) || !(g.ring_station[r] < 1))
      return "ring stations must increase strictly inside (0, 1) (ring " + std::to_string(r + 1) + ")";
    prev = g.ring_station[r];
    if (!(g.ring_half_width[r] > 0) || !(g.ring_half_height[r] > 0))
      return "ring " + std::to_string(r + 1) + " must have a positive half-width and half-height";
  }
  return "";
}

FishGeometry reimplementationGeometry() {
  FishGeometry g;
  constexpr double L = 26;
  g.ring_station = {5 / L, 10 / L, 15 / L, 20 / L, 22 / L};
  g.ring_half_width = {2 / L, 3 / L, 2 / L, 1 / L, 0.8 / L};
  g.ring_half_height = g.ring_half_width;
  g.tail_half_height = 3 / L;
  return g;
}

FaceFrame faceNormal(const NodeMatrix& x, const Face& f) {
  const Eigen::Vector3d d02 = (x.row(f.node[2]) - x.row(f.node[0])).transpose();
  const Eigen::Vector3d d13 = (x.row(f.node[3]) - x.row(f.node[1])).transpose();
  const Eigen::Vector3d c = d02.cross(d13);
  const double norm = c.norm();
  return {norm > 0 ? Eigen::Vector3d(c / norm) : Eigen::Vector3d::Zero(), 0.5 * norm};
}

FishModel buildFish(const FishGeometry& g, const UnitParams& u) {
  for (const std::string& problem : {g.validate(), u.validate()})
    if (!problem.empty()) throw std::invalid_argument(problem);
  FishModel fish;
  fish.body_length_m = g.body_length_m;
  const double L = g.body_length_m;

  // Nodes and masses.
  NodeMatrix& x = fish.rest_positions_m;
  x.setZero();
  auto& net = fish.network;
  net.addParticle(u.mass_unit_kg * u.mass_units[0], false);  // snout at the origin
  for (int r = 0; r < 5; ++r) {
    const double px = -g.ring_station[r] * L, hw = g.ring_half_width[r] * L, hh = g.ring_half_height[r] * L;
    const double ys[4] = {hw, hw, -hw, -hw}, zs[4] = {hh, -hh, -hh, hh};
    for (int k = 0; k < 4; ++k) {
      const int i = net.addParticle(u.mass_unit_kg * u.mass_units[1 + r], false);
      x.row(i) << px, ys[k], zs[k];
    }
  }
  for (double z : {g.tail_half_height * L, -g.tail_half_height * L}) {
    const int i = net.addParticle(u.mass_unit_kg * u.mass_units[6], false);
    x.row(i) << -L, 0.0, z;
  }

  // Units: rest lengths are the initial distances (spec §1, thesis).
  auto add = [&](int a, int b, UnitClass cls) {
    const double c = cls == UnitClass::cross    ? u.stiffness_cross_n_per_m
                     : cls == UnitClass::muscle ? u.stiffness_muscle_n_per_m
                                                : u.stiffness_other_n_per_m;
    const int e = net.addSpring(a, b, (x.row(a) - x.row(b)).norm(), c, u.damping_ns_per_m);
    fish.unit_class.push_back(cls);
    return e;
  };
  for (int k = 0; k < 4; ++k) add(kSnout, ringNode(0, k), UnitClass::other);  // 4
  for (int r = 0; r < 5; ++r) {                                                // 5 x 6 = 30
    for (int k = 0; k < 4; ++k) add(ringNode(r, k), ringNode(r, k + 1), UnitClass::other);
    add(ringNode(r, 0), ringNode(r, 2), UnitClass::cross);
    add(ringNode(r, 1), ringNode(r, 3), UnitClass::cross);
  }
  int m = 0;
  for (int r = 0; r < 4; ++r) {  // 4 x 12 = 48; the longitudinal units of gaps 1-2, 2-3, 3-4 are muscles
    for (int k = 0; k < 4; ++k) {
      const bool muscle = r < 3;
      const int e = add(ringNode(r, k), ringNode(r + 1, k), muscle ? UnitClass::muscle : UnitClass::other);
      if (muscle) fish.muscles[m++] = {e, r, k < 2 ? 0 : 1};  // nodes 0, 1 of a ring are on the left
    }
    for (int k = 0; k < 4; ++k) {  // two diagonals on each of the four faces
      add(ringNode(r, k), ringNode(r + 1, k + 1), UnitClass::cross);
      add(ringNode(r, k + 1), ringNode(r + 1, k), UnitClass::cross);
    }
  }
  // 8: each ring-5 node to both tips. The units that run diagonally across a tail face (an upper
  // node to the ventral tip, a lower one to the dorsal tip) are cross units, as in the
  // reimplementation's FishData.cs InitSprings (17-22, 18-22, 19-21, 20-21 Cross); the others are
  // the faces' edges.
  for (int k = 0; k < 4; ++k) {
    const bool upper = k == 0 || k == 3;
    for (int tip : {kDorsalTip, kVentralTip})
      add(ringNode(4, k), tip, upper == (tip == kVentralTip) ? UnitClass::cross : UnitClass::other);
  }
  add(kDorsalTip, kVentralTip, UnitClass::other);  // 1

  // Faces: side k of a segment lies between ring nodes k and k+1 (0 left, 1 bottom, 2 right, 3 top).
  int f = 0;
  // A triangle repeats the vertex that lies on the mirror planes (the snout, a tail tip), so that a
  // face's mean velocity and its split among corners are mirror-symmetric left-right and top-bottom.
  for (int k = 0; k < 4; ++k)
    fish.faces[f++] = {{kSnout, ringNode(0, k), ringNode(0, k + 1), kSnout}, 0};
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k)
      fish.faces[f++] = {{ringNode(r, k), ringNode(r + 1, k), ringNode(r + 1, k + 1), ringNode(r, k + 1)}, r + 1};
  fish.faces[f++] = {{ringNode(4, 0), kDorsalTip, kVentralTip, ringNode(4, 1)}, 5};      // left
  fish.faces[f++] = {{ringNode(4, 1), ringNode(4, 2), kVentralTip, kVentralTip}, 5};    // bottom
  fish.faces[f++] = {{ringNode(4, 2), kVentralTip, kDorsalTip, ringNode(4, 3)}, 5};      // right
  fish.faces[f++] = {{ringNode(4, 3), ringNode(4, 0), kDorsalTip, kDorsalTip}, 5};      // top
  // Orient every face outward: its normal must point away from its segment's centre on the axis.
  for (Face& face : fish.faces) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int c : face.node) centroid += x.row(c).transpose() / 4.0;
    const Eigen::Vector3d axis(centroid.x(), 0.0, 0.0);
    if (faceNormal(x, face).normal.dot(centroid - axis) < 0) std::swap(face.node[0], face.node[3]), std::swap(face.node[1], face.node[2]);
  }

  if (net.springCount() != kUnits || net.particleCount() != kNodes || m != kMuscles)
    throw std::logic_error("fish topology: counts do not match thesis ch. 4 (23 nodes, 91 units, 12 muscles)");
  if (auto problem = net.validate(); !problem.empty()) throw std::invalid_argument("fish: " + problem);
  return fish;
}

}  // namespace creaturelab::fish
