#pragma once
// The swimmer's part of the control_fluid kind (Lentine et al. 2010 §7.2, Fig. 7,
// "Creature Control in a Fluid Environment"): the mouth and its phases (coupling/mouth.hpp),
// the controlled joints' sense per phase, and what the rise recorder (control/swimmer_run.hpp) tracks.
#include <cstdint>
#include <string>
#include <vector>

#include "control/controller_params.hpp"
#include "control/swimmer_run.hpp"
#include "coupling/rigid_fluid_coupling.hpp"
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// The swimmer's parameters, appended to control_fluid's (lists as comma-separated text).
struct SwimmerSettings {
  std::string mouth_body;
  double mouth_centre_x_m = 0.0;
  double mouth_centre_z_m = 0.0;
  double mouth_width_m = 0.1;
  double mouth_normal_x = 0.0;
  double mouth_normal_z = -1.0;
  double cycle_s = 1.0;
  std::string phase_fractions;
  std::string phase_senses;
  std::string phase_flux_m_per_s;
  std::string phase_strength_rad_per_s;
  std::string rise_body;
  std::int64_t rise_cycles = 2;
  bool armature_added_mass = false;

  template <class V>
  void describe(V& v) {
    v.text("mouth_body", mouth_body, "", "§7.2: body carrying the mouth (coupling/mouth.hpp); empty: no mouth");
    v.real("mouth_centre_x_m", mouth_centre_x_m, "m", -1e3, 1e3, "mouth centre, x in the frame of the body's first geom");
    v.real("mouth_centre_z_m", mouth_centre_z_m, "m", -1e3, 1e3, "mouth centre, z in that frame");
    v.real("mouth_width_m", mouth_width_m, "m", 1e-6, 1e3, "width of the mouth's segment of markers");
    v.real("mouth_normal_x", mouth_normal_x, "", -1, 1, "outward (expelling) normal of the mouth, x in that frame");
    v.real("mouth_normal_z", mouth_normal_z, "", -1, 1, "outward normal, z");
    v.real("cycle_s", cycle_s, "s", 1e-6, 1e6, "period of the phases (§7.2's three; ours: the paper gives none)");
    v.text("phase_fractions", phase_fractions, "", "share of cycle_s of each phase, comma-separated, summing to 1; empty: none");
    v.text("phase_senses", phase_senses, "", "sense of every controlled joint per phase: min | max, comma-separated");
    v.text("phase_flux_m_per_s", phase_flux_m_per_s, "m/s", "mouth flux per phase (+ expels along the normal, - draws in)");
    v.text("phase_strength_rad_per_s", phase_strength_rad_per_s, "rad/s",
           "strength of the controlled joints per phase (§2.1's step per frame; the paper gives one); empty: "
           "strength_rad_per_s throughout");
    v.text("rise_body", rise_body, "", "body whose subtree's centre of mass is tracked for the rise; empty: none");
    v.integer("rise_cycles", rise_cycles, 1, 100000, "rise per cycle: mean over the last this many cycles");
    v.boolean("armature_added_mass", armature_added_mass,
              "free joints' MJCF armature as the fluid's added mass, its lagged force given back (stabilises the "
              "staggered coupling of light free bodies; fluid_controller.hpp)");
  }

  // The mouth and its phase schedule; throws std::invalid_argument naming the key.
  coupling::MouthParams mouthParams() const;
  // Per phase, the sense of every controlled joint (phase_senses; empty: the fixed senses).
  std::vector<std::vector<control::Sense>> phaseSenses(int joints) const;
  // Per phase, the strength (rad/s) of every controlled joint (phase_strength_rad_per_s; empty: fixed).
  std::vector<double> phaseStrengths() const;
  // "" when the swimmer's parameters fit the rest (the model, the frame and the run's frames), else
  // what is wrong.
  std::string validate(const rigid::RigidModel& model, double frame_s, std::int64_t frames) const;
  // The phases' senses and strengths (for `joints` controlled joints) and what the rise recorder
  // tracks (checked by validate).
  control::SwimmerPhases swimmerPhases(int joints) const;
  control::RiseSettings riseSettings(const rigid::RigidModel& model, double frame_s) const;
};

std::vector<MetricSpec> swimmerMetrics();

}  // namespace creaturelab::kinds
