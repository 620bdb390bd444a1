#pragma once
// The 3-D fluid box's and the 3-D coupling's parameters of the kinds over the 3-D coupled fluid
// (control_fluid3d, control_fluid3d_swimmer), declared once here; each kind passes its own source
// for what differs.
#include "control/fluid_controller.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "fluid3d/fluid_params3.hpp"

namespace creaturelab::kinds {

// The fluid (src/fluid3d): a box of cubic cells, z up. `density_doc`: the kind's fluid density and source.
template <class V>
void describeFluidBox3(V& v, fluid3d::FluidParams3& fluid, const char* density_doc) {
  v.real("domain_x_m", fluid.domain_x_m, "m", 1e-3, 1e3, "box length along x (the paper gives none)");
  v.real("domain_y_m", fluid.domain_y_m, "m", 1e-3, 1e3, "box length along y");
  v.real("domain_z_m", fluid.domain_z_m, "m", 1e-3, 1e3, "box height (z up)");
  v.integer("cells", fluid.cells_x, 4, 1024, "cells along x; along y and z from the box's proportions (cubic cells)");
  v.real("density_kg_per_m3", fluid.density_kg_per_m3, "kg/m^3", 1e-3, 1e6, density_doc);
  v.real("kinematic_viscosity_m2_per_s", fluid.kinematic_viscosity_m2_per_s, "m^2/s", 0, 10,
         "0: the paper's inviscid Eq. 5 (the advection's numerical viscosity remains)");
  fluid.describeSides(v);
  fluid.describeSchemes(v);
  v.integer("fluid_threads", fluid.threads, 1, 16,
            "threads inside the frame's fluid steps, and the evaluations' when threads = 1 (bitwise the same "
            "for any count)");
  v.real("blowup_speed_m_per_s", fluid.blowup_speed_m_per_s, "m/s", 1e-6, 1e6, "a fluid faster than this stops the run (exit 3)");
}

// Which force on a body the controller's objective reads (control::ObjectiveForce).
template <class V>
void describeObjectiveForce3(V& v, control::ObjectiveForce& objective_force) {
  v.choice("objective_force", objective_force,
           {{"fluid_on_flesh", control::ObjectiveForce::fluid_on_flesh},
            {"flesh_on_bone", control::ObjectiveForce::flesh_on_bone}},
           "the force on a body the objective reads: fluid_on_flesh (the fluid's on its surface, with flesh on the "
           "flesh: Eq. 10 over the creature's surface) | flesh_on_bone (the force its bone takes: the flesh's binding "
           "reaction and the fluid's on its interior); the same without flesh");
}

// The coupling (src/coupling3d). `forcing_doc`: the forcing choices as the kind uses them.
template <class V>
void describeCoupling3(V& v, coupling3d::RigidFluidParams3& coupling, const char* forcing_doc) {
  v.choice("forcing", coupling.forcing,
           {{"projected", coupling3d::Forcing3::projected}, {"coupled", coupling3d::Forcing3::coupled},
            {"off", coupling3d::Forcing3::off}},
           forcing_doc);
  v.choice("kernel", coupling.kernel, {ib::Kernel::bilinear, ib::Kernel::peskin4}, "IB kernel of the markers (Peskin 2002 §6)");
  v.real("marker_spacing_cells", coupling.marker_spacing_cells, "cells", 1e-3, 1,
         "surface marker spacing; at most 1 cell (leak)");
  v.boolean("interior_markers", coupling.interior_markers,
            "also markers inside each primitive geom, a kernel's half-width below its surface");
  v.real("forcing_tolerance", coupling.forcing_tolerance, "", 1e-12, 1,
         "projected and coupled forcing: CG tolerance, fraction of the largest speed");
  v.integer("max_forcing_iterations", coupling.max_forcing_iterations, 1, 10000,
            "projected and coupled forcing: CG iterations at most per step");
  v.real("forcing_regularisation", coupling.forcing_regularisation, "", 0, 1,
         "projected and coupled forcing: Tikhonov weight on the marker forces (relative to the direct-forcing "
         "mass); the markers slip by about this fraction of their forcing at every step");
  v.real("origin_x_m", coupling.origin_m[0], "m", -1e4, 1e4, "world x of the fluid box's corner");
  v.real("origin_y_m", coupling.origin_m[1], "m", -1e4, 1e4, "world y of the fluid box's corner");
  v.real("origin_z_m", coupling.origin_m[2], "m", -1e4, 1e4, "world z of the fluid box's floor");
  v.real("max_marker_cells_per_step", coupling.max_marker_cells_per_step, "cells", 1e-6, 2,
         "coupled stability limit: a marker moving farther in one step stops the point (exit 3)");
}

}  // namespace creaturelab::kinds
