#include "kinds/control_fluid3d.hpp"

#include <cmath>

#include "control/coupled_flesh_fluid3.hpp"
#include "control/coupled_fluid3.hpp"
#include "control/fluid_run3.hpp"
#include "kinds/fluid3_box.hpp"
#include "kinds/validate_fluid3.hpp"

namespace creaturelab::kinds {
namespace {
// Every geom's pose per frame as /lagrangian tracks (its size too: /topology holds integers only) and
// its type and body as /topology; the stored fluid frames as /fields, placed in the world.
void addRecorded(Result& result, const control::FluidRunRecorder3& recorder, const std::array<double, 3>& origin_m) {
  const control::GeomPoses3& g = recorder.geoms();
  result.topology["geom_type"] = g.type;
  result.topology["geom_body"] = g.body;
  const auto track = [&](const std::string& name, std::vector<double> data, int dim, const std::string& unit) {
    Tracks& t = result.lagrangian[name];
    t.time_s = g.time_s, t.data = std::move(data), t.points = g.geoms(), t.dim = dim, t.unit = unit;
  };
  track("geom_position_m", g.position_m, 3, "m");
  track("geom_rotation", g.rotation, 9, "");
  std::vector<double> size;
  for (std::size_t f = 0; f < g.time_s.size(); ++f) size.insert(size.end(), g.size_m.begin(), g.size_m.end());
  track("geom_size_m", std::move(size), 3, "m");
  const control::FluidFrames3& fluid = recorder.fluid();
  if (fluid.time_s.empty()) return;
  FieldFrames& out = result.fields;
  out.time_s = fluid.time_s;
  out.dx_m = out.dy_m = fluid.dx_m;
  out.nx = fluid.n[0];
  out.origin_x_m = origin_m[0];
  if (fluid.plane_layer >= 0) {  // rows along z
    out.ny = fluid.n[2];
    out.origin_y_m = origin_m[2];
  } else {
    out.ny = fluid.n[1], out.nz = fluid.n[2];
    out.dz_m = fluid.dx_m;
    out.origin_y_m = origin_m[1], out.origin_z_m = origin_m[2];
  }
  for (const auto& f : fluid.fields) out.fields[f.name] = {f.values, f.unit};
}
// The flesh's skin for its .glb (Fig. 13): each vertex's world position per frame as
// /lagrangian/flesh_position_m, the triangles (three vertex indices each) and each vertex's body as /topology.
void addFlesh(Result& result, const control::CoupledFleshFluid3* flesh, std::vector<double> time_s,
              std::vector<double> position_m) {
  if (!flesh) return;
  const flesh::FleshMesh& mesh = flesh->coupling().flesh().mesh();
  std::vector<std::int64_t>& tri = result.topology["flesh_triangles"];
  for (const auto& t : mesh.triangles) tri.insert(tri.end(), t.begin(), t.end());
  result.topology["flesh_vertex_body"].assign(mesh.body.begin(), mesh.body.end());
  Tracks& x = result.lagrangian["flesh_position_m"];
  x.time_s = std::move(time_s), x.data = std::move(position_m), x.points = mesh.vertices(), x.dim = 3, x.unit = "m";
}
}  // namespace

ControlFluid3dKind::ControlFluid3dKind() {
  metrics_ = {
      {"mean_up_force_n", "N", "§7.1: the fluid's upward force on all bodies, mean over the last force_cycles flap periods"},
      {"mean_up_force_n_stderr", "N", "standard error of mean_up_force_n from the scatter of its force_cycles flaps' "
                                      "means (NaN with one flap)"},
      {"mean_derivative_per_rad", "1/rad", "first controlled joint: the controller's central difference of its "
                                          "objective (the objective's unit per rad), mean over the same flap periods"},
      {"mean_objective_maximising", "", "first controlled joint: its objective (N for a drag) in the frames it is "
                                        "maximised, each of the last force_cycles flaps' mean averaged"},
      {"mean_objective_maximising_stderr", "", "standard error of mean_objective_maximising from its flaps' means"},
      {"mean_objective_minimising", "", "the same over the frames it is minimised"},
      {"mean_objective_minimising_stderr", "", "standard error of mean_objective_minimising from its flaps' means"},
      {"max_servo_residual_rad", "rad", "largest servo miss before projection over the run"},
      {"forcing_iterations_most", "", "most CG iterations of the projected forcing in any coupled step"},
      {"markers", "", "surface and interior markers"},
  };
}

std::string ControlFluid3dKind::doc() const {
  return "creature controller in the two-way coupled 3-D fluid: the driven flyer (Lentine et al. 2010 §7.1)";
}

fluid3d::FluidParams3 ControlFluid3dParams::fluidParams() const {
  return coupledFluidBox3(fluid, controller.frame_s, controller.substeps);
}

control::FluidControlParams ControlFluid3dParams::fluidControlParams() const {
  control::FluidControlParams f = fluidControlParams3(*this);
  f.creature_force = objective_bodies == "creature";
  f.stroke = parseStrokeSense(stroke_sense, splitList(controller.controlled, ','));
  return f;
}

control::FluidRecording3 ControlFluid3dParams::recording() const {
  control::FluidRecording3 r;
  r.stored = stored_fields == "volume"  ? control::StoredFields3::volume
             : stored_fields == "plane" ? control::StoredFields3::plane
                                        : control::StoredFields3::none;
  r.field_every = int(field_every);
  return r;
}

std::vector<std::pair<std::string, double>> ControlFluid3dParams::initialRad() const {
  return initialHingeRad3(controller);
}

std::string ControlFluid3dParams::validate() const {
  // With flesh, its vertices.
  const auto probe = [&](const rigid::RigidData& data, const fluid3d::FluidParams3& box,
                         const coupling3d::RigidFluidParams3& c) {
    return buildMarkers3(data, box, c, flesh ? &flesh_params : nullptr);
  };
  const auto against = [&](const rigid::RigidModel& model) {
    return checkInBox3(*this, model, [&] { return coupling; }, probe);
  };
  return validateControlInFluid(*this, noCheck, against, [&] { return checkFlapCycles(*this); });
}

control::CoupledFluidFactory ControlFluid3dParams::coupledFluid() const {
  if (!flesh) return control::spatialFluid(fluidParams(), coupling);
  return control::fleshFluid(fluidParams(), coupling, flesh_params);
}

CostEstimate ControlFluid3dKind::estimateCost(const Params& params) const {
  try {
    const ControlFluid3dParams q = readParams<ControlFluid3dParams>(params);
    const ControllerSettings& k = q.controller;
    const fluid3d::FluidParams3 f = q.fluidParams();
    CostEstimate c;
    const double joints = double(splitList(k.controlled, ',').size());
    const double per_frame = k.coupledStepsPerFrame(double(k.substeps + q.settle_steps));
    c.steps = double(k.frames) * per_frame + double(q.warmup_frames * k.substeps);
    const double cells = double(f.cells_x) * f.cells_y * f.cells_z;
    // Stored fields: 6 x 8 B per cell (volume) or per cell of the y plane, every field_every frames.
    const double stored = q.stored_fields == "volume" ? cells : q.stored_fields == "plane" ? cells / f.cells_y : 0;
    const double stored_frames = std::ceil(double(k.frames) / double(q.field_every));
    c.memory_bytes = 64.0 * (1 << 20) + (1 + 2 * joints) * cells * 8 * 24 + stored * 48 * stored_frames;
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
                                      q.coupledFluid());
  control::FluidRunRecorder3 recorder(model, p, q.recording());
  const auto* rigid3 = dynamic_cast<const control::CoupledFluid3*>(&controller.coupledFluid());
  const auto* flesh3 = dynamic_cast<const control::CoupledFleshFluid3*>(&controller.coupledFluid());
  const int markers = rigid3 ? int(rigid3->coupling().markers().size()) : flesh3->coupling().markers();
  std::vector<double> flesh_time_s, flesh_m;  // with flesh: its vertices per frame
  Result result;
  try {
    controller.hold(int(q.warmup_frames * k.substeps));
    for (long f = 0; f < k.frames; ++f) {
      recorder.record(controller.frame(), controller);
      if (!flesh3) continue;
      const Eigen::Matrix3Xd& x = flesh3->coupling().flesh().positions_m();
      flesh_time_s.push_back(controller.data().time_s());
      flesh_m.insert(flesh_m.end(), x.data(), x.data() + x.size());
    }
  } catch (const std::exception& e) {
    addSeries(result, recorder.series());
    addRecorded(result, recorder, q.coupling.origin_m);
    addFlesh(result, flesh3, std::move(flesh_time_s), std::move(flesh_m));
    throw RunFailure("control_fluid3d at t = " + std::to_string(controller.data().time_s()) + " s: " + e.what(), result);
  }
  addSeries(result, recorder.series());
  addRecorded(result, recorder, q.coupling.origin_m);
  addFlesh(result, flesh3, std::move(flesh_time_s), std::move(flesh_m));
  addMetrics(result, recorder.measure(framesPerCycle(q.flap_period_s, k.frame_s), int(q.force_cycles),
                                      markers, controller.maxForcingIterations()));
  return result;
}

}  // namespace creaturelab::kinds
