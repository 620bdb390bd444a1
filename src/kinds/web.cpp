#include "kinds/web.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

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

}  // namespace

web::WebParams WebKindParams::webParams() const {
  web::WebParams w = web;
  if (!attachment_points_m.empty()) {
    w.attachment_points_m.clear();
    if (std::string err = parsePoints(attachment_points_m, w.attachment_points_m); !err.empty())
      throw std::invalid_argument(err);
  } else {
    w.attachment_points_m = frame_shape == "triangle" ? regularFrame(3)
                            : frame_shape == "square"  ? regularFrame(4)
                            : frame_shape == "hexagon" ? regularFrame(6)
                            : frame_shape == "decagon" ? regularFrame(10)
                                                       : web::defaultAttachmentPointsM();
  }
  for (auto& p : w.attachment_points_m) p *= frame_scale;
  if (overextension > 0) w.overextension = overextension;
  return w;
}

springs::SimulationOptions WebKindParams::simulationOptions() const {
  springs::SimulationOptions opt;
  opt.integrator = parseIntegratorOrThrow(integrator);
  opt.frame_interval_s = frame_interval_s;
  opt.dt_s = dt_s.is_auto ? 0.0 : dt_s.value;
  opt.auto_safety = auto_safety;
  opt.end_time_s = end_time_s;
  opt.settling_fraction = settling_fraction;
  return opt;
}

std::string WebKindParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  try {
    return webParams().validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

WebKind::WebKind() {
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

// The step at the web as built (the run may start from the static shape instead: omega_max
// changes little between the two, and this is an estimate).
CostEstimate WebKind::estimateCost(const Params& p) const {
  try {
    const WebKindParams q = readParams<WebKindParams>(p);
    const springs::SimulationOptions opt = q.simulationOptions();
    if (opt.end_time_s <= 0) return {};
    const web::WebModel model = web::build(q.webParams());
    return springRunCost(model.network, model.state, opt, q.integrator);
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
web::WindGen windGen(const WebKindParams& q) {
  return {q.web.particle_mass_kg * q.web.gravity_m_per_s2 * 10.0 * q.wind_scale, q.web.seed};
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
  const WebKindParams q = readParams<WebKindParams>(p);
  const web::WebModel model = web::build(q.webParams());
  // The inward frame force is constant (Fig. 5.8), so it belongs to the potential: the static solve
  // includes it and the dynamic settle ends in the same shape. The wind (time-dependent) is external.
  springs::System<3> system(model.network);
  system.setConstantForce(model.external_force_n);
  springs::State<3> statics = model.state;
  const auto eq = springs::solveStaticEquilibrium(system, statics);
  springs::State<3> state = q.start == "static" ? statics : model.state;
  const bool windy = q.wind_scale > 0;
  web::WebWind wind(model, state, windGen(q));
  if (windy) system.setExternalForce([&wind](double, const springs::State<3>&, springs::Points<3>& f) { f += wind.force_n(); });
  web::WebRunRecorder recorder(model, web::hubPositionM(model, state),
                               std::max(1, int(std::lround(q.lagrangian_interval_s / q.frame_interval_s))));
  auto record = [&](int frame, double t, const springs::State<3>& s) {
    recorder.record(frame, t, s);
    if (windy) wind.next();  // windgen once per frame (Fig. 5.45), held until the next
  };
  const springs::SimulationOptions opt = q.simulationOptions();
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
