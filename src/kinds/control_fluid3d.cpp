#include "kinds/control_fluid3d.hpp"

#include <cmath>
#include <numbers>

#include "control/coupled_fluid3.hpp"
#include "control/fluid_run3.hpp"

namespace creaturelab::kinds {
namespace {
constexpr double kDeg3 = 180.0 / std::numbers::pi;
}  // namespace

ControlFluid3dKind::ControlFluid3dKind() {
  metrics_ = {
      {"mean_up_force_n", "N", "§7.1: the fluid's upward force on all bodies, mean over the last force_cycles flap periods"},
      {"mean_up_force_n_stderr", "N", "standard error of mean_up_force_n from the scatter of its force_cycles flaps' "
                                      "means (NaN with one flap)"},
      {"max_servo_residual_rad", "rad", "largest servo miss before projection over the run"},
      {"forcing_iterations_most", "", "most CG iterations of the projected forcing in any coupled step"},
      {"markers", "", "surface and interior markers"},
  };
}

std::string ControlFluid3dKind::doc() const {
  return "creature controller in the two-way coupled 3-D fluid: the driven flyer (Lentine et al. 2010 §7.1)";
}

fluid3d::FluidParams3 ControlFluid3dParams::fluidParams() const {
  fluid3d::FluidParams3 f = fluid;
  f.cells_y = int(std::lround(double(f.cells_x) * f.domain_y_m / f.domain_x_m));
  f.cells_z = int(std::lround(double(f.cells_x) * f.domain_z_m / f.domain_x_m));
  // The coupled step is fixed; a fluid running away is caught as a blow-up.
  f.time_step_policy = fluid3d::TimeStepPolicy3::fixed;
  f.fixed_step_s = controller.frame_s / double(controller.substeps);
  return f;
}

control::FluidControlParams ControlFluid3dParams::fluidControlParams() const {
  control::FluidControlParams f;
  f.perturbation = perturbation == "placed" ? control::Perturbation::placed : control::Perturbation::moved;
  f.settle_steps = int(settle_steps);
  f.creature_force = objective_bodies == "creature";
  f.average_steps = int(average_steps);
  f.limit_rad = controlled_limit_deg / kDeg3;
  f.stroke = parseStrokeSense(stroke_sense, splitList(controller.controlled, ','));
  f.planar_fluid = false;
  return f;
}

std::vector<std::pair<std::string, double>> ControlFluid3dParams::initialRad() const {
  std::vector<std::pair<std::string, double>> a;
  for (const auto& pose : controller.initialPoses()) {
    if (pose.deg.size() != 1) throw std::invalid_argument("initial_deg: '" + pose.joint + "' needs one angle (hinges only)");
    a.push_back({pose.joint, pose.deg[0] / kDeg3});
  }
  return a;
}

std::string ControlFluid3dParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  try {
    const auto model = controller.loadModel();
    if (auto e = fluidControlParams().validate(controller.controllerParams(), model); !e.empty()) return e;
    if (auto e = controller.checkInitialPoses(model, true); !e.empty()) return e;
    const auto f = fluidParams();
    if (auto e = f.validate(); !e.empty()) return e;
    if (auto e = coupling.validate(f); !e.empty()) return e;
    rigid::RigidData data(model);
    for (const auto& [joint, rad] : initialRad()) data.qpos()[model.joint(model.findJoint(joint)).qpos] = rad;
    data.kinematics();
    coupling3d::RigidFluidCoupling3 probe(data, f, coupling);  // a body outside the box
    if (controller.average_frames > controller.frames) return "average_frames is larger than frames";
    if (framesPerCycle(flap_period_s, controller.frame_s) * force_cycles > controller.frames)
      return "force_cycles x flap_period_s is longer than frames";
  } catch (const rigid::RigidError& e) {
    return std::string("model_file: ") + e.what();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

CostEstimate ControlFluid3dKind::estimateCost(const Params& params) const {
  try {
    const ControlFluid3dParams q = readParams<ControlFluid3dParams>(params);
    const ControllerSettings& k = q.controller;
    const fluid3d::FluidParams3 f = q.fluidParams();
    CostEstimate c;
    const double joints = double(splitList(k.controlled, ',').size());
    const double per_frame = double(k.substeps) * (1 + 2 * joints) + 2 * joints * double(q.settle_steps);
    c.steps = double(k.frames) * per_frame + double(q.warmup_frames * k.substeps);
    const double cells = double(f.cells_x) * f.cells_y * f.cells_z;
    c.memory_bytes = 64.0 * (1 << 20) + (1 + 2 * joints) * cells * 8 * 24;
    c.detail = std::to_string(k.frames) + " frames x " + std::to_string(int(per_frame)) + " coupled steps";
    return c;
  } catch (const std::exception&) {
    return {};
  }
}

Result ControlFluid3dKind::run(const Params& params) const {
  const ControlFluid3dParams q = readParams<ControlFluid3dParams>(params);
  const ControllerSettings& k = q.controller;
  const rigid::RigidModel model = k.loadModel();
  const control::ControllerParams p = k.controllerParams();
  control::FluidController controller(model, p, q.fluidControlParams(), q.initialRad(),
                                      control::spatialFluid(q.fluidParams(), q.coupling));
  control::FluidRunRecorder3 recorder(model, p);
  const auto& fluid3 = dynamic_cast<const control::CoupledFluid3&>(controller.coupledFluid());
  Result result;
  try {
    controller.hold(int(q.warmup_frames * k.substeps));
    for (long f = 0; f < k.frames; ++f) recorder.record(controller.frame(), controller);
  } catch (const std::exception& e) {
    addSeries(result, recorder.series());
    throw RunFailure("control_fluid3d at t = " + std::to_string(controller.data().time_s()) + " s: " + e.what(), result);
  }
  addSeries(result, recorder.series());
  addMetrics(result, recorder.measure(framesPerCycle(q.flap_period_s, k.frame_s), int(q.force_cycles),
                                      int(fluid3.coupling().markers().size()), controller.maxForcingIterations()));
  return result;
}

}  // namespace creaturelab::kinds
