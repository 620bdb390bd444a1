#include "kinds/control.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "control/controller.hpp"
#include "control/simple_wind.hpp"
#include "control/wind_run.hpp"
#include "kinds/control_params.hpp"
#include "rigid/geom_surface.hpp"

namespace creaturelab::kinds {
namespace {

// initial_deg: a hinge's angle or a ball joint's rotation vector, degrees to radians.
void setInitialPoses(control::Controller& controller, const std::vector<InitialPose>& poses) {
  const double deg = 180.0 / std::numbers::pi;
  for (const auto& pose : poses) {
    if (pose.deg.size() == 3) controller.setRotation(pose.joint, {pose.deg[0] / deg, pose.deg[1] / deg, pose.deg[2] / deg});
    else controller.setAngle(pose.joint, pose.deg[0] / deg);
  }
}

// The recorded series, the geoms' frames for drawing and their types and bodies.
Result windRunResult(const control::WindRunRecorder& recorder) {
  Result result;
  addSeries(result, recorder.series());
  const control::GeomFrames& g = recorder.geoms();
  Tracks& tracks = result.lagrangian["geom_frames_m"];
  tracks.time_s = g.time_s;
  tracks.data = g.data;
  tracks.points = g.points;
  tracks.dim = 3;
  result.topology["geom_type"] = g.type;
  result.topology["geom_body"] = g.body;
  return result;
}

}  // namespace

ControlKind::ControlKind() {
  metrics_ = {
      {"final_angle_deg", "deg", "first controlled DOF (a ball: its rotation vector's x): mean angle over the last "
                                 "average_frames"},
      {"final_angle_deg_2", "deg", "second controlled DOF: mean angle over the last average_frames (NaN if none)"},
      {"final_angle_deg_3", "deg", "third controlled DOF: mean angle over the last average_frames (NaN if none)"},
      {"max_contacts", "", "most contacts MuJoCo held at once over the run (e.g. arm against leg)"},
      {"converged_frame", "", "first frame from which every controlled angle stays within the tolerance of its final "
                              "mean (Fig. 2); frames + 1 if never"},
      {"flow_angle_deg", "deg", "line of the first controlled joint's body (anchor to centre of mass) against the wind, "
                                "in [0, 90], mean over the last average_frames"},
      {"load_line_angle_deg", "deg",
       "|lean_deg - net_force_lean_deg|: the line from the first controlled joint's anchor to the centre of mass it "
       "carries against the net external force on those bodies (gravity + wind at zero velocity), from the signed "
       "means over the last average_frames (Fig. 4: 0 at zero effort)"},
      {"com_offset_m", "m", "distance of that centre of mass from the line through the anchor along the net force"},
      {"com_arm_m", "m", "distance of that centre of mass from the anchor (the scale of com_offset_m)"},
      {"lean_deg", "deg", "angle of anchor->centre of mass from the vertical line, positive towards +x, mean over the "
                          "last average_frames"},
      {"net_force_lean_deg", "deg", "angle of the net external force's line through the anchor from the vertical, on the "
                                    "centre of mass's side, positive towards +x, mean over the last average_frames"},
      {"final_effort_n_m_s", "N m s", "first controlled joint: mean effort (Eq. 1) over the last average_frames"},
      {"gravity_effort_n_m_s", "N m s", "the same joint's effort if the bodies it carries were held horizontal: "
                                        "m g |arm| dt, the scale of final_effort"},
      {"effort_ratio", "", "final_effort_n_m_s / gravity_effort_n_m_s (the mean |torque|: the chatter of the fixed "
                           "step about the optimum, proportional to strength)"},
      {"mean_torque_ratio", "", "|mean torque| over the last average_frames / (m g |arm|): the sustained load, near 0 "
                                "where the load passes through the joint"},
      {"median_torque_ratio", "", "median |torque| over the last average_frames / (m g |arm|): the sustained load without "
                                  "the rare contact impulses (an arm servoed into a leg) that dominate a mean"},
      {"final_drag_n", "N", "first controlled joint: mean |F_d| over its bodies over the last average_frames"},
      {"mean_speed_deg_per_s", "deg/s", "first controlled joint: mean angular velocity over the last average_frames"},
      {"max_servo_residual_rad", "rad", "largest servo miss before projection over the run"},
      {"max_kinematic_error_rad", "rad", "largest |q - pattern(t)| of the kinematic joints at a frame's end over the run"},
      {"max_pd_error_rad", "rad", "largest |q - pattern(t)| of the PD-driven joints at a frame's end over the run"},
      {"load_line_angle_3d_deg", "deg", "angle between the mean line anchor->centre of mass of the first controlled "
                                        "joint and the mean net external force over the last average_frames, in 3-D"},
      {"triangles", "", "wind surface triangles on moving bodies"},
  };
}

std::string ControlKind::doc() const {
  return "creature controller: gradient descent per joint under gravity and simple wind (Lentine et al. 2010 §2-3, §5)";
}

control::ControllerParams ControlParams::controllerParams() const {
  control::ControllerParams p = controller.controllerParams();
  p.steady_state = steady_state;
  p.servo_projection = servo_projection;
  return p;
}

std::string ControlParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  try {
    const auto model = controller.loadModel();
    if (auto e = controllerParams().validate(model); !e.empty()) return e;
    if (auto e = controller.checkInitialPoses(model, false); !e.empty()) return e;
    if (controller.average_frames > controller.frames) return "average_frames is larger than frames";
  } catch (const rigid::RigidError& e) {
    return std::string("model_file: ") + e.what();
  } catch (const std::invalid_argument& e) {  // a text parameter that does not parse (names itself)
    return e.what();
  }
  return "";
}

CostEstimate ControlKind::estimateCost(const Params& params) const {
  try {
    const ControllerSettings c = readParams<ControlParams>(params).controller;
    CostEstimate cost;
    const double evals = 2.0 * double(splitList(c.controlled, ',').size()) + 1;
    cost.steps = double(c.frames) * double(c.substeps) * evals;
    cost.memory_bytes = 64.0 * (1 << 20) + double(c.frames) * 2048;
    cost.detail = std::to_string(c.frames) + " frames x " + std::to_string(int(evals)) + " frame evaluations";
    return cost;
  } catch (const std::exception&) {
    return {};
  }
}

Result ControlKind::run(const Params& params) const {
  const ControlParams q = readParams<ControlParams>(params);
  const rigid::RigidModel model = q.controller.loadModel();
  const control::ControllerParams p = q.controllerParams();
  const control::SimpleWind force(rigid::geomSurfaces(model, int(q.surface_slices)), q.density_kg_per_m3,
                                  control::constantWind(q.windVelocity()));
  control::Controller controller(model, p, force);
  setInitialPoses(controller, q.controller.initialPoses());
  control::WindRunRecorder recorder(model, p, force, q.windVelocity(), q.controller.gravity_m_per_s2, controller);
  try {
    for (long f = 0; f < q.controller.frames; ++f) recorder.record(controller.frame(), controller);
  } catch (const std::exception& e) {
    throw RunFailure("control at t = " + std::to_string(controller.data().time_s()) + " s: " + e.what(),
                     windRunResult(recorder));
  }
  Result result = windRunResult(recorder);
  addMetrics(result, recorder.measure(int(q.controller.average_frames), q.controller.convergence_tolerance_deg,
                                      force.triangles()));
  return result;
}

}  // namespace creaturelab::kinds
