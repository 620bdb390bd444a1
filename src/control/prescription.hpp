#pragma once
// The prescribed joints of a controller (Lentine et al. 2010 §2.2, §5;
// seeds/creature-control-lentine-2010.txt): the controlled joints first, in order, then the
// kinematic ones; and per controlled joint the passive hinges and slides outboard of it, held
// rigid with it while it is perturbed (§5). Shared by the wind and the fluid controllers.
#include <vector>

#include "control/controller_params.hpp"
#include "control/target_servo.hpp"

namespace creaturelab::control {

struct Prescription {
  Prescribed prescribed;               // targets zero
  std::vector<std::vector<int>> holds; // per controlled joint: joint ids held with it
};

// p must pass validate(p, model).
Prescription prescription(const ControllerParams& p, const rigid::RigidModel& model);

// pr = base with `holds` (joint ids) appended, every target at the angle it has in qpos, and the
// prescribed entry `joint` moved by offset.
void perturbation(const Prescribed& base, const std::vector<int>& holds, const rigid::RigidModel& model,
                  const double* qpos, int joint, double offset_rad, Prescribed& pr);

}  // namespace creaturelab::control
