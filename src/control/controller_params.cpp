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
std::string checkHinge(const rigid::RigidModel& model, const std::string& name, const char* what) {
  const int id = model.findJoint(name);
  if (id < 0) return std::string(what) + " joint '" + name + "' is not in the model " + model.path();
  if (model.joint(id).type != rigid::JointType::hinge)
    return std::string(what) + " joint '" + name + "' is not a hinge (the controller drives one angle per joint)";
  return "";
}
}  // namespace

std::string validate(const ControllerParams& p, const rigid::RigidModel& model) {
  const int n = int(p.controlled.size());
  if (n == 0) return "no controlled joints";
  std::set<std::string> seen;
  for (const auto& name : p.controlled) {
    if (auto e = checkHinge(model, name, "controlled"); !e.empty()) return e;
    if (!seen.insert(name).second) return "controlled joint '" + name + "' is listed twice";
  }
  for (const auto& name : p.kinematic) {
    if (auto e = checkHinge(model, name, "kinematic"); !e.empty()) return e;
    if (!seen.insert(name).second) return "joint '" + name + "' is both controlled and kinematic, or listed twice";
  }
  if (int(p.objectives.size()) != n)
    return "objectives: " + std::to_string(p.objectives.size()) + " given for " + std::to_string(n) + " controlled joints";
  if (int(p.senses.size()) != n)
    return "senses: " + std::to_string(p.senses.size()) + " given for " + std::to_string(n) + " controlled joints";
  if (!p.weights.empty()) {
    if (int(p.weights.size()) != n)
      return "weights: " + std::to_string(p.weights.size()) + " rows for " + std::to_string(n) + " controlled joints";
    for (int i = 0; i < n; ++i) {
      if (int(p.weights[i].size()) != n)
        return "weights: row " + std::to_string(i + 1) + " (" + p.controlled[i] + ") has " +
               std::to_string(p.weights[i].size()) + " weights, expected " + std::to_string(n) + " (one per controlled joint)";
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
