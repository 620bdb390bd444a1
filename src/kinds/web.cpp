#include "kinds/web.hpp"

#include <cmath>
#include <sstream>

#include "kinds/spring_run.hpp"
#include "kinds/web_wind.hpp"
#include "springs/equilibrium.hpp"
#include "springs/provot.hpp"
#include "web/build.hpp"
#include "web/measure.hpp"

namespace creaturelab::kinds {
namespace {

using web::Point2;
using web::StrandType;

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

// Mean strain (length - rest) / rest of one family of strands in state s: how elongated the
// strands are (thesis Figs. 5.19-5.23 compare how "elongated" and "taut" each family looks).
double meanElongation(const web::WebModel& m, const springs::State<3>& s, std::initializer_list<StrandType> types) {
  double sum = 0;
  int n = 0;
  for (StrandType t : types) {
    int count = 0;
    for (StrandType u : m.spring_type) count += (u == t);
    sum += web::meanStrain(m, s, t) * count;
    n += count;
  }
  return n ? sum / n : std::nan("");
}

// How much of the web the spiral spans, as laid: the annulus between the spiral's innermost and
// outermost particles (about the hub) over the disc of the inner frame's mean radius. The thesis
// describes its spiral variants by how much of the web they cover (§5.3.4, Figs. 5.24-5.27).
double spiralCoverage(const web::WebModel& m) {
  const Eigen::Vector2d hub(m.hub_centre_m.x(), m.hub_centre_m.y());
  auto radius = [&](int i) { return (m.state.x_m.col(i).head<2>() - hub).norm(); };
  double r_min = HUGE_VAL, r_max = 0, frame = 0;
  for (int s = 0; s < m.network.springCount(); ++s) {
    if (m.spring_type[s] != StrandType::spiral) continue;
    for (int i : {m.network.spring_a[s], m.network.spring_b[s]}) {
      r_min = std::min(r_min, radius(i));
      r_max = std::max(r_max, radius(i));
    }
  }
  for (int i : m.inner_frame_particles) frame += radius(i) / double(m.inner_frame_particles.size());
  return r_max > 0 ? (r_max * r_max - r_min * r_min) / (frame * frame) : 0.0;
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

Result WebKind::run(const Params& p) const {
  ParamReader r(p);
  std::string err;
  const web::WebModel model = web::build(webParams(r, err));
  const auto& c = model.counts;

  // The inward frame force is constant (Fig. 5.8), so it belongs to the potential: the static solve
  // includes it and the dynamic settle ends in the same shape. The wind (time-dependent) is external.
  springs::System<3> system(model.network);
  system.setConstantForce(model.external_force_n);
  springs::State<3> state = model.state;
  springs::State<3> statics = model.state;
  const auto eq = springs::solveStaticEquilibrium(system, statics);
  if (r.text("start") == "static") state = statics;
  const Eigen::Vector3d hub0 = web::hubPositionM(model, state);

  const double wind_scale = r.real("wind_scale");
  WindGen wind{r.real("particle_mass_kg") * r.real("gravity_m_per_s2") * 10.0 * wind_scale,
               std::uint64_t(r.integer("seed"))};
  // exp(distance to the hub / alpha), alpha = web radius * 50 (Fig. 5.45), per particle.
  Eigen::VectorXd wind_weight = Eigen::VectorXd::Ones(state.x_m.cols());
  springs::Points<3> wind_force = springs::Points<3>::Zero(3, state.x_m.cols());  // held for a frame
  if (wind_scale > 0) {
    double radius = 0;
    for (int a : model.attachment_particles)
      radius = std::max(radius, (model.state.x_m.col(a) - web::hubPositionM(model, model.state)).norm());
    for (int i = 0; i < state.x_m.cols(); ++i) wind_weight[i] = std::exp((state.x_m.col(i) - hub0).norm() / (radius * 50));
    system.setExternalForce([&wind_force](double, const springs::State<3>&, springs::Points<3>& f) { f += wind_force; });
  }

  Result result;
  auto& hub_sag = result.timeseries["hub_sag_m"] = {{}, "m"};
  Tracks& tracks = result.lagrangian["positions_m"];
  tracks.points = int(state.x_m.cols());
  tracks.dim = 3;
  const double frame_s = r.real("frame_interval_s");
  const int frames_per_track = std::max(1, int(std::lround(r.real("lagrangian_interval_s") / frame_s)));
  double sum_d2 = 0;
  int frames = 0;
  auto record = [&](int frame, double t, const springs::State<3>& s) {
    hub_sag.values.push_back(web::hubSagM(model, s));
    const double d = (web::hubPositionM(model, s) - hub0).norm();
    sum_d2 += d * d;
    ++frames;
    if (frame % frames_per_track == 0) {
      tracks.time_s.push_back(t);
      tracks.data.insert(tracks.data.end(), s.x_m.data(), s.x_m.data() + s.x_m.size());
    }
    if (wind_scale > 0) {  // windgen once per frame (Fig. 5.45), held until the next
      wind.next();
      for (int i = 0; i < wind_force.cols(); ++i) wind_force.col(i) = wind_weight[i] * Eigen::Vector3d(wind.x, wind.y, wind.z);
    }
  };

  const springs::SimulationOptions opt = simulationOptions(r);
  const double nan = std::nan("");
  std::optional<double> settling;
  double dt_used = nan;
  if (opt.end_time_s > 0) {
    const auto summary = runOrFail(system, state, opt, record, result);
    result.timeseries["time_s"] = {summary.time_s, "s"};
    result.timeseries["kinetic_energy_j"] = {summary.kinetic_energy_j, "J"};
    settling = summary.settling_time_s;
    dt_used = summary.dt_used_s;
  } else {
    state = statics;
    record(0, 0.0, state);
    result.timeseries["time_s"] = {{0.0}, "s"};
  }

  result.metrics["particles"] = {double(c.particles), ""};
  result.metrics["springs"] = {double(c.springs), ""};
  result.metrics["spokes"] = {double(c.spokes), ""};
  result.metrics["spiral_segments"] = {double(c.spiral_segments), ""};
  result.metrics["spiral_coverage"] = {spiralCoverage(model), ""};
  result.metrics["silk_length_m"] = {c.silk_length_m, "m"};
  result.metrics["web_mass_kg"] = {c.web_mass_kg, "kg"};
  result.metrics["hub_sag_m"] = {web::hubSagM(model, state), "m"};
  result.metrics["static_hub_sag_m"] = {eq.converged ? web::hubSagM(model, statics) : nan, "m"};
  result.metrics["static_sag_rel_diff"] = {
      std::fabs(result.metrics["hub_sag_m"].value - result.metrics["static_hub_sag_m"].value) /
          result.metrics["static_hub_sag_m"].value,
      ""};
  result.metrics["static_iterations"] = {eq.converged ? double(eq.iterations) : nan, ""};
  result.metrics["max_strain"] = {springs::maxStrain(system.network(), state), ""};
  result.metrics["settling_time_s"] = {settling.value_or(nan), "s"};
  result.metrics["elongation_outer_frame"] = {meanElongation(model, state, {StrandType::outer_frame}), ""};
  result.metrics["elongation_inner_frame"] = {meanElongation(model, state, {StrandType::inner_frame}), ""};
  result.metrics["elongation_radial"] = {
      meanElongation(model, state, {StrandType::primary_spoke, StrandType::secondary_spoke}), ""};
  result.metrics["elongation_spiral"] = {meanElongation(model, state, {StrandType::spiral}), ""};
  result.metrics["hub_rms_displacement_m"] = {frames ? std::sqrt(sum_d2 / frames) : nan, "m"};
  result.metrics["dt_used_s"] = {dt_used, "s"};

  // Which particles each spring joins and its strand type (web::StrandType order: outer_frame,
  // inner_frame, primary_spoke, hub, secondary_spoke, spiral), so figures can draw and colour it.
  auto& topo = result.topology;
  for (int s = 0; s < model.network.springCount(); ++s) {
    topo["spring_a"].push_back(model.network.spring_a[s]);
    topo["spring_b"].push_back(model.network.spring_b[s]);
    topo["spring_type"].push_back(static_cast<int>(model.spring_type[s]));
  }
  for (int a : model.attachment_particles) topo["attachment_particles"].push_back(a);
  for (int h : model.hub_particles) topo["hub_particles"].push_back(h);
  return result;
}

}  // namespace creaturelab::kinds
