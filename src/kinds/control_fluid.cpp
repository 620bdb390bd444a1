#include "kinds/control_fluid.hpp"

#include <cmath>
#include <numbers>

#include "control/fluid_controller.hpp"
#include "control/fluid_run.hpp"
#include "kinds/control_params.hpp"
#include "kinds/control_fluid_swimmer.hpp"
#include "kinds/validate_fluid3.hpp"

namespace creaturelab::kinds {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

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
      {"final_derivative_per_rad", "1/rad",
       "first controlled joint: mean of the controller's central difference of its objective (the objective's unit "
       "per rad) over the last average_frames"},
      {"max_servo_residual_rad", "rad", "largest servo miss before projection over the run"},
      {"forcing_iterations_most", "", "most CG iterations of the projected forcing in any coupled step"},
      {"markers", "", "outline markers"},
      {"marker_cells_per_step_most", "", "largest marker displacement in one coupled step of the main run, cells"},
      {"mean_up_force_n", "N", "§7.1: the fluid's upward force on all bodies (per depth_m), mean over the last "
                               "force_cycles flap periods (flap_period_s > 0) or the last average_frames"},
      {"mean_up_force_n_stderr", "N", "standard error of mean_up_force_n from the scatter of its force_cycles flaps' "
                                      "means (NaN with one flap or flap_period_s = 0)"},
  };
  for (auto& spec : swimmerMetrics()) metrics_.push_back(std::move(spec));
}

std::string ControlFluidKind::doc() const {
  return "creature controller in the two-way coupled 2-D fluid (Lentine et al. 2010 §4, §6, §7)";
}

fluid::FluidParams ControlFluidParams::fluidParams() const {
  fluid::FluidParams f = fluid;
  f.makeSquare();
  // The coupled step is fixed; a fluid running away is caught as a blow-up.
  f.time_step_policy = fluid::TimeStepPolicy::fixed;
  f.fixed_step_s = controller.frame_s / double(controller.substeps);
  // An inflow wall enters at the stream's or the source's speed (coupling/inflow.hpp).
  if (f.walls.left.type == fluid::WallType::inflow) f.walls.left.inflow_m_per_s = coupling.inflow.stream_m_per_s;
  if (f.walls.bottom.type == fluid::WallType::inflow) f.walls.bottom.inflow_m_per_s = coupling.inflow.source_m_per_s;
  return f;
}

coupling::RigidFluidParams ControlFluidParams::rigidFluidParams() const {
  coupling::RigidFluidParams c = coupling;
  c.mouth = swimmer.mouthParams();
  return c;
}

control::FluidControlParams ControlFluidParams::fluidControlParams() const {
  control::FluidControlParams f;
  f.perturbation = perturbation == "placed" ? control::Perturbation::placed : control::Perturbation::moved;
  f.settle_steps = int(settle_steps);
  f.creature_force = objective_bodies == "creature";
  f.average_steps = int(average_steps);
  f.limit_rad = controlled_limit_deg / kDeg;
  f.stroke = parseStrokeSense(stroke_sense, splitList(controller.controlled, ','));
  f.armature_added_mass = swimmer.armature_added_mass;
  return f;
}

std::vector<std::pair<std::string, double>> ControlFluidParams::initialRad() const {
  std::vector<std::pair<std::string, double>> a;
  for (const auto& pose : controller.initialPoses()) {
    if (pose.deg.size() != 1) throw std::invalid_argument("initial_deg: '" + pose.joint + "' needs one angle (hinges only in the planar fluid)");
    a.push_back({pose.joint, pose.deg[0] / kDeg});
  }
  return a;
}

std::string ControlFluidParams::validate() const {
  const auto against = [&](const rigid::RigidModel& model) -> std::string {
    if (auto e = swimmer.validate(model, controller.frame_s, controller.frames); !e.empty()) return e;
    const auto f = fluidParams();
    const auto c = rigidFluidParams();
    if (auto e = c.validate(f); !e.empty()) return e;
    const auto rad = initialRad();
    for (const auto& pose : rad)
      if (model.findJoint(pose.first) < 0) return "initial_deg: joint '" + pose.first + "' is not in the model " + model.path();
    const rigid::RigidData data = posedData(model, rad);
    coupling::RigidFluidCoupling probe(data, f, c);  // a body outside the box, a geom without outline
    return "";
  };
  return validateControlInFluid(*this, noCheck, against, [&] { return checkFlapCycles(*this); });
}

CostEstimate ControlFluidKind::estimateCost(const Params& params) const {
  try {
    const ControlFluidParams q = readParams<ControlFluidParams>(params);
    const ControllerSettings& k = q.controller;
    CostEstimate c;
    const double joints = double(splitList(k.controlled, ',').size());
    const double per_frame = k.coupledStepsPerFrame(double(k.substeps + q.settle_steps));
    c.steps = double(k.frames) * per_frame + double(q.warmup_frames * k.substeps);
    const double cells = double(q.fluid.cells_x) * double(q.fluid.cells_x);
    const double fields = q.field_every_frames > 0 ? double(k.frames) / q.field_every_frames : 0;
    c.memory_bytes = 64.0 * (1 << 20) + (2 + 2 * joints) * cells * 8 * 8 + fields * cells * 8;
    c.detail = std::to_string(k.frames) + " frames x " + std::to_string(int(per_frame)) + " coupled steps";
    return c;
  } catch (const std::exception&) {
    return {};
  }
}

Result ControlFluidKind::run(const Params& params) const {
  const ControlFluidParams q = readParams<ControlFluidParams>(params);
  const ControllerSettings& k = q.controller;
  const rigid::RigidModel model = k.loadModel();
  const control::ControllerParams p = k.controllerParams();
  const coupling::RigidFluidParams cp = q.rigidFluidParams();
  control::FluidController controller(model, p, q.fluidControlParams(), q.initialRad(), q.fluidParams(), cp);
  control::FluidRunRecorder recorder(model, p, controller, cp.origin_x_m, cp.origin_z_m, q.field_every_frames);
  // The swimmer (§7.2): the joints' senses follow the mouth's phases; the rise.
  const control::SwimmerPhases phases = q.swimmer.swimmerPhases(int(p.controlled.size()));
  control::RiseRecorder rise(q.swimmer.riseSettings(model, k.frame_s));
  const double density_ratio = control::densityRatio(model, controller.coupling(), q.fluid.density_kg_per_m3);
  Result result;
  try {
    controller.hold(int(q.warmup_frames * k.substeps));
    rise.start(controller.data());
    recorder.start(controller);
    for (long f = 0; f < k.frames; ++f) {
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
  const int frames_per_cycle = q.flap_period_s > 0 ? framesPerCycle(q.flap_period_s, k.frame_s) : 0;
  addMetrics(result, recorder.measure(int(k.average_frames), k.convergence_tolerance_deg, frames_per_cycle,
                                      int(q.force_cycles), controller.maxForcingIterations()));
  addMetrics(result, rise.measure(density_ratio));
  return result;
}

}  // namespace creaturelab::kinds
