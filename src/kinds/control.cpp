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

control::Vec3 windVelocity(const ParamReader& r) {
  return {r.real("wind_x_m_per_s"), r.real("wind_y_m_per_s"), r.real("wind_z_m_per_s")};
}

control::ControllerParams windControllerParams(const ParamReader& r) {
  control::ControllerParams p = controllerParams(r);
  p.steady_state = r.boolean("steady_state");
  p.servo_projection = r.boolean("servo_projection");
  return p;
}

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
  params_ = {
      text("model_file", "experiments/control/models/block.xml", "",
           "MJCF creature (path from the working folder); 2-D creatures live in the x-z plane"),
      text("controlled", "hinge", "",
           "controlled joints, comma-separated: hinges (one DOF) or ball joints (three, about the body's axes)"),
      text("kinematic", "", "",
           "joints that follow kinematic_pattern exactly whatever the load (hinges; ball joints hold), comma-separated"),
      text("objectives", "effort", "",
           "per controlled joint: effort (Eq. 1, N m s) | drag (|Eq. 3|, N) | drag_along (Eq. 4 along drag_direction, N)"),
      text("senses", "min", "", "per controlled joint: min | max"),
      text("weights", "", "",
           "rows 'w11,w12,..; w21,..': joint i descends sum_j w_ij F_j (§5), weights carrying unit conversion; one "
           "row per controlled joint; empty = each its own"),
      text("initial_deg", "", "",
           "initial poses 'hinge=degrees, ball=x y z, ...' (ball: rotation vector in degrees; default: the model's "
           "reference)"),
      real("drag_direction_x", 1, "", -1e9, 1e9, "w of Eq. 4 (normalised); lift = drag along up"),
      real("drag_direction_y", 0, "", -1e9, 1e9, "w of Eq. 4"),
      real("drag_direction_z", 0, "", -1e9, 1e9, "w of Eq. 4"),
      real("wind_x_m_per_s", 10, "m/s", -1e4, 1e4, "constant wind (§3.1); the paper gives no speed: 10 m/s"),
      real("wind_y_m_per_s", 0, "m/s", -1e4, 1e4, "constant wind"),
      real("wind_z_m_per_s", 0, "m/s", -1e4, 1e4, "constant wind"),
      real("density_kg_per_m3", 1.2, "kg/m^3", 0, 1e5,
           "rho of Eq. 2; the paper's fluid was 'similar to water' (§7) at an unstated speed: air here, with "
           "model masses chosen so that the leans are visible"),
      real("gravity_m_per_s2", 9.81, "m/s^2", 0, 1e3, "gravity along -z (0: the wind alone, Fig. 6)"),
      real("frame_s", 1.0 / 60, "s", 1e-5, 1, "one controller step (a frame; Fig. 2 counts frames)"),
      integer("substeps", 1, 1, 1000, "MuJoCo steps per frame (the servo reaches its targets at each)"),
      integer("frames", 240, 1, 10000000, "frames to run"),
      real("strength_rad_per_s", 1.0, "rad/s", 0, 1e4,
           "the creature's strength: largest joint angle change per second, the fixed descent step (§2.1)"),
      real("delta_rad", 0.01, "rad", 1e-9, 1,
           "central-difference perturbation (§2.1; not given: 0.01 rad, large against round-off, small against "
           "the objectives' curvature)"),
      boolean("one_sided", false, "forward differences (§2.1: biased, off in the paper)"),
      integer("search_every_frames", 1, 1, 100000, "re-determine the direction every k frames (§2.1)"),
      boolean("steady_state", false,
              "§3.3: freeze the shape before evaluating objectives (joint velocities zeroed, a free creature keeps its "
              "rigid velocity); else §3.2, dynamic"),
      boolean("rigidify_outboard", true, "§5: hold the bodies outboard of a perturbed joint rigid with it"),
      integer("threads", 1, 1, 16, "threads for the per-DOF evaluations (§5, Fig. 10); results do not depend on it"),
      boolean("servo_projection", true,
              "test only: false skips the servo's projection of its last residual (§2.2 post-stabilisation), so the "
              "kinematic joints end where the servo's Newton iteration left them"),
      integer("surface_slices", 12, 3, 256, "segments around round geoms in the wind's surface triangles"),
      real("convergence_tolerance_deg", 1.0, "deg", 1e-6, 90,
           "converged frame: from it every controlled angle stays this close to its final mean"),
      integer("average_frames", 30, 1, 100000, "frames at the end over which final angles are averaged"),
  };
  addMotionPatternSpecs(params_);
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

std::string ControlKind::validate(const Params& params) const {
  ParamReader r(params);
  try {
    const auto model = loadModel(r);
    const auto p = windControllerParams(r);
    if (auto e = control::validate(p, model); !e.empty()) return e;
    for (const auto& pose : initialPoses(r)) {
      const int id = model.findJoint(pose.joint);
      if (id < 0) return "initial_deg: joint '" + pose.joint + "' is not in the model " + model.path();
      const auto type = model.joint(id).type;
      if (type == rigid::JointType::free) return "initial_deg: joint '" + pose.joint + "' is a free joint";
      if ((type == rigid::JointType::ball) != (pose.deg.size() == 3))
        return "initial_deg: joint '" + pose.joint + "' takes " + (type == rigid::JointType::ball ? "three numbers (a ball)" : "one angle");
    }
    if (r.integer("average_frames") > r.integer("frames")) return "average_frames is larger than frames";
  } catch (const rigid::RigidError& e) {
    return std::string("model_file: ") + e.what();
  } catch (const std::invalid_argument& e) {  // a text parameter that does not parse (names itself)
    return e.what();
  }
  return "";
}

CostEstimate ControlKind::estimateCost(const Params& params) const {
  try {
    ParamReader r(params);
    CostEstimate c;
    const double evals = 2.0 * double(splitList(r.text("controlled"), ',').size()) + 1;
    c.steps = double(r.integer("frames")) * double(r.integer("substeps")) * evals;
    c.memory_bytes = 64.0 * (1 << 20) + double(r.integer("frames")) * 2048;
    c.detail = std::to_string(r.integer("frames")) + " frames x " + std::to_string(int(evals)) + " frame evaluations";
    return c;
  } catch (const std::exception&) {
    return {};
  }
}

Result ControlKind::run(const Params& params) const {
  ParamReader r(params);
  const rigid::RigidModel model = loadModel(r);
  const control::ControllerParams p = windControllerParams(r);
  const control::SimpleWind force(rigid::geomSurfaces(model, int(r.integer("surface_slices"))),
                                  r.real("density_kg_per_m3"), control::constantWind(windVelocity(r)));
  control::Controller controller(model, p, force);
  setInitialPoses(controller, initialPoses(r));
  control::WindRunRecorder recorder(model, p, force, windVelocity(r), r.real("gravity_m_per_s2"), controller);
  try {
    for (long f = 0; f < r.integer("frames"); ++f) recorder.record(controller.frame(), controller);
  } catch (const std::exception& e) {
    throw RunFailure("control at t = " + std::to_string(controller.data().time_s()) + " s: " + e.what(),
                     windRunResult(recorder));
  }
  Result result = windRunResult(recorder);
  addMetrics(result, recorder.measure(int(r.integer("average_frames")), r.real("convergence_tolerance_deg"),
                                      force.triangles()));
  return result;
}

}  // namespace creaturelab::kinds
