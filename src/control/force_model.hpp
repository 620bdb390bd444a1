#pragma once
// The external-force stage of a creature step: a swappable stage (the coupled
// fluid can stand here instead of the simple wind). It reads the current pose and
// velocities (RigidData::kinematics() done), adds its generalized forces to the data's applied
// forces and reports the force on each body, from which the drag objectives are taken
// (Lentine et al. 2010 §3.2, Eqs. 3-4). Implementations are immutable once built, so any number
// of threads may call apply() at once, each on its own data.
#include <vector>

#include "rigid/rigid_data.hpp"

namespace creaturelab::control {

using rigid::Vec3;

class ForceModel {
 public:
  virtual ~ForceModel() = default;
  // body_force_n has one entry per body (resized here): the net force of this stage on it, N.
  virtual void apply(rigid::RigidData& data, std::vector<Vec3>& body_force_n) const = 0;
};

// No external force (gravity alone is MuJoCo's own).
class NoForce final : public ForceModel {
 public:
  void apply(rigid::RigidData& data, std::vector<Vec3>& body_force_n) const override {
    body_force_n.assign(data.model().bodies(), Vec3{});
  }
};

}  // namespace creaturelab::control
