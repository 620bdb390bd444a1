#include "kinds/control_fluid.hpp"

#include <cmath>
#include <numbers>

#include "control/fluid_controller.hpp"
#include "control/fluid_run.hpp"
#include "kinds/control_params.hpp"
#include "kinds/ib_params.hpp"
#include "kinds/control_fluid_swimmer.hpp"

namespace creaturelab::kinds {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

fluid::WallType wall(const ParamReader& r, const std::string& name) { return *fluid::parseWallType(r.text(name)); }

fluid::FluidParams fluidParams(const ParamReader& r) {
  fluid::FluidParams f = squareFluidParams(r, r.real("frame_s") / double(r.integer("substeps")));
  f.walls.left.type = wall(r, "wall_left");
  f.walls.right.type = wall(r, "wall_right");
  f.walls.bottom.type = wall(r, "wall_bottom");
  f.walls.top.type = wall(r, "wall_top");
  // An inflow wall enters at the stream's or the source's speed (coupling/inflow.hpp).
  if (f.walls.left.type == fluid::WallType::inflow) f.walls.left.inflow_m_per_s = r.real("stream_m_per_s");
  if (f.walls.bottom.type == fluid::WallType::inflow) f.walls.bottom.inflow_m_per_s = r.real("source_m_per_s");
  return f;
}

coupling::RigidFluidParams rigidFluidParams(const ParamReader& r) {
  coupling::RigidFluidParams c;
  c.forcing = r.text("forcing") == "sweeps" ? coupling::Forcing::sweeps : coupling::Forcing::projected;
  c.kernel = *ib::parseKernel(r.text("kernel"));
  c.marker_spacing_cells = r.real("marker_spacing_cells");
  c.forcing_tolerance = r.real("forcing_tolerance");
  c.max_forcing_iterations = int(r.integer("max_forcing_iterations"));
  c.forcing_preconditioner = r.text("forcing_preconditioner") == "gram" ? coupling::ForcingPreconditioner::gram
                                                                         : coupling::ForcingPreconditioner::mass;
  c.depth_m = r.real("depth_m");
  c.origin_x_m = r.real("origin_x_m");
  c.origin_z_m = r.real("origin_z_m");
  c.max_marker_cells_per_step = r.real("max_marker_cells_per_step");
  c.inflow.stream_m_per_s = r.real("stream_m_per_s");
  c.inflow.stream_columns = int(r.integer("stream_columns"));
  c.inflow.source_m_per_s = r.real("source_m_per_s");
  c.inflow.source_rows = int(r.integer("source_rows"));
  c.mouth = mouthParams(r);
  return c;
}

control::FluidControlParams fluidControlParams(const ParamReader& r) {
  control::FluidControlParams f;
  f.perturbation = r.text("perturbation") == "placed" ? control::Perturbation::placed : control::Perturbation::moved;
  f.settle_steps = int(r.integer("settle_steps"));
  f.creature_force = r.text("objective_bodies") == "creature";
  f.average_steps = int(r.integer("average_steps"));
  f.limit_rad = r.real("controlled_limit_deg") / kDeg;
  f.stroke = parseStrokeSense(r.text("stroke_sense"), splitList(r.text("controlled"), ','));
  f.armature_added_mass = r.boolean("armature_added_mass");
  return f;
}

std::vector<std::pair<std::string, double>> initialRad(const ParamReader& r) {
  std::vector<std::pair<std::string, double>> a;
  for (const auto& pose : initialPoses(r)) {
    if (pose.deg.size() != 1) throw std::invalid_argument("initial_deg: '" + pose.joint + "' needs one angle (hinges only in the planar fluid)");
    a.push_back({pose.joint, pose.deg[0] / kDeg});
  }
  return a;
}

// The recorded series (the controller's and the swimmer's rise), the outline markers with their
// bodies, and the vorticity frames.
void addFluidRun(Result& result, const control::FluidRunRecorder& recorder, const control::RiseRecorder& rise) {
  addSeries(result, recorder.series());
  addSeries(result, rise.series());
  const control::MarkerFrames& m = recorder.markers();
  result.topology["marker_body"] = m.body;
  Tracks& outline = result.lagrangian["markers_m"];
  outline.time_s = m.time_s;
  outline.data = m.data;
  outline.points = m.points;
  outline.dim = 2;
  const control::VorticityFrames& w = recorder.vorticity();
  FieldFrames& fields = result.fields;
  fields.nx = w.nx;
  fields.ny = w.ny;
  fields.dx_m = fields.dy_m = w.dx_m;
  fields.origin_x_m = w.origin_x_m;
  fields.origin_y_m = w.origin_z_m;
  fields.time_s = w.time_s;
  if (!w.time_s.empty()) fields.fields["vorticity_per_s"] = {w.data, "1/s"};
}

}  // namespace

ControlFluidKind::ControlFluidKind() {
  params_ = {
      text("model_file", "experiments/control/models/block.xml", "",
           "MJCF creature (path from the working folder), planar in the x-z plane"),
      text("controlled", "hinge", "", "controlled hinge joints, comma-separated (one DOF each)"),
      text("kinematic", "", "",
           "hinges that follow kinematic_pattern exactly whatever the load (the fluid's too), comma-separated"),
      text("objectives", "drag_along", "",
           "per controlled joint: drag (|F|, N) | drag_along (Eq. 10: F . w, N), F the fluid's force on the bodies "
           "it moves | effort (Eq. 1: |torque| x frame_s, N m s)"),
      text("senses", "min", "", "per controlled joint: min | max"),
      text("weights", "", "", "rows 'w11,w12,..; w21,..': joint i descends sum_j w_ij F_j (§5)"),
      text("initial_deg", "", "", "initial angles 'joint=degrees, ...' (default: the model's reference)"),
      real("drag_direction_x", 1, "", -1e9, 1e9, "w of Eq. 10 (normalised)"),
      real("drag_direction_y", 0, "", -1e9, 1e9, "w of Eq. 10"),
      real("drag_direction_z", 0, "", -1e9, 1e9, "w of Eq. 10"),
      real("gravity_m_per_s2", 0, "m/s^2", 0, 1e3, "gravity along -z on the bodies (the fluid has none)"),
      real("frame_s", 1.0 / 60, "s", 1e-5, 1, "one controller step (a frame; Fig. 2 counts frames)"),
      integer("substeps", 1, 1, 1000, "coupled fluid-solid steps per frame (the servo reaches its targets at each)"),
      integer("frames", 240, 1, 10000000, "controlled frames to run"),
      integer("warmup_frames", 60, 0, 10000000, "frames with the pose held before control, for the flow to develop"),
      real("strength_rad_per_s", 1.0, "rad/s", 0, 1e4, "largest joint angle change per second (§2.1)"),
      real("delta_rad", 0.02, "rad", 1e-9, 1,
           "central-difference perturbation (§2.1, §4.3: 'non-negligible changes in the configuration' against the "
           "fluid's noise)"),
      boolean("one_sided", false, "forward differences (§2.1)"),
      integer("search_every_frames", 1, 1, 100000, "re-determine the direction every k frames (§2.1)"),
      boolean("rigidify_outboard", true, "§5: hold the bodies outboard of a perturbed joint rigid with it"),
      integer("threads", 1, 1, 16, "threads for the per-DOF evaluations (§5, Fig. 10); results do not depend on it"),
      choice("perturbation", "moved", {"moved", "placed"},
             "how a derivative evaluation reaches its pose: moved over one frame of coupled steps (§4.3) | placed at "
             "once, joint velocities zero (§3.3's steady state)"),
      choice("objective_bodies", "moved", {"moved", "creature"},
             "the bodies whose fluid force a joint's drag objective takes: moved (those the joint moves) | creature "
             "(every body but the world; §7.1: 'maximize drag (F_d) on the body')"),
      integer("settle_steps", 0, 0, 100000,
              "§4.3 validation mode: coupled steps with the perturbed pose held before the force is taken (0: off)"),
      integer("average_steps", 1, 1, 100000, "the objective: mean force over an evaluation's last this many steps"),
      real("convergence_tolerance_deg", 1.0, "deg", 1e-6, 90,
           "converged frame: from it every controlled angle stays this close to its final mean"),
      integer("average_frames", 30, 1, 100000, "frames at the end over which final values are averaged"),
      // The fluid (src/fluid): a square box; the paper gives no sizes.
      real("domain_m", 4.0, "m", 1e-3, 100, "side of the square fluid box (the paper gives none: 4 block lengths)"),
      integer("cells", 128, 8, 2048, "cells per side (issue 16's speed goal: 128^2)"),
      real("density_kg_per_m3", 1000.0, "kg/m^3", 1e-3, 1e6, "fluid density (§7: 'similar to water')"),
      real("kinematic_viscosity_m2_per_s", 0.0, "m^2/s", 0, 10,
           "0: the paper's inviscid Eq. 5 (the advection's numerical viscosity remains)"),
      choice("advection", "semi_lagrangian", {"semi_lagrangian", "maccormack", "upwind2_rk2"},
             "velocity advection scheme (upwind2_rk2: explicit, its CFL bound checked each step)"),
      viscositySchemeSpec(),
      integer("fluid_threads", 1, 1, 16,
              "threads inside the frame's fluid steps, and the evaluations' when threads = 1 (bitwise the same "
              "for any count)"),
      choice("wall_left", "open", {"free_slip", "no_slip", "open", "inflow"},
             "left wall (open: the stream's band enters there; inflow: the stream enters through it)"),
      choice("wall_right", "open", {"free_slip", "no_slip", "open"}, "right wall (open: the stream leaves)"),
      choice("wall_bottom", "free_slip", {"free_slip", "no_slip", "open", "inflow"},
             "floor (inflow: the source enters through it at source_m_per_s, a flux the projection keeps)"),
      choice("wall_top", "free_slip", {"free_slip", "no_slip", "open"}, "top"),
      real("blowup_speed_m_per_s", 50.0, "m/s", 1e-6, 1e6, "a fluid faster than this stops the run (exit 3)"),
      real("stream_m_per_s", 1.0, "m/s", -1e3, 1e3, "rightward stream held in the inflow band (Fig. 8); 0: none"),
      integer("stream_columns", 3, 0, 1000, "width of the held inflow band, cells (0: none, with wall_left = inflow)"),
      real("source_m_per_s", 0.0, "m/s", -1e3, 1e3, "upward floor source (§7.1); 0: none"),
      integer("source_rows", 0, 0, 1000, "height of the held source band, cells (0: none, with wall_bottom = inflow)"),
      // The coupling (src/coupling).
      choice("forcing", "projected", {"projected", "sweeps"},
             "projected: forces solved so that the projected flow meets the bodies; sweeps: direct forcing before "
             "the projection, which leaks"),
      choice("kernel", "peskin4", {"bilinear", "peskin4"}, "IB kernel of the markers (Peskin 2002 §6)"),
      real("marker_spacing_cells", 0.5, "cells", 1e-3, 1e3, "outline marker spacing; at most 1 cell (leak)"),
      real("forcing_tolerance", 1e-3, "", 1e-12, 1, "projected forcing: CG tolerance, fraction of the largest speed"),
      integer("max_forcing_iterations", 50, 1, 10000, "projected forcing: CG iterations at most per step"),
      choice("forcing_preconditioner", "mass", {"mass", "gram"},
             "projected forcing: CG preconditioner (mass: each marker's direct-forcing mass; gram: the forcing "
             "without the projection, its stencils' Gram matrix factored each step)"),
      real("depth_m", 1.0, "m", 1e-6, 1e3, "bodies' extent along y (the fluid is per metre of depth)"),
      real("origin_x_m", -1.2, "m", -1e4, 1e4, "world x of the fluid box's left wall"),
      real("origin_z_m", -2.0, "m", -1e4, 1e4, "world z of the fluid box's floor"),
      real("max_marker_cells_per_step", 1.0, "cells", 1e-6, 2,
           "coupled stability limit: a marker moving farther in one step stops the point (exit 3)"),
      integer("field_every_frames", 0, 0, 1000000, "vorticity field and markers every k frames (0: never)"),
      // The driven flyer (§7.1, flyer.toml).
      text("stroke_sense", "", "",
           "§7.1: 'controlled = [+|-]inboard, ...': the joint has its given sense while the inboard joint's pattern "
           "angle rises (+) or falls (-)"),
      real("flap_period_s", 0, "s", 0, 1e4,
           "period of the flap, a whole number of frames; 0: mean_up_force_n over the last average_frames"),
      integer("force_cycles", 2, 1, 100000, "mean_up_force_n: whole flap cycles at the end averaged"),
      real("controlled_limit_deg", 0, "deg", 0, 360, "controlled angles kept within +-this (0: no limit; the paper gives none)"),
  };
  addMotionPatternSpecs(params_);
  metrics_ = {
      {"final_angle_deg", "deg", "first controlled joint: mean angle over the last average_frames"},
      {"flow_angle_deg", "deg",
       "line of the first controlled joint's bodies (anchor to centre of mass) against the stream, in [0, 90]: the "
       "axial mean line over the last average_frames (a mean of folded angles is biased where the block wanders "
       "across the perpendicular or the stream)"},
      {"converged_frame", "", "first frame from which every controlled angle stays within the tolerance of its final "
                              "mean (Fig. 2); frames + 1 if never"},
      {"final_drag_n", "N", "first controlled joint: mean |F| of the fluid on its bodies over the last average_frames"},
      {"final_drag_along_n", "N", "the same along w (Eq. 10)"},
      {"final_effort_n_m_s", "N m s", "first controlled joint: mean effort (Eq. 1, |torque| x frame_s) over the last "
                                      "average_frames"},
      {"max_servo_residual_rad", "rad", "largest servo miss before projection over the run"},
      {"forcing_iterations_most", "", "most CG iterations of the projected forcing in any coupled step"},
      {"markers", "", "outline markers"},
      {"marker_cells_per_step_most", "", "largest marker displacement in one coupled step of the main run, cells"},
      {"mean_up_force_n", "N", "§7.1: the fluid's upward force on all bodies (per depth_m), mean over the last "
                               "force_cycles flap periods (flap_period_s > 0) or the last average_frames"},
      {"mean_up_force_n_stderr", "N", "standard error of mean_up_force_n from the scatter of its force_cycles flaps' "
                                      "means (NaN with one flap or flap_period_s = 0)"},
  };
  for (auto& spec : swimmerParams()) params_.push_back(std::move(spec));
  for (auto& spec : swimmerMetrics()) metrics_.push_back(std::move(spec));
}

std::string ControlFluidKind::doc() const {
  return "creature controller in the two-way coupled 2-D fluid (Lentine et al. 2010 §4, §6, §7)";
}

std::string ControlFluidKind::validate(const Params& params) const {
  ParamReader r(params);
  try {
    const auto model = loadModel(r);
    const auto p = controllerParams(r);
    if (auto e = control::validate(p, fluidControlParams(r), model); !e.empty()) return e;
    if (auto e = validateSwimmer(r, model); !e.empty()) return e;
    const auto f = fluidParams(r);
    const auto c = rigidFluidParams(r);
    if (auto e = coupling::validate(c, f); !e.empty()) return e;
    rigid::RigidData data(model);
    for (const auto& [joint, rad] : initialRad(r)) {
      if (model.findJoint(joint) < 0) return "initial_deg: joint '" + joint + "' is not in the model " + model.path();
      data.qpos()[model.joint(model.findJoint(joint)).qpos] = rad;
    }
    data.kinematics();
    coupling::RigidFluidCoupling probe(data, f, c);  // a body outside the box, a geom without outline
    if (r.integer("average_frames") > r.integer("frames")) return "average_frames is larger than frames";
    if (r.real("flap_period_s") > 0 &&
        framesPerCycle(r.real("flap_period_s"), r.real("frame_s")) * r.integer("force_cycles") > r.integer("frames"))
      return "force_cycles x flap_period_s is longer than frames";
  } catch (const rigid::RigidError& e) {
    return std::string("model_file: ") + e.what();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

CostEstimate ControlFluidKind::estimateCost(const Params& params) const {
  try {
    ParamReader r(params);
    CostEstimate c;
    const double joints = double(splitList(r.text("controlled"), ',').size());
    const double per_frame = double(r.integer("substeps")) * (1 + 2 * joints) +
                             2 * joints * double(r.integer("settle_steps"));
    c.steps = double(r.integer("frames")) * per_frame + double(r.integer("warmup_frames") * r.integer("substeps"));
    const double cells = double(r.integer("cells")) * double(r.integer("cells"));
    const double fields = r.integer("field_every_frames") > 0 ? double(r.integer("frames")) / r.integer("field_every_frames") : 0;
    c.memory_bytes = 64.0 * (1 << 20) + (2 + 2 * joints) * cells * 8 * 8 + fields * cells * 8;
    c.detail = std::to_string(r.integer("frames")) + " frames x " + std::to_string(int(per_frame)) + " coupled steps";
    return c;
  } catch (const std::exception&) {
    return {};
  }
}

Result ControlFluidKind::run(const Params& params) const {
  ParamReader r(params);
  const rigid::RigidModel model = loadModel(r);
  const control::ControllerParams p = controllerParams(r);
  const coupling::RigidFluidParams cp = rigidFluidParams(r);
  control::FluidController controller(model, p, fluidControlParams(r), initialRad(r), fluidParams(r), cp);
  control::FluidRunRecorder recorder(model, p, controller, cp.origin_x_m, cp.origin_z_m, r.integer("field_every_frames"));
  // The swimmer (§7.2): the joints' senses follow the mouth's phases; the rise.
  const control::SwimmerPhases phases = swimmerPhases(r, int(p.controlled.size()));
  control::RiseRecorder rise(riseSettings(r, model));
  const double density_ratio = control::densityRatio(model, controller.coupling(), r.real("density_kg_per_m3"));
  Result result;
  try {
    controller.hold(int(r.integer("warmup_frames") * r.integer("substeps")));
    rise.start(controller.data());
    recorder.start(controller);
    for (long f = 0; f < r.integer("frames"); ++f) {
      phases.apply(controller);
      const control::FrameRecord fr = controller.frame();
      rise.record(controller.data());
      recorder.record(fr, controller);
    }
  } catch (const std::exception& e) {
    addFluidRun(result, recorder, rise);
    throw RunFailure("control_fluid at t = " + std::to_string(controller.data().time_s()) + " s: " + e.what() +
                         (rise.active() ? control::stabilityHint(density_ratio) : std::string()),
                     result);
  }
  addFluidRun(result, recorder, rise);
  const double period_s = r.real("flap_period_s");
  addMetrics(result, recorder.measure(int(r.integer("average_frames")), r.real("convergence_tolerance_deg"),
                                      period_s > 0 ? framesPerCycle(period_s, r.real("frame_s")) : 0,
                                      int(r.integer("force_cycles")), controller.maxForcingIterations()));
  addMetrics(result, rise.measure(density_ratio));
  return result;
}

}  // namespace creaturelab::kinds
