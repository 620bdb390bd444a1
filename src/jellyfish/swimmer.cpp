#include "jellyfish/swimmer.hpp"

#include <cmath>
#include <stdexcept>

namespace creaturelab::jellyfish {
namespace {

std::vector<fluid::Vec2> placed(const BellModel& model, const SwimmerConfig& c) {
  const double x0 = c.start_x_fraction * c.fluid.domain_width_m;
  const double y0 = c.start_y_fraction * c.fluid.domain_height_m;
  std::vector<fluid::Vec2> out = model.rest_positions_m;
  for (auto& p : out) p = {p.x + x0, p.y + y0};
  return out;
}

// The coupling's parameters with the tentacles' own kernel stretch, if they have one.
ib::CouplingParams couplingFor(const BellModel& model, const SwimmerConfig& c) {
  ib::CouplingParams out = c.coupling;
  if (c.tentacle_kernel_scale > 0 && c.tentacle_kernel_scale != c.coupling.kernel_scale && !model.tentacle_markers.empty()) {
    out.marker_kernel_scales.assign(model.rest_positions_m.size(), c.coupling.kernel_scale);
    for (const int m : model.tentacle_markers) out.marker_kernel_scales[m] = c.tentacle_kernel_scale;
  }
  return out;
}

}  // namespace

fluid::FluidParams jellyfishFluid() {
  fluid::FluidParams f;
  f.domain_width_m = 0.25;
  f.cells_x = 375;
  f.cells_y = 540;
  f.domain_height_m = f.cells_y * f.domain_width_m / f.cells_x;
  f.kinematic_viscosity_m2_per_s = 5e-5;
  f.advection = fluid::AdvectionScheme::maccormack;
  f.force_stage = fluid::ForceStage::after_advection;
  f.viscosity_tolerance = 1e-8;
  // The coupled step is fixed; a fluid running away is caught as a blow-up.
  f.time_step_policy = fluid::TimeStepPolicy::fixed;
  f.fixed_step_s = 1.0 / 300.0;
  f.blowup_speed_m_per_s = 5.0;
  return f;
}

ib::CouplingParams jellyfishCoupling() {
  ib::CouplingParams c;
  c.kernel = ib::Kernel::peskin4;
  c.kernel_scale = 3;
  c.implicit_theta = 0.5;
  return c;
}

SwimmerConfig paperSwimmer() {
  SwimmerConfig c;
  c.bell = paperBell();
  c.activation = paperActivation();
  c.fluid = fluid::FluidParams{};
  c.coupling = ib::CouplingParams{};
  c.tentacle_kernel_scale = 0;
  c.dt_s = 0.005;
  c.start_y_fraction = 0.25;
  return c;
}

std::string SwimmerConfig::validate() const {
  for (const std::string& err : {bell.validate(), activation.validate(), fluid.validate()})
    if (!err.empty()) return err;
  if (!(dt_s > 0) || !std::isfinite(dt_s)) return "time step must be > 0";
  if (tentacle_kernel_scale < 0) return "the tentacles' kernel stretch must be >= 0";
  // JellyfishBody's Darcy coefficient is the permeability over rho nu.
  const bool permeable = bell.tentacles && (bell.tentacle_permeability_m > 0 || bell.tentacle_axial_permeability_m > 0);
  if (permeable && !(fluid.dynamicViscosity_pa_s() > 0))
    return "permeable tentacles (tentacle_permeability_m or tentacle_axial_permeability_m > 0) need "
           "kinematic_viscosity_m2_per_s > 0";
  return "";
}

Swimmer::Swimmer(const SwimmerConfig& config) : config_(config) {
  if (const std::string err = config.validate(); !err.empty()) throw std::invalid_argument(err);
  fluid_ = std::make_unique<fluid::FluidSolver2>(config.fluid);
  body_ = std::make_unique<JellyfishBody>(buildBell(config.bell), config.activation, config.fluid.dynamicViscosity_pa_s());
  coupling_ = std::make_unique<ib::ImmersedBoundary2>(*fluid_, *body_, placed(body_->model(), config),
                                                      couplingFor(body_->model(), config));
  initial_elastic_j_per_m_ = elasticEnergy_j_per_m();
}

ib::CouplingStepReport Swimmer::step() {
  previous_ = coupling_->markers_m();
  const double t0 = fluid_->time_s(), t1 = t0 + config_.dt_s;
  body_->muscleTensions(t1, previous_, tension_);
  const auto& muscles = body_->model().muscles;
  const bool active = body_->model().muscle_model == MuscleModel::active_tension;
  // The contractile element's shortening: the rest length's (a spring's) or the muscle's own length.
  if (!active)
    for (std::size_t m = 0; m < tension_.size(); ++m)
      muscle_work_j_per_m_ += tension_[m] * muscles[m].relaxed_length_m *
                              (body_->muscleFactor(int(m), t0) - body_->muscleFactor(int(m), t1));
  const auto report = coupling_->step(config_.dt_s);
  checkChain();
  if (active) {
    const auto& x = coupling_->markers_m();
    for (std::size_t m = 0; m < tension_.size(); ++m) {
      const MuscleSpring& s = muscles[m];
      const double before = std::hypot(previous_[s.a].x - previous_[s.b].x, previous_[s.a].y - previous_[s.b].y);
      const double after = std::hypot(x[s.a].x - x[s.b].x, x[s.a].y - x[s.b].y);
      muscle_work_j_per_m_ += tension_[m] * (before - after);
    }
  }
  const auto& force = coupling_->appliedForce_n_per_m();
  const auto& x = coupling_->markers_m();
  for (std::size_t k = 0; k < x.size(); ++k)
    fluid_work_j_per_m_ += force[k].x * (x[k].x - previous_[k].x) + force[k].y * (x[k].y - previous_[k].y);
  return report;
}

void Swimmer::checkChain() const {
  // A coupled step that is too large does not always blow up: it can crumple the chain (markers
  // bunching and folding at the grid scale). Smooth runs keep every bell segment within 0.48-1.15
  // of its rest length (explicit steps of 2e-4 s at 0.7 Hz); a factor of three beyond is no
  // longer the bell the paper describes.
  const auto& x = coupling_->markers_m();
  const auto& net = body_->model().network;
  for (int s = 0; s < body_->model().bell_markers - 1; ++s) {
    const int a = net.spring_a[s], b = net.spring_b[s];
    const double ratio = std::hypot(x[b].x - x[a].x, x[b].y - x[a].y) / net.rest_length_m[s];
    if (ratio < kCrumpledRatio || ratio > 1.0 / kCrumpledRatio)
      throw std::runtime_error("the bell crumpled: segment " + std::to_string(s) + " is at " + std::to_string(ratio) +
                               " of its rest length at t = " + std::to_string(fluid_->time_s()) +
                               " s; reduce dt_s (" + std::to_string(config_.dt_s) +
                               " s), or use the semi-implicit coupling with kernel = \"peskin4\"");
  }
}

double Swimmer::elasticEnergy_j_per_m() const {
  return body_->elasticEnergy(fluid_->time_s(), coupling_->markers_m());
}

SwimmerObservation Swimmer::observe() const {
  SwimmerObservation o;
  o.time_s = fluid_->time_s();
  const auto& x = coupling_->markers_m();
  const int n = body_->model().bell_markers;
  double sx = 0, sy = 0;
  for (int i = 0; i < n; ++i) {
    sx += x[i].x;
    sy += x[i].y;
  }
  o.centroid_m = {sx / n, sy / n};
  o.diameter_ratio = std::hypot(x[n - 1].x - x[0].x, x[n - 1].y - x[0].y) / body_->model().aperture_width_m;
  return o;
}

}  // namespace creaturelab::jellyfish
