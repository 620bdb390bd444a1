#include "kinds/control_fluid3d_swimmer.hpp"


#include "control/coupled_flesh_fluid3.hpp"
#include "coupling3d/flesh_fluid_coupling3.hpp"
#include "kinds/control_fluid_swimmer.hpp"
#include "kinds/fluid3_box.hpp"
#include "kinds/validate_fluid3.hpp"

namespace creaturelab::kinds {
namespace {
// The 2-D swimmer's settings without a mouth: they parse and check the phases and the rise's body and
// cycles the same way (the same keys in their messages).
SwimmerSettings phaseSettings(const ControlFluid3dSwimmerParams& q) {
  SwimmerSettings s;
  s.cycle_s = q.cycle_s;
  s.phase_fractions = q.phase_fractions;
  s.phase_senses = q.phase_senses;
  s.phase_strength_rad_per_s = q.phase_strength_rad_per_s;
  s.rise_body = q.rise_body;
  s.rise_cycles = q.rise_cycles;
  s.mouth_body = q.mouth_body;
  s.phase_flux_m_per_s = q.phase_flux_m_per_s;
  s.mouth_width_m = 2 * q.mouth_radius_m;
  return s;
}
}  // namespace

ControlFluid3dSwimmerKind::ControlFluid3dSwimmerKind() {
  metrics_ = {
      {"rise_per_cycle_m", "m", "§7.2: rise of rise_body's subtree centre of mass per cycle, mean over the last rise_cycles"},
      {"rise_per_cycle_m_stderr", "m", "standard error of rise_per_cycle_m from the scatter of its cycles' rises "
                                       "(NaN with one cycle)"},
      {"rise_total_m", "m", "rise of that centre of mass over the run"},
      {"drift_m", "m", "horizontal distance of that centre of mass from its start at the end"},
      {"creature_density_ratio", "", "creature mass over the fluid mass its geoms displace"},
      {"max_servo_residual_rad", "rad", "largest servo miss before projection over the run"},
      {"forcing_iterations_most", "", "most CG iterations of the forcing in any coupled step"},
      {"markers", "", "surface and interior markers"},
  };
}

std::string ControlFluid3dSwimmerKind::doc() const {
  return "creature controller in the two-way coupled 3-D fluid: the aqueous swimmer (Lentine et al. 2010 §7.2)";
}

fluid3d::FluidParams3 ControlFluid3dSwimmerParams::fluidParams() const {
  return coupledFluidBox3(fluid, controller.frame_s, controller.substeps);
}

control::FluidControlParams ControlFluid3dSwimmerParams::fluidControlParams() const {
  control::FluidControlParams f = fluidControlParams3(*this);
  f.armature_added_mass = armature_added_mass;
  return f;
}

control::SwimmerPhases ControlFluid3dSwimmerParams::swimmerPhases(int joints) const {
  return phaseSettings(*this).swimmerPhases(joints);
}

control::RiseSettings3 ControlFluid3dSwimmerParams::riseSettings(const rigid::RigidModel& model) const {
  const control::RiseSettings r = phaseSettings(*this).riseSettings(model, controller.frame_s);
  return {r.body, r.mouth.schedule, mouth_body.empty() ? std::vector<double>{} : r.mouth.flux_m_per_s,
          r.frames_per_cycle, r.cycles};
}

coupling3d::RigidFluidParams3 ControlFluid3dSwimmerParams::rigidFluidParams(const rigid::RigidModel& model) const {
  coupling3d::RigidFluidParams3 c = coupling;
  if (mouth_body.empty()) return c;
  int body = -1;
  for (int b = 1; b < model.bodies(); ++b)
    if (model.bodyName(b) == mouth_body) body = b;
  if (body < 0) throw std::invalid_argument("mouth_body: the model " + model.path() + " has no body '" + mouth_body + "'");
  coupling3d::Mouth3 m;
  for (int g = 0; g < model.geoms() && m.geom < 0; ++g)
    if (model.geomBody(g) == body) m.geom = g;
  if (m.geom < 0) throw std::invalid_argument("mouth_body: body '" + mouth_body + "' has no geom");
  m.centre_geom_m = {0.0, 0.0, mouth_centre_z_m};
  m.normal_geom = {0.0, 0.0, -1.0};
  m.radius_m = mouth_radius_m;
  c.mouths.push_back(m);
  return c;
}

std::vector<std::pair<std::string, double>> ControlFluid3dSwimmerParams::initialRad() const {
  return initialHingeRad3(controller);
}

std::string ControlFluid3dSwimmerParams::validate() const {
  const auto keys = [&]() -> std::string {
    if (rise_body.empty()) return "rise_body: give the body whose rise is measured";
    if (armature_added_mass && coupling.forcing == coupling3d::Forcing3::coupled)
      return "armature_added_mass: only with forcing = projected (forcing = coupled solves the fluid's added mass "
             "itself; the armature would count it twice)";
    return "";
  };
  const auto against = [&](const rigid::RigidModel& model) -> std::string {
    if (auto e = phaseSettings(*this).validate(model, controller.frame_s, controller.frames); !e.empty()) return e;
    // The markers (with flesh its vertices) and the mouth built in the box: a body, the flesh or the mouth
    // outside it throws.
    const auto probe = [&](const rigid::RigidData& data, const fluid3d::FluidParams3& box,
                           const coupling3d::RigidFluidParams3& c) {
      return buildMarkers3(data, box, c, flesh ? &flesh_params : nullptr);
    };
    return checkInBox3(*this, model, [&] { return rigidFluidParams(model); }, probe);
  };
  return validateControlInFluid(*this, keys, against, noCheck);
}

control::CoupledFluidFactory ControlFluid3dSwimmerParams::coupledFluid(const rigid::RigidModel& model,
                                                                      const control::RiseSettings3& rs) const {
  if (!flesh) return control::swimmerFluid(fluidParams(), rigidFluidParams(model), rs.schedule, rs.flux_m_per_s);
  return control::fleshFluid(fluidParams(), rigidFluidParams(model), flesh_params, {rs.schedule, rs.flux_m_per_s});
}

CostEstimate ControlFluid3dSwimmerKind::estimateCost(const Params& params) const {
  try {
    const ControlFluid3dSwimmerParams q = readParams<ControlFluid3dSwimmerParams>(params);
    const ControllerSettings& k = q.controller;
    const fluid3d::FluidParams3 f = q.fluidParams();
    CostEstimate c;
    const double joints = double(splitList(k.controlled, ',').size());
    const double per_frame = k.coupledStepsPerFrame(double(k.substeps + q.settle_steps));
    c.steps = double(k.frames) * per_frame + double(q.warmup_frames * k.substeps);
    const double cells = double(f.cells_x) * f.cells_y * f.cells_z;
    c.memory_bytes = 64.0 * (1 << 20) + (1 + 2 * joints) * cells * 8 * 24;
    c.detail = std::to_string(k.frames) + " frames x " + std::to_string(int(per_frame)) + " coupled steps";
    return c;
  } catch (const std::exception&) {
    return {};
  }
}

Result ControlFluid3dSwimmerKind::run(const Params& params) const {
  const ControlFluid3dSwimmerParams q = readParams<ControlFluid3dSwimmerParams>(params);
  const ControllerSettings& k = q.controller;
  const rigid::RigidModel model = k.loadModel();
  const control::ControllerParams p = k.controllerParams();
  // §7.2: the mouth's flux follows the phases.
  const control::RiseSettings3 rs = q.riseSettings(model);
  control::FluidController controller(model, p, q.fluidControlParams(), q.initialRad(), q.coupledFluid(model, rs));
  control::FluidRunRecorder3 recorder(model, p);
  // §7.2: the legs' senses and strengths follow the phases; the rise.
  const control::SwimmerPhases phases = q.swimmerPhases(int(p.controlled.size()));
  control::RiseRecorder3 rise(rs);
  const double density_ratio = control::densityRatio3(model, q.fluid.density_kg_per_m3);
  const auto* rigid3 = dynamic_cast<const control::SwimmerFluid3*>(&controller.coupledFluid());
  const auto* flesh3 = dynamic_cast<const control::CoupledFleshFluid3*>(&controller.coupledFluid());
  const int markers = rigid3 ? int(rigid3->coupling().markers().size()) : flesh3->coupling().markers();
  Result result;
  try {
    controller.hold(int(q.warmup_frames * k.substeps));
    rise.start(controller.data());
    for (long f = 0; f < k.frames; ++f) {
      phases.apply(controller);
      const control::FrameRecord fr = controller.frame();
      rise.record(controller.data());
      recorder.record(fr, controller);
    }
  } catch (const std::exception& e) {
    addSeries(result, recorder.series());
    addSeries(result, rise.series());
    throw RunFailure("control_fluid3d_swimmer at t = " + std::to_string(controller.data().time_s()) + " s: " + e.what() +
                         control::stabilityHint3(density_ratio, q.coupling.forcing == coupling3d::Forcing3::projected),
                     result);
  }
  addSeries(result, recorder.series());
  addSeries(result, rise.series());
  addMetrics(result, rise.measure(density_ratio));
  // The recorder's servo residual, forcing iterations and markers (its other readings are the flyer's, over
  // flap periods).
  for (const auto& v : recorder.measure(1, 1, markers, controller.maxForcingIterations()))
    if (v.name == "max_servo_residual_rad" || v.name == "forcing_iterations_most" || v.name == "markers")
      addMetrics(result, {v});
  return result;
}

}  // namespace creaturelab::kinds
