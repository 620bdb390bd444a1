#include "control/objectives.hpp"

#include <algorithm>
#include <cmath>

namespace creaturelab::control {

ObjectiveLayout makeLayout(const ControllerParams& p, const rigid::RigidModel& model) {
  ObjectiveLayout l;
  for (const auto& name : p.controlled) {
    const rigid::JointInfo j = model.joint(model.findJoint(name));
    l.dof.push_back(j.dof);
    l.ndof.push_back(j.type == rigid::JointType::ball ? 3 : 1);
    std::vector<char> moves(model.bodies(), 0);
    for (int b = 0; b < model.bodies(); ++b) moves[b] = model.inSubtree(b, j.body) ? 1 : 0;
    l.moves.push_back(std::move(moves));
  }
  l.kinds = p.objectives;
  const double norm = std::sqrt(p.drag_direction[0] * p.drag_direction[0] + p.drag_direction[1] * p.drag_direction[1] +
                                p.drag_direction[2] * p.drag_direction[2]);
  for (int k = 0; k < 3; ++k) l.direction[k] = p.drag_direction[k] / norm;
  l.frame_s = p.frame_s;
  l.steady_state = p.steady_state;
  return l;
}

void measure(rigid::RigidData& data, const ObjectiveLayout& l, const ForceModel& force, MeasureScratch& s,
             JointMeasures& out) {
  const int nv = data.model().dofs();
  const int n = int(l.dof.size());
  if (l.steady_state) data.freezeShape();
  data.kinematics();
  std::fill(data.appliedForces(), data.appliedForces() + nv, 0.0);
  force.apply(data, s.body_force_n);
  // Eq. 1: the torques that keep the current velocities, i.e. cancel the acceleration: inverse
  // dynamics at qacc = 0 (gravity, wind and contacts included), minus the applied wind itself.
  s.zero.assign(nv, 0.0);
  s.torque.assign(nv, 0.0);
  data.actuatorForcesFor(s.zero.data(), s.torque.data());
  out.torque_n_m.assign(n, 0);
  out.effort_n_m_s.assign(n, 0);
  out.drag_n.assign(n, 0);
  out.drag_along_n.assign(n, 0);
  out.objective.assign(n, 0);
  out.drag_vector_n.assign(n, Vec3{});
  for (int j = 0; j < n; ++j) {
    if (l.ndof[j] == 1) {
      out.torque_n_m[j] = s.torque[l.dof[j]];
    } else {
      double t2 = 0;
      for (int a = 0; a < l.ndof[j]; ++a) t2 += s.torque[l.dof[j] + a] * s.torque[l.dof[j] + a];
      out.torque_n_m[j] = std::sqrt(t2);
    }
    out.effort_n_m_s[j] = std::abs(out.torque_n_m[j]) * l.frame_s;
    Vec3 f{};  // Eq. 3 over the bodies joint j moves, summed in body order
    for (int b = 0; b < int(s.body_force_n.size()); ++b)
      if (l.moves[j][b])
        for (int k = 0; k < 3; ++k) f[k] += s.body_force_n[b][k];
    out.drag_vector_n[j] = f;
    out.drag_n[j] = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    out.drag_along_n[j] = f[0] * l.direction[0] + f[1] * l.direction[1] + f[2] * l.direction[2];
    switch (l.kinds[j]) {
      case Objective::effort: out.objective[j] = out.effort_n_m_s[j]; break;
      case Objective::drag: out.objective[j] = out.drag_n[j]; break;
      case Objective::drag_along: out.objective[j] = out.drag_along_n[j]; break;
    }
  }
}

double combined(const std::vector<std::vector<double>>& weights, const std::vector<double>& objective, int i) {
  if (weights.empty()) return objective[i];
  double sum = 0;
  for (int j = 0; j < int(objective.size()); ++j) sum += weights[i][j] * objective[j];
  return sum;
}

}  // namespace creaturelab::control
