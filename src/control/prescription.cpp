#include "control/prescription.hpp"

#include <algorithm>
#include <cmath>

namespace creaturelab::control {
namespace {

Slot slotOf(const rigid::RigidModel& model, const std::string& name, const Pattern* pattern,
            Prescribed& pr) {
  const auto j = model.joint(model.findJoint(name));
  Slot s{j.qpos, j.dof, 0, j.type == rigid::JointType::ball, j.limited, j.range_lo, j.range_hi};
  if (s.ball) {
    s.index = int(pr.balls.size());
    pr.balls.push_back({j.qpos, j.dof, {1, 0, 0, 0}});
  } else {
    s.index = int(pr.qpos.size());
    pr.qpos.push_back(j.qpos);
    pr.dof.push_back(j.dof);
    pr.target.push_back(0.0);
    pr.pattern.push_back(pattern);
  }
  return s;
}

}  // namespace

double clampToRange(const Slot& s, double target_rad) {
  return s.limited ? std::clamp(target_rad, s.lo, s.hi) : target_rad;
}

rigid::Quat clampToRange(const Slot& s, const rigid::Quat& target) {
  if (!s.limited) return target;
  const Vec3 r = rigid::quatLog(target);
  const double angle = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  if (angle <= s.hi) return target;
  const double shrink = s.hi / angle;
  return rigid::quatExp({shrink * r[0], shrink * r[1], shrink * r[2]});
}

rigid::Quat quatAt(const double* qpos, int address) {
  return {qpos[address], qpos[address + 1], qpos[address + 2], qpos[address + 3]};
}

Prescription prescription(const ControllerParams& p, const rigid::RigidModel& model) {
  Prescription out;
  Prescribed& pr = out.prescribed;
  const int n = int(p.controlled.size());
  for (int i = 0; i < n; ++i) {
    out.controlled.push_back(slotOf(model, p.controlled[i], nullptr, pr));
    for (int a = 0; a < (out.controlled.back().ball ? 3 : 1); ++a) {
      out.dof_joint.push_back(i);
      out.dof_axis.push_back(a);
    }
  }
  for (std::size_t k = 0; k < p.kinematic.size(); ++k) {
    const bool moves = !p.kinematic_patterns.empty() && p.kinematic_patterns[k].kind != Pattern::Kind::hold;
    out.kinematic.push_back(slotOf(model, p.kinematic[k], moves ? &p.kinematic_patterns[k] : nullptr, pr));
  }
  for (std::size_t k = 0; k < p.pd_driven.size(); ++k) {
    const auto j = model.joint(model.findJoint(p.pd_driven[k]));
    const Pattern* pat = p.pd_patterns[k].kind == Pattern::Kind::hold ? nullptr : &p.pd_patterns[k];
    pr.pd.push_back({j.qpos, j.dof, pat, 0.0, p.pd_kp_n_m_per_rad, p.pd_kd_n_m_s_per_rad});
  }
  out.holds.resize(n);
  for (int i = 0; i < n && p.rigidify_outboard; ++i) {
    const int body = model.joint(model.findJoint(p.controlled[i])).body;
    for (int id = 0; id < model.joints(); ++id) {
      const auto j = model.joint(id);
      if (j.type == rigid::JointType::free) continue;
      bool prescribed = false;
      for (const Slot& s : out.controlled) prescribed = prescribed || s.qpos == j.qpos;
      for (const Slot& s : out.kinematic) prescribed = prescribed || s.qpos == j.qpos;
      if (!prescribed && model.inSubtree(j.body, body)) out.holds[i].push_back(id);
    }
  }
  return out;
}

void captureHolds(Prescription& p, const double* qpos) {
  for (const Slot& s : p.kinematic) {
    if (s.ball) p.prescribed.balls[s.index].target = quatAt(qpos, s.qpos);
    else p.prescribed.target[s.index] = qpos[s.qpos];
  }
  for (PdDrive& d : p.prescribed.pd) d.hold_rad = qpos[d.qpos];
}

void perturbation(const Prescription& base, const rigid::RigidModel& model, const double* qpos, int t,
                  double offset, Prescribed& pr) {
  pr = base.prescribed;
  for (std::size_t k = 0; k < pr.qpos.size(); ++k)
    if (!pr.pattern[k]) pr.target[k] = qpos[pr.qpos[k]];
  for (auto& b : pr.balls) b.target = quatAt(qpos, b.qpos);
  const int i = base.dof_joint[t];
  const Slot& s = base.controlled[i];
  if (s.ball) {
    Vec3 r{};
    r[base.dof_axis[t]] = offset;
    pr.balls[s.index].target = clampToRange(s, rigid::quatRotate(pr.balls[s.index].target, r));
  } else {
    pr.target[s.index] = clampToRange(s, pr.target[s.index] + offset);
  }
  for (int id : base.holds[i]) {
    const auto j = model.joint(id);
    if (j.type == rigid::JointType::ball) {
      pr.balls.push_back({j.qpos, j.dof, quatAt(qpos, j.qpos)});
    } else {
      pr.qpos.push_back(j.qpos);
      pr.dof.push_back(j.dof);
      pr.target.push_back(qpos[j.qpos]);
      pr.pattern.push_back(nullptr);
    }
    std::erase_if(pr.pd, [&](const PdDrive& d) { return d.qpos == j.qpos; });
  }
}

}  // namespace creaturelab::control
