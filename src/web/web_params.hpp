#pragma once
// Parameters of the orb-web construction (Mehla 2005 §5.2, pseudo-code
// Figs. 5.5, 5.10, 5.15, 5.16; values of §5.2.1 and the tables of §5.3).
//
// Units. The pseudo-code gives lengths in 'units' (Fig. 5.5: "each mass is laid at a distance of 20
// units"), while the tables of §5.3.4-5.3.5 give the same values in mm (frame placement 20 mm, rest
// 15 mm; spoke placement 7 mm, rest 3 mm) and §5.2.1 gives the rest length as 3 mm. So 1 unit = 1 mm,
// converted once here: every field below is SI (metres, kilograms, newtons, seconds).
//
// How a strand is laid (all strand types). A strand between two masses a distance d apart is a chain
// of n = max(1, round(d / placement)) springs, its masses evenly spaced at s = d / n. Each spring's
// rest length is s * rest / placement, so every spring of a type starts at the same over-extension
// placement / rest - 1 (thesis §5.1: "laying the springs out at length which is 75% to 250% more than
// their rest lengths") and none starts compressed, whatever the strand's length. Where d is a
// multiple of the placement this is exactly the thesis's rest length.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "web/geometry2.hpp"

namespace creaturelab::web {

// The default frame: seven anchor points of an irregular, slightly taller-than-wide heptagon
// 1.07 m wide and 1.05 m tall (the issue asks for "a natural 6-8 point frame about 1 m across";
// thesis §5.2.1: "diameter of the orb web up to 1 meter"; the anchors of Fig. 5.6 are irregular).
std::vector<Point2> defaultAttachmentPointsM();

// Where a primary spoke ends (thesis §5.2, Fig. 5.10 steps 1-2).
enum class PrimarySpokeEnd {
  // The inner-frame mass nearest the ray from the segment's middle mass through the centre, beyond the
  // centre: the text's "a section of the inner frame opposite it". Every primary spoke then passes
  // through the centre and the hub forms there.
  opposite,
  // The literal pseudo-code: the mass of the other segments farthest from the middle mass. On most
  // frames that is a corner, and on even-sided frames (square, hexagon) the spokes then miss each
  // other by several centimetres, so no single intersection exists for the hub.
  farthest,
};

// The fraction of the explicit stability limit that a web's automatic substep uses
// (springs::SimulationOptions::auto_safety; the engine's default is 0.5). The limit divides the
// integrator's stability interval (RK4: omega h <= 2 sqrt(2) = 2.83) by a Gershgorin UPPER bound on
// omega_max, so the full limit is still a stable step. On the default web the bound lies within a few
// percent of the true omega_max (the short stiff outer frame, sqrt(4 k / m)), where RK4 damps the top
// mode; half the limit doubles the cost of a settle and barely moves its settling time.
inline constexpr double kAutoStepSafety = 1.0;

struct WebParams {
  // --- frame (Fig. 5.5) -----------------------------------------------------------------------
  // Anchor points in order around the frame, metres, in the vertical x-y plane (y up). 3 to 10
  // points (§5.2: "the user can choose up to ten attachment points"), no two closer than 1 mm, no
  // three consecutive ones collinear, a simple polygon containing the centre of its bounding box.
  std::vector<Point2> attachment_points_m = defaultAttachmentPointsM();
  // MOVE_OUTER (Fig. 5.5 step 5): how far each anchor moves toward the centre to give its
  // inner-frame corner, metres. The thesis gives no value; 50 mm (5% of the web) keeps the outer
  // frame "short" (§5.2) yet long enough for ten springs at the outer-frame placement.
  double move_outer_m = 0.05;

  // Outer frame: anchor -> inner-frame corner. Fig. 5.5 step 7: masses 5 units apart, rest length 2.
  double outer_frame_placement_m = 0.005;
  double outer_frame_rest_length_m = 0.002;
  // §5.2 calls these strands "short stiff"; Fig. 5.5 and §5.3.3 say 0.001 N/m. Chosen 0.08 N/m: see
  // web_params.cpp.
  double outer_frame_k_n_per_m = 0.08;

  // Inner frame: between consecutive corners. Fig. 5.5 step 10 and the Fig. 5.33 table (preset):
  // placement 20 mm, rest 15 mm. The thesis's k is 0.001 N/m; 0.05 N/m chosen: see web_params.cpp.
  double frame_placement_m = 0.020;
  double frame_rest_length_m = 0.015;
  double frame_k_n_per_m = 0.05;
  // Inward radial force on the inner frame (Fig. 5.8; Fig. 5.10 step 8: "apply inward radial force
  // on inner frame segments"), newtons per metre of frame, pointing at the centre. Each inner-frame
  // mass gets this times half the length of its two frame springs as laid. The thesis gives no value;
  // see web_params.cpp for the choice.
  double inner_frame_inward_force_n_per_m = 5e-5;

  // --- spokes and hub (Fig. 5.10) ----------------------------------------------------------------
  // Primary and secondary spokes and the hub strands. Fig. 5.10 step 3 and the Fig. 5.28 table.
  double spoke_placement_m = 0.007;
  double spoke_rest_length_m = 0.003;
  double spoke_k_n_per_m = 0.01;
  PrimarySpokeEnd primary_spoke_end = PrimarySpokeEnd::opposite;  // see PrimarySpokeEnd above
  // A primary spoke whose line is within this angle of an earlier primary spoke is not laid (with an
  // even number of sides the middle of side j and the middle of the opposite side pick each other,
  // Fig. 5.10 steps 1-2, which would lay the same strand twice). Radians.
  double primary_spoke_min_angle_rad = 0.2;
  // The hub (Fig. 5.10 steps 4-7) joins, on each arm of each primary spoke, the mass nearest this
  // distance from the primary spokes' intersection, metres. Fig. 5.11 shows a small polygon.
  double hub_radius_m = 0.03;
  // Secondary spokes start at every stride-th inner-frame mass (§5.2: "repeated for all the masses
  // in the inner frame"). Every mass (stride 1) gives 125 radii on the default frame (the angle rule
  // below drops the rest), 1.5 mm apart on the hub ring, with 17,700 springs; stride 4 gives 43 radii,
  // which look like the thesis's webs (Figs. 5.12, 5.29) and keep ~6,100 particles (ch. 3: 5,000-7,000).
  int secondary_spoke_stride = 4;
  // A secondary spoke is skipped when its frame end is within this angle (seen from the hub) of a
  // radius already laid, so no two radii run nearly on top of each other. Radians.
  double secondary_spoke_min_angle_rad = 0.04;
  // §5.2: secondary spokes "are connected randomly to the masses in the hub": each goes to one of
  // the hub_attach_choices hub masses closest to its frame end (leaving out any whose spoke would cross
  // a radius already laid), drawn from the seeded generator (1 = the closest, Fig. 5.10 step 10).
  int hub_attach_choices = 3;

  // --- spiral (Figs. 5.15, 5.16) -------------------------------------------------------------------
  // Spiral strands join masses of neighbouring spokes. The thesis gives no spiral values of its own
  // (§5.2.1 lists one spring constant, 0.01 N/m, and one rest length, 3 mm, for the whole web).
  // Chosen: placement 21 mm, rest 12 mm (75% over-extension, the low end of §5.1), k = 2.5e-4 N/m;
  // see web_params.cpp.
  double spiral_placement_m = 0.021;
  double spiral_rest_length_m = 0.012;
  double spiral_k_n_per_m = 2.5e-4;
  // SPIRAL_DENSITY (Fig. 5.16 step 3): the processed spiral is repeated while some spoke has more
  // than this many masses outside the free zone that no spiral strand touches.
  int spiral_density = 5;
  // Where the spiral stops short of the hub: it leaves this many masses at the hub end of every radius
  // (the hub mass included) without spiral, and no spiral strand crosses the disc through them.
  // Thesis §5.2: "We end this process a little distance away from the hub of the web so that a distinct
  // hub is still visible"; the distance is counted in spoke masses, as Fig. 5.15 walks "all masses in
  // first spoke" from the frame mass by mass ("initial_mass + 1"), and §5.3.4 finds the hub gap growing
  // with the spoke placement (Fig. 5.26: "a much bigger gap in the hub", Fig. 5.27 "least web coverage"),
  // which a fixed distance would not give. The thesis gives no count: 6 masses at the default 7 mm
  // placement leave a free zone of ~70 mm about the 30 mm hub ring (Fig. 5.14); see web_params.cpp.
  int spiral_free_masses = 6;
  // §5.2: "the spiral has to have a small amount of randomness in it". Probability that a step of a
  // spiral goes to a neighbour (along the spoke) of the closest mass instead of the closest mass.
  double spiral_jitter = 0.1;

  // Optional override of every rest length: rest = placement / (1 + overextension) for all six strand
  // types (thesis §5.1 lays strands 75% to 250% over rest, i.e. 0.75 to 2.5). Unset: the per-type
  // rest lengths above (over-extensions: outer 1.5, frame 0.33, spokes 1.33, spiral 0.75).
  std::optional<double> overextension;

  // --- physics (§5.2.1, ch. 3) ---------------------------------------------------------------------
  double particle_mass_kg = 1e-8;     // 10 ug (§5.2.1; Fig. 5.5: mass = 0.00000001)
  double air_drag_ns_per_m = 1e-8;    // air friction 0.00000001 Ns/m (§5.2.1), Eq. 4.7
  double gravity_m_per_s2 = 9.81;     // along -y: the web hangs in the vertical x-y plane
  std::uint64_t seed = 1;             // every random choice: core::rng keyed by (seed, purpose, index)

  // For the web and charlotte kinds (kinds/describe.hpp: name, unit, range, one-line doc; the
  // in-class defaults are the web kind's): every field a user sets. The attachment points, the two
  // angles, hub_attach_choices and the overextension stay the kind's or internal.
  template <class V>
  void describe(V& v) {
    v.real("move_outer_m", move_outer_m, "m", 1e-4, 10, "MOVE_OUTER: anchor to inner-frame corner (Fig. 5.5; thesis gives none)");
    v.real("outer_frame_placement_m", outer_frame_placement_m, "m", 1e-5, 1, "outer frame spacing as laid (Fig. 5.5: 5 units)");
    v.real("outer_frame_rest_length_m", outer_frame_rest_length_m, "m", 1e-5, 1, "outer frame rest length (Fig. 5.5: 2 units)");
    v.real("outer_frame_k_n_per_m", outer_frame_k_n_per_m, "N/m", 1e-9, 1e3,
           "outer frame k; thesis 0.001 collapses the web in SI (see src/web/web_params.cpp)");
    v.real("frame_placement_m", frame_placement_m, "m", 1e-5, 1, "inner frame spacing as laid (Fig. 5.33: 20 mm)");
    v.real("frame_rest_length_m", frame_rest_length_m, "m", 1e-5, 1, "inner frame rest length (Fig. 5.33: 15 mm)");
    v.real("frame_k_n_per_m", frame_k_n_per_m, "N/m", 1e-9, 1e3,
           "inner frame k; thesis 0.001 collapses the web in SI (see src/web/web_params.cpp)");
    v.real("inner_frame_inward_force_n_per_m", inner_frame_inward_force_n_per_m, "N/m", 0, 1,
           "inward radial force on the inner frame per metre (Fig. 5.8; thesis gives none)");
    v.real("spoke_placement_m", spoke_placement_m, "m", 1e-5, 1, "spoke spacing as laid (Fig. 5.28: 7 mm)");
    v.real("spoke_rest_length_m", spoke_rest_length_m, "m", 1e-5, 1, "spoke rest length (§5.2.1, Fig. 5.28: 3 mm)");
    v.real("spoke_k_n_per_m", spoke_k_n_per_m, "N/m", 1e-9, 1e3, "radial spoke k (§5.2.1: 0.01 N/m)");
    v.choice("primary_spoke_end", primary_spoke_end,
             {{"opposite", PrimarySpokeEnd::opposite}, {"farthest", PrimarySpokeEnd::farthest}},
             "primary spoke to the frame mass opposite through the centre, or the literal farthest mass (Fig. 5.10)");
    v.real("hub_radius_m", hub_radius_m, "m", 1e-4, 1, "hub ring radius (Fig. 5.11; thesis gives none)");
    v.integer("secondary_spoke_stride", secondary_spoke_stride, 1, 1000,
              "a secondary spoke from every n-th inner-frame mass (on the default frame 4: 43 radii; 2: ~80, with "
              "spiral segments short enough for letters)");
    v.real("spiral_placement_m", spiral_placement_m, "m", 1e-5, 1, "spiral spacing as laid (thesis gives none)");
    v.real("spiral_rest_length_m", spiral_rest_length_m, "m", 1e-5, 1, "spiral rest length (thesis gives none)");
    v.real("spiral_k_n_per_m", spiral_k_n_per_m, "N/m", 1e-9, 1e3,
           "spiral k; thesis 0.01 makes the radii zigzag (see src/web/web_params.cpp)");
    v.integer("spiral_density", spiral_density, 1, 1000, "SPIRAL_DENSITY of the processed spiral (Fig. 5.16: 5)");
    v.integer("spiral_free_masses", spiral_free_masses, 1, 1000,
              "masses at the hub end of each radius left without spiral (§5.2 'a little distance away from the hub')");
    v.real("spiral_jitter", spiral_jitter, "", 0, 1, "randomness of the spiral (§5.2: 'a small amount of randomness')");
    v.real("particle_mass_kg", particle_mass_kg, "kg", 1e-15, 1, "particle mass (§5.2.1: 10 ug)");
    v.real("drag_ns_per_m", air_drag_ns_per_m, "N*s/m", 0, 1,
           "air friction (§5.2.1: 1e-8 N s/m); with 10 ug masses motion decays as exp(-t / 2 s)");
    v.real("gravity_m_per_s2", gravity_m_per_s2, "m/s^2", 0, 1000, "gravity along -y (the web hangs in the x-y plane)");
    v.integer("seed", seed, 0, std::int64_t(1) << 62,
              "seed of every random choice (spiral, hub links, wind, random attachments and gaps)");
  }

  // "" when the web can be built; otherwise one sentence naming the first problem, e.g.
  // "attachment points 2, 3 and 4 are collinear; move one of them off the line".
  std::string validate() const;
};

}  // namespace creaturelab::web
