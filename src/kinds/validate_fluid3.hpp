#pragma once
// What validate() of a creature controller's kind in a coupled fluid checks (control_fluid in 2-D,
// control_fluid3d and control_fluid3d_swimmer in 3-D), in one order written once: each kind passes
// its own checks.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kinds/control_params.hpp"
#include "kinds/describe.hpp"
#include "rigid/rigid_data.hpp"
#include "rigid/rigid_model.hpp"

namespace creaturelab::kinds {

// No check of the kind's own at that place: "".
inline std::string noCheck() { return ""; }

// In this order: the ranges of `q`'s keys; `keys()`, the kind's checks that need no model; with
// q.controller's model loaded, the derivative evaluations' parameters (q.fluidControlParams()) against
// the controller and the model, then `against(model)`, the kind's checks of its fluid and coupling
// against the model; average_frames within frames; `last()`. Each check returns "" or what is wrong,
// and the first that is wrong is the answer; a model that does not load is named as model_file, a
// std::invalid_argument thrown by a check (a parse error, a body outside the box) by its message.
template <class P, class Keys, class Against, class Last>
std::string validateControlInFluid(const P& q, Keys&& keys, Against&& against, Last&& last) {
  if (std::string problems = rangeProblems(q); !problems.empty()) return problems;
  if (std::string e = keys(); !e.empty()) return e;
  try {
    const rigid::RigidModel model = q.controller.loadModel();
    if (auto e = q.fluidControlParams().validate(q.controller.controllerParams(), model); !e.empty()) return e;
    if (std::string e = against(model); !e.empty()) return e;
    if (q.controller.average_frames > q.controller.frames) return "average_frames is larger than frames";
    return last();
  } catch (const rigid::RigidError& e) {
    return std::string("model_file: ") + e.what();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

// The model's data with each joint of `rad` (hinges, as (name, radians)) at its angle and the
// positions computed: the creature as the fluid first sees it.
inline rigid::RigidData posedData(const rigid::RigidModel& model, const std::vector<std::pair<std::string, double>>& rad) {
  rigid::RigidData data(model);
  for (const auto& [joint, a] : rad) data.qpos()[model.joint(model.findJoint(joint)).qpos] = a;
  data.kinematics();
  return data;
}

// The driven flyer's force_cycles flap periods (§7.1) within frames; no flap (flap_period_s = 0): "".
// framesPerCycle throws std::invalid_argument for a period not a whole number of frames.
template <class P>
std::string checkFlapCycles(const P& q) {
  if (q.flap_period_s > 0 && framesPerCycle(q.flap_period_s, q.controller.frame_s) * q.force_cycles > q.controller.frames)
    return "force_cycles x flap_period_s is longer than frames";
  return "";
}

}  // namespace creaturelab::kinds
