#include "control/prescription.hpp"

namespace creaturelab::control {

Prescription prescription(const ControllerParams& p, const rigid::RigidModel& model) {
  Prescription out;
  Prescribed& pr = out.prescribed;
  for (const auto* names : {&p.controlled, &p.kinematic})
    for (const auto& name : *names) {
      const auto j = model.joint(model.findJoint(name));
      pr.qpos.push_back(j.qpos);
      pr.dof.push_back(j.dof);
    }
  pr.target.assign(pr.qpos.size(), 0.0);
  const int n = int(p.controlled.size());
  out.holds.resize(n);
  for (int i = 0; i < n && p.rigidify_outboard; ++i) {
    const int body = model.joint(model.findJoint(p.controlled[i])).body;
    for (int id = 0; id < model.joints(); ++id) {
      const auto j = model.joint(id);
      if (j.type != rigid::JointType::hinge && j.type != rigid::JointType::slide) continue;
      bool prescribed = false;
      for (int q : pr.qpos) prescribed = prescribed || q == j.qpos;
      if (!prescribed && model.inSubtree(j.body, body)) out.holds[i].push_back(id);
    }
  }
  return out;
}

void perturbation(const Prescribed& base, const std::vector<int>& holds, const rigid::RigidModel& model,
                  const double* qpos, int joint, double offset, Prescribed& pr) {
  pr = base;
  for (std::size_t k = 0; k < pr.qpos.size(); ++k) pr.target[k] = qpos[pr.qpos[k]];
  pr.target[joint] += offset;
  for (int id : holds) {
    const auto j = model.joint(id);
    pr.qpos.push_back(j.qpos);
    pr.dof.push_back(j.dof);
    pr.target.push_back(qpos[j.qpos]);
  }
}

}  // namespace creaturelab::control
