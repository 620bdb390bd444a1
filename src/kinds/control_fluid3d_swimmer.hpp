#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "control/fluid_controller.hpp"
#include "control/swimmer_run.hpp"
#include "control/swimmer_run3.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "flesh/flesh_params.hpp"
#include "fluid3d/fluid_params3.hpp"
#include "kinds/control_params.hpp"
#include "kinds/describe_fluid3.hpp"
#include "kinds/describe_kind.hpp"

namespace creaturelab::kinds {

// The swimmer's controller (Lentine et al. 2010 §7.2; the 2-D swimmer's experiments/control/swimmer.toml):
// the five legs of models/swimmer3d.xml controlled for the fluid's downward force on each (Eq. 10,
// w = -z), the sense and strength following the phases; 1/60 s frames of two coupled steps, the
// evaluations moved over one frame (§4.3: in still water a placed pose feels no force) with the force
// over both steps, as in 2-D; no gravity.
inline ControllerSettings swimmer3dControllerDefaults() {
  ControllerSettings c;
  c.model_file = "experiments/control/models/swimmer3d.xml";
  c.controlled = "leg0, leg1, leg2, leg3, leg4";
  c.objectives = "drag_along, drag_along, drag_along, drag_along, drag_along";
  c.senses = "min, min, min, min, min";
  c.drag_direction_x = 0;
  c.drag_direction_z = -1;
  c.gravity_m_per_s2 = 0;
  c.frame_s = 1.0 / 60;
  c.substeps = 2;
  c.frames = 240;
  c.strength_rad_per_s = 1.0;
  c.delta_rad = 0.02;
  c.average_frames = 60;
  return c;
}

// §7.2's water "open at the top and closed elsewhere" (the paper gives no box): 1.5 m x 1.5 m round the
// creature's 0.9 m span and 3 m high, so that it can rise for cycles; free-slip sides and floor, an open
// top; inviscid (Eq. 5) as the 2-D swimmer; 16 cells across (0.094 m cubes: the legs are half a cell
// thick, the body 3.2 cells across), the exact FFT pressure solve.
inline fluid3d::FluidParams3 swimmer3dFluid() {
  fluid3d::FluidParams3 f;
  f.domain_x_m = 1.5;
  f.domain_y_m = 1.5;
  f.domain_z_m = 3.0;
  f.cells_x = 16;
  f.density_kg_per_m3 = 1000.0;
  f.kinematic_viscosity_m2_per_s = 0.0;
  f.boundaries.axis[2].high = fluid3d::BoundaryType3::open;
  f.pressure_solver = fluid3d::PressureSolverType3::spectral;
  f.blowup_speed_m_per_s = 20.0;
  return f;
}

// The fluid box's corner in the world: the creature (at the origin) centred across, 0.6 m above the floor;
// Eq. 9's coupled solve (the fluid's added mass felt in the step: stable for a free creature this close to
// the water's density).
inline coupling3d::RigidFluidParams3 swimmer3dCoupling() {
  coupling3d::RigidFluidParams3 c;
  c.origin_m = {-0.75, -0.75, -0.6};
  c.forcing = coupling3d::Forcing3::coupled;
  return c;
}

// The control_fluid3d_swimmer kind's parameters: the controller's (ControllerSettings), the derivative
// evaluations', the phases (§7.2's three), the rise's reading, the 3-D fluid box (fluid3d::FluidParams3)
// and the coupling (coupling3d::RigidFluidParams3).
struct ControlFluid3dSwimmerParams {
  ControllerSettings controller = swimmer3dControllerDefaults();
  std::int64_t warmup_frames = 0;
  std::string perturbation = "moved";
  std::int64_t settle_steps = 0;
  std::int64_t average_steps = 2;
  double controlled_limit_deg = 60;
  double cycle_s = 1.0;
  std::string phase_fractions = "0.2, 0.1, 0.7";
  std::string phase_senses = "min, min, max";
  std::string phase_strength_rad_per_s = "2.0, 2.0, 0.8571428571428571";
  std::string mouth_body;
  double mouth_centre_z_m = -0.34;
  double mouth_radius_m = 0.07;
  std::string phase_flux_m_per_s = "-0.25, 0.5, 0.0";
  std::string rise_body = "body";
  std::int64_t rise_cycles = 3;
  bool armature_added_mass = false;
  fluid3d::FluidParams3 fluid = swimmer3dFluid();
  coupling3d::RigidFluidParams3 coupling = swimmer3dCoupling();
  // §7.2: the creature wrapped in flesh (src/flesh/), its vertices the fluid's markers
  // (coupling3d/flesh_fluid_coupling3.hpp); the flesh's parameters are FleshParams' own (as control_fluid3d).
  bool flesh = false;
  flesh::FleshParams flesh_params;
  control::ObjectiveForce objective_force = control::ObjectiveForce::fluid_on_flesh;

  template <class V>
  void describe(V& v) {
    controller.describeCreature(v);
    controller.describeRun(v);
    v.integer("warmup_frames", warmup_frames, 0, 10000000, "frames with the pose held before control");
    controller.describeDescent(v);
    v.choice("perturbation", perturbation, {"moved", "placed"},
             "how a derivative evaluation reaches its pose: moved over one frame of coupled steps (§4.3) | placed at "
             "once, joint velocities zero (§3.3's steady state)");
    v.integer("settle_steps", settle_steps, 0, 100000,
              "§4.3 validation mode: coupled steps with the perturbed pose held before the force is taken (0: off)");
    v.integer("average_steps", average_steps, 1, 100000, "the objective: mean force over an evaluation's last this many steps");
    controller.describeMeasures(v);
    v.real("controlled_limit_deg", controlled_limit_deg, "deg", 0, 360,
           "controlled angles kept within +-this (0: no limit; the paper gives none; 60 keeps the legs from crossing "
           "under the body)");
    describeSwimmer(v);
    describeFluid(v);
    describeCoupling(v);
    describeFlesh(v);
  }
  template <class V>
  void describeFlesh(V& v) {
    v.boolean("flesh", flesh,
              "§7.2: the swimmer wrapped in flesh bound to its geoms, the flesh's vertices the fluid's markers (with "
              "forcing = coupled: the flesh's backward Euler step in the coupled solve, stable in water)");
    flesh_params.describe(v);
    describeObjectiveForce3(v, objective_force);
  }
  // The phases (§7.2: draw in and minimise drag, expel and minimise, maximise without propulsion) and the rise.
  template <class V>
  void describeSwimmer(V& v) {
    v.real("cycle_s", cycle_s, "s", 1e-6, 1e6, "period of the phases (§7.2's three; the paper gives none), whole frames");
    v.text("phase_fractions", phase_fractions, "", "share of cycle_s of each phase, comma-separated, summing to 1");
    v.text("phase_senses", phase_senses, "", "sense of every controlled joint per phase: min | max, comma-separated");
    v.text("phase_strength_rad_per_s", phase_strength_rad_per_s, "rad/s",
           "strength of the controlled joints per phase (§2.1's step per frame; the paper gives one); empty: "
           "strength_rad_per_s throughout");
    v.text("mouth_body", mouth_body, "",
           "§7.2: body carrying the mouth on its first geom (coupling3d's Mouth3: a disc of markers whose fluid is "
           "driven along the geom's -z); empty: no mouth");
    v.real("mouth_centre_z_m", mouth_centre_z_m, "m", -1e3, 1e3,
           "the mouth disc's centre on the geom's z axis, in its frame (keep it a kernel's half-width outside the "
           "surface: 0.15 m + 2 cells of 0.094 m)");
    v.real("mouth_radius_m", mouth_radius_m, "m", 1e-6, 1e3, "the mouth disc's radius (the 2-D swimmer's 0.14 m mouth)");
    v.text("phase_flux_m_per_s", phase_flux_m_per_s, "m/s",
           "mouth flux per phase (+ expels downwards, - draws in; the 2-D swimmer's: the same volume in and out)");
    v.text("rise_body", rise_body, "", "body whose subtree's centre of mass is tracked for the rise");
    v.integer("rise_cycles", rise_cycles, 1, 100000, "rise per cycle: mean over the last this many whole cycles");
    v.boolean("armature_added_mass", armature_added_mass,
              "the root's MJCF armature (slides and hinges) as the fluid's added mass, its lagged force given back "
              "(stabilises projected forcing's staggered coupling of a creature near the water's density; "
              "fluid_controller.hpp); not with forcing = coupled, which solves the added mass");
  }
  // The fluid (src/fluid3d) and the coupling (src/coupling3d): describe_fluid3.hpp.
  template <class V>
  void describeFluid(V& v) {
    describeFluidBox3(v, fluid, "fluid density (§7: 'similar to water')");
  }
  template <class V>
  void describeCoupling(V& v) {
    describeCoupling3(v, coupling,
             "coupled: marker forces solved with the bodies' velocities, felt in the same step (Eq. 9); projected: "
             "solved so that the projected flow meets the bodies, felt a step later (here needs armature_added_mass "
             "and a model with the root's armature); off: the bodies do not touch the fluid (a breaking switch)");
  }

  // The solvers' parameters: the box's cells from its proportions with the fixed coupled step
  // (frame_s / substeps); the evaluations'; the phases; what the rise tracks.
  fluid3d::FluidParams3 fluidParams() const;
  control::FluidControlParams fluidControlParams() const;
  control::SwimmerPhases swimmerPhases(int joints) const;
  control::RiseSettings3 riseSettings(const rigid::RigidModel& model) const;
  // The coupling with the mouth (mouth_body's first geom) when one is given; throws std::invalid_argument
  // naming the key.
  coupling3d::RigidFluidParams3 rigidFluidParams(const rigid::RigidModel& model) const;
  // The coupled fluid of the run: the geoms' surfaces as markers, or with flesh its vertices; the mouth's
  // flux following the phases (rs: riseSettings).
  control::CoupledFluidFactory coupledFluid(const rigid::RigidModel& model, const control::RiseSettings3& rs) const;
  std::vector<std::pair<std::string, double>> initialRad() const;
  // Ranges, then against the model: the controller, the phases, the rise's cycles within frames, the
  // fluid and coupling, the bodies inside the box.
  std::string validate() const;
};

// The aqueous swimmer of Lentine et al. 2010 §7.2 (Fig. 7; the mouth with mouth_body, the flesh with flesh) in
// the 3-D fluid: the controller of kind control_fluid over the two-way coupled 3-D fluid
// (coupling3d), a free creature whose legs follow §7.2's phases.
class ControlFluid3dSwimmerKind : public DescribedKind<ControlFluid3dSwimmerParams> {
 public:
  ControlFluid3dSwimmerKind();
  std::string name() const override { return "control_fluid3d_swimmer"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
