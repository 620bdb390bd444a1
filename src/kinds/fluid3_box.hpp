#pragma once
// What the kinds over the 3-D coupled fluid (control_fluid3d, control_fluid3d_swimmer) build alike from
// their parameters, written once: the box as the coupled run steps it, the evaluations' common
// parameters, the initial hinge angles and the checks of the box and the coupling against the model.
// Each kind adds what is its own.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "control/fluid_controller.hpp"
#include "coupling3d/flesh_fluid_coupling3.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "flesh/flesh_params.hpp"
#include "fluid3d/fluid_params3.hpp"
#include "kinds/control_params.hpp"
#include "kinds/validate_fluid3.hpp"
#include "rigid/rigid_model.hpp"

namespace creaturelab::kinds {

// The box as the coupled run steps it: the cells along y and z from the box's proportions (cubic
// cells), the fixed coupled step frame_s / substeps; a fluid running away is caught as a blow-up.
inline fluid3d::FluidParams3 coupledFluidBox3(const fluid3d::FluidParams3& fluid, double frame_s, std::int64_t substeps) {
  fluid3d::FluidParams3 f = fluid;
  f.cells_y = int(std::lround(double(f.cells_x) * f.domain_y_m / f.domain_x_m));
  f.cells_z = int(std::lround(double(f.cells_x) * f.domain_z_m / f.domain_x_m));
  f.time_step_policy = fluid3d::TimeStepPolicy3::fixed;
  f.fixed_step_s = frame_s / double(substeps);
  return f;
}

// The derivative evaluations' parameters a 3-D kind's `q` sets alike (its keys perturbation,
// settle_steps, average_steps, controlled_limit_deg, objective_force), in the spatial fluid; the kind sets the rest.
template <class P>
control::FluidControlParams fluidControlParams3(const P& q) {
  control::FluidControlParams f;
  f.perturbation = q.perturbation == "placed" ? control::Perturbation::placed : control::Perturbation::moved;
  f.settle_steps = int(q.settle_steps);
  f.average_steps = int(q.average_steps);
  f.objective_force = q.objective_force;
  f.limit_rad = q.controlled_limit_deg / (180.0 / std::numbers::pi);
  f.planar_fluid = false;
  return f;
}

// initial_deg as (hinge, radians); throws std::invalid_argument naming initial_deg for a pose with
// other than one angle.
inline std::vector<std::pair<std::string, double>> initialHingeRad3(const ControllerSettings& controller) {
  std::vector<std::pair<std::string, double>> a;
  for (const auto& pose : controller.initialPoses()) {
    if (pose.deg.size() != 1) throw std::invalid_argument("initial_deg: '" + pose.joint + "' needs one angle (hinges only)");
    a.push_back({pose.joint, pose.deg[0] / (180.0 / std::numbers::pi)});
  }
  return a;
}

// A 3-D kind's checks against the model, in this order: q's initial poses (hinges), its box
// (q.fluidParams()), the coupling `coupling()` in the box; then, with the creature posed at its initial
// angles, `probe(data, box, coupling)` builds the kind's coupling there (which throws
// std::invalid_argument when a body is outside the box) and returns "" or what else is wrong.
template <class P, class Coupling, class Probe>
std::string checkInBox3(const P& q, const rigid::RigidModel& model, Coupling&& coupling, Probe&& probe) {
  if (auto e = q.controller.checkInitialPoses(model, true); !e.empty()) return e;
  const fluid3d::FluidParams3 box = q.fluidParams();
  if (auto e = box.validate(); !e.empty()) return e;
  const coupling3d::RigidFluidParams3 c = coupling();
  if (auto e = c.validate(box); !e.empty()) return e;
  const rigid::RigidData data = posedData(model, q.initialRad());
  return probe(data, box, c);
}

// A 3-D kind's probe for checkInBox3: the markers built in the box from the posed creature, the geoms'
// surfaces or, with `flesh` (its parameters checked first), the flesh's vertices; a body or the flesh
// outside the box throws std::invalid_argument. "" or what is wrong with the flesh.
inline std::string buildMarkers3(const rigid::RigidData& data, const fluid3d::FluidParams3& box,
                                 const coupling3d::RigidFluidParams3& coupling, const flesh::FleshParams* flesh) {
  if (!flesh) {
    coupling3d::RigidFluidCoupling3 markers(data, box, coupling);
    return "";
  }
  if (auto e = flesh->validate(); !e.empty()) return e;
  coupling3d::FleshFluidCoupling3 flesh_markers(data, box, coupling, *flesh);
  return "";
}

}  // namespace creaturelab::kinds
