#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "control/fluid_controller.hpp"
#include "control/fluid_run3.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "flesh/flesh_params.hpp"
#include "fluid3d/fluid_params3.hpp"
#include "kinds/control_params.hpp"
#include "kinds/describe_fluid3.hpp"
#include "kinds/describe_kind.hpp"

namespace creaturelab::kinds {

// The driven flyer's controller (Lentine et al. 2010 §7.1; the 2-D flyer's experiments/control/flyer.toml):
// the outer wing joints of models/flyer3d.xml controlled for F_d (|F| on the whole creature), maximised
// while the PD-driven inner joints flap down and minimised while they flap up; a 30 deg flap at 0.5 Hz
// (not in the paper), the PD gains scaled with the 4 kg segments; §3.3's steady-state evaluation.
inline ControllerSettings flyer3dControllerDefaults() {
  ControllerSettings c;
  c.model_file = "experiments/control/models/flyer3d.xml";
  c.controlled = "outer_r, outer_l";
  c.objectives = "drag, drag";
  c.senses = "max, max";
  c.pd_driven = "inner_r, inner_l";
  c.pd_pattern = "inner_r = sine(0, 30, 0.5, 0); inner_l = sine(0, 30, 0.5, 0)";
  c.pd_kp_n_m_per_rad = 800;
  c.pd_kd_n_m_s_per_rad = 40;
  c.gravity_m_per_s2 = 0;
  c.frame_s = 1.0 / 60;
  c.substeps = 2;
  c.frames = 240;
  c.strength_rad_per_s = 2.0;
  c.delta_rad = 0.02;
  c.average_frames = 30;
  return c;
}

// §7.1's box (the paper gives none): 4 m x 2 m x 4 m around the 2.3 m span, air (the segments must be
// far heavier than the fluid they displace for the staggered coupling) at Re = 0.5 m/s x 1 m / nu = 100
// as the 2-D flyer's; "open at the top and closed elsewhere with a source term at the floor": free-slip
// sides, an inflow floor at 0.5 m/s, an open top. 32 cells along x (0.125 m cubes); the box's sides
// allow the exact eigenbasis pressure solve, each forcing iteration's projection then costing one solve.
inline fluid3d::FluidParams3 flyer3dFluid() {
  fluid3d::FluidParams3 f;
  f.domain_x_m = 4.0;
  f.domain_y_m = 2.0;
  f.domain_z_m = 4.0;
  f.cells_x = 32;
  f.density_kg_per_m3 = 1.2;
  f.kinematic_viscosity_m2_per_s = 0.005;
  f.boundaries.axis[2].low = fluid3d::BoundaryType3::inflow;
  f.boundaries.axis[2].low_inflow_m_per_s = 0.5;
  f.boundaries.axis[2].high = fluid3d::BoundaryType3::open;
  f.pressure_solver = fluid3d::PressureSolverType3::spectral;
  f.blowup_speed_m_per_s = 50.0;
  return f;
}

// The fluid box's corner in the world: the creature (at the origin) in the box's middle. The forcing
// solved to 1e-8 of the largest speed (at most 1000 CG iterations): the unconverged part of the forcing is
// not mirror symmetric, and the sign-only step amplifies it where the two wings' derivatives cross zero.
inline coupling3d::RigidFluidParams3 flyer3dCoupling() {
  coupling3d::RigidFluidParams3 c;
  c.origin_m = {-2.0, -1.0, -2.0};
  c.forcing_tolerance = 1e-8;
  c.max_forcing_iterations = 1000;
  return c;
}

// The control_fluid3d kind's parameters: the controller's (ControllerSettings), the derivative
// evaluations', the flyer's flap and reading, the 3-D fluid box (fluid3d::FluidParams3) and the
// coupling (coupling3d::RigidFluidParams3).
struct ControlFluid3dParams {
  ControllerSettings controller = flyer3dControllerDefaults();
  std::int64_t warmup_frames = 60;
  // Lentine et al. 2010 §4.3: each derivative's pose reached over one frame and its force read there with the
  // pseudo-velocity; §8 uses §3.3's steady state "only ... in the simple two-dimensional cases".
  std::string perturbation = "moved";
  std::string objective_bodies = "creature";
  std::int64_t settle_steps = 0;
  std::int64_t average_steps = 2;
  std::string stroke_sense = "outer_r = +inner_r, outer_l = +inner_l";
  double flap_period_s = 2.0;
  std::int64_t force_cycles = 2;
  double controlled_limit_deg = 90;
  fluid3d::FluidParams3 fluid = flyer3dFluid();
  coupling3d::RigidFluidParams3 coupling = flyer3dCoupling();
  std::string stored_fields = "none";
  std::int64_t field_every = 10;
  // Lentine et al. 2010 Fig. 13: the creature wrapped in flesh (src/flesh/), its vertices the fluid's
  // markers (coupling3d/flesh_fluid_coupling3.hpp).
  bool flesh = false;
  flesh::FleshParams flesh_params;
  control::ObjectiveForce objective_force = control::ObjectiveForce::fluid_on_flesh;

  template <class V>
  void describe(V& v) {
    controller.describeCreature(v);
    controller.describeRun(v);
    v.integer("warmup_frames", warmup_frames, 0, 10000000, "frames with the pose held before control, for the flow to develop");
    controller.describeDescent(v);
    v.choice("perturbation", perturbation, {"moved", "placed"},
             "how a derivative evaluation reaches its pose: moved over one frame of coupled steps (§4.3) | placed at "
             "once, joint velocities zero (§3.3's steady state)");
    v.choice("objective_bodies", objective_bodies, {"moved", "creature"},
             "the bodies whose fluid force a joint's drag objective takes: moved (those the joint moves) | creature "
             "(every body but the world; §7.1: 'maximize drag (F_d) on the body')");
    v.integer("settle_steps", settle_steps, 0, 100000,
              "§4.3 validation mode: coupled steps with the perturbed pose held before the force is taken (0: off)");
    v.integer("average_steps", average_steps, 1, 100000, "the objective: mean force over an evaluation's last this many steps");
    controller.describeMeasures(v);
    v.text("stroke_sense", stroke_sense, "",
           "§7.1: 'controlled = [+|-]inboard, ...': the joint has its given sense while the inboard joint's pattern "
           "angle rises (+) or falls (-)");
    v.real("flap_period_s", flap_period_s, "s", 1e-6, 1e4, "period of the flap, a whole number of frames");
    v.integer("force_cycles", force_cycles, 1, 100000, "mean_up_force_n: whole flap cycles at the end averaged");
    v.real("controlled_limit_deg", controlled_limit_deg, "deg", 0, 360,
           "controlled angles kept within +-this (0: no limit; the paper gives none)");
    describeFluid(v);
    describeCoupling(v);
    describeRecording(v);
    describeFlesh(v);
  }
  template <class V>
  void describeFlesh(V& v) {
    v.boolean("flesh", flesh,
              "Fig. 13: the creature wrapped in flesh bound to its geoms, the flesh's vertices the fluid's markers "
              "(with forcing = coupled, the flesh's backward Euler step inside the coupled solve; projected needs "
              "forcing_regularisation near 3e-2 to keep the flesh stable, and the force then depends on the step)");
    flesh_params.describe(v);
    describeObjectiveForce3(v, objective_force);
  }
  // What the run stores for renders beside every geom's pose per frame (always).
  template <class V>
  void describeRecording(V& v) {
    v.choice("stored_fields", stored_fields, {"none", "plane", "volume"},
             "fluid fields stored every field_every frames, cell-centred u, v, w, pressure, |vorticity| and Q: none, "
             "the centre plane normal to y (frames, nz, nx), or the whole box (frames, nz, ny, nx: 48 B per cell)");
    v.integer("field_every", field_every, 1, 1000000, "frames between stored fields (the first after frame 1)");
  }
  // The fluid (src/fluid3d) and the coupling (src/coupling3d): describe_fluid3.hpp.
  template <class V>
  void describeFluid(V& v) {
    describeFluidBox3(v, fluid, "fluid density (air: 1.2)");
  }
  template <class V>
  void describeCoupling(V& v) {
    describeCoupling3(v, coupling,
             "projected: marker forces solved so that the projected flow meets the bodies, the bodies feel them a "
             "step later; coupled: solved with the bodies' velocities, felt in the same step (Eq. 9; stable for "
             "bodies lighter than the fluid); off: the bodies do not touch the fluid (a breaking switch)");
  }

  // The solvers' parameters: the box's cells from its proportions with the fixed coupled step
  // (frame_s / substeps); the coupling; the evaluations'.
  fluid3d::FluidParams3 fluidParams() const;
  control::FluidControlParams fluidControlParams() const;
  control::FluidRecording3 recording() const;
  std::vector<std::pair<std::string, double>> initialRad() const;
  // Ranges, then against the model: the controller, the fluid and coupling, the bodies inside the box,
  // the flap cycles within frames.
  std::string validate() const;
  // The coupled fluid of the run: the geoms' surfaces as markers, or with flesh its vertices.
  control::CoupledFluidFactory coupledFluid() const;
};

// The driven flyer of Lentine et al. 2010 §7.1 (Figs. 11-13, without flesh) in the 3-D fluid: the
// controller of kind control_fluid over the two-way coupled 3-D fluid (coupling3d).
class ControlFluid3dKind : public DescribedKind<ControlFluid3dParams> {
 public:
  ControlFluid3dKind();
  std::string name() const override { return "control_fluid3d"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
