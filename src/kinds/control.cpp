#include "kinds/control.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "control/controller.hpp"
#include "control/simple_wind.hpp"
#include "kinds/control_params.hpp"
#include "rigid/geom_surface.hpp"

namespace creaturelab::kinds {
namespace {

using control::Vec3;
constexpr double kDeg = 180.0 / std::numbers::pi;

Vec3 wind(const ParamReader& r) { return {r.real("wind_x_m_per_s"), r.real("wind_y_m_per_s"), r.real("wind_z_m_per_s")}; }

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

control::ControllerParams windControllerParams(const ParamReader& r) {
  control::ControllerParams p = controllerParams(r);
  p.steady_state = r.boolean("steady_state");
  return p;
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
                                  r.real("density_kg_per_m3"), control::constantWind(wind(r)));
  control::Controller controller(model, p, force);
  for (const auto& pose : initialPoses(r)) {
    if (pose.deg.size() == 3) controller.setRotation(pose.joint, {pose.deg[0] / kDeg, pose.deg[1] / kDeg, pose.deg[2] / kDeg});
    else controller.setAngle(pose.joint, pose.deg[0] / kDeg);
  }

  const int n = int(p.controlled.size());
  const int nd = controller.controlledDofs();
  // Per controlled DOF a name: the hinge's, or the ball's with _x, _y, _z (its rotation vector).
  std::vector<std::string> dof_names;
  for (const auto& j : p.controlled) {
    if (model.joint(model.findJoint(j)).type != rigid::JointType::ball) dof_names.push_back(j);
    else
      for (const char* axis : {"_x", "_y", "_z"}) dof_names.push_back(j + axis);
  }
  const long frames = r.integer("frames");
  Result result;
  auto& ts = result.timeseries;
  Series& time = ts["time_s"] = {{}, "s"};
  Series& residual = ts["servo_residual_rad"] = {{}, "rad"};
  std::vector<Series*> angle, target, objective, derivative, effort, torque, drag, drag_along;
  for (const auto& d : dof_names) {
    angle.push_back(&(ts["angle_deg_" + d] = {{}, "deg"}));
    target.push_back(&(ts["target_deg_" + d] = {{}, "deg"}));
    derivative.push_back(&(ts["derivative_per_rad_" + d] = {{}, "1/rad"}));
  }
  for (const auto& j : p.controlled) {
    objective.push_back(&(ts["objective_" + j] = {{}, ""}));
    effort.push_back(&(ts["effort_n_m_s_" + j] = {{}, "N m s"}));
    torque.push_back(&(ts["torque_n_m_" + j] = {{}, "N m"}));
    drag.push_back(&(ts["drag_n_" + j] = {{}, "N"}));
    drag_along.push_back(&(ts["drag_along_n_" + j] = {{}, "N"}));
  }
  // Geom frames for drawing: centre and the three axis tips scaled by the half-extents.
  Tracks& geoms = result.lagrangian["geom_frames_m"];
  geoms.points = 4 * model.geoms();
  geoms.dim = 3;
  auto& types = result.topology["geom_type"];
  auto& bodies = result.topology["geom_body"];
  for (int g = 0; g < model.geoms(); ++g) {
    types.push_back(model.geomType(g));
    bodies.push_back(model.geomBody(g));
  }
  auto recordGeoms = [&](double t) {
    geoms.time_s.push_back(t);
    const auto& d = controller.data();
    for (int g = 0; g < model.geoms(); ++g) {
      const double* c = d.geomPosition(g);
      const double* R = d.geomRotation(g);
      // Half-extents along the geom's axes: MuJoCo's sizes are (radius, half-length) for
      // capsules and cylinders (along z), (radius) for spheres.
      Vec3 s = model.geomSize(g);
      if (types[g] == 3 || types[g] == 5) s = {s[0], s[0], s[1]};
      if (types[g] == 2) s = {s[0], s[0], s[0]};
      geoms.data.insert(geoms.data.end(), c, c + 3);
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k) geoms.data.push_back(c[k] + s[a] * R[3 * k + a]);
    }
  };
  recordGeoms(controller.data().time_s());

  // The first controlled joint's load: the line from its anchor to the centre of mass it carries,
  // and the net external force on those bodies at zero velocity (gravity + Eq. 3), every frame.
  const auto j0 = model.joint(model.findJoint(p.controlled[0]));
  const int j0_id = model.findJoint(p.controlled[0]);
  const double mass = model.subtreeMass_kg(j0.body);
  const double g = r.real("gravity_m_per_s2");
  control::ControllerParams steady = p;
  steady.steady_state = true;
  steady.threads = 1;
  control::Controller probe(model, steady, force);
  Series& flow = ts["flow_angle_deg"] = {{}, "deg"};
  Series& load = ts["load_line_angle_deg"] = {{}, "deg"};
  Series& lean = ts["lean_deg"] = {{}, "deg"};
  Series& force_lean = ts["net_force_lean_deg"] = {{}, "deg"};
  Series& offset = ts["com_offset_m"] = {{}, "m"};
  Series& arm_length = ts["com_arm_m"] = {{}, "m"};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> arm_x, arm_y, arm_z, net_x, net_y, net_z;
  auto recordLoad = [&]() {
    auto& d = controller.data();
    d.kinematics();
    const double* anchor = d.jointAnchor(j0_id);
    const double* com = d.subtreeCom(j0.body);
    const Vec3 arm = {com[0] - anchor[0], com[1] - anchor[1], com[2] - anchor[2]};
    probe.data().restore(d.save());
    const control::JointMeasures still = probe.measureNow();
    const Vec3 net = {still.drag_vector_n[0][0], still.drag_vector_n[0][1], still.drag_vector_n[0][2] - mass * g};
    const double nn = norm(net);
    double off = 0;
    if (nn > 0) {
      const double along = (arm[0] * net[0] + arm[1] * net[1] + arm[2] * net[2]) / nn;
      off = std::sqrt(std::max(0.0, norm(arm) * norm(arm) - along * along));
    }
    flow.values.push_back(norm(wind(r)) > 0 ? lineAngleDeg(arm, wind(r)) : nan);
    load.values.push_back(nn > 0 ? lineAngleDeg(arm, net) : nan);
    // Leans from the vertical line through the anchor, positive towards +x: the carried centre of
    // mass, and the point of the load line on the same side (below the anchor for a hanging
    // block, above it for an upright trunk).
    lean.values.push_back(std::atan2(arm[0], std::abs(arm[2])) * kDeg);
    const double side = arm[0] * net[0] + arm[1] * net[1] + arm[2] * net[2] >= 0 ? 1.0 : -1.0;
    force_lean.values.push_back(nn > 0 ? std::atan2(side * net[0], std::abs(net[2])) * kDeg : nan);
    offset.values.push_back(off);
    arm_length.values.push_back(norm(arm));
    arm_x.push_back(arm[0]);
    arm_y.push_back(arm[1]);
    arm_z.push_back(arm[2]);
    net_x.push_back(net[0]);
    net_y.push_back(net[1]);
    net_z.push_back(net[2]);
  };

  double max_residual = 0, max_kinematic = 0, max_pd = 0;
  int max_contacts = 0;
  try {
    for (long f = 0; f < frames; ++f) {
      const control::FrameRecord fr = controller.frame();
      time.values.push_back(fr.time_s);
      residual.values.push_back(fr.servo_residual_rad);
      max_residual = std::max(max_residual, fr.servo_residual_rad);
      max_contacts = std::max(max_contacts, controller.data().contacts());
      max_kinematic = std::max(max_kinematic, fr.kinematic_error_rad);
      max_pd = std::max(max_pd, fr.pd_error_rad);
      for (int t = 0; t < nd; ++t) {
        angle[t]->values.push_back(fr.angle_rad[t] * kDeg);
        target[t]->values.push_back(fr.target_rad[t] * kDeg);
        derivative[t]->values.push_back(fr.derivative[t]);
      }
      for (int i = 0; i < n; ++i) {
        objective[i]->values.push_back(fr.objective[i]);
        effort[i]->values.push_back(fr.measures.effort_n_m_s[i]);
        torque[i]->values.push_back(fr.measures.torque_n_m[i]);
        drag[i]->values.push_back(fr.measures.drag_n[i]);
        drag_along[i]->values.push_back(fr.measures.drag_along_n[i]);
      }
      recordGeoms(fr.time_s);
      recordLoad();
    }
  } catch (const std::exception& e) {
    throw RunFailure("control at t = " + std::to_string(controller.data().time_s()) + " s: " + e.what(), result);
  }

  // Final values: means over the last average_frames (the strength-limited step chatters by one
  // step about an optimum).
  const int tail = int(std::min<long>(r.integer("average_frames"), frames));
  auto tailMean = [&](const std::vector<double>& v) {
    double sum = 0;
    for (int k = int(v.size()) - tail; k < int(v.size()); ++k) sum += v[k] / tail;
    return sum;
  };
  std::vector<std::vector<double>> angles;
  for (int t = 0; t < nd; ++t) angles.push_back(angle[t]->values);

  auto& m = result.metrics;
  m["final_angle_deg"] = {tailMean(angle[0]->values), "deg"};
  m["final_angle_deg_2"] = {nd > 1 ? tailMean(angle[1]->values) : nan, "deg"};
  m["final_angle_deg_3"] = {nd > 2 ? tailMean(angle[2]->values) : nan, "deg"};
  m["max_contacts"] = {double(max_contacts), ""};
  m["converged_frame"] = {convergedFrame(angles, r.real("convergence_tolerance_deg"), tail), ""};
  m["flow_angle_deg"] = {tailMean(flow.values), "deg"};
  // Signed means: the strength-limited step chatters about the optimum, and the steady state is
  // the mean pose of that chatter.
  m["load_line_angle_deg"] = {std::abs(tailMean(lean.values) - tailMean(force_lean.values)), "deg"};
  m["com_offset_m"] = {tailMean(offset.values), "m"};
  m["com_arm_m"] = {tailMean(arm_length.values), "m"};
  m["lean_deg"] = {tailMean(lean.values), "deg"};
  m["net_force_lean_deg"] = {tailMean(force_lean.values), "deg"};
  m["final_effort_n_m_s"] = {tailMean(effort[0]->values), "N m s"};
  m["gravity_effort_n_m_s"] = {mass * g * tailMean(arm_length.values) * p.frame_s, "N m s"};
  m["effort_ratio"] = {m["final_effort_n_m_s"].value / m["gravity_effort_n_m_s"].value, ""};
  m["mean_torque_ratio"] = {std::abs(tailMean(torque[0]->values)) / (mass * g * tailMean(arm_length.values)), ""};
  {
    std::vector<double> last(torque[0]->values.end() - tail, torque[0]->values.end());
    for (double& x : last) x = std::abs(x);
    std::sort(last.begin(), last.end());
    const double median = tail % 2 ? last[tail / 2] : 0.5 * (last[tail / 2 - 1] + last[tail / 2]);
    m["median_torque_ratio"] = {median / (mass * g * tailMean(arm_length.values)), ""};
  }
  m["final_drag_n"] = {tailMean(drag[0]->values), "N"};
  const auto& a0 = angle[0]->values;
  m["mean_speed_deg_per_s"] = {tail > 1 ? (a0.back() - a0[a0.size() - tail]) / ((tail - 1) * p.frame_s) : 0.0, "deg/s"};
  m["max_servo_residual_rad"] = {max_residual, "rad"};
  m["max_kinematic_error_rad"] = {max_kinematic, "rad"};
  m["max_pd_error_rad"] = {max_pd, "rad"};
  // The 3-D angle between the mean carried arm and the mean net force (a ball joint's Fig. 4).
  m["load_line_angle_3d_deg"] = {lineAngleDeg({tailMean(arm_x), tailMean(arm_y), tailMean(arm_z)},
                                              {tailMean(net_x), tailMean(net_y), tailMean(net_z)}), "deg"};
  m["triangles"] = {double(force.triangles()), ""};
  return result;
}

}  // namespace creaturelab::kinds
