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

// Calibrated parameters of the active-tension bell (issue 13). B = 1e-4 N m was chosen on 200² with
// Peskin's grid kernel to put the pluck's f_n at the paper's resonant 0.7 Hz (§3.3, Fig. 5: 0.73 Hz
// there). On the converged default setting (below) the same B rings at f_n = 0.575 Hz
// (frequency_peak_viscous.toml, 1 mm pluck), and was kept. T_max = 14 N/m² with the 0.3 s pulse was
// chosen at ν = 1.304e-5 on 1 mm to close the bell to Fig. 3's 0.56 of its diameter at 0.6 Hz
// (convergence_pulse.toml's probes); in the default, more viscous fluid the bell closes only to 0.67
// of its diameter at 0.6 Hz and 0.72 at 0.7 Hz (frequency_peak_viscous.toml), not Fig. 3's 0.56, and
// was not recalibrated: every converged measurement was made with 14.
constexpr double kCalibratedBendingRigidity = 1.0e-4;
constexpr double kCalibratedTension = 14.0;

// The default setting is that of convergence_default.toml (issue 13 §1, §4: the grid, step, scheme and
// box checks pass at 0.6-0.8 Hz): ν = 5e-5 m²/s, the 0.3 s activation pulse, Peskin's kernel at the
// bell's 4 mm, 256 segments, 1 mm cells, the force added after the advection at 0.000625 s, in a 0.25 m
// by 0.36 m box with the aperture 0.18 m above its floor (convergence_box_default.toml). In the
// afternoon of 2026-12-03 the box was 0.3 m tall, 1.3% short of a 0.4 m by 0.6 m box at 0.6 Hz
// (convergence_short_box.toml); before that the step was 0.00125 s, first in a square
// 0.3 m box with the aperture at 0.09 m, whose floor pushed the bell 2.9% farther at 0.6 Hz, then in the
// 0.3 m tall box, where it missed the 0.6 Hz grid check (+5.8%). From 2026-11-29 to 2026-12-03 it was the same body
// and fluid with the force before the advection at 0.000625 s in a box 1.5 times as tall
// (convergence.toml's setting; the two meet in their 1 mm step limits within 0.1-1.4%); until 2026-11-29
// ν = 1.304e-5, the Hermite curve at T_max 5, the hat kernel, segments following the grid, 2 mm cells in
// a 0.4 m box at 0.00125 s. The files measured on an earlier setting pin it in their [params].

// bell_segments = 0 follows the grid: the fewest even segments whose drawn length is at most
// marker_spacing_cells cells (issue 13: markers about half a cell apart, so that the boundary does
// not leak as the grid is refined; the membrane experiment measures leaks of 23-49% at 2-4 cells).
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
  c.fluid.viscosity_tolerance = r.real("viscosity_tolerance");
  c.fluid.force_stage = *fluid::parse_force_stage(r.text("force_stage"));
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
    work_->values.push_back(s.fluid_work_j_per_m());
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
    fluid::vorticity_at_centres(s.fluid().grid(), s.fluid().walls(), w_);
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
             "hermite shape: staggered: aperture springs expand more slowly than apex springs (§3.3, Fig. 4 right); "
             "unison: all alike. The pulse's counterpart is pulse_stagger"),
      real("stagger", act.stagger, "", 0, 0.99,
           "apex springs expand 1/(1 - stagger) times faster than the aperture's (not given in the paper; see "
           "jellyfish/contraction_curve.hpp)"),
      integer("contraction_knots", std::int64_t(act.knots.size()), 1, kMaxKnots,
              "Hermite knots of the rest-length curve used (knot0_* .. knot{N-1}_*); the paper gives none"),
      real("synaptic_delay_s", act.synaptic_delay_s, "s", 0, 10,
           "Spencer's synaptic delay per muscle pair from the aperture (§3.1); 0 = off"),
      choice("activation_shape", "pulse", {"hermite", "pulse"},
             "pulse (default): sin^2 over pulse_duration_s at each cycle's start, then the elastic bell recoils "
             "freely (Hoover, Porras & Miller 2019); hermite: the §3.3 curve (activation 1 at its lowest knot), whose "
             "tension held through the cycle made the distance a small difference of surge and slide that did not "
             "converge in the grid (convergence_peskin4.toml)"),
      real("pulse_duration_s", act.pulse_duration_s, "s", 1e-4, 100, "pulse shape: length of the contraction pulse"),
      real("pulse_stagger", act.pulse_stagger, "", 0, 0.99,
           "pulse shape: staggered expansion (§3.3, Fig. 4 right): the apex muscle's release, the pulse's falling half, "
           "runs 1/(1 - pulse_stagger) times faster than the aperture's, so the apex relaxes first; 0 = every muscle "
           "alike (unison; expansion and stagger shape the Hermite curve only). stagger.toml compares 0.5 with 0"),
      integer("active_cycles", 0, 0, 100000,
              "cycles with activation, 0 = all; 1 with a short pulse is a pluck (natural_frequency.toml)"),
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
              "springs along the subumbrella (even, >= 8; apex in the middle); 0 = follow the grid: the fewest "
              "with markers at most marker_spacing_cells apart. The body is defined by continuum properties, so "
              "refining it refines the same bell (issue 13). 256 by default: markers 0.25 cells apart on 1 mm and "
              "0.5 on 0.5 mm, so the grid study refines the fluid around one discretised body. On 1 mm 128 / 256 "
              "/ 512 segments give 1.642 / 1.595 / 1.574 mm per cycle at 0.7 Hz (512 within 1.6% of 256 at "
              "0.6-0.8 Hz) and stroke amplitudes 0.313 / 0.301 / 0.295 (512 1.2-2.5% below 256, still falling; "
              "convergence_segments.toml)"),
      real("marker_spacing_cells", 0.5, "", 0.05, 4,
           "bell_segments = 0: largest marker spacing in cells (immersed boundaries want <= 1; 0.5 is Peskin 2002's "
           "rule and keeps the membrane's leak small, membrane.toml)"),
      real("bell_modulus_pa", bell.bell_modulus_pa, "Pa", 1e-6, 1e12, "bell mesoglea, λ = 1186 Pa (Fig. 12); k = E t / L"),
      real("bending_rigidity_n_m", kCalibratedBendingRigidity, "N m", 0, 1e6,
           "bending rigidity B per metre of depth; a joint's angular spring is B / L. Calibrated: 1e-4 puts the 4 cm "
           "bell's natural frequency in the 0.6-0.8 Hz of the paper's resonant gait (§3.3, Fig. 5; 0.63 Hz on 200², "
           "frequency_sweep.toml). "
           "Fig. 12's 1.186 N·m/rad has no depth or segment length: read per metre of depth on the 32-segment chain it "
           "is 2.352e-3 (f_n 2.9 Hz); the plate value E t^3/12 of the paper's mesoglea is 6.3e-6"),
      real("stiffness_scale", 1.0, "", 1e-3, 1e3,
           "multiplies bell_modulus_pa and bending_rigidity_n_m together (natural_frequency.toml sweeps it)"),
      choice("muscle_model", "active_tension", {"rest_length", "active_tension"},
             "active_tension: a tension T_max a(t) that the elastic bell re-expands against, so the stroke can resonate "
             "(issue 13); rest_length: muscle springs whose rest length follows the curve (the paper, §3.3; it "
             "prescribes the stroke)"),
      real("muscle_band_fraction", bell.muscle_band_fraction, "", 0.01, 0.99,
           "fraction of the half-arc from the aperture that the muscle band covers (Fig. 4's model: 14 of 16)"),
      real("muscle_modulus_pa", bell.muscle_modulus_pa, "Pa", 1e-6, 1e12, "circumferential muscle, 400 kPa (§3.2)"),
      real("muscle_section_per_arc", bell.muscle_section_per_arc, "", 1e-9, 10,
           "rest_length: muscle cross-section per metre of depth per metre of band arc (not given; a 0.1 mm layer "
           "every two 1.98 mm segments, see jellyfish_params.hpp)"),
      real("muscle_tension_n_per_m2", kCalibratedTension, "N/m^2", 0, 1e9,
           "active_tension: peak tension per metre of depth per metre of band arc. Not given by the paper; calibrated: 14 "
           "with the 0.3 s pulse closes the 4 cm bell to Fig. 3's 0.56 of its diameter at 0.6 Hz and ν = 1.304e-5 "
           "(convergence_pulse.toml); at the default ν = 5e-5 it closes to 0.67 / 0.72 at 0.6 / 0.7 Hz. With the Hermite "
           "curve 5 did (0.53-0.59 at 0.6-0.7 Hz)"),
      boolean("tentacles", bell.tentacles, "passive tentacle chains at the aperture (§3.2)"),
      real("tentacle_length_m", bell.tentacle_length_m, "m", 1e-5, 10, "not given; half a diameter"),
      real("tentacle_area_factor", bell.tentacle_area_factor, "", 1e-9, 10, "Fig. 12: 1/100 of the bell's section"),
  };
  // --- fluid (§3.2, Fig. 12)
  const std::vector<ParamSpec> fluid_specs = fluidBoxSpecs({
      .domain_m = 0.25,
      .domain_doc = "width of the free-slip box (its height is box_aspect times it): 6.25 diameters. The default "
                    "0.25 m by 0.36 m box, the aperture 0.18 m above the floor, is 0.53 / 0.17 / 0.22% below a 0.4 m "
                    "by 0.6 m one (10 diameters, the paper's width, §3.2) in the 1 mm distance per cycle at 0.6 / 0.7 / "
                    "0.8 Hz and the default step, at 3/8 of its cells (convergence_default.toml); the width (0.25 to "
                    "0.4 m) moves it by at most 0.3% (convergence_box_force_after.toml). The depth below the bell "
                    "matters most: with the aperture 0.09 m above the floor (the square 0.3 m box of 2026-12-03) "
                    "the bell swims 2.9 / 0.7 / 1.2% farther",
      .cells_doc = "fluid cells across the box (Fig. 12: 100 in 0.4 m; also 50). 250 by default, 1 mm cells: at "
                   "0.6-0.8 Hz the 0.5 mm grid (dt halved alongside, at the default 0.000625 s) moves the distance "
                   "per cycle by +2.4 / +1.3 / -3.1%, the stroke by +1.3 / +1.3 / +3.1%, 2 mm is 11-15% off "
                   "(convergence_default.toml); at twice the step +5.8 / +2.0 / -1.7%, beyond the 5% check at "
                   "0.6 Hz (in the 0.3 m tall box, convergence_box_force_after.toml)",
      .cells = 250,
      .density_doc = "paper: '1' without units, read as g/cm^3",
      .kinematic_viscosity_m2_per_s = 5e-5,
      .viscosity_doc = "38 times water, Re about 16 for the 4 cm bell (2D IB jellyfish studies run Re 10-300). The "
                       "paper's 1.304e-3 has no units; read as Pa s (water at 10 C) it gives 1.304e-6 m^2/s, Re about 600, "
                       "whose boundary layers (1.4 mm at 0.7 Hz) no affordable grid resolves. 1.304e-5 (Re 60, the "
                       "default until 2026-11-29) does not converge either: 0.5 mm cells move the 1 mm distance per "
                       "cycle by 10-13% with the Hermite drive (convergence_fine.toml) and up to 33% with the pulse "
                       "(convergence_pulse.toml), whose free recoil is damped in a Stokes layer (1.7 mm at 0.7 Hz) under "
                       "two 1 mm cells. At 5e-5 the layer is 3.4 mm: 0.5 and 1 mm agree to 1% (convergence.toml) and "
                       "upwind2_rk2 to 2.6-4.4% of MacCormack on 0.5 mm at 0.6-0.7 Hz, 5.7% at 0.8 Hz, where the two "
                       "schemes' step errors add (at a converged step on 1 mm: 3.5% and 2.9% at 0.7 and 0.8 Hz, "
                       "convergence_step_scheme.toml; on 0.5 mm at half the step 3.8% at 0.8 Hz, "
                       "convergence_fine_step.toml). See dt_s and bell_segments for what is left. 1.304e-6 is one override away",
      .advection_doc = "velocity advection: MacCormack (Selle et al. 2008, second order in space; the default since "
                       "the first-order scheme moved distances 2-5x, issue 13), the paper's semi-Lagrangian (Stam 1999), or "
                       "upwind2_rk2 (Fromm upwind fluxes + Heun, second order, CFL <= 0.5; the scheme change of "
                       "convergence.toml)",
      .advection = "maccormack",
  });
  // --- coupling (§3.2; Peskin 2002)
  const std::vector<ParamSpec> coupling_specs = couplingSpecs({
      .kernel = "peskin4",
      .kernel_doc = "spreading/interpolation: Peskin's 4-point function (default), or the paper's bilinear hat "
                    "(§3.2), stretched to kernel_radius_m; with the hat the coupled bell did not converge in its "
                    "segment count (+11% from 128 to 256 on 2 mm, convergence_fine.toml), with Peskin's it does "
                    "(convergence_peskin4.toml)",
      .mobility_doc = "fluid response assumed by the semi-implicit force: through the markers' stencils "
                      "(ib/coupling.hpp), or each marker alone",
      .kernel_radius_m = 0.004,
      .kernel_radius_doc = "radius of the kernel's support: the bell's thickness (Fig. 12: 4 mm), so the regularised "
                           "boundary is as thick as the umbrella on every grid and a grid study refines one body (with "
                           "the grid's own kernel, 2-4 cells, the distance moved 2-5x per halving, issue 13). A whole "
                           "multiple of the kernel's reach in cells (1 bilinear, 2 peskin4): Peskin's is stretched 1, 2, "
                           "4 times on 2, 1, 0.5 mm cells; a grid too coarse for it keeps its own kernel; 0 = the "
                           "grid's own kernel. Metric kernel_cells",
      .implicit_theta = 0.5,
      .implicit_theta_doc =
          "Default 0.5 since 2026-12-05 (1 before; files measured then pin it): the backward-Euler force is the "
          "leading step error of the coupled bell (on 1 mm at 0.6 Hz halving 0.00125 s moves the distance per cycle "
          "+3.7% at 1, +1.4% at 0.5), so at 0.5 the step doubles (dt_s) and a converged point costs half "
          "(BM_SimulatedSecondDefault: 5.5 against 10.7 CPU s per simulated s on 1 mm). Stable at 0.01 s on the "
          "paper's 100² grid: all 27 points of frequency_sweep_paper_grid.toml ran with implicit_theta = 0.5 "
          "(a probe of 2026-12-04; tests/physics/jellyfish_swim_test.cpp holds 0.2, 0.7 and 1.5 Hz of it)",
  });
  const std::vector<ParamSpec> rest = {
      real("viscosity_tolerance", 1e-8, "", 1e-14, 1e-2,
           "relative residual of the implicit viscous solve (fluid/diffusion2.hpp). 1e-8 since 2026-12-05 (the "
           "fluid's 1e-10 before; files measured then pin it): on the default setting the solve's Chebyshev sweeps "
           "fall from 10 to 8 a step, a point's CPU by about 5% (56.2 against 59.3 s), and the distance per cycle "
           "of a whole 0.7 Hz point moves by 2e-8 relative (1e-7: 4.4e-7; the 44 points of the four default-setting "
           "files at most 9.1e-7), against the step's 0.5-1.4% and the grid's 1.3-3.0%"),
      real("dt_s", 0.00125, "s", 1e-7, 0.1,
           "coupled step, first order in time (ib/coupling.hpp). 0.00125 s since 2026-12-05, with implicit_theta = "
           "0.5; on 1 mm in the default box it gives 1.6822 / 1.4922 / 1.1025 mm per cycle at "
           "0.6 / 0.7 / 0.8 Hz, half of it +1.4 / +0.5 / +0.7%, 2.2 / 0.9 / 1.3% below the Richardson limits, and "
           "every check of the grid study passes with each of its steps doubled (convergence_theta.toml: the grid "
           "halves it with the cell, dt ∝ dx, 0.0025 / 0.00125 / 0.000625 s on 2 / 1 / 0.5 mm). At implicit_theta = "
           "1 (the setting before 2026-12-05, at 0.000625 s) 0.00125 / 0.000625 / 0.0003125 s give 1.6251 / 1.6858 / "
           "1.7067, 1.4781 / 1.4924 / 1.4994 and 1.0882 / 1.1037 / 1.1104 mm per cycle (observed order 1.5, 1.0, "
           "1.2): 0.000625 s lies 1.9 / 0.9 / 1.0% below the limits, 0.00125 s 5.4 / 1.9 / 2.4% "
           "(convergence_default.toml). With the force before the advection (force_stage; the default until "
           "2026-12-03) 0.000625 / 0.0003125 / 0.00015625 s gave 1.5945 / 1.5504 / 1.5334 at 0.7 Hz, 4.7% above its "
           "limit at 0.000625 s (convergence_step_scheme.toml). The paper's 0.01 s is stable with the semi-implicit "
           "step"),
      choice("force_stage", "after_advection", {"before_advection", "after_advection"},
             "where the bell's force enters the fluid step: after the advection (the default since 2026-12-03: the "
             "force a source of the momentum equation, Peskin 2002 §6), or before it (Stam 1999 §2.2, the paper's "
             "order), when MacCormack then carries the force's velocity increment before the projection removes its "
             "gradient part. Both are first order in dt; on 1 mm at 0.7 Hz, 0.0025 / 0.00125 / "
             "0.000625 s give 1.438 / 1.492 / 1.506 mm per cycle with the force after (observed order 1.9, limit "
             "1.512) and 1.799 / 1.665 / 1.595 with it before (order 1, limit 1.523; probes of 2026-12-03 and "
             "convergence_step_scheme.toml in the tall box); in the default box at 0.000625 s and below the force after "
             "shows order 1.0-1.5 at 0.6-0.8 Hz (dt_s; in the 0.3 m tall box 0.83-1.3)"),
      real("blowup_speed_m_per_s", 5.0, "m/s", 1e-6, 1e6, "fluid speed taken as a blow-up (100x the swimming flow)"),
      real("start_y_fraction", 0.5, "", 0.05, 0.95,
           "aperture's starting height in the box (the bell swims up, its wake goes down): 0.18 m above the floor "
           "in the default box. At 0.09 m (0.3 in the square 0.3 m box of "
           "2026-12-03, 0.2 in the tall one before it) the floor pushes the bell 2.9% farther at 0.6 Hz; at 0.18 m "
           "with 0.27 m above (a 0.45 m tall box) it is within 0.1% of a 0.4 m by 0.6 m box "
           "(convergence_box_force_after.toml, at 0.00125 s). 0.6 in the 0.3 m tall box, the default until the "
           "evening of 2026-12-03"),
      real("box_aspect", 1.44, "", 0.25, 8,
           "box height / width (domain_m is the width); cells * box_aspect must be whole (with the default 1.44: "
           "cells a multiple of 25). The default box is 0.36 m tall, 0.18 m of water above the aperture, where "
           "the bell swims 9-11 mm in its window at 0.6-0.8 Hz: at the default step it lies -0.53 / -0.17 / "
           "-0.22% from a 0.4 m by 0.6 m box in distance per cycle at 0.6 / 0.7 / 0.8 Hz, where the 0.3 m tall "
           "box (1.2, the default until the evening of 2026-12-03, 0.12 m above the aperture) lay -1.3 / -0.3 / "
           "-0.5%, beyond the 1% bound at 0.6 Hz (convergence_short_box.toml); 0.195 and 0.22 m above change "
           "it by 0.04% more (convergence_box_default.toml). A fast swimmer needs a taller box to swim its "
           "whole window without meeting the top wall"),
      // --- measurement
      real("warmup_cycles", 1.0, "", 0, 1000, "cycles before the measured window"),
      real("duration_s", 10.0, "s", 1e-6, 1e6,
           "measured window, the same for every frequency. When contraction_hz x duration_s is not whole the "
           "window ends part way through a cycle and distance_m carries that part's surge or slide (at 0.65 Hz, "
           "6.5 cycles in 10 s, the pulse-driven bell's was 14.33 mm against 10.84 and 11.65 at 0.6 and 0.7 Hz, "
           "twice frequency_sweep_viscous's step): compare frequencies by cycle_speed_m_per_s, which counts "
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
       "stiff muscle, which falls in proportion to dt (0.51, 0.25, 0.13 J/m at dt 0.01, 0.005, 0.0025 s at 0.7 Hz)"},
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
// cycle of the window to the last, relative to the window's distance per cycle. On 1 mm the cycles
// trend through the 10 s window rather than scatter (the viscous time D² / ν of the 4 cm bell is
// 32 s at the default ν): 0.6 Hz rises 1.38 -> 1.99 mm, 0.8 Hz falls 1.52 -> 1.04 mm, and
// cycleSpread then measures that trend, not a noise.
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
        start_work = swimmer.muscle_work_j_per_m();
        start_fluid = swimmer.fluid_work_j_per_m();
      }
      if (step == plan.work_end_step) {
        cycles_end_y = o.centroid_m.y;
        end_work = swimmer.muscle_work_j_per_m();
        end_fluid = swimmer.fluid_work_j_per_m();
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
