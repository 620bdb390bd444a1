#pragma once
// The scene of the controller tests over the 3-D fluid (control_fluid3_test.cpp, control_flesh_test.cpp):
// the chain's hinged capsules (control_models.hpp, 0.4 m along +x from the origin) in a stream, its first
// two joints controlled, and what a run's frames record.
#include <string>
#include <utility>
#include <vector>

#include "control/fluid_controller.hpp"
#include "control_models.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "fluid3d/fluid_params3.hpp"
#include "rigid/rigid_model.hpp"

namespace creaturelab::testing {

// A 1.6 x 0.8 x 1.2 m box of 16 x 8 x 12 cells, a 0.5 m/s stream entering at x low and leaving at x high,
// inviscid, the fixed step 1/60 s; `fluid_threads` inside its steps.
inline fluid3d::FluidParams3 chainStream3(int fluid_threads) {
  fluid3d::FluidParams3 f;
  f.domain_x_m = 1.6;
  f.domain_y_m = 0.8;
  f.domain_z_m = 1.2;
  f.cells_x = 16;
  f.cells_y = 8;
  f.cells_z = 12;
  f.kinematic_viscosity_m2_per_s = 0;
  f.boundaries.axis[0].low = fluid3d::BoundaryType3::inflow;
  f.boundaries.axis[0].low_inflow_m_per_s = 0.5;
  f.boundaries.axis[0].high = fluid3d::BoundaryType3::open;
  f.time_step_policy = fluid3d::TimeStepPolicy3::fixed;
  f.fixed_step_s = 1.0 / 60;
  f.threads = fluid_threads;
  return f;
}

// The chain's model from the file `xml`: no gravity, 60 frames a second.
inline rigid::RigidModel chainModel3(const std::string& xml) {
  rigid::RigidModel model = rigid::RigidModel::load(xml);
  model.setGravity({0, 0, 0});
  model.setTimestep(1.0 / 60);
  return model;
}

// The box's corner in the world: the chain in the box's middle across.
inline coupling3d::RigidFluidParams3 chainCoupling3() {
  coupling3d::RigidFluidParams3 cp;
  cp.origin_m = {-0.4, -0.4, -0.6};
  return cp;
}

// j0 minimises the drag along w, j1 maximises |F|, on `threads` evaluation threads, 0.02 rad perturbations.
inline control::ControllerParams chainController3(int threads) {
  control::ControllerParams p;
  p.controlled = {"j0", "j1"};
  p.objectives = {control::Objective::drag_along, control::Objective::drag};
  p.senses = {control::Sense::minimize, control::Sense::maximize};
  p.threads = threads;
  p.delta_rad = 0.02;
  return p;
}

// The evaluations: one settle step (§4.3's validation mode), in the spatial fluid, reaching their poses as
// `perturbation`.
inline control::FluidControlParams chainEvaluations3(control::Perturbation perturbation = control::Perturbation::moved) {
  control::FluidControlParams f;
  f.settle_steps = 1;
  f.planar_fluid = false;
  f.perturbation = perturbation;
  return f;
}

// The chain's initial angles (rad).
inline std::vector<std::pair<std::string, double>> chainInitialRad3() { return {{"j0", -0.3}, {"j1", 0.2}}; }

// `frames` frames of `c`: each frame's angles, derivatives and objectives appended to `out`.
inline void recordFrames(control::FluidController& c, int frames, std::vector<double>& out) {
  for (int k = 0; k < frames; ++k) {
    const control::FrameRecord r = c.frame();
    out.insert(out.end(), r.angle_rad.begin(), r.angle_rad.end());
    out.insert(out.end(), r.derivative.begin(), r.derivative.end());
    out.insert(out.end(), r.objective.begin(), r.objective.end());
  }
}

// Every value of a grid's array (or an Eigen matrix) appended to `out`.
template <class A>
void appendValues(const A& a, std::vector<double>& out) {
  out.insert(out.end(), a.data(), a.data() + a.size());
}

}  // namespace creaturelab::testing
