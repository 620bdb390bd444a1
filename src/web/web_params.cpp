#include "web/web_params.hpp"

#include <cmath>
#include <sstream>

#include "web/frame_geometry.hpp"

namespace creaturelab::web {

// Choices where the thesis (Mehla 2005) gives no value, or gives one that cannot
// work in SI. Figures quoted are for the default web (6,096 particles, 43 radii; tests/physics/web_*).
// The load path: each radius is laid at tension k (placement - rest) = 0.01 x 4 mm = 4e-5 N and pulls
// its frame mass inward; 43 radii on 3.1 m of frame are a line load q ~ 5.5e-4 N/m. The web's weight
// (6e-4 N) and that pull end on the seven outer-frame strands.
//
// frame_k_n_per_m = 0.05 N/m (thesis 0.001 N/m, Fig. 5.5 step 10 and §5.3.3). A frame at tension T under
//   the line load q bends with radius T / q. The thesis's frame, laid at 0.001 x 5 mm = 5e-6 N, would bend
//   with a radius of ~1 cm: the radii drag it to the hub, and the web collapses (many springs slack,
//   Newton's static solve does not converge). 0.05 N/m gives T = 2.5e-4 N, a bend radius of ~0.5 m: the
//   inward bow of Figs. 5.8 and 3.2.
//
// outer_frame_k_n_per_m = 0.08 N/m (thesis 0.001 N/m, with "short stiff strands" in §5.2). Laid at
//   5 mm over 2 mm rest (Fig. 5.5) it starts at 2.4e-4 N, of the order of the frame tension it holds
//   plus a share of the weight; its strands still lengthen ~50% on settling (the upper ones ~90%). It
//   sets omega_max = sqrt(4k/m) = 5,700 rad/s and so the explicit time step: the hub masses, where
//   many radii meet, come next at ~4,100 rad/s.
//
// inner_frame_inward_force_n_per_m = 5e-5 N/m. Fig. 5.8 only shows the result, a frame bowed further
//   inward; a tenth of the radii's own line load q gives a visible but gentle extra bow (it lowers the
//   settled hub by under 1%). It is constant, so it is
//   given to springs::System::setConstantForce and the static solve includes it.
//
// spiral: placement 21 mm, rest 12 mm, k = 2.5e-4 N/m. The thesis never says whether a spiral strand
//   carries masses of its own. The spokes' 7 mm would put 3-8 extra masses on every chord near the
//   frame and take the default web to ~12,000 particles, twice the thesis's "5000-7000 masses" (ch. 3);
//   three spoke placements put one to three masses on a chord near the frame (so chords can sag and
//   flutter in the wind) and give ~6,100 particles. Stiffness: each radius meets ~50 turns, each
//   pulling it inward by T_spiral x (angle between radii, ~0.15 rad). At 0.01 N/m (the thesis's one
//   constant) and 75% over-extension T_spiral ~ 1e-4 N and the turns pull a radius inward with ~18
//   times its own tension: the radii zigzag and the static solve stalls. At 2.5e-4 N/m the turns add
//   ~40% to a radius's tension, and 75% over-extension (§5.1's lower bound) keeps every spiral spring
//   taut after settling.
//
// hub_radius_m = 30 mm: Fig. 5.11 shows a small hub polygon; the thesis gives no value.
//
// spiral_free_masses = 6: the spiral stops a count of spoke masses short of the hub (web_params.hpp).
//   The thesis gives no count; 6 gives the default web the free zone it had with the fixed 70 mm radius
//   used before (innermost spiral mass 69 mm from the hub; Fig. 5.14 shows a free zone a few hub radii
//   across). With the Fig. 5.28 spoke placements 9, 11 and 15 mm it moves out to 78, 91 and 114 mm
//   (Fig. 5.26: "a much bigger gap in the hub"), and the spiral's coverage of the web falls with it.
std::vector<Point2> defaultAttachmentPointsM() {
  return {{-0.05, 0.55}, {-0.52, 0.22}, {-0.48, -0.30}, {-0.08, -0.50},
          {0.36, -0.44}, {0.55, -0.04}, {0.40, 0.40}};
}

namespace {

std::string positive(const char* name, double v, const char* unit) {
  if (v > 0 && std::isfinite(v)) return "";
  std::ostringstream m;
  m << name << " is " << v << (*unit ? " " : "") << unit << "; it must be positive";
  return m.str();
}

std::string nonNegative(const char* name, double v, const char* unit) {
  if (v >= 0 && std::isfinite(v)) return "";
  std::ostringstream m;
  m << name << " is " << v << " " << unit << "; it must be zero or positive";
  return m.str();
}

std::string placementNotShorter(const char* what, double placement, double rest) {
  if (placement >= rest) return "";
  std::ostringstream m;
  m << what << " placement (" << placement << " m) is shorter than its rest length (" << rest
    << " m); strands are laid at or beyond their rest length (thesis §5.1)";
  return m.str();
}

}  // namespace

std::string WebParams::validate() const {
  std::ostringstream m;
  const int n = static_cast<int>(attachment_points_m.size());
  if (n < 3 || n > 10) {
    m << "there are " << n << " attachment points; an orb web needs 3 to 10 (thesis §5.2)";
    return m.str();
  }
  for (int i = 0; i < n; ++i)
    if (!attachment_points_m[i].allFinite()) {
      m << "attachment point " << i << " has a coordinate that is not a finite number";
      return m.str();
    }

  // Numbers first: each check names the parameter.
  for (const std::string& e : {
           positive("move_outer_m", move_outer_m, "m"),
           positive("outer_frame_placement_m", outer_frame_placement_m, "m"),
           positive("outer_frame_rest_length_m", outer_frame_rest_length_m, "m"),
           positive("outer_frame_k_n_per_m", outer_frame_k_n_per_m, "N/m"),
           positive("frame_placement_m", frame_placement_m, "m"),
           positive("frame_rest_length_m", frame_rest_length_m, "m"),
           positive("frame_k_n_per_m", frame_k_n_per_m, "N/m"),
           nonNegative("inner_frame_inward_force_n_per_m", inner_frame_inward_force_n_per_m, "N/m"),
           positive("spoke_placement_m", spoke_placement_m, "m"),
           positive("spoke_rest_length_m", spoke_rest_length_m, "m"),
           positive("spoke_k_n_per_m", spoke_k_n_per_m, "N/m"),
           nonNegative("primary_spoke_min_angle_rad", primary_spoke_min_angle_rad, "rad"),
           positive("hub_radius_m", hub_radius_m, "m"),
           nonNegative("secondary_spoke_min_angle_rad", secondary_spoke_min_angle_rad, "rad"),
           positive("spiral_placement_m", spiral_placement_m, "m"),
           positive("spiral_rest_length_m", spiral_rest_length_m, "m"),
           positive("spiral_k_n_per_m", spiral_k_n_per_m, "N/m"),
           positive("particle_mass_kg", particle_mass_kg, "kg"),
           nonNegative("air_drag_ns_per_m", air_drag_ns_per_m, "N*s/m"),
           nonNegative("gravity_m_per_s2", gravity_m_per_s2, "m/s^2"),
       })
    if (!e.empty()) return e;
  if (overextension) {
    if (const auto e = positive("overextension", *overextension, ""); !e.empty()) return e;
  } else {
    for (const std::string& e : {
             placementNotShorter("the outer-frame", outer_frame_placement_m, outer_frame_rest_length_m),
             placementNotShorter("the inner-frame", frame_placement_m, frame_rest_length_m),
             placementNotShorter("the spoke", spoke_placement_m, spoke_rest_length_m),
             placementNotShorter("the spiral", spiral_placement_m, spiral_rest_length_m),
         })
      if (!e.empty()) return e;
  }
  if (!(spiral_jitter >= 0 && spiral_jitter <= 1)) {
    m << "spiral_jitter is " << spiral_jitter << "; it is a probability, from 0 to 1";
    return m.str();
  }
  if (secondary_spoke_stride < 1) {
    m << "secondary_spoke_stride is " << secondary_spoke_stride << "; it must be 1 or more (1 = every frame mass)";
    return m.str();
  }
  if (hub_attach_choices < 1) {
    m << "hub_attach_choices is " << hub_attach_choices << "; it must be 1 or more (1 = the closest hub mass)";
    return m.str();
  }
  if (spiral_density < 0) {
    m << "spiral_density is " << spiral_density << "; it must be 0 or more";
    return m.str();
  }
  if (spiral_free_masses < 1) {
    m << "spiral_free_masses is " << spiral_free_masses
      << "; it must be 1 or more (the hub mass of each radius carries no spiral)";
    return m.str();
  }

  // Then the frame's shape.
  return validateFrameGeometry(*this);
}

}  // namespace creaturelab::web
