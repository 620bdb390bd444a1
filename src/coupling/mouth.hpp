#pragma once
// The swimmer's mouth (Lentine et al. 2010 §7.2: "enforcing
// a non-zero flux across the 'mouth' (located on the bottom) of the creature").
//
// The paper's solids are closed: it enforces the flux as a boundary condition of its coupled
// solve (Eq. 9). Here the bodies' outlines are closed marker loops whose inside moves rigidly, so a
// flux through the outline itself would need a source inside the body (the incompressible fluid
// inside cannot take it). The mouth is therefore an open segment of markers just outside the body
// (a siphon across the body's bottom), fixed in the frame of the body's first geom, whose velocity
// is the body's plus flux_m_per_s along the mouth's outward normal: fluid is pushed across the
// segment and returns round its ends, like an actuator disc. The force the coupling needs for it
// goes into the fluid as at any marker, and its reaction onto the body, so the jet's thrust is the
// momentum the fluid receives, balanced to round-off (tests/unit/coupling_mouth_test.cpp).
//
// The flux follows a cycle of phases (§7.2's three: draw in, expel, rest; lengths are ours:
// experiments/control/swimmer.toml documents them); positive flux expels (along the normal).
#include <string>
#include <vector>

#include "coupling/outline.hpp"

namespace creaturelab::coupling {

// A repeating cycle of phases: phase k lasts fractions[k] of cycle_s (the fractions sum to 1).
struct PhaseSchedule {
  double cycle_s = 1.0;
  std::vector<double> fractions;  // empty: no phases
};

// Phase index at time t_s (>= 0), 0 when the schedule has no phases.
int phaseAt(const PhaseSchedule& s, double t_s);
// Cycles completed at t_s, fractional.
double cyclesAt(const PhaseSchedule& s, double t_s);

struct MouthParams {
  std::string body;                         // "" : no mouth
  double centre_x_m = 0.0, centre_z_m = 0.0;  // segment centre in the frame of the body's first geom
  double width_m = 0.0;
  double normal_x = 0.0, normal_z = -1.0;   // outward (expelling) normal in that frame; normalised
  PhaseSchedule schedule;
  std::vector<double> flux_m_per_s;         // per phase; + expels along the normal, - draws in

  // "" when usable, else what is wrong (phase table lengths, fractions summing to 1, width).
  std::string validate() const;
};

// Flux speed (m/s, + expelling) at time t_s.
double mouthFlux_m_per_s(const MouthParams& m, double t_s);

// The mouth's markers, spacing_m apart, on the body's first geom; throws std::invalid_argument
// naming the body when the model has no such body or it has no geom.
std::vector<OutlineMarker> mouthMarkers(const rigid::RigidModel& model, const MouthParams& m, double spacing_m);

}  // namespace creaturelab::coupling
