#include "kinds/jellyfish.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "fluid/diagnostics2.hpp"

namespace creaturelab::kinds {
namespace {

// bell_segments = 0 follows the grid: the fewest even segments whose drawn length is at most
// marker_spacing_cells cells (markers about half a cell apart, so that the boundary does not leak as the grid
// is refined; Peskin 2002).
int bellSegments(const JellyfishKindParams& q) {
  if (q.swimmer.bell.segments > 0) return q.swimmer.bell.segments;
  jellyfish::BellParams probe;
  probe.diameter_m = q.swimmer.bell.diameter_m;
  probe.height_m = q.swimmer.bell.height_m;
  probe.thickness_m = q.swimmer.bell.thickness_m;
  probe.segments = 64;
  probe.tentacles = false;
  if (!probe.validate().empty()) return 32;  // validate() reports the geometry's problem
  const double arc_m = 64 * jellyfish::buildBell(probe).segment_m;
  const double spacing_m = q.marker_spacing_cells * q.swimmer.fluid.domain_width_m / double(q.swimmer.fluid.cells_x);
  const int segments = 2 * int(std::ceil(arc_m / spacing_m / 2.0));
  return std::max(8, segments);
}

// Passive tracers (Fig. 6): an n x n lattice over the square of side 4 bell diameters around
// the bell's starting position.
void seedTracers(const JellyfishKindParams& q, const jellyfish::Swimmer& s, std::vector<fluid::Vec2>& out) {
  const int n = int(q.tracers_per_side);
  const double side = 4 * q.swimmer.bell.diameter_m;
  const double cx = 0.5 * q.swimmer.fluid.domain_width_m;
  const double cy = s.observe().centroid_m.y;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      out.push_back({cx - side / 2 + (i + 0.5) * side / n, cy - side / 2 + (j + 0.5) * side / n});
}

// The recorder: series, marker tracks, optional fields; plain data the runner writes.
class Recorder {
 public:
  Recorder(Result& result, const jellyfish::Swimmer& s) : result_(result) {
    time_ = &(result.timeseries["time_s"] = {{}, "s"});
    cx_ = &(result.timeseries["centroid_x_m"] = {{}, "m"});
    cy_ = &(result.timeseries["centroid_y_m"] = {{}, "m"});
    ratio_ = &(result.timeseries["diameter_ratio"] = {{}, ""});
    factor_ = &(result.timeseries["aperture_muscle_factor"] = {{}, ""});
    work_ = &(result.timeseries["work_on_fluid_j_per_m"] = {{}, "J/m"});
    markers_ = &result.lagrangian["markers_m"];
    markers_->points = int(s.markers_m().size());
    markers_->dim = 2;
    tracers_ = &result.lagrangian["tracers_m"];
    tracers_->points = int(s.fluid().tracers_m().size());
    tracers_->dim = 2;
    // Each muscle element's activation a in [0, 1] (0 relaxed, 1 fully contracted): the muscle
    // state the renderer's compression ridges follow (Rudolf & Mould 2009 §3.5; src/render/).
    activation_ = &result.lagrangian["muscle_activation"];
    activation_->points = int(s.body().model().muscles.size());
    activation_->dim = 1;
    activation_->unit = "";
    const auto& g = s.fluid().grid();
    result.fields.nx = g.nx;
    result.fields.ny = g.ny;
    result.fields.dx_m = result.fields.dy_m = g.dx_m;
  }
  void frame(const jellyfish::Swimmer& s) {
    const auto o = s.observe();
    time_->values.push_back(o.time_s);
    cx_->values.push_back(o.centroid_m.x);
    cy_->values.push_back(o.centroid_m.y);
    ratio_->values.push_back(o.diameter_ratio);
    factor_->values.push_back(s.body().muscleFactor(0, o.time_s));
    work_->values.push_back(s.fluidWork_j_per_m());
    markers_->time_s.push_back(o.time_s);
    for (const auto& p : s.markers_m()) markers_->data.insert(markers_->data.end(), {p.x, p.y});
    if (activation_->points > 0) {
      activation_->time_s.push_back(o.time_s);
      for (int m = 0; m < activation_->points; ++m) activation_->data.push_back(s.body().activation(m, o.time_s));
    }
    if (tracers_->points > 0) {
      tracers_->time_s.push_back(o.time_s);
      for (const auto& p : s.fluid().tracers_m()) tracers_->data.insert(tracers_->data.end(), {p.x, p.y});
    }
  }
  void field(const jellyfish::Swimmer& s) {
    fluid::vorticityAtCentres(s.fluid().grid(), s.fluid().walls(), w_);
    result_.fields.time_s.push_back(s.time_s());
    Field& f = result_.fields.fields["vorticity_per_s"];
    f.unit = "1/s";
    f.data.insert(f.data.end(), w_.data(), w_.data() + w_.size());
  }

 private:
  Result& result_;
  Series *time_, *cx_, *cy_, *ratio_, *factor_, *work_;
  Tracks *markers_, *tracers_, *activation_;
  fluid::Array2 w_;
};

void addTopology(Result& result, const jellyfish::BellModel& m) {
  auto& chain = result.topology["springs"];
  for (int s = 0; s < m.network.springCount(); ++s) chain.insert(chain.end(), {m.network.spring_a[s], m.network.spring_b[s]});
  auto& muscles = result.topology["muscles"];
  for (const auto& s : m.muscles) muscles.insert(muscles.end(), {s.a, s.b});
  result.topology["bell_markers"] = {m.bell_markers};
}

// The observer's measures (jellyfish::SwimMeasures::describe) as the kind's metric list, and as a
// run's metrics.
struct MetricList {
  std::vector<MetricSpec> specs;
  void metric(const std::string& name, double&, const std::string& unit, const std::string& doc) {
    specs.push_back({name, unit, doc});
  }
};

struct MetricValues {
  Result& result;
  void metric(const std::string& name, double& value, const std::string& unit, const std::string&) {
    result.metrics[name] = {value, unit};
  }
};

}  // namespace

JellyfishKindParams::TentacleCoupling JellyfishKindParams::tentacleCoupling() const {
  const jellyfish::ModelPreset preset = jellyfish::modelPreset(model);
  const auto pick = [](const RealOrAuto& given, double preset_value) {
    return given.is_auto ? preset_value : given.value;
  };
  const double preset_radius_m = preset.tentacle_kernel_radius_m.value_or(kernel_radius_m);
  return {pick(tentacle_kernel_radius_m, preset_radius_m), pick(tentacle_permeability_m, preset.tentacle_permeability_m),
          pick(tentacle_axial_permeability_m, preset.tentacle_axial_permeability_m)};
}

jellyfish::SwimmerConfig JellyfishKindParams::setup() const {
  jellyfish::SwimmerConfig c = swimmer;
  auto& b = c.bell;
  const jellyfish::ModelPreset preset = jellyfish::modelPreset(model);
  b.muscle_model = muscle_model == "auto"           ? preset.muscle_model
                   : muscle_model == "rest_length" ? jellyfish::MuscleModel::rest_length
                                                   : jellyfish::MuscleModel::active_tension;
  c.activation.shape = activation_shape == "auto"     ? preset.activation_shape
                       : activation_shape == "hermite" ? jellyfish::ActivationShape::hermite
                                                       : jellyfish::ActivationShape::pulse;
  const double bending_n_m = bending_rigidity_n_m.is_auto ? preset.bending_rigidity_n_m : bending_rigidity_n_m.value;
  b.segments = bellSegments(*this);
  b.bell_modulus_pa = swimmer.bell.bell_modulus_pa * stiffness_scale;
  b.bending_rigidity_n_m = bending_n_m * stiffness_scale;
  const TentacleCoupling tentacle = tentacleCoupling();
  b.tentacle_root_spacing_m = 2 * tentacle.kernel_radius_m;
  b.tentacle_permeability_m = tentacle.permeability_m;
  b.tentacle_axial_permeability_m = tentacle.axial_permeability_m;
  c.activation.knots = knots.curve();
  // A tall box: the bell swims up its axis and must not meet the top within the window.
  c.fluid.cells_y = int(std::lround(box_aspect * c.fluid.cells_x));
  c.fluid.domain_height_m = c.fluid.cells_y * c.fluid.domain_width_m / c.fluid.cells_x;
  // The coupled step is fixed; a fluid running away is caught as a blow-up.
  c.fluid.time_step_policy = fluid::TimeStepPolicy::fixed;
  c.fluid.fixed_step_s = c.dt_s;
  const double dx_m = swimmer.fluid.cellSize_m();
  c.coupling.kernel_scale = kernelScale(c.coupling.kernel, kernel_radius_m, dx_m, "kernel_radius_m").scale;
  c.tentacle_kernel_scale = kernelScale(c.coupling.kernel, tentacle.kernel_radius_m, dx_m, "tentacle_kernel_radius_m").scale;
  return c;
}

jellyfish::SwimSchedule JellyfishKindParams::schedule() const {
  return jellyfish::swimSchedule(window, swimmer.dt_s, swimmer.activation.contraction_hz);
}

std::string JellyfishKindParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  if (std::string err = knots.validate(); !err.empty()) return err;
  const jellyfish::SwimmerConfig c = setup();
  if (std::string err = c.validate(); !err.empty()) return err;
  // A bell without tentacles has no tentacle kernel to fit to the grid.
  const double tentacle_radius_m = swimmer.bell.tentacles ? tentacleCoupling().kernel_radius_m : 0.0;
  for (const auto& [radius_m, name] : {std::pair{kernel_radius_m, "kernel_radius_m"},
                                       std::pair{tentacle_radius_m, "tentacle_kernel_radius_m"}})
    if (std::string err = kernelScale(c.coupling.kernel, radius_m, swimmer.fluid.cellSize_m(), name).error; !err.empty())
      return err;
  if (tentacle_radius_m > kernel_radius_m && kernel_radius_m > 0)
    return "tentacle_kernel_radius_m must not exceed kernel_radius_m (filaments are narrower than the bell)";
  try {
    jellyfish::buildBell(c.bell);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  if (3 * swimmer.bell.diameter_m > swimmer.fluid.domain_width_m)
    return "the box (domain_m) must be at least three bell diameters wide";
  const double rows = box_aspect * double(swimmer.fluid.cells_x);
  if (std::abs(rows - std::round(rows)) > 1e-9)
    return "cells x box_aspect must be a whole number of cells (got " + std::to_string(rows) + ")";
  if (const long segments = swimmer.bell.segments; segments != 0 && (segments < 8 || segments % 2 != 0))
    return "bell_segments must be 0 (follow the grid) or even and at least 8, got " + std::to_string(segments);
  if (swimmer.dt_s > window.duration_s) return "dt_s is longer than duration_s";
  return "";
}

JellyfishKind::JellyfishKind() {
  MetricList list;
  jellyfish::SwimMeasures().describe(list);
  metrics_ = std::move(list.specs);
}

std::string JellyfishKind::doc() const {
  return "2D jellyfish bell swimming by muscle contraction, IB-coupled to the fluid (Rudolf & Mould 2009 §3)";
}

// Steps from the schedule; memory: the fluid's arrays (the fluid kind's 280 bytes per cell, plus
// MacCormack's four bound and two predictor arrays), the dense implicit system and its LU
// (ib/coupling.cpp: (2 markers)² doubles, twice), and the recorded frames of markers, tracers and
// vorticity fields.
CostEstimate JellyfishKind::estimateCost(const Params& p) const {
  try {
    const JellyfishKindParams q = readParams<JellyfishKindParams>(p);
    const jellyfish::SwimSchedule plan = q.schedule();
    const double cells_x = double(q.swimmer.fluid.cells_x);
    const double cells = cells_x * std::round(q.box_aspect * cells_x);
    const double segments = bellSegments(q);
    const double markers = 1.5 * (segments + 1);  // tentacles add about half a bell's markers
    const double steps = double(plan.total_steps);
    const double frames = 1 + steps / double(plan.steps_per_frame);
    const double fields = plan.steps_per_field > 0 ? 1 + steps / double(plan.steps_per_field) : 0;
    const double tracers = double(q.tracers_per_side) * double(q.tracers_per_side);
    CostEstimate cost;
    cost.steps = steps;
    cost.memory_bytes = 32.0 * (1 << 20) + cells * (280 + 48) + 2 * 8 * (2 * markers) * (2 * markers) +
                        frames * 16 * (markers + tracers) + fields * 8 * cells;
    char detail[160];
    std::snprintf(detail, sizeof detail, "%.0f cells, %.0f markers, %.0f steps, %.0f field frames", cells, markers,
                  steps, fields);
    cost.detail = detail;
    return cost;
  } catch (const std::exception&) {
    return {};
  }
}

Result JellyfishKind::run(const Params& p) const {
  const JellyfishKindParams q = readParams<JellyfishKindParams>(p);
  jellyfish::Swimmer swimmer(q.setup());
  seedTracers(q, swimmer, swimmer.fluid().tracers_m());
  const jellyfish::SwimSchedule plan = q.schedule();

  Result result;
  addTopology(result, swimmer.body().model());
  Recorder recorder(result, swimmer);
  recorder.frame(swimmer);
  if (plan.steps_per_field > 0) recorder.field(swimmer);
  jellyfish::SwimObserver observer(swimmer, plan);
  try {
    for (long step = 1; step <= plan.total_steps; ++step) {
      observer.afterStep(step, swimmer, swimmer.step());
      if (step % plan.steps_per_frame == 0) recorder.frame(swimmer);
      if (plan.steps_per_field > 0 && step % plan.steps_per_field == 0) recorder.field(swimmer);
    }
  } catch (const std::exception& e) {
    throw RunFailure("jellyfish at t = " + std::to_string(swimmer.time_s()) + " s: " + e.what(), result);
  }
  MetricValues metrics{result};
  observer.measures(swimmer).describe(metrics);
  return result;
}

}  // namespace creaturelab::kinds
