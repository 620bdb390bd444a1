#pragma once
// The dynamic fish of Tu (1996): 23 point masses joined by 91 Voigt units, 12 of them muscles, and
// the 24 faces that meet the water. Topology from docs/fish-spec.md §1 (thesis
// ch. 4, counts; the node / unit numbering of the public reimplementation); the node coordinates
// are ours (FishGeometry below). The masses, units and rest lengths are stored in a
// springs::Network<3> (src/springs), the project's spring-mass data, so that its validate() and
// its force convention are shared; the fish's own solver (semi_implicit.hpp) reads them.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "springs/network.hpp"

namespace creaturelab::fish {

constexpr int kNodes = 23;
constexpr int kUnits = 91;
constexpr int kFaces = 24;
constexpr int kMuscles = 12;
constexpr int kSegments = 6;  // body segments S0 (head) .. S5 (tail), four faces each (seed, §"six segments")

// Node positions or velocities: one row per node (x, y, z), so one n x n matrix acts on all three
// coordinate columns at once (spec §2: "one n x n effective-stiffness matrix shared by x, y, z").
using NodeMatrix = Eigen::Matrix<double, kNodes, 3>;

// Unit classes: each has its own stiffness (spec §1, thesis: "cross units stiffest, muscles and the
// rest each their own").
enum class UnitClass : int { cross = 0, muscle = 1, other = 2 };

// The fish is built with its snout at the origin, the body along -x (it swims towards +x), +y to
// its left and +z up. Ring nodes go around the cross-section as upper-left, lower-left,
// lower-right, upper-right, so the two left longitudinal units of a gap are nodes 0 and 1 of the ring.
// The parameter structs' in-class defaults are the fish kind's (kinds/fish.hpp); each describes its
// fields for it (kinds/describe.hpp: name, unit, range, one-line doc).
struct FishGeometry {
  double body_length_m = 2.0;  // snout to tail tip
  // Ours (no coordinates survive in text, spec §1): a laterally compressed, fusiform body, deepest
  // at ring 2, narrowing to a caudal peduncle at rings 4-5 and a forked tail. Fractions of the body
  // length: station (distance behind the snout), half-width (y) and half-height (z) of rings 1-5.
  std::array<double, 5> ring_station = {0.19, 0.38, 0.58, 0.77, 0.85};
  std::array<double, 5> ring_half_width = {0.06, 0.09, 0.06, 0.03, 0.025};
  std::array<double, 5> ring_half_height = {0.08, 0.12, 0.08, 0.04, 0.032};
  double tail_half_height = 0.12;  // the dorsal and ventral tail-fin tips (nodes 21, 22) at the tail end

  template <class V>
  void describe(V& v) {
    v.real("body_length_m", body_length_m, "m", 1e-3, 1e3,
           "snout to tail (ours: with the [reimpl] masses, 107 kg, our shape then has about the density of water)");
    v.real("tail_half_height", tail_half_height, "", 1e-3, 10,
           "height of the dorsal and ventral tail-fin tips (nodes 21, 22) above and below the axis, in body lengths "
           "(shape = ours)");
  }

  // "" if the shape can be built (positive sizes, ring stations increasing inside (0, 1)), else
  // what is wrong, naming the parameter.
  std::string validate() const;
};

// The reimplementation's own node coordinates (FishData.cs InitNodes: snout at 0, rings at 5, 10,
// 15, 20, 22 units behind it with square sections of half-size 2, 3, 2, 1, 0.8, tail-fin tips 3
// above and below the axis 26 units back), as fractions of its 26-unit length; for checking that
// our shape is not what makes the fish slow.
FishGeometry reimplementationGeometry();

struct UnitParams {
  // Ours: 400 x the [reimpl] (spec §1) c = 38 cross, 30 other, 28 muscle, so that the body's lowest
  // sideways mode sits just above the fastest swim stroke; gamma = 0.1 for all [reimpl].
  double stiffness_cross_n_per_m = 15200.0;
  double stiffness_other_n_per_m = 12000.0;
  double stiffness_muscle_n_per_m = 11200.0;
  double damping_ns_per_m = 0.1;
  // Masses [reimpl] in units of m = 1.1 kg: snout 1, ring 1: 6, ring 2: 10, ring 3: 6, rings 4-5: 1,
  // tail nodes 0.15.
  double mass_unit_kg = 1.1;
  std::array<double, 7> mass_units = {1.0, 6.0, 10.0, 6.0, 1.0, 1.0, 0.15};  // snout, rings 1-5, tail nodes

  template <class V>
  void describe(V& v) {
    v.real("mass_unit_kg", mass_unit_kg, "kg", 1e-9, 1e9,
           "mass unit m of the [reimpl] masses (snout 1, rings 6/10/6/1/1, tail 0.15 m)");
    v.real("tail_mass_units", mass_units[6], "", 1e-9, 1e9,
           "mass of each tail-fin tip (nodes 21, 22) in units of mass_unit_kg ([reimpl] 0.15; the lightest nodes, "
           "they carry the body's stiffest vibration)");
    v.real("stiffness_cross_n_per_m", stiffness_cross_n_per_m, "N/m", 1e-9, 1e9,
           "cross units: 400 x the [reimpl] 38 (spec §1; its ratios kept), so that the body's lowest sideways mode "
           "sits just above the fastest swim stroke and the body follows every gait (the [reimpl] 38 puts it 15x "
           "below; studies/fish/units.toml)");
    v.real("stiffness_other_n_per_m", stiffness_other_n_per_m, "N/m", 1e-9, 1e9,
           "other passive units: 400 x the [reimpl] 30 (as the cross units)");
    v.real("stiffness_muscle_n_per_m", stiffness_muscle_n_per_m, "N/m", 1e-9, 1e9,
           "muscle units: 400 x the [reimpl] 28 (as the cross units)");
    v.real("damping_ns_per_m", damping_ns_per_m, "N*s/m", 0, 1e9, "Voigt damping gamma of every unit (spec §1 [reimpl])");
  }

  // "" if every stiffness and mass is positive and the damping >= 0, else what is wrong, naming it.
  std::string validate() const;
};

// One muscle: its unit, its segment (0 anterior, 1 middle, 2 posterior: ring gaps 1-2, 2-3, 3-4),
// and its side (0 left, 1 right).
struct Muscle {
  int unit;
  int segment;
  int side;
};

// A face: four node indices (a triangle repeats a vertex), ordered so that
// (c2 - c0) x (c3 - c1) points out of the body (spec §4 "faces oriented outward").
struct Face {
  std::array<int, 4> node;
  int segment;  // S0 .. S5
};

struct FishModel {
  springs::Network<3> network;       // masses, units (spring_a/b, rest, c, gamma)
  std::vector<UnitClass> unit_class;  // per unit
  std::array<Muscle, kMuscles> muscles;
  std::array<Face, kFaces> faces;
  NodeMatrix rest_positions_m;  // the undeformed fish, snout at the origin
  double body_length_m = 1.0;
  double totalMassKg() const { return network.mass_kg.sum(); }
};


// Builds the fish; throws std::invalid_argument with validate()'s message on bad input.
FishModel buildFish(const FishGeometry& g, const UnitParams& u);

// Unit normal and area of a face from its corners: n = normalize((c2 - c0) x (c3 - c1)),
// area = |(c2 - c0) x (c3 - c1)| / 2 (exact for planar quads and for a triangle with a repeated
// vertex; robust for non-planar quads, spec §4 "choices").
struct FaceFrame {
  Eigen::Vector3d normal;
  double area_m2;
};
FaceFrame faceNormal(const NodeMatrix& x, const Face& f);

}  // namespace creaturelab::fish
