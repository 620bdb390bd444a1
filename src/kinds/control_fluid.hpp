#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "control/fluid_controller.hpp"
#include "coupling/rigid_fluid_coupling.hpp"
#include "fluid/fluid_params.hpp"
#include "kinds/control_fluid_swimmer.hpp"
#include "kinds/control_params.hpp"
#include "kinds/describe_kind.hpp"

namespace creaturelab::kinds {

// The controller's defaults in the fluid: the drag along w as objective, and a perturbation large
// against the fluid's noise (§4.3: "non-negligible changes in the configuration"); no gravity.
inline ControllerSettings fluidControllerDefaults() {
  ControllerSettings c;
  c.objectives = "drag_along";
  c.delta_rad = 0.02;
  c.gravity_m_per_s2 = 0;
  return c;
}

// The fluid box the creature swims in (the paper gives no sizes): 4 m square, 128 cells, water
// without viscosity (the paper's inviscid Eq. 5), a stream entering on the left and leaving right.
inline fluid::FluidParams controlFluidBox() {
  fluid::FluidParams f;
  f.domain_width_m = 4.0;
  f.cells_x = 128;
  f.density_kg_per_m3 = 1000.0;
  f.kinematic_viscosity_m2_per_s = 0.0;
  f.walls.left.type = f.walls.right.type = fluid::WallType::open;
  f.blowup_speed_m_per_s = 50.0;
  return f;
}

// The coupling's defaults here: the fluid box's corner at (-1.2, -2) m in the world, a 1 m/s stream
// held in three columns (Fig. 8).
inline coupling::RigidFluidParams controlFluidCoupling() {
  coupling::RigidFluidParams c;
  c.origin_x_m = -1.2;
  c.origin_z_m = -2.0;
  c.inflow.stream_m_per_s = 1.0;
  c.inflow.stream_columns = 3;
  return c;
}

// The control_fluid kind's parameters: the controller's (ControllerSettings), the derivative
// evaluations', the fluid box (fluid::FluidParams), the coupling (coupling::RigidFluidParams), the
// recording, the driven flyer's (§7.1) and the swimmer's (§7.2, SwimmerSettings).
struct ControlFluidParams {
  ControllerSettings controller = fluidControllerDefaults();
  std::int64_t warmup_frames = 60;
  std::string perturbation = "moved";
  std::string objective_bodies = "moved";
  std::int64_t settle_steps = 0;
  std::int64_t average_steps = 1;
  fluid::FluidParams fluid = controlFluidBox();
  coupling::RigidFluidParams coupling = controlFluidCoupling();
  std::int64_t field_every_frames = 0;
  std::string stroke_sense;
  double flap_period_s = 0;
  std::int64_t force_cycles = 2;
  double controlled_limit_deg = 0;
  SwimmerSettings swimmer;

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
    describeFluid(v);
    describeCoupling(v);
    v.integer("field_every_frames", field_every_frames, 0, 1000000, "vorticity field and markers every k frames (0: never)");
    // The driven flyer (§7.1, flyer.toml).
    v.text("stroke_sense", stroke_sense, "",
           "§7.1: 'controlled = [+|-]inboard, ...': the joint has its given sense while the inboard joint's pattern "
           "angle rises (+) or falls (-)");
    v.real("flap_period_s", flap_period_s, "s", 0, 1e4,
           "period of the flap, a whole number of frames; 0: mean_up_force_n over the last average_frames");
    v.integer("force_cycles", force_cycles, 1, 100000, "mean_up_force_n: whole flap cycles at the end averaged");
    v.real("controlled_limit_deg", controlled_limit_deg, "deg", 0, 360,
           "controlled angles kept within +-this (0: no limit; the paper gives none)");
    swimmer.describe(v);
  }
  // The fluid (src/fluid): a square box.
  template <class V>
  void describeFluid(V& v) {
    using fluid::WallType;
    v.real("domain_m", fluid.domain_width_m, "m", 1e-3, 100, "side of the square fluid box (the paper gives none: 4 block lengths)");
    v.integer("cells", fluid.cells_x, 8, 2048, "cells per side");
    v.real("density_kg_per_m3", fluid.density_kg_per_m3, "kg/m^3", 1e-3, 1e6, "fluid density (§7: 'similar to water')");
    v.real("kinematic_viscosity_m2_per_s", fluid.kinematic_viscosity_m2_per_s, "m^2/s", 0, 10,
           "0: the paper's inviscid Eq. 5 (the advection's numerical viscosity remains)");
    v.choice("advection", fluid.advection,
             {fluid::AdvectionScheme::semi_lagrangian, fluid::AdvectionScheme::maccormack,
              fluid::AdvectionScheme::upwind2_rk2},
             "velocity advection scheme (upwind2_rk2: explicit, its CFL bound checked each step)");
    v.choice("viscosity_scheme", fluid.viscosity_scheme,
             {fluid::ViscosityScheme::backward_euler, fluid::ViscosityScheme::crank_nicolson},
             "viscous term in time: backward Euler (Stam 1999 §2.2, first order) or Crank-Nicolson (second order "
             "for that stage alone)");
    v.integer("fluid_threads", fluid.threads, 1, 16,
              "threads inside the frame's fluid steps, and the evaluations' when threads = 1 (bitwise the same "
              "for any count)");
    v.choice("wall_left", fluid.walls.left.type, {WallType::free_slip, WallType::no_slip, WallType::open, WallType::inflow},
             "left wall (open: the stream's band enters there; inflow: the stream enters through it)");
    v.choice("wall_right", fluid.walls.right.type, {WallType::free_slip, WallType::no_slip, WallType::open},
             "right wall (open: the stream leaves)");
    v.choice("wall_bottom", fluid.walls.bottom.type,
             {WallType::free_slip, WallType::no_slip, WallType::open, WallType::inflow},
             "floor (inflow: the source enters through it at source_m_per_s, a flux the projection keeps)");
    v.choice("wall_top", fluid.walls.top.type, {WallType::free_slip, WallType::no_slip, WallType::open}, "top");
    v.real("blowup_speed_m_per_s", fluid.blowup_speed_m_per_s, "m/s", 1e-6, 1e6, "a fluid faster than this stops the run (exit 3)");
    v.real("stream_m_per_s", coupling.inflow.stream_m_per_s, "m/s", -1e3, 1e3,
           "rightward stream held in the inflow band (Fig. 8); 0: none");
    v.integer("stream_columns", coupling.inflow.stream_columns, 0, 1000,
              "width of the held inflow band, cells (0: none, with wall_left = inflow)");
    v.real("source_m_per_s", coupling.inflow.source_m_per_s, "m/s", -1e3, 1e3, "upward floor source (§7.1); 0: none");
    v.integer("source_rows", coupling.inflow.source_rows, 0, 1000,
              "height of the held source band, cells (0: none, with wall_bottom = inflow)");
  }
  // The coupling (src/coupling).
  template <class V>
  void describeCoupling(V& v) {
    v.choice("forcing", coupling.forcing,
             {{"projected", coupling::Forcing::projected}, {"sweeps", coupling::Forcing::sweeps}},
             "projected: forces solved so that the projected flow meets the bodies; sweeps: direct forcing before "
             "the projection, which leaks");
    v.choice("kernel", coupling.kernel, {ib::Kernel::bilinear, ib::Kernel::peskin4}, "IB kernel of the markers (Peskin 2002 §6)");
    v.real("marker_spacing_cells", coupling.marker_spacing_cells, "cells", 1e-3, 1e3,
           "outline marker spacing; at most 1 cell (leak)");
    v.real("forcing_tolerance", coupling.forcing_tolerance, "", 1e-12, 1,
           "projected forcing: CG tolerance, fraction of the largest speed");
    v.integer("max_forcing_iterations", coupling.max_forcing_iterations, 1, 10000,
              "projected forcing: CG iterations at most per step");
    v.choice("forcing_preconditioner", coupling.forcing_preconditioner,
             {{"mass", coupling::ForcingPreconditioner::mass}, {"gram", coupling::ForcingPreconditioner::gram}},
             "projected forcing: CG preconditioner (mass: each marker's direct-forcing mass; gram: the forcing "
             "without the projection, its stencils' Gram matrix factored each step)");
    v.real("depth_m", coupling.depth_m, "m", 1e-6, 1e3, "bodies' extent along y (the fluid is per metre of depth)");
    v.real("origin_x_m", coupling.origin_x_m, "m", -1e4, 1e4, "world x of the fluid box's left wall");
    v.real("origin_z_m", coupling.origin_z_m, "m", -1e4, 1e4, "world z of the fluid box's floor");
    v.real("max_marker_cells_per_step", coupling.max_marker_cells_per_step, "cells", 1e-6, 2,
           "coupled stability limit: a marker moving farther in one step stops the point (exit 3)");
  }

  // The solvers' parameters: the square box with its fixed coupled step (frame_s / substeps) and the
  // inflow walls' speeds; the coupling with the mouth; the evaluations'.
  fluid::FluidParams fluidParams() const;
  coupling::RigidFluidParams rigidFluidParams() const;
  control::FluidControlParams fluidControlParams() const;
  // initial_deg as (hinge, radians).
  std::vector<std::pair<std::string, double>> initialRad() const;
  // Ranges, then against the model: the controller, the swimmer, the coupling, the initial poses,
  // the bodies inside the box, and the averaging windows within frames.
  std::string validate() const;
};

// A planar creature driven by the controller of Lentine et al. 2010 in the project's 2-D fluid,
// two-way coupled (Lentine et al. 2010 §4, §6, §7): kind `control`'s
// controller with the fluid force (Eq. 10) instead of the simple wind.
class ControlFluidKind : public DescribedKind<ControlFluidParams> {
 public:
  ControlFluidKind();
  std::string name() const override { return "control_fluid"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
