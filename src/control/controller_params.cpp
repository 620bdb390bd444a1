#include "control/controller_params.hpp"

#include <cmath>
#include <set>

namespace creaturelab::control {

std::string toString(Objective o) {
  switch (o) {
    case Objective::effort: return "effort";
    case Objective::drag: return "drag";
    case Objective::drag_along: return "drag_along";
  }
  return "?";
}

std::string toString(Sense s) { return s == Sense::minimize ? "min" : "max"; }

namespace {
std::string checkJoint(const rigid::RigidModel& model, const std::string& name, const char* what, bool ball_ok) {
  const int id = model.findJoint(name);
  if (id < 0) return std::string(what) + " joint '" + name + "' is not in the model " + model.path();
  const auto type = model.joint(id).type;
  if (type == rigid::JointType::hinge || (ball_ok && type == rigid::JointType::ball)) return "";
  return std::string(what) + " joint '" + name + "' is not a hinge" + (ball_ok ? " or a ball joint" : "") +
         " (a " + (type == rigid::JointType::free ? "free" : type == rigid::JointType::slide ? "slide" : "ball") + " joint)";
}

std::string checkPatterns(const std::vector<Pattern>& patterns, const std::vector<std::string>& joints,
                          const rigid::RigidModel& model, const char* key) {
  for (std::size_t k = 0; k < patterns.size(); ++k) {
    if (auto e = patterns[k].validate(); !e.empty()) return std::string(key) + ": joint '" + joints[k] + "': " + e;
    if (patterns[k].kind != Pattern::Kind::hold && model.joint(model.findJoint(joints[k])).type != rigid::JointType::hinge)
      return std::string(key) + ": joint '" + joints[k] + "' is a ball joint: it can only hold its initial pose";
  }
  return "";
}
}  // namespace

std::string ControllerParams::validate(const rigid::RigidModel& model) const {
  const ControllerParams& p = *this;
  const int n = int(p.controlled.size());
  if (n == 0) return "no controlled joints";
  std::set<std::string> seen;
  bool ball = false;
  for (const auto& name : p.controlled) {
    if (auto e = checkJoint(model, name, "controlled", true); !e.empty()) return e;
    if (!seen.insert(name).second) return "controlled joint '" + name + "' is listed twice";
    ball = ball || model.joint(model.findJoint(name)).type == rigid::JointType::ball;
  }
  for (const auto& name : p.kinematic) {
    if (auto e = checkJoint(model, name, "kinematic", true); !e.empty()) return e;
    if (!seen.insert(name).second) return "joint '" + name + "' is both controlled and kinematic, or listed twice";
  }
  for (const auto& name : p.pd_driven) {
    if (auto e = checkJoint(model, name, "pd_driven", false); !e.empty()) return e;
    if (!seen.insert(name).second) return "pd_driven joint '" + name + "' is also controlled or kinematic, or listed twice";
  }
  if (!p.kinematic_patterns.empty() && p.kinematic_patterns.size() != p.kinematic.size())
    return "kinematic_pattern: " + std::to_string(p.kinematic_patterns.size()) + " patterns for " +
           std::to_string(p.kinematic.size()) + " kinematic joints";
  if (auto e = checkPatterns(p.kinematic_patterns, p.kinematic, model, "kinematic_pattern"); !e.empty()) return e;
  if (p.pd_patterns.size() != p.pd_driven.size())
    return "pd_pattern: " + std::to_string(p.pd_patterns.size()) + " patterns for " + std::to_string(p.pd_driven.size()) +
           " pd_driven joints";
  if (auto e = checkPatterns(p.pd_patterns, p.pd_driven, model, "pd_pattern"); !e.empty()) return e;
  if (!(p.pd_kp_n_m_per_rad >= 0) || !std::isfinite(p.pd_kp_n_m_per_rad)) return "pd_kp_n_m_per_rad must be zero or positive";
  if (!(p.pd_kd_n_m_s_per_rad >= 0) || !std::isfinite(p.pd_kd_n_m_s_per_rad))
    return "pd_kd_n_m_s_per_rad must be zero or positive";
  const std::string ball_note = ball ? " (a ball joint counts once: its three axes share its objective)" : "";
  if (int(p.objectives.size()) != n)
    return "objectives: " + std::to_string(p.objectives.size()) + " given for " + std::to_string(n) + " controlled joints";
  if (int(p.senses.size()) != n)
    return "senses: " + std::to_string(p.senses.size()) + " given for " + std::to_string(n) + " controlled joints";
  if (!p.weights.empty()) {
    if (int(p.weights.size()) != n)
      return "weights: " + std::to_string(p.weights.size()) + " rows for " + std::to_string(n) + " controlled joints" + ball_note;
    for (int i = 0; i < n; ++i) {
      if (int(p.weights[i].size()) != n)
        return "weights: row " + std::to_string(i + 1) + " (" + p.controlled[i] + ") has " +
               std::to_string(p.weights[i].size()) + " weights, expected " + std::to_string(n) +
               " (one per controlled joint)" + ball_note;
      for (double w : p.weights[i])
        if (!std::isfinite(w)) return "weights: row " + std::to_string(i + 1) + " has a weight that is not a finite number";
    }
  }
  const double w2 = p.drag_direction[0] * p.drag_direction[0] + p.drag_direction[1] * p.drag_direction[1] +
                    p.drag_direction[2] * p.drag_direction[2];
  if (!(w2 > 0) || !std::isfinite(w2)) return "drag_direction must be a nonzero finite vector";
  if (!(p.frame_s > 0)) return "frame_s must be positive";
  if (p.substeps < 1) return "substeps must be at least 1";
  if (!(p.strength_rad_per_s >= 0) || !std::isfinite(p.strength_rad_per_s)) return "strength must be zero or positive";
  if (!(p.delta_rad > 0) || !std::isfinite(p.delta_rad)) return "delta_rad (the perturbation) must be positive";
  if (p.search_every_frames < 1) return "search_every_frames must be at least 1";
  if (p.threads < 1) return "threads must be at least 1";
  return "";
}

}  // namespace creaturelab::control
