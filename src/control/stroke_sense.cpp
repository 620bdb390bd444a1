#include "control/stroke_sense.hpp"

namespace creaturelab::control {

const Pattern* strokePattern(const StrokeFollow& follow, const ControllerParams& p) {
  if (follow.joint.empty()) return nullptr;
  for (std::size_t k = 0; k < p.pd_driven.size() && k < p.pd_patterns.size(); ++k)
    if (p.pd_driven[k] == follow.joint) return &p.pd_patterns[k];
  for (std::size_t k = 0; k < p.kinematic.size() && k < p.kinematic_patterns.size(); ++k)
    if (p.kinematic[k] == follow.joint) return &p.kinematic_patterns[k];
  return nullptr;
}

std::string validate(const std::vector<StrokeFollow>& follow, const ControllerParams& p) {
  if (follow.empty()) return "";
  if (follow.size() != p.controlled.size())
    return "stroke_sense: " + std::to_string(follow.size()) + " entries for " + std::to_string(p.controlled.size()) +
           " controlled joints (one each, or none)";
  for (const auto& f : follow) {
    if (f.joint.empty()) continue;
    if (f.sign != 1.0 && f.sign != -1.0) return "stroke_sense: '" + f.joint + "': the sign must be + or -";
    const Pattern* pat = strokePattern(f, p);
    if (!pat) return "stroke_sense: '" + f.joint + "' is not a pd_driven or kinematic joint with a pattern";
    if (pat->kind == Pattern::Kind::hold) return "stroke_sense: '" + f.joint + "' holds (its pattern has no stroke)";
  }
  return "";
}

Sense senseAt(Sense given, const Pattern* pattern, double sign, double t_s) {
  if (!pattern) return given;
  const double r = sign * pattern->rate(t_s);
  if (r >= 0) return given;
  return given == Sense::maximize ? Sense::minimize : Sense::maximize;
}

}  // namespace creaturelab::control
