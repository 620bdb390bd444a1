#include "kinds/web.hpp"

#include <cmath>
#include <sstream>

#include "kinds/spring_run.hpp"
#include "springs/equilibrium.hpp"
#include "web/build.hpp"
#include "web/measure.hpp"
#include "web/web_run.hpp"
#include "web/wind_gen.hpp"

namespace creaturelab::kinds {
namespace {

using web::Point2;

// A regular polygon, first corner at the top, circumradius 0.5 m (a web about 1 m across).
std::vector<Point2> regularFrame(int corners) {
  std::vector<Point2> p;
  for (int k = 0; k < corners; ++k) {
    const double a = M_PI / 2 + 2 * M_PI * k / corners;
    p.emplace_back(0.5 * std::cos(a), 0.5 * std::sin(a));
  }
  return p;
}

// "x,y; x,y; ..." in metres. Returns "" or what is wrong.
std::string parsePoints(const std::string& text, std::vector<Point2>& out) {
  std::stringstream all(text);
  std::string item;
  while (std::getline(all, item, ';')) {
    if (item.find_first_not_of(" \t") == std::string::npos) continue;
    double x = 0, y = 0;
    char comma = 0, tail = 0;
    std::stringstream one(item);
    if (!(one >> x >> comma >> y) || comma != ',' || (one >> tail))
      return "attachment_points_m: '" + item + "' is not 'x,y' (metres); write \"x1,y1; x2,y2; ...\"";
    out.emplace_back(x, y);
  }
  return "";
}

std::string framePoints(const ParamReader& r, std::vector<Point2>& points) {
  if (!r.text("attachment_points_m").empty()) {
    if (std::string err = parsePoints(r.text("attachment_points_m"), points); !err.empty()) return err;
  } else {
    const std::string& shape = r.text("frame_shape");
    points = shape == "triangle" ? regularFrame(3)
             : shape == "square" ? regularFrame(4)
             : shape == "hexagon" ? regularFrame(6)
             : shape == "decagon" ? regularFrame(10)
                                  : web::defaultAttachmentPointsM();
  }
  for (auto& p : points) p *= r.real("frame_scale");
  return "";
}

web::WebParams webParams(const ParamReader& r, std::string& error) {
  web::WebParams w;
  error = framePoints(r, w.attachment_points_m);
  w.move_outer_m = r.real("move_outer_m");
  w.outer_frame_placement_m = r.real("outer_frame_placement_m");
  w.outer_frame_rest_length_m = r.real("outer_frame_rest_length_m");
  w.outer_frame_k_n_per_m = r.real("outer_frame_k_n_per_m");
  w.frame_placement_m = r.real("frame_placement_m");
  w.frame_rest_length_m = r.real("frame_rest_length_m");
  w.frame_k_n_per_m = r.real("frame_k_n_per_m");
  w.inner_frame_inward_force_n_per_m = r.real("inner_frame_inward_force_n_per_m");
  w.spoke_placement_m = r.real("spoke_placement_m");
  w.spoke_rest_length_m = r.real("spoke_rest_length_m");
  w.spoke_k_n_per_m = r.real("spoke_k_n_per_m");
  w.primary_spoke_end =
      r.text("primary_spoke_end") == "farthest" ? web::PrimarySpokeEnd::farthest : web::PrimarySpokeEnd::opposite;
  w.hub_radius_m = r.real("hub_radius_m");
  w.secondary_spoke_stride = int(r.integer("secondary_spoke_stride"));
  w.spiral_placement_m = r.real("spiral_placement_m");
  w.spiral_rest_length_m = r.real("spiral_rest_length_m");
  w.spiral_k_n_per_m = r.real("spiral_k_n_per_m");
  w.spiral_density = int(r.integer("spiral_density"));
  w.spiral_free_masses = int(r.integer("spiral_free_masses"));
  w.spiral_jitter = r.real("spiral_jitter");
  if (r.real("overextension") > 0) w.overextension = r.real("overextension");
  w.particle_mass_kg = r.real("particle_mass_kg");
  w.air_drag_ns_per_m = r.real("drag_ns_per_m");
  w.gravity_m_per_s2 = r.real("gravity_m_per_s2");
  w.seed = std::uint64_t(r.integer("seed"));
  return w;
}

}  // namespace

WebKind::WebKind() {
  const web::WebParams d;  // the construction's documented defaults (src/web/web_params.hpp)
  params_ = {
      choice("frame_shape", "default", {"default", "triangle", "square", "hexagon", "decagon"},
             "attachment points: an irregular 7-point frame 1.07 m across, or a regular polygon 1 m across (Fig. 5.18)"),
      text("attachment_points_m", "", "m", "custom attachment points \"x1,y1; x2,y2; ...\" (3 to 10); overrides frame_shape"),
      real("frame_scale", 1.0, "", 0.05, 20, "scales the attachment points (web size, thesis Fig. 5.17)"),
      real("move_outer_m", d.move_outer_m, "m", 1e-4, 10, "MOVE_OUTER: anchor to inner-frame corner (Fig. 5.5; thesis gives none)"),
      real("outer_frame_placement_m", d.outer_frame_placement_m, "m", 1e-5, 1, "outer frame spacing as laid (Fig. 5.5: 5 units)"),
      real("outer_frame_rest_length_m", d.outer_frame_rest_length_m, "m", 1e-5, 1, "outer frame rest length (Fig. 5.5: 2 units)"),
      real("outer_frame_k_n_per_m", d.outer_frame_k_n_per_m, "N/m", 1e-9, 1e3,
           "outer frame k; thesis 0.001 collapses the web in SI (see src/web/web_params.cpp)"),
      real("frame_placement_m", d.frame_placement_m, "m", 1e-5, 1, "inner frame spacing as laid (Fig. 5.33: 20 mm)"),
      real("frame_rest_length_m", d.frame_rest_length_m, "m", 1e-5, 1, "inner frame rest length (Fig. 5.33: 15 mm)"),
      real("frame_k_n_per_m", d.frame_k_n_per_m, "N/m", 1e-9, 1e3,
           "inner frame k; thesis 0.001 collapses the web in SI (see src/web/web_params.cpp)"),
      real("inner_frame_inward_force_n_per_m", d.inner_frame_inward_force_n_per_m, "N/m", 0, 1,
           "inward radial force on the inner frame per metre (Fig. 5.8; thesis gives none)"),
      real("spoke_placement_m", d.spoke_placement_m, "m", 1e-5, 1, "spoke spacing as laid (Fig. 5.28: 7 mm)"),
      real("spoke_rest_length_m", d.spoke_rest_length_m, "m", 1e-5, 1, "spoke rest length (§5.2.1, Fig. 5.28: 3 mm)"),
      real("spoke_k_n_per_m", d.spoke_k_n_per_m, "N/m", 1e-9, 1e3, "radial spoke k (§5.2.1: 0.01 N/m)"),
      choice("primary_spoke_end", "opposite", {"opposite", "farthest"},
             "primary spoke to the frame mass opposite through the centre, or the literal farthest mass (Fig. 5.10)"),
      real("hub_radius_m", d.hub_radius_m, "m", 1e-4, 1, "hub ring radius (Fig. 5.11; thesis gives none)"),
      integer("secondary_spoke_stride", d.secondary_spoke_stride, 1, 1000, "a secondary spoke from every n-th inner-frame mass"),
      real("spiral_placement_m", d.spiral_placement_m, "m", 1e-5, 1, "spiral spacing as laid (thesis gives none)"),
      real("spiral_rest_length_m", d.spiral_rest_length_m, "m", 1e-5, 1, "spiral rest length (thesis gives none)"),
      real("spiral_k_n_per_m", d.spiral_k_n_per_m, "N/m", 1e-9, 1e3,
           "spiral k; thesis 0.01 makes the radii zigzag (see src/web/web_params.cpp)"),
      integer("spiral_density", d.spiral_density, 1, 1000, "SPIRAL_DENSITY of the processed spiral (Fig. 5.16: 5)"),
      integer("spiral_free_masses", d.spiral_free_masses, 1, 1000,
              "masses at the hub end of each radius left without spiral (§5.2 'a little distance away from the hub')"),
      real("spiral_jitter", d.spiral_jitter, "", 0, 1, "randomness of the spiral (§5.2: 'a small amount of randomness')"),
      real("overextension", 0.0, "", 0, 10, "if > 0, every rest length = placement / (1 + this) (§5.1: 0.75-2.5)"),
      real("particle_mass_kg", d.particle_mass_kg, "kg", 1e-15, 1, "particle mass (§5.2.1: 10 ug)"),
      real("drag_ns_per_m", d.air_drag_ns_per_m, "N*s/m", 0, 1, "air friction (§5.2.1: 1e-8 N s/m)"),
      real("gravity_m_per_s2", d.gravity_m_per_s2, "m/s^2", 0, 1000, "gravity along -y (the web hangs in the x-y plane)"),
      integer("seed", std::int64_t(d.seed), 0, std::int64_t(1) << 62, "seed of every random choice (spiral, hub links, wind)"),
      choice("start", "laid", {"laid", "static"},
             "start from the web as laid, or from its static equilibrium (for wind)"),
      choice("integrator", "rk4", {"euler", "symplectic_euler", "rk4", "implicit_euler"}, "time integrator (thesis: rk4)"),
      realOrAuto("dt_s", "s", 1e-9, 1, "substep; \"auto\" = auto_safety times the stability limit"),
      real("auto_safety", web::kAutoStepSafety, "", 1e-3, 1,
           "fraction of the stability limit (from an upper bound on omega_max) that dt_s = \"auto\" uses"),
      real("frame_interval_s", 0.02, "s", 1e-6, 10, "output frame (thesis §5.2.1 'time step' 0.02 s)"),
      real("end_time_s", 10.0, "s", 0, 1e5, "simulated time; 0 = build and solve the statics only"),
      real("settling_fraction", 1e-4, "", 1e-12, 1, "settled when kinetic energy stays below this fraction of its peak"),
      real("lagrangian_interval_s", 1.0, "s", 1e-6, 1e5, "interval between stored particle positions"),
      real("wind_scale", 0.0, "", 0, 1e6, "wind of Fig. 5.45 times this (1 = WIND = m g 10); 0 = no wind"),
  };
  metrics_ = {
      {"particles", "", "particles, anchors included"},
      {"springs", "", "springs"},
      {"spokes", "", "radii (a primary spoke counts twice)"},
      {"spiral_segments", "", "spiral strands"},
      {"spiral_coverage", "", "spiral annulus area over the inner frame's disc, as laid (§5.3.4)"},
      {"silk_length_m", "m", "sum of rest lengths (thesis ch. 3: 20-60 m)"},
      {"web_mass_kg", "kg", "sum of particle masses"},
      {"hub_sag_m", "m", "hub drop from the laid web at the end of the run"},
      {"static_hub_sag_m", "m", "hub drop in the static Newton equilibrium"},
      {"static_sag_rel_diff", "", "|hub_sag_m - static_hub_sag_m| / static_hub_sag_m"},
      {"static_iterations", "", "Newton iterations of the static solve (NaN: did not converge)"},
      {"max_strain", "", "largest (length - rest) / rest at the end"},
      {"settling_time_s", "s", "earliest time after which kinetic energy stays below settling_fraction of its peak"},
      {"elongation_outer_frame", "", "mean (length - rest) / rest of outer-frame springs at the end"},
      {"elongation_inner_frame", "", "mean (length - rest) / rest of inner-frame springs at the end"},
      {"elongation_radial", "", "mean (length - rest) / rest of primary and secondary spoke springs at the end"},
      {"elongation_spiral", "", "mean (length - rest) / rest of spiral springs at the end"},
      {"hub_rms_displacement_m", "m", "rms over frames of the hub's distance from its starting position"},
      {"dt_used_s", "s", "the substep used"},
  };
}

std::string WebKind::doc() const {
  return "an orb web built strand by strand and settled (A. Mehla, Modeling and Animation of Orb Webs, MSc thesis "
         "2005, §5.2-5.3)";
}

std::string WebKind::validate(const Params& p) const {
  ParamReader r(p);
  std::string err;
  const web::WebParams w = webParams(r, err);
  if (!err.empty()) return err;
  return w.validate();
}

namespace {

springs::SimulationOptions simulationOptions(const ParamReader& r) {
  springs::SimulationOptions opt;
  opt.integrator = parseIntegratorOrThrow(r.text("integrator"));
  opt.frame_interval_s = r.real("frame_interval_s");
  opt.dt_s = r.isAuto("dt_s") ? 0.0 : r.real("dt_s");
  opt.auto_safety = r.real("auto_safety");
  opt.end_time_s = r.real("end_time_s");
  opt.settling_fraction = r.real("settling_fraction");
  return opt;
}

}  // namespace

// The step at the web as built (the run may start from the static shape instead: omega_max
// changes little between the two, and this is an estimate).
CostEstimate WebKind::estimateCost(const Params& p) const {
  try {
    ParamReader r(p);
    std::string err;
    const web::WebParams w = webParams(r, err);
    if (!err.empty()) return {};
    const springs::SimulationOptions opt = simulationOptions(r);
    if (opt.end_time_s <= 0) return {};
    const web::WebModel model = web::build(w);
    return springRunCost(model.network, model.state, opt, r.text("integrator"));
  } catch (const std::exception&) {
    return {};  // the point itself will say what is wrong
  }
}

namespace {

// The recorded hub sag and positions.
void addWebRun(Result& result, const web::WebRunRecorder& recorder) {
  result.timeseries["hub_sag_m"] = {recorder.hubSag_m(), "m"};
  Tracks& tracks = result.lagrangian["positions_m"];
  tracks.points = recorder.positions().points;
  tracks.dim = 3;
  tracks.time_s = recorder.positions().time_s;
  tracks.data = recorder.positions().data;
}

void addWebMeasures(Result& result, const std::vector<core::NamedValue>& measures) {
  for (const auto& m : measures) result.metrics[m.name] = {m.value, m.unit};
}

// The thesis's wind (web/wind_gen.hpp): WIND = m g 10 x wind_scale.
web::WindGen windGen(const ParamReader& r) {
  return {r.real("particle_mass_kg") * r.real("gravity_m_per_s2") * 10.0 * r.real("wind_scale"),
          std::uint64_t(r.integer("seed"))};
}

// The run's frames from `state`, recorded by `record`; with no time to run, the static shape alone
// (one frame at t = 0, dt_used_s NaN). A divergence fails the point with the frames recorded so far.
template <class Record>
springs::SimulationSummary settle(const springs::System<3>& system, springs::State<3>& state,
                                  const springs::State<3>& statics, const springs::SimulationOptions& opt,
                                  Record&& record, const web::WebRunRecorder& recorder) {
  springs::SimulationSummary summary{};
  if (opt.end_time_s <= 0) {
    state = statics;
    record(0, 0.0, state);
    summary.time_s = {0.0};
    summary.dt_used_s = std::nan("");
    return summary;
  }
  try {
    return springs::simulate<3>(system, state, opt, record);
  } catch (const springs::DivergenceError& e) {
    Result partial;
    addWebRun(partial, recorder);
    throw RunFailure(e.what(), partial);
  }
}

}  // namespace

Result WebKind::run(const Params& p) const {
  ParamReader r(p);
  std::string err;
  const web::WebModel model = web::build(webParams(r, err));
  // The inward frame force is constant (Fig. 5.8), so it belongs to the potential: the static solve
  // includes it and the dynamic settle ends in the same shape. The wind (time-dependent) is external.
  springs::System<3> system(model.network);
  system.setConstantForce(model.external_force_n);
  springs::State<3> statics = model.state;
  const auto eq = springs::solveStaticEquilibrium(system, statics);
  springs::State<3> state = r.text("start") == "static" ? statics : model.state;
  const bool windy = r.real("wind_scale") > 0;
  web::WebWind wind(model, state, windGen(r));
  if (windy) system.setExternalForce([&wind](double, const springs::State<3>&, springs::Points<3>& f) { f += wind.force_n(); });
  web::WebRunRecorder recorder(model, web::hubPositionM(model, state),
                               std::max(1, int(std::lround(r.real("lagrangian_interval_s") / r.real("frame_interval_s")))));
  auto record = [&](int frame, double t, const springs::State<3>& s) {
    recorder.record(frame, t, s);
    if (windy) wind.next();  // windgen once per frame (Fig. 5.45), held until the next
  };
  const springs::SimulationOptions opt = simulationOptions(r);
  const springs::SimulationSummary summary = settle(system, state, statics, opt, record, recorder);
  Result result;
  addWebRun(result, recorder);
  result.timeseries["time_s"] = {summary.time_s, "s"};
  if (opt.end_time_s > 0) result.timeseries["kinetic_energy_j"] = {summary.kinetic_energy_j, "J"};
  addWebMeasures(result, web::webMeasures(model, system.network(), {state, statics, eq, summary.settling_time_s,
                                                                    summary.dt_used_s, recorder.hubRmsDisplacement_m()}));
  result.topology = web::webTopology(model);
  return result;
}

}  // namespace creaturelab::kinds
