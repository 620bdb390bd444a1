#pragma once
// The swimmer's part of the control_fluid kind (Lentine et al. 2010 §7.2, Fig. 7,
// "Creature Control in a Fluid Environment"; issue 16): the mouth and its phases (coupling/mouth.hpp),
// the controlled joints' sense per phase, and what the rise recorder (control/swimmer_run.hpp) tracks.
#include <string>
#include <vector>

#include "control/controller_params.hpp"
#include "control/swimmer_run.hpp"
#include "coupling/rigid_fluid_coupling.hpp"
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// Parameters and metrics appended to control_fluid's.
std::vector<ParamSpec> swimmerParams();
std::vector<MetricSpec> swimmerMetrics();

// The mouth and its phase schedule; throws std::invalid_argument naming the key.
coupling::MouthParams mouthParams(const ParamReader& r);

// Per phase, the sense of every controlled joint (phase_senses; empty: the fixed senses).
std::vector<std::vector<control::Sense>> phaseSenses(const ParamReader& r, int joints);

// Per phase, the strength (rad/s) of every controlled joint (phase_strength_rad_per_s; empty: fixed).
std::vector<double> phaseStrengths(const ParamReader& r);

// "" when the swimmer's parameters fit the rest, else what is wrong.
std::string validateSwimmer(const ParamReader& r, const rigid::RigidModel& model);

// The phases' senses and strengths (swimmerPhases: for `joints` controlled joints) and what the rise
// recorder tracks, from the parameters (checked by validateSwimmer).
control::SwimmerPhases swimmerPhases(const ParamReader& r, int joints);
control::RiseSettings riseSettings(const ParamReader& r, const rigid::RigidModel& model);

}  // namespace creaturelab::kinds
