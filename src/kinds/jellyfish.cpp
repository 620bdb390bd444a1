#include "kinds/jellyfish.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>

#include "fluid/diagnostics2.hpp"
#include "jellyfish/ringdown.hpp"
#include "jellyfish/swimmer.hpp"
#include "kinds/ib_params.hpp"

namespace creaturelab::kinds {
namespace {

using jellyfish::Knot;

std::string knotName(int k, const char* field) { return "knot" + std::to_string(k) + "_" + field; }

// The default curve (jellyfish_params.hpp), padded with unused knots at (0, 1, 0).
Knot defaultKnot(int k) {
  const jellyfish::ActivationParams defaults;
  if (k < int(defaults.knots.size())) return defaults.knots[k];
  return {0.0, 1.0, 0.0};
}

std::vector<Knot> knots(const ParamReader& r) {
  std::vector<Knot> out;
  for (int k = 0; k < int(r.integer("contraction_knots")); ++k)
    out.push_back({r.real(knotName(k, "phase")), r.real(knotName(k, "value")), r.real(knotName(k, "tangent"))});
  return out;
}

// Constants of the active-tension bell the paper does not give: B was chosen on a 200² grid to put the pluck's
// natural frequency f_n near the resonant 0.7 Hz (Rudolf & Mould 2009 §3.3, Fig. 5), T_max in a less viscous
// fluid to close the bell to Fig. 3's 0.56 of its diameter; on the default setting the bell rings lower and
// closes less (experiments/jellyfish/frequency.toml's pluck, morphology.toml's known deviation).
constexpr double kCalibratedBendingRigidity = 1.0e-4;
constexpr double kCalibratedTension = 14.0;

// The defaults are the converged setting of the jellyfish convergence experiments (grid, step, scheme and box
// refined together): a viscous fluid, the activation pulse, Peskin's kernel at the bell's 4 mm, 256 segments,
// 1 mm cells, the force after the advection, a 0.25 m by 0.36 m box.

// bell_segments = 0 follows the grid: the fewest even segments whose drawn length is at most
// marker_spacing_cells cells (markers about half a cell apart, so that the boundary does not leak as the grid
// is refined; Peskin 2002).
int bellSegments(const ParamReader& r) {
  const long given = r.integer("bell_segments");
  if (given > 0) return int(given);
  jellyfish::BellParams probe;
  probe.diameter_m = r.real("bell_diameter_m");
  probe.height_m = r.real("bell_height_m");
  probe.thickness_m = r.real("bell_thickness_m");
  probe.segments = 64;
  probe.tentacles = false;
  if (!jellyfish::validate(probe).empty()) return 32;  // validate() reports the geometry's problem
  const double arc_m = 64 * jellyfish::buildBell(probe).segment_m;
  const double spacing_m = r.real("marker_spacing_cells") * r.real("domain_m") / double(r.integer("cells"));
  const int segments = 2 * int(std::ceil(arc_m / spacing_m / 2.0));
  return std::max(8, segments);
}

jellyfish::SwimmerConfig config(const ParamReader& r) {
  jellyfish::SwimmerConfig c;
  auto& b = c.bell;
  b.diameter_m = r.real("bell_diameter_m");
  b.height_m = r.real("bell_height_m");
  b.thickness_m = r.real("bell_thickness_m");
  b.segments = bellSegments(r);
  b.bell_modulus_pa = r.real("bell_modulus_pa") * r.real("stiffness_scale");
  b.bending_rigidity_n_m = r.real("bending_rigidity_n_m") * r.real("stiffness_scale");
  b.muscle_model = r.text("muscle_model") == "active_tension" ? jellyfish::MuscleModel::active_tension
                                                              : jellyfish::MuscleModel::rest_length;
  b.muscle_band_fraction = r.real("muscle_band_fraction");
  b.muscle_modulus_pa = r.real("muscle_modulus_pa");
  b.muscle_section_per_arc = r.real("muscle_section_per_arc");
  b.muscle_tension_n_per_m2 = r.real("muscle_tension_n_per_m2");
  b.tentacles = r.boolean("tentacles");
  b.tentacle_length_m = r.real("tentacle_length_m");
  b.tentacle_area_factor = r.real("tentacle_area_factor");
  b.tentacles_per_side = int(r.integer("tentacles_per_side"));
  b.tentacle_root_spacing_m = 2 * r.real("tentacle_kernel_radius_m");
  // Darcy: α = κ / μ, the permeability length over the dynamic viscosity ρ ν.
  b.tentacle_porosity_m_per_pa_s =
      r.real("tentacle_permeability_m") / (r.real("density_kg_per_m3") * r.real("kinematic_viscosity_m2_per_s"));

  auto& a = c.activation;
  a.contraction_hz = r.real("contraction_hz");
  a.knots = knots(r);
  a.expansion = r.text("expansion") == "unison" ? jellyfish::Expansion::unison : jellyfish::Expansion::staggered;
  a.stagger = r.real("stagger");
  a.synaptic_delay_s = r.real("synaptic_delay_s");
  a.shape = r.text("activation_shape") == "pulse" ? jellyfish::ActivationShape::pulse : jellyfish::ActivationShape::hermite;
  a.pulse_duration_s = r.real("pulse_duration_s");
  a.pulse_stagger = r.real("pulse_stagger");
  a.active_cycles = int(r.integer("active_cycles"));

  c.fluid = fluidBoxParams(r);
  // A tall box: the bell swims up its axis and must not meet the top within the window.
  c.fluid.cells_y = int(std::lround(r.real("box_aspect") * c.fluid.cells_x));
  c.fluid.domain_height_m = c.fluid.cells_y * c.fluid.domain_width_m / c.fluid.cells_x;
  c.coupling = couplingParams(r);
  c.tentacle_kernel_scale = kernelScale(r, "tentacle_kernel_radius_m").scale;
  c.fluid.viscosity_tolerance = r.real("viscosity_tolerance");
  c.fluid.force_stage = *fluid::parseForceStage(r.text("force_stage"));
  c.dt_s = r.real("dt_s");
  c.start_y_fraction = r.real("start_y_fraction");
  return c;
}

// Times of a run: warm-up cycles, then the measured window; every time lands on a step.
struct Schedule {
  long warmup_steps = 0;
  long total_steps = 0;
  long work_end_step = 0;  // end of the last whole cycle in the window (muscle work is per whole cycles)
  double whole_cycles = 0;  // whole cycles in the window; 0: shorter than a cycle (work_end_step = total_steps)
  long steps_per_frame = 1;
  long steps_per_field = 0;  // 0: no fields
};

Schedule schedule(const ParamReader& r) {
  const double dt = r.real("dt_s");
  Schedule s;
  s.warmup_steps = std::lround(r.real("warmup_cycles") / r.real("contraction_hz") / dt);
  s.total_steps = s.warmup_steps + std::lround(r.real("duration_s") / dt);
  const double whole_cycles = std::floor(r.real("duration_s") * r.real("contraction_hz") + 1e-9);
  s.whole_cycles = whole_cycles;
  s.work_end_step = whole_cycles >= 1 ? s.warmup_steps + std::lround(whole_cycles / r.real("contraction_hz") / dt)
                                      : s.total_steps;
  s.work_end_step = std::min(s.work_end_step, s.total_steps);
  s.steps_per_frame = std::max(1L, std::lround(1.0 / (r.real("frame_rate_hz") * dt)));
  if (r.boolean("store_fields")) s.steps_per_field = std::max(1L, std::lround(1.0 / (r.real("field_rate_hz") * dt)));
  return s;
}

// Passive tracers (Fig. 6): an n x n lattice over the square of side 4 bell diameters around
// the bell's starting position.
void seedTracers(const ParamReader& r, const jellyfish::Swimmer& s, std::vector<fluid::Vec2>& out) {
  const int n = int(r.integer("tracers_per_side"));
  const double side = 4 * r.real("bell_diameter_m");
  const double cx = 0.5 * r.real("domain_m");
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

}  // namespace

JellyfishKind::JellyfishKind() {
  const jellyfish::BellParams bell;
  const jellyfish::ActivationParams act;
  params_ = {
      // --- activation (§3.3, Fig. 4)
      real("contraction_hz", act.contraction_hz, "Hz", 1e-3, 100, "contraction frequency (Fig. 12: 0.7 Hz)"),
      choice("expansion", "staggered", {"staggered", "unison"},
             "hermite shape: staggered, aperture springs expand more slowly than apex springs (§3.3, Fig. 4 right), "
             "or unison; the pulse's is pulse_stagger"),
      real("stagger", act.stagger, "", 0, 0.99,
           "apex springs expand 1/(1 - stagger) times faster than the aperture's; not given in the paper "
           "(jellyfish/contraction_curve.hpp)"),
      integer("contraction_knots", std::int64_t(act.knots.size()), 1, kMaxKnots,
              "Hermite knots of the rest-length curve used (knot0_* .. knot{N-1}_*); the paper gives none"),
      real("synaptic_delay_s", act.synaptic_delay_s, "s", 0, 10,
           "Spencer's synaptic delay per muscle pair from the aperture (§3.1); 0 = off"),
      choice("activation_shape", "pulse", {"hermite", "pulse"},
             "pulse: sin^2 over pulse_duration_s each cycle, then free recoil (Hoover, Porras & Miller 2019); "
             "hermite: the §3.3 curve, whose held tension does not converge in the grid"),
      real("pulse_duration_s", act.pulse_duration_s, "s", 1e-4, 100, "pulse shape: length of the contraction pulse"),
      real("pulse_stagger", act.pulse_stagger, "", 0, 0.99,
           "pulse shape: the apex muscle's release runs 1/(1 - pulse_stagger) times faster than the aperture's "
           "(§3.3, Fig. 4 right); 0 = unison"),
      integer("active_cycles", 0, 0, 100000,
              "cycles with activation, 0 = all; 1 with a short pulse is a pluck (frequency.toml)"),
  };
  for (int k = 0; k < kMaxKnots; ++k) {
    const Knot d = defaultKnot(k);
    params_.push_back(real(knotName(k, "phase"), d.phase, "", 0, 0.999999, "phase of knot " + std::to_string(k) + " in [0, 1)"));
    params_.push_back(real(knotName(k, "value"), d.value, "", 0.05, 1.5,
                           "rest-length factor at knot " + std::to_string(k) + " (paper: curve between 1 and 0.56)"));
    params_.push_back(real(knotName(k, "tangent"), d.tangent, "1/cycle", -100, 100,
                           "slope d value / d phase at knot " + std::to_string(k)));
  }
  const std::vector<ParamSpec> bell_specs = {
      // --- bell (§3.2, Fig. 12)
      real("bell_diameter_m", bell.diameter_m, "m", 1e-4, 10, "Fig. 12: 40 mm"),
      real("bell_height_m", bell.height_m, "m", 1e-4, 10, "Fig. 12: 28 mm"),
      real("bell_thickness_m", bell.thickness_m, "m", 1e-5, 1, "Fig. 12: 4 mm; the markers are the subumbrella"),
      integer("bell_segments", 256, 0, 2048,
              "springs along the subumbrella (even, >= 8); 0 = follow the grid (marker_spacing_cells); 256 keeps one "
              "body, markers <= 0.5 cells apart, in the grid study"),
      real("marker_spacing_cells", 0.5, "", 0.05, 4,
           "bell_segments = 0: largest marker spacing in cells; 0.5 is Peskin 2002's rule and keeps the membrane's "
           "leak small"),
      real("bell_modulus_pa", bell.bell_modulus_pa, "Pa", 1e-6, 1e12, "bell mesoglea, λ = 1186 Pa (Fig. 12); k = E t / L"),
      real("bending_rigidity_n_m", kCalibratedBendingRigidity, "N m", 0, 1e6,
           "bending rigidity B per metre of depth (a joint's angular spring is B / L); not given by the paper, "
           "chosen on a 200² grid for a pluck ringing near §3.3's resonant 0.7 Hz"),
      real("stiffness_scale", 1.0, "", 1e-3, 1e3,
           "multiplies bell_modulus_pa and bending_rigidity_n_m together"),
      choice("muscle_model", "active_tension", {"rest_length", "active_tension"},
             "active_tension: a tension T_max a(t) that the elastic bell re-expands against, so the stroke can "
             "resonate; rest_length: the paper's rest-length curve (§3.3)"),
      real("muscle_band_fraction", bell.muscle_band_fraction, "", 0.01, 0.99,
           "fraction of the half-arc from the aperture that the muscle band covers (Fig. 4's model: 14 of 16)"),
      real("muscle_modulus_pa", bell.muscle_modulus_pa, "Pa", 1e-6, 1e12, "circumferential muscle, 400 kPa (§3.2)"),
      real("muscle_section_per_arc", bell.muscle_section_per_arc, "", 1e-9, 10,
           "rest_length: muscle cross-section per metre of depth per metre of band arc; not given "
           "(jellyfish_params.hpp)"),
      real("muscle_tension_n_per_m2", kCalibratedTension, "N/m^2", 0, 1e9,
           "active_tension: peak tension per metre of depth per metre of band arc; not given, calibrated to close the "
           "bell toward Fig. 3's 0.56 of its diameter"),
      boolean("tentacles", bell.tentacles, "passive tentacle chains at the aperture (§3.2)"),
      real("tentacle_length_m", bell.tentacle_length_m, "m", 1e-5, 10, "not given; half a diameter"),
      real("tentacle_area_factor", bell.tentacle_area_factor, "", 1e-9, 10, "Fig. 12: 1/100 of the bell's section"),
      integer("tentacles_per_side", bell.tentacles_per_side, 1, 8,
              "tentacle chains per side of the slice, from the aperture inward, roots two tentacle kernel radii "
              "apart; not given (§3.2: one per aperture point)"),
      real("tentacle_kernel_radius_m", 0.004, "m", 0, 10,
           "the tentacles' own kernel support radius (at most kernel_radius_m; 0 = the grid's kernel); the "
           "default is the bell's: 2 mm filaments made porous lose their chain on the 1 mm grid"),
      real("tentacle_permeability_m", 0.0, "m", 0, 10,
           "Darcy permeability over thickness of a tentacle chain, slip = permeability / (rho nu) x normal load "
           "per length (Kim & Peskin's porous boundary); 0 = impermeable; 1.7e-3 estimates a ring of 16 "
           "filaments 0.5 mm thick in Stokes flow, h ln(h/d) / 4 pi"),
  };
  // --- fluid (§3.2, Fig. 12)
  const std::vector<ParamSpec> fluid_specs = fluidBoxSpecs({
      .domain_m = 0.25,
      .domain_doc = "width of the free-slip box (its height is box_aspect times it): 6.25 bell diameters, "
                    "chosen close to the paper's 10-diameter box (§3.2) in distance per cycle",
      .cells_doc = "fluid cells across the box (Fig. 12: 100 in 0.4 m); 250 gives 1 mm cells, the converged grid of "
                   "the convergence study",
      .cells = 250,
      .density_doc = "paper: '1' without units, read as g/cm^3",
      .kinematic_viscosity_m2_per_s = 5e-5,
      .viscosity_doc = "38 times water (Re ~16, within 2-D IB jellyfish studies' 10-300) so 1 mm cells resolve "
                       "the Stokes layer; the paper's 1.304e-3, read as Pa s, gives 1.304e-6",
      .advection_doc = "velocity advection: MacCormack (Selle et al. 2008, second order in space), the paper's "
                       "semi-Lagrangian (Stam 1999), or upwind2_rk2 (Fromm upwind + Heun, CFL <= 0.5)",
      .advection = "maccormack",
  });
  // --- coupling (§3.2; Peskin 2002)
  const std::vector<ParamSpec> coupling_specs = couplingSpecs({
      .kernel = "peskin4",
      .kernel_doc = "spreading/interpolation: Peskin's 4-point function, or the paper's bilinear hat (§3.2), "
                    "stretched to kernel_radius_m; the hat's bell does not converge in its segments",
      .mobility_doc = "fluid response assumed by the semi-implicit force: through the markers' stencils "
                      "(ib/coupling.hpp), or each marker alone",
      .kernel_radius_m = 0.004,
      .kernel_radius_doc = "kernel support radius: the bell's 4 mm thickness (Fig. 12), so a grid study refines "
                           "one body; a whole multiple of the kernel's reach in cells; 0 = the grid's kernel",
      .implicit_theta = 0.5,
      .implicit_theta_doc = "0.5 doubles the step at the same accuracy",
  });
  const std::vector<ParamSpec> rest = {
      real("viscosity_tolerance", 1e-8, "", 1e-14, 1e-2,
           "relative residual of the implicit viscous solve (fluid/diffusion2.hpp); far below the step's and the "
           "grid's errors"),
      real("dt_s", 0.00125, "s", 1e-7, 0.1,
           "coupled step, first order in time (ib/coupling.hpp); with implicit_theta = 0.5 within about 2% of the "
           "step limit; the paper's 0.01 s is stable"),
      choice("force_stage", "after_advection", {"before_advection", "after_advection"},
             "where the bell's force enters the fluid step: after the advection (a source of the momentum equation, "
             "Peskin 2002 §6), or before it (Stam 1999 §2.2, the paper's order)"),
      real("blowup_speed_m_per_s", 5.0, "m/s", 1e-6, 1e6, "fluid speed taken as a blow-up (100x the swimming flow)"),
      real("start_y_fraction", 0.5, "", 0.05, 0.95,
           "aperture's starting height as a fraction of the box's (the bell swims up, its wake goes down): 0.18 m "
           "above the floor"),
      real("box_aspect", 1.44, "", 0.25, 8,
           "box height / width; cells x box_aspect must be whole (1.44: cells a multiple of 25); tall enough that "
           "floor and top barely move the swim"),
      // --- measurement
      real("warmup_cycles", 1.0, "", 0, 1000, "cycles before the measured window"),
      real("duration_s", 10.0, "s", 1e-6, 1e6,
           "measured window, the same for every frequency; compare frequencies by cycle_speed_m_per_s, which counts "
           "whole cycles only"),
      real("frame_rate_hz", 25.0, "Hz", 1e-3, 1e4, "series and marker frames"),
      boolean("store_fields", false, "store vorticity fields (frames × ny × nx) with an XDMF sidecar"),
      real("field_rate_hz", 10.0, "Hz", 1e-3, 1e4, "field frames per second when store_fields"),
      integer("tracers_per_side", 0, 0, 200, "trace particles on an n x n lattice around the bell (Fig. 6)"),
  };
  for (const auto* specs : {&bell_specs, &fluid_specs, &coupling_specs, &rest})
    params_.insert(params_.end(), specs->begin(), specs->end());
  metrics_ = {
      {"distance_m", "m", "axial (+y) displacement of the bell's centroid over the measured window"},
      {"distance_per_cycle_m", "m",
       "displacement over the window's whole cycles / their number (distance_m / cycles when the window has "
       "less than one): a window that ends part way through a cycle would add that part's surge or slide"},
      {"mean_speed_m_per_s", "m/s", "distance_m / duration_s"},
      {"cycle_speed_m_per_s", "m/s",
       "distance_per_cycle_m x contraction_hz: the mean speed over the window's whole cycles, the measure of "
       "Fig. 5's 'distance in a given time' that does not depend on where the window cuts the last cycle"},
      {"whole_cycles", "", "whole contraction cycles in the window (distance_per_cycle_m, the work measures)"},
      {"min_diameter_ratio", "", "smallest aperture width / drawn width in the window"},
      {"stroke_amplitude", "", "largest minus smallest diameter ratio over the second half of the window (the "
                               "frequency response's amplitude, once the start-up has died away)"},
      {"ringdown_hz", "Hz", "active_cycles > 0: damped frequency of the diameter's free decay after the last active "
                          "cycle (zero crossings of ratio - 1); NaN without two half periods"},
      {"natural_hz", "Hz", "active_cycles > 0: the bell-water natural frequency f_n from a fit of one damped mode "
                         "to the whole free decay, sqrt(sigma^2 + omega^2) / 2 pi (jellyfish/ringdown.hpp)"},
      {"damping_ratio", "", "the same fit's sigma / sqrt(sigma^2 + omega^2)"},
      {"mode_residual", "", "rms residual of that fit over the decay's rms: how much of the decay is not one mode"},
      {"lateral_drift_m", "m", "x displacement of the centroid over the window"},
      {"forward_travel_m", "m",
       "sum of the centroid's upward steps over the window: the bell surges forward on each contraction and "
       "slides back on each re-expansion, and distance_m is what is left of the surge"},
      {"net_fraction", "",
       "distance_m / forward_travel_m: near 1 a stroke that keeps its surge; small, a nearly reciprocal one, "
       "whose distance is a small difference of two large excursions and converges slowly in the grid"},
      {"cycle_distance_spread", "",
       "standard error of the mean distance per whole cycle in the window over distance_per_cycle_m (sample "
       "deviation of the cycles' distances / sqrt(cycles)): how far the window is from periodic. Whether that "
       "is a scatter or a start-up trend, see cycle_distance_growth; a steady trend is deterministic and a "
       "grid study compares it like any other number. NaN with fewer than two whole cycles"},
      {"cycle_distance_growth", "",
       "least-squares line through the whole cycles' distances against their order, its rise from the "
       "window's first cycle to its last over distance_per_cycle_m: positive while the bell still gains "
       "speed, negative while the surge of its first strokes fades. NaN with fewer than two whole cycles"},
      {"muscle_work_j", "J/m",
       "muscles' net work over the whole cycles of the window, per metre of depth: the work the body did on the "
       "fluid, sum F . dX (the body has no internal dissipation, so over periodic cycles the muscles' work goes "
       "to the fluid); converged in dt"},
      {"muscle_work_direct_j", "J/m",
       "the same from -sum T dr (tension x rest-length shortening): adds the semi-implicit step's damping of the "
       "stiff muscle, which falls in proportion to dt"},
      {"cost_of_transport", "J/(kg m)",
       "muscle_work_j / (bell mass per metre x distance over those whole cycles); NaN if that distance <= 0"},
      {"cycles", "", "contraction cycles in the measured window"},
      {"max_cfl", "", "largest max(|u|,|v|) dt / dx of any step"},
      {"max_marker_speed_m_per_s", "m/s", "largest marker speed of any step"},
      {"markers", "", "immersed-boundary markers (bell + tentacles)"},
      {"kernel_cells", "", "the kernel's stretch: its radius in units of its own reach in cells (1 = the grid's kernel)"},
      {"segment_cells", "", "drawn bell segment length in fluid cells (bell_segments = 0 keeps it <= marker_spacing_cells)"},
      {"steps", "", "coupled steps taken"},
  };
}

std::string JellyfishKind::doc() const {
  return "2D jellyfish bell swimming by muscle contraction, IB-coupled to the fluid (Rudolf & Mould 2009 §3)";
}

std::string JellyfishKind::validate(const Params& p) const {
  ParamReader r(p);
  const int used = int(r.integer("contraction_knots"));
  for (int k = used; k < kMaxKnots; ++k) {
    const Knot d = defaultKnot(k), given{r.real(knotName(k, "phase")), r.real(knotName(k, "value")),
                                        r.real(knotName(k, "tangent"))};
    if (given.phase != d.phase || given.value != d.value || given.tangent != d.tangent)
      return knotName(k, "*") + " is set but contraction_knots = " + std::to_string(used) +
             ": raise contraction_knots or remove the knot";
  }
  const auto c = config(r);
  if (std::string err = jellyfish::validate(c.bell); !err.empty()) return err;
  if (std::string err = jellyfish::validate(c.activation); !err.empty()) return err;
  if (std::string err = c.fluid.validate(); !err.empty()) return err;
  if (std::string err = kernelScale(r).error; !err.empty()) return err;
  if (std::string err = kernelScale(r, "tentacle_kernel_radius_m").error; !err.empty()) return err;
  if (r.real("tentacle_kernel_radius_m") > r.real("kernel_radius_m") && r.real("kernel_radius_m") > 0)
    return "tentacle_kernel_radius_m must not exceed kernel_radius_m (filaments are narrower than the bell)";
  try {
    jellyfish::buildBell(c.bell);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  if (3 * r.real("bell_diameter_m") > r.real("domain_m"))
    return "the box (domain_m) must be at least three bell diameters wide";
  const double rows = r.real("box_aspect") * double(r.integer("cells"));
  if (std::abs(rows - std::round(rows)) > 1e-9)
    return "cells x box_aspect must be a whole number of cells (got " + std::to_string(rows) + ")";
  if (const long segments = r.integer("bell_segments"); segments != 0 && (segments < 8 || segments % 2 != 0))
    return "bell_segments must be 0 (follow the grid) or even and at least 8, got " + std::to_string(segments);
  if (r.real("dt_s") > r.real("duration_s")) return "dt_s is longer than duration_s";
  return "";
}

// Steps from the schedule; memory: the fluid's arrays (the fluid kind's 280 bytes per cell, plus
// MacCormack's four bound and two predictor arrays), the dense implicit system and its LU
// (ib/coupling.cpp: (2 markers)² doubles, twice), and the recorded frames of markers, tracers and
// vorticity fields.
CostEstimate JellyfishKind::estimateCost(const Params& p) const {
  try {
    ParamReader r(p);
    const Schedule plan = schedule(r);
    const double cells = double(r.integer("cells")) * std::round(r.real("box_aspect") * double(r.integer("cells")));
    const double segments = bellSegments(r);
    const double markers = 1.5 * (segments + 1);  // tentacles add about half a bell's markers
    const double steps = double(plan.total_steps);
    const double frames = 1 + steps / double(plan.steps_per_frame);
    const double fields = plan.steps_per_field > 0 ? 1 + steps / double(plan.steps_per_field) : 0;
    const double tracers = double(r.integer("tracers_per_side")) * double(r.integer("tracers_per_side"));
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

namespace {
// The distances of the window's whole cycles, from the heights at successive cycle starts.
std::vector<double> cycleDistances(const std::vector<double>& start_y) {
  std::vector<double> d;
  for (std::size_t k = 0; k + 1 < start_y.size(); ++k) d.push_back(start_y[k + 1] - start_y[k]);
  return d;
}

// Standard error of the mean of the cycles' distances, relative to the window's distance per cycle.
double cycleSpread(const std::vector<double>& d, double per_cycle) {
  if (d.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double mean = 0, var = 0;
  for (double v : d) mean += v / double(d.size());
  for (double v : d) var += (v - mean) * (v - mean) / double(d.size() - 1);
  return std::sqrt(var / double(d.size())) / std::abs(per_cycle);
}

// The least-squares line through the cycles' distances against the cycle's index, from the first
// cycle of the window to the last, relative to the window's distance per cycle. A window shorter than
// the viscous time D² / ν (32 s for the 4 cm bell at the default ν) shows a trend rather than a
// scatter, which cycleSpread alone would read as noise.
double cycleGrowth(const std::vector<double>& d, double per_cycle) {
  if (d.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  const double n = double(d.size()), mid = 0.5 * (n - 1);
  double mean = 0, sxy = 0, sxx = 0;
  for (double v : d) mean += v / n;
  for (std::size_t k = 0; k < d.size(); ++k) {
    sxy += (double(k) - mid) * (d[k] - mean);
    sxx += (double(k) - mid) * (double(k) - mid);
  }
  return sxy / sxx * (n - 1) / std::abs(per_cycle);
}
}  // namespace

Result JellyfishKind::run(const Params& p) const {
  ParamReader r(p);
  jellyfish::Swimmer swimmer(config(r));
  seedTracers(r, swimmer, swimmer.fluid().tracers_m());
  const Schedule plan = schedule(r);
  const double dt = r.real("dt_s");

  Result result;
  addTopology(result, swimmer.body().model());
  Recorder recorder(result, swimmer);
  recorder.frame(swimmer);
  if (plan.steps_per_field > 0) recorder.field(swimmer);

  jellyfish::SwimmerObservation start;
  double start_work = 0, end_work = 0, start_fluid = 0, end_fluid = 0, min_ratio = std::numeric_limits<double>::infinity(), max_cfl = 0, max_speed = 0;
  double forward_travel = 0, last_y = 0, cycles_end_y = 0;
  std::vector<double> cycle_start_y;  // centroid height at each whole cycle's start and end in the window
  const double period_steps = 1.0 / (r.real("contraction_hz") * dt);
  auto cycleBoundary = [&](long step) {
    const double k = double(step - plan.warmup_steps) / period_steps;
    return step >= plan.warmup_steps && step <= plan.work_end_step &&
           step - plan.warmup_steps == std::lround(std::round(k) * period_steps);
  };
  // Stroke amplitude over the window's second half; the free decay after the last active cycle.
  const long second_half_step = plan.warmup_steps + (plan.total_steps - plan.warmup_steps) / 2;
  double late_min = std::numeric_limits<double>::infinity(), late_max = -late_min;
  const long active_cycles = r.integer("active_cycles");
  // The activation ends with the last active cycle's pulse (pulse shape) or with the cycle (hermite).
  const double last_cycle_s = (active_cycles - 1) / r.real("contraction_hz");
  const double release_s = last_cycle_s + (r.text("activation_shape") == "pulse" ? r.real("pulse_duration_s")
                                                                                 : 1.0 / r.real("contraction_hz"));
  const long release_step = active_cycles > 0 ? std::lround(release_s / dt) : -1;
  std::vector<double> decay_t, decay_d;
  if (plan.warmup_steps == 0) start = swimmer.observe();
  last_y = swimmer.observe().centroid_m.y;
  if (cycleBoundary(0)) cycle_start_y.push_back(last_y);
  try {
    for (long step = 1; step <= plan.total_steps; ++step) {
      const auto report = swimmer.step();
      max_cfl = std::max(max_cfl, report.fluid.cfl_number);
      max_speed = std::max(max_speed, report.max_marker_speed_m_per_s);
      const auto o = swimmer.observe();
      if (step == plan.warmup_steps) {
        start = o;
        start_work = swimmer.muscleWork_j_per_m();
        start_fluid = swimmer.fluidWork_j_per_m();
      }
      if (step == plan.work_end_step) {
        cycles_end_y = o.centroid_m.y;
        end_work = swimmer.muscleWork_j_per_m();
        end_fluid = swimmer.fluidWork_j_per_m();
      }
      if (step > plan.warmup_steps) {
        min_ratio = std::min(min_ratio, o.diameter_ratio);
        forward_travel += std::max(0.0, o.centroid_m.y - last_y);
      }
      last_y = o.centroid_m.y;
      if (cycleBoundary(step)) cycle_start_y.push_back(o.centroid_m.y);
      if (step > second_half_step) {
        late_min = std::min(late_min, o.diameter_ratio);
        late_max = std::max(late_max, o.diameter_ratio);
      }
      if (release_step >= 0 && step >= release_step) {
        decay_t.push_back(o.time_s);
        decay_d.push_back(o.diameter_ratio - 1.0);
      }
      if (step % plan.steps_per_frame == 0) recorder.frame(swimmer);
      if (plan.steps_per_field > 0 && step % plan.steps_per_field == 0) recorder.field(swimmer);
    }
  } catch (const std::exception& e) {
    throw RunFailure("jellyfish at t = " + std::to_string(swimmer.time_s()) + " s: " + e.what(), result);
  }

  const auto end = swimmer.observe();
  const double duration = (plan.total_steps - plan.warmup_steps) * dt;
  const double distance = end.centroid_m.y - start.centroid_m.y;
  const double cycles = duration * r.real("contraction_hz");
  // Work is counted over whole cycles, so that the two work measures compare like with like
  // (over whole cycles the elastic energy stored, far larger than one cycle's work, nearly cancels).
  // A window that ends part way through a cycle adds that part's surge or slide to distance_m (see
  // duration_s), so the per-cycle measures count the whole cycles only. A window shorter than one
  // cycle counts all of itself, work and distance alike.
  const double work_cycles = plan.whole_cycles;
  const double work_distance = work_cycles >= 1 ? cycles_end_y - start.centroid_m.y : distance;
  const double per_cycle = work_cycles >= 1 ? work_distance / work_cycles : distance / cycles;
  const double work = end_work - start_work;
  const double fluid_work = end_fluid - start_fluid;
  const double bell_mass = r.real("density_kg_per_m3") * swimmer.body().model().bell_area_m2;
  auto& m = result.metrics;
  m["distance_m"] = {distance, "m"};
  m["distance_per_cycle_m"] = {per_cycle, "m"};
  m["mean_speed_m_per_s"] = {distance / duration, "m/s"};
  m["cycle_speed_m_per_s"] = {per_cycle * r.real("contraction_hz"), "m/s"};
  m["whole_cycles"] = {work_cycles, ""};
  m["min_diameter_ratio"] = {min_ratio, ""};
  m["stroke_amplitude"] = {late_max - late_min, ""};
  // Two estimates of the free decay (jellyfish/ringdown.hpp): zero crossings of the first two periods
  // after release, with a hysteresis of a fifth of the last extremum (ringdown_hz), and a fit of one
  // damped mode to the whole decay at the frame rate (natural_hz, damping_ratio): the crossings lose
  // a half period whenever a higher mode beating in the tail keeps the signal under the hysteresis.
  const jellyfish::Ringdown ring = jellyfish::measureRingdown(decay_t, decay_d, 0.2, 4);
  std::vector<double> frame_t, frame_d;
  for (std::size_t i = 0; i < decay_t.size(); i += std::size_t(std::max(1L, plan.steps_per_frame)))
    frame_t.push_back(decay_t[i]), frame_d.push_back(decay_d[i]);
  const jellyfish::DampedFit fit = jellyfish::fitDampedOscillation(frame_t, frame_d);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m["ringdown_hz"] = {release_step >= 0 ? ring.damped_hz : nan, "Hz"};
  m["natural_hz"] = {release_step >= 0 ? fit.natural_hz : nan, "Hz"};
  m["damping_ratio"] = {release_step >= 0 ? fit.damping_ratio : nan, ""};
  m["mode_residual"] = {release_step >= 0 ? fit.residual_fraction : nan, ""};
  m["lateral_drift_m"] = {end.centroid_m.x - start.centroid_m.x, "m"};
  m["forward_travel_m"] = {forward_travel, "m"};
  const std::vector<double> cycle_distances = cycleDistances(cycle_start_y);
  m["cycle_distance_spread"] = {cycleSpread(cycle_distances, per_cycle), ""};
  m["cycle_distance_growth"] = {cycleGrowth(cycle_distances, per_cycle), ""};
  m["net_fraction"] = {forward_travel > 0 ? distance / forward_travel : nan, ""};
  m["muscle_work_j"] = {end_fluid - start_fluid, "J/m"};
  m["muscle_work_direct_j"] = {work, "J/m"};
  m["cost_of_transport"] = {work_distance > 0 ? fluid_work / (bell_mass * work_distance) : nan, "J/(kg m)"};
  m["cycles"] = {cycles, ""};
  m["max_cfl"] = {max_cfl, ""};
  m["max_marker_speed_m_per_s"] = {max_speed, "m/s"};
  m["markers"] = {double(swimmer.markers_m().size()), ""};
  m["kernel_cells"] = {double(swimmer.config().coupling.kernel_scale), ""};
  m["segment_cells"] = {swimmer.body().model().segment_m / swimmer.fluid().grid().dx_m, ""};
  m["steps"] = {double(plan.total_steps), ""};
  return result;
}

}  // namespace creaturelab::kinds
