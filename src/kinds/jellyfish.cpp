#include "kinds/jellyfish.hpp"

#include <cmath>
#include <exception>
#include <limits>

#include "fluid/diagnostics2.hpp"
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

jellyfish::SwimmerConfig config(const ParamReader& r) {
  jellyfish::SwimmerConfig c;
  auto& b = c.bell;
  b.diameter_m = r.real("bell_diameter_m");
  b.height_m = r.real("bell_height_m");
  b.thickness_m = r.real("bell_thickness_m");
  b.segments = int(r.integer("bell_segments"));
  b.bell_modulus_pa = r.real("bell_modulus_pa");
  b.angular_stiffness_nm_per_rad = r.real("angular_stiffness_nm_per_rad");
  b.muscle_modulus_pa = r.real("muscle_modulus_pa");
  b.muscle_thickness_m = r.real("muscle_thickness_m");
  b.muscle_pairs = int(r.integer("muscle_pairs"));
  b.muscle_stride = int(r.integer("muscle_stride"));
  b.tentacles = r.boolean("tentacles");
  b.tentacle_length_m = r.real("tentacle_length_m");
  b.tentacle_area_factor = r.real("tentacle_area_factor");

  auto& a = c.activation;
  a.contraction_hz = r.real("contraction_hz");
  a.knots = knots(r);
  a.expansion = r.text("expansion") == "unison" ? jellyfish::Expansion::unison : jellyfish::Expansion::staggered;
  a.stagger = r.real("stagger");
  a.synaptic_delay_s = r.real("synaptic_delay_s");

  c.fluid = fluidBoxParams(r);
  c.coupling = couplingParams(r);
  c.fluid.viscosity_tolerance = r.real("viscosity_tolerance");
  c.dt_s = r.real("dt_s");
  c.start_y_fraction = r.real("start_y_fraction");
  return c;
}

// Times of a run: warm-up cycles, then the measured window; every time lands on a step.
struct Schedule {
  long warmup_steps = 0;
  long total_steps = 0;
  long work_end_step = 0;  // end of the last whole cycle in the window (muscle work is per whole cycles)
  long steps_per_frame = 1;
  long steps_per_field = 0;  // 0: no fields
};

Schedule schedule(const ParamReader& r) {
  const double dt = r.real("dt_s");
  Schedule s;
  s.warmup_steps = std::lround(r.real("warmup_cycles") / r.real("contraction_hz") / dt);
  s.total_steps = s.warmup_steps + std::lround(r.real("duration_s") / dt);
  const double whole_cycles = std::floor(r.real("duration_s") * r.real("contraction_hz") + 1e-9);
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
  Tracks *markers_, *tracers_;
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
             "staggered: aperture springs expand more slowly than apex springs (§3.3, Fig. 4 right); unison: all alike"),
      real("stagger", act.stagger, "", 0, 0.99,
           "apex springs expand 1/(1 - stagger) times faster than the aperture's (not given in the paper; see "
           "jellyfish/contraction_curve.hpp)"),
      integer("contraction_knots", std::int64_t(act.knots.size()), 1, kMaxKnots,
              "Hermite knots of the rest-length curve used (knot0_* .. knot{N-1}_*); the paper gives none"),
      real("synaptic_delay_s", act.synaptic_delay_s, "s", 0, 10,
           "Spencer's synaptic delay per muscle pair from the aperture (§3.1); 0 = off"),
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
      integer("bell_segments", bell.segments, 8, 512,
              "springs along the subumbrella (even; apex in the middle). Refining it keeps the body only with "
              "muscle_stride and angular_stiffness_nm_per_rad scaled alike (x2 each for 64: convergence.toml)"),
      real("bell_modulus_pa", bell.bell_modulus_pa, "Pa", 1e-6, 1e12, "bell mesoglea, λ = 1186 Pa (Fig. 12); k = E t / L"),
      real("angular_stiffness_nm_per_rad", bell.angular_stiffness_nm_per_rad, "N m/rad", 0, 1e6,
           "per joint, per metre of depth (Fig. 12: 1.186 N·m/rad, depth not given)"),
      real("muscle_modulus_pa", bell.muscle_modulus_pa, "Pa", 1e-6, 1e12, "circumferential muscle, 400 kPa (§3.2)"),
      real("muscle_thickness_m", bell.muscle_thickness_m, "m", 1e-9, 1,
           "muscle layer thickness (not given; 0.1 mm, see jellyfish_params.hpp)"),
      integer("muscle_pairs", bell.muscle_pairs, 1, 256, "muscle springs across the bell (Fig. 4)"),
      integer("muscle_stride", bell.muscle_stride, 1, 64, "markers between muscle springs, from the aperture"),
      boolean("tentacles", bell.tentacles, "passive tentacle chains at the aperture (§3.2)"),
      real("tentacle_length_m", bell.tentacle_length_m, "m", 1e-5, 10, "not given; half a diameter"),
      real("tentacle_area_factor", bell.tentacle_area_factor, "", 1e-9, 10, "Fig. 12: 1/100 of the bell's section"),
  };
  // --- fluid (§3.2, Fig. 12)
  const std::vector<ParamSpec> fluid_specs = fluidBoxSpecs({
      .domain_m = 0.4,
      .domain_doc = "side of the square free-slip box: ten diameters (§3.2)",
      .cells_doc = "fluid cells per side (Fig. 12: 100; also 50). Distances over several cycles converge in dt_s "
                   "only from 200: experiments/jellyfish/convergence.toml",
      .density_doc = "paper: '1' without units, read as g/cm^3",
      .kinematic_viscosity_m2_per_s = 1.304e-6,
      .viscosity_doc = "paper: 1.304e-3 without units, read as Pa s (water at 10 C) over 1000 kg/m^3",
      .advection_doc = "velocity advection: the paper's semi-Lagrangian (Stam 1999) or MacCormack",
  });
  // --- coupling (§3.2; Peskin 2002)
  const std::vector<ParamSpec> coupling_specs = couplingSpecs({
      .kernel = "peskin4",
      .kernel_doc = "spreading/interpolation: Peskin's 4-point kernel (default: at dt 0.01 s the semi-implicit step "
                    "keeps the bell smooth only with it, ib/coupling.hpp) or the paper's bilinear 4-face stencil "
                    "(§3.2)",
      .mobility_doc = "fluid response assumed by the semi-implicit force: through the markers' stencils "
                      "(ib/coupling.hpp), or each marker alone",
  });
  const std::vector<ParamSpec> rest = {
      real("viscosity_tolerance", fluid::FluidParams{}.viscosity_tolerance, "", 1e-14, 1e-2,
           "relative residual of the implicit viscous solve (fluid/diffusion2.hpp); raising it perturbs the flow "
           "slightly, a test of how sensitive a distance over several cycles is"),
      real("dt_s", 0.01, "s", 1e-7, 0.1,
           "coupled step (the paper: unstable near 0.01 s explicitly; the semi-implicit step is stable at 0.01 s). "
           "Distances over several cycles: on 100² not converged in it, on 200² to a few mm from 0.0025 s "
           "(experiments/jellyfish/convergence.toml)"),
      real("blowup_speed_m_per_s", 5.0, "m/s", 1e-6, 1e6, "fluid speed taken as a blow-up (100x the swimming flow)"),
      real("start_y_fraction", 0.25, "", 0.05, 0.95, "aperture's starting height in the box (the bell swims up)"),
      // --- measurement
      real("warmup_cycles", 1.0, "", 0, 1000, "cycles before the measured window"),
      real("duration_s", 10.0, "s", 1e-6, 1e6, "measured window, the same for every frequency"),
      real("frame_rate_hz", 25.0, "Hz", 1e-3, 1e4, "series and marker frames"),
      boolean("store_fields", false, "store vorticity fields (frames × ny × nx) with an XDMF sidecar"),
      real("field_rate_hz", 10.0, "Hz", 1e-3, 1e4, "field frames per second when store_fields"),
      integer("tracers_per_side", 0, 0, 200, "trace particles on an n x n lattice around the bell (Fig. 6)"),
  };
  for (const auto* specs : {&bell_specs, &fluid_specs, &coupling_specs, &rest})
    params_.insert(params_.end(), specs->begin(), specs->end());
  metrics_ = {
      {"distance_m", "m", "axial (+y) displacement of the bell's centroid over the measured window"},
      {"distance_per_cycle_m", "m", "distance_m / cycles in the window"},
      {"mean_speed_m_per_s", "m/s", "distance_m / duration_s"},
      {"min_diameter_ratio", "", "smallest aperture width / drawn width in the window"},
      {"lateral_drift_m", "m", "x displacement of the centroid over the window"},
      {"muscle_work_j", "J/m",
       "muscles' net work over the whole cycles of the window, per metre of depth: the work the body did on the "
       "fluid, sum F . dX (the body has no internal dissipation, so over periodic cycles the muscles' work goes "
       "to the fluid); converged in dt"},
      {"muscle_work_direct_j", "J/m",
       "the same from -sum T dr (tension x rest-length shortening): adds the semi-implicit step's damping of the "
       "stiff muscle, which falls in proportion to dt (0.51, 0.25, 0.13 J/m at dt 0.01, 0.005, 0.0025 s at 0.7 Hz)"},
      {"cost_of_transport", "J/(kg m)",
       "muscle_work_j / (bell mass per metre x distance over those cycles at the window's mean rate); NaN if distance <= 0"},
      {"cycles", "", "contraction cycles in the measured window"},
      {"max_cfl", "", "largest max(|u|,|v|) dt / dx of any step"},
      {"max_marker_speed_m_per_s", "m/s", "largest marker speed of any step"},
      {"markers", "", "immersed-boundary markers (bell + tentacles)"},
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
  if (3 * r.real("bell_diameter_m") > r.real("domain_m"))
    return "the box (domain_m) must be at least three bell diameters wide";
  if (r.real("dt_s") > r.real("duration_s")) return "dt_s is longer than duration_s";
  return "";
}

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
  if (plan.warmup_steps == 0) start = swimmer.observe();
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
        end_work = swimmer.muscle_work_j_per_m();
        end_fluid = swimmer.fluid_work_j_per_m();
      }
      if (step > plan.warmup_steps) min_ratio = std::min(min_ratio, o.diameter_ratio);
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
  const double work_cycles = std::round((plan.work_end_step - plan.warmup_steps) * dt * r.real("contraction_hz"));
  const double work_distance = distance / cycles * std::max(1.0, work_cycles);
  const double work = end_work - start_work;
  const double fluid_work = end_fluid - start_fluid;
  const double bell_mass = r.real("density_kg_per_m3") * swimmer.body().model().bell_area_m2;
  auto& m = result.metrics;
  m["distance_m"] = {distance, "m"};
  m["distance_per_cycle_m"] = {distance / cycles, "m"};
  m["mean_speed_m_per_s"] = {distance / duration, "m/s"};
  m["min_diameter_ratio"] = {min_ratio, ""};
  m["lateral_drift_m"] = {end.centroid_m.x - start.centroid_m.x, "m"};
  m["muscle_work_j"] = {end_fluid - start_fluid, "J/m"};
  m["muscle_work_direct_j"] = {work, "J/m"};
  m["cost_of_transport"] = {distance > 0 ? fluid_work / (bell_mass * work_distance) : std::nan(""), "J/(kg m)"};
  m["cycles"] = {cycles, ""};
  m["max_cfl"] = {max_cfl, ""};
  m["max_marker_speed_m_per_s"] = {max_speed, "m/s"};
  m["markers"] = {double(swimmer.markers_m().size()), ""};
  m["steps"] = {double(plan.total_steps), ""};
  return result;
}

}  // namespace creaturelab::kinds
