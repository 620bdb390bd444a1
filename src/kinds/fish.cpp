#include "kinds/fish.hpp"

#include <cmath>
#include <stdexcept>

#include "fish/fish_measure.hpp"
#include "fish/fish_run.hpp"

namespace creaturelab::kinds {
namespace {

const char* kSpec = "../shared/specs/artificial-fish.md";

struct FishSetup {
  fish::FishGeometry geometry;
  fish::UnitParams units;
  fish::SolverParams solver;
  fish::MotorParams motor;
  std::vector<fish::ScheduleItem> schedule;
};

// Throws std::invalid_argument naming the key for what the per-key ranges cannot catch.
FishSetup setupOf(const ParamReader& r) {
  FishSetup s;
  s.geometry.body_length_m = r.real("body_length_m");
  s.units.mass_unit_kg = r.real("mass_unit_kg");
  s.units.stiffness_cross_n_per_m = r.real("stiffness_cross_n_per_m");
  s.units.stiffness_other_n_per_m = r.real("stiffness_other_n_per_m");
  s.units.stiffness_muscle_n_per_m = r.real("stiffness_muscle_n_per_m");
  s.units.damping_ns_per_m = r.real("damping_ns_per_m");
  s.solver.dt_s = r.real("dt_s");
  const std::string scheme = r.text("scheme");
  s.solver.scheme = scheme == "explicit_euler"     ? fish::Scheme::explicit_euler
                    : scheme == "symplectic_euler" ? fish::Scheme::symplectic_euler
                                                   : fish::Scheme::semi_implicit;
  s.solver.water.mu = r.real("water_mu");
  s.solver.water.law = r.text("water_law") == "quadratic" ? fish::WaterLaw::quadratic : fish::WaterLaw::linear;
  s.solver.water.current_m_per_s = {r.real("current_x_m_per_s"), r.real("current_y_m_per_s"), r.real("current_z_m_per_s")};
  s.solver.blowup_strain = r.real("blowup_strain");
  auto& m = s.motor;
  m.contracted_fraction = r.real("contracted_fraction");
  m.r_max = r.real("r_max");
  m.reference_step_s = r.real("reference_step_s");
  m.posterior_lag_rad = r.real("posterior_lag_rad");
  m.turn_amplitude = r.real("turn_amplitude");
  m.turn_rate = r.real("turn_rate");
  m.turn_relax_fraction = r.real("turn_relax_fraction");
  const double speed = r.real("swim_desired_speed");
  if (speed > 0) {
    m.swim = fish::swimFromSpeed(speed, m.r_max);
  } else {
    m.swim = {r.real("swim_amplitude"), r.real("swim_rate"), r.real("swim_amplitude"), r.real("swim_rate")};
  }
  if (auto e = fish::validate(m); !e.empty()) throw std::invalid_argument(e);
  if (auto e = fish::validate(s.geometry, s.units); !e.empty()) throw std::invalid_argument(e);
  if (auto e = fish::validate(s.solver); !e.empty()) throw std::invalid_argument(e);
  try {
    s.schedule = fish::parseSchedule(r.text("schedule"));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("schedule: ") + e.what());
  }
  return s;
}

std::vector<std::int64_t> flat(const std::vector<int>& v) { return {v.begin(), v.end()}; }

}  // namespace

FishKind::FishKind() {
  params_ = {
      text("task", "simulate", "",
           "simulate (run the schedule) | stable_step (bisect the largest step that survives the schedule)"),
      text("schedule", "swim 30", "",
           "controller schedule, \"NAME SECONDS; ...\" with NAME swim | left | right | glide (spec §3)"),
      real("body_length_m", 2.0, "m", 1e-3, 1e3,
           "snout to tail (ours: with the [reimpl] masses, 107 kg, our shape then has about the density of water)"),
      real("mass_unit_kg", 1.1, "kg", 1e-9, 1e9, "mass unit m of the [reimpl] masses (snout 1, rings 6/10/6/1/1, tail 0.15 m)"),
      real("stiffness_cross_n_per_m", 38.0, "N/m", 1e-9, 1e9, "cross units (spec §1 [reimpl])"),
      real("stiffness_other_n_per_m", 30.0, "N/m", 1e-9, 1e9, "other passive units (spec §1 [reimpl])"),
      real("stiffness_muscle_n_per_m", 28.0, "N/m", 1e-9, 1e9, "muscle units (spec §1 [reimpl])"),
      real("damping_ns_per_m", 0.1, "N*s/m", 0, 1e9, "Voigt damping gamma of every unit (spec §1 [reimpl])"),
      real("contracted_fraction", 0.7, "", 1e-6, 1 - 1e-6,
           "fully contracted length / rest length of a muscle (ours: the thesis value is not in text; 0.7 keeps the tail from folding at alpha = 1)"),
      real("water_mu", 100.0, "", 0, 1e9,
           "water force coefficient mu (linear: N*s/m^3; quadratic: N*s^2/m^4). Ours: mu A dt / m = 0.25 on the tail-fin tips, half the explicit limit; 0 = in air"),
      choice("water_law", "linear", {"linear", "quadratic"},
             "f = min(0, -mu A (n.v)) n (linear) or min(0, -mu A |v| (n.v)) n (quadratic, [reimpl]); spec §2"),
      real("current_x_m_per_s", 0.0, "m/s", -1e3, 1e3, "uniform water current, x (still water by default)"),
      real("current_y_m_per_s", 0.0, "m/s", -1e3, 1e3, "uniform water current, y"),
      real("current_z_m_per_s", 0.0, "m/s", -1e3, 1e3, "uniform water current, z"),
      real("dt_s", 0.055, "s", 1e-9, 100, "time step ([reimpl] 0.055 s, spec §2)"),
      choice("scheme", "semi_implicit", {"semi_implicit", "explicit_euler", "symplectic_euler"},
             "time integrator (spec §2: semi-implicit Euler; the explicit ones for the stability comparison)"),
      real("blowup_strain", 2.0, "", 1e-3, 1e3,
           "a unit longer than (1 + this) or shorter than 1/(1 + this) times its undeformed length counts as a blow-up"),
      real("swim_amplitude", 0.7, "", 0, 1, "swim-MC amplitude alpha in (0, 1]: the fraction of full contraction reached (spec §3)"),
      real("swim_rate", 0.004, "", 0, 1,
           "swim-MC rate r in (0, r_max]: rest-length change per reference step as a fraction of the rest length (spec §3)"),
      real("swim_desired_speed", 0.0, "", 0, 1,
           "if > 0: desired speed as a fraction of the top one; alpha = r / r_max = sqrt(it) (ours), overriding swim_amplitude/rate"),
      real("posterior_lag_rad", M_PI / 2, "rad", -100, 100, "phase lag of the posterior swim segment (spec §3 [choose]: pi/2)"),
      real("turn_amplitude", 0.7, "", 0, 1, "turn-MC amplitude alpha in (0, 1]"),
      real("turn_rate", 0.016, "", 0, 1, "turn-MC rate r in (0, r_max] of the contraction"),
      real("turn_relax_fraction", 0.25, "", 0, 1, "turn-MC: relaxation rate / contraction rate (ours: a quick bend, a slow return)"),
      real("r_max", 0.075, "", 1e-9, 1, "the largest rate ([reimpl] 0.075)"),
      real("reference_step_s", 0.055, "s", 1e-9, 100, "the step the rates are defined per (the [reimpl] step)"),
      real("warmup_s", 10.0, "s", 0, 1e6, "speed is measured from this time to the end (the gait settles first)"),
      choice("on_blowup", "fail", {"fail", "record"},
             "fail: a blow-up fails the point (exit 3); record: the run stops there and the step is a metric (air experiment)"),
      integer("frame_every_steps", 1, 1, 1000000, "record a frame every this many steps"),
      real("stable_lo_s", 1e-4, "s", 1e-9, 100, "stable_step: the smallest step tried"),
      real("stable_hi_s", 5.0, "s", 1e-9, 1000, "stable_step: the largest step tried"),
      integer("stable_iterations", 30, 1, 200, "stable_step: bisection steps (on a log scale)"),
  };
  metrics_ = {
      {"body_length_m", "m", "snout to tail"},
      {"mass_kg", "kg", "total mass"},
      {"steps", "", "steps taken"},
      {"speed_body_lengths_per_s", "1/s", "centre-of-mass speed from warmup_s to the end, in body lengths per second"},
      {"speed_m_per_s", "m/s", "the same in metres per second"},
      {"forward_distance_m", "m", "centre-of-mass displacement along the initial heading (+x) over the run"},
      {"lateral_drift_m", "m", "|sideways displacement| of the centre of mass over the run"},
      {"lateral_drift_fraction", "", "lateral_drift_m / forward_distance_m"},
      {"vertical_drift_m", "m", "|vertical displacement| of the centre of mass"},
      {"com_travel_m", "m", "|com(end) - com(0)|"},
      {"com_travel_body_lengths", "", "com_travel_m / body length"},
      {"heading_change_deg", "deg", "heading change over the first turn item (left > 0)"},
      {"turn_path_m", "m", "centre-of-mass path over the first turn item"},
      {"turn_radius_m", "m", "turn_path_m / |heading change|"},
      {"turn_radius_body_lengths", "", "turn_radius_m / body length"},
      {"momentum_drift_rel", "", "max |sum m v - sum m v(0)| / max sum m |v| over the run (conserved when water_mu = 0)"},
      {"blew_up", "", "1 if the run stopped at a blow-up (on_blowup = record)"},
      {"blowup_step", "", "the step that blew up, -1 if none"},
      {"blowup_time_s", "s", "its time, -1 if none"},
      {"max_stable_dt_s", "s", "stable_step: the largest step that survives the schedule"},
  };
}

std::string FishKind::doc() const {
  return std::string("Tu's artificial fish: 23 masses, 91 Voigt units, semi-implicit Euler, swim/turn motor controllers (") +
         kSpec + ")";
}

std::string FishKind::validate(const Params& p) const {
  try {
    ParamReader r(p);
    const std::string task = r.text("task");
    if (task != "simulate" && task != "stable_step") return "task: unknown task \"" + task + "\" (expected simulate or stable_step)";
    setupOf(r);
    if (!(r.real("stable_lo_s") < r.real("stable_hi_s"))) return "stable_lo_s must be below stable_hi_s";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

CostEstimate FishKind::estimateCost(const Params& p) const {
  try {
    ParamReader r(p);
    const FishSetup s = setupOf(r);
    const double steps = std::ceil(fish::scheduleDurationS(s.schedule) / s.solver.dt_s);
    CostEstimate c;
    const double runs = r.text("task") == "stable_step" ? double(r.integer("stable_iterations") + 2) : 1.0;
    c.steps = steps * runs;
    c.memory_bytes = 8.0 * (1 << 20) + steps / double(r.integer("frame_every_steps")) * 8.0 * (fish::kNodes * 3 + 30);
    c.detail = std::to_string(long(steps)) + " steps of " + std::to_string(s.solver.dt_s) + " s" +
               (runs > 1 ? " x " + std::to_string(long(runs)) + " runs" : "");
    return c;
  } catch (const std::exception&) {
    return {};
  }
}

Result FishKind::run(const Params& p) const {
  ParamReader r(p);
  const FishSetup s = setupOf(r);
  const fish::FishModel model = fish::buildFish(s.geometry, s.units);
  const double L = model.body_length_m, nan = std::nan("");
  Result result;
  result.metrics["body_length_m"] = {L, "m"};
  result.metrics["mass_kg"] = {model.totalMassKg(), "kg"};
  for (const char* m : {"max_stable_dt_s"}) result.metrics[m] = {nan, "s"};

  // The model's topology: unit ends and classes, muscles (unit, segment, side), faces.
  {
    std::vector<int> ends, cls, muscles, faces;
    for (int e = 0; e < fish::kUnits; ++e) {
      ends.push_back(model.network.spring_a[e]);
      ends.push_back(model.network.spring_b[e]);
      cls.push_back(int(model.unit_class[e]));
    }
    for (const auto& m : model.muscles) muscles.insert(muscles.end(), {m.unit, m.segment, m.side});
    for (const auto& f : model.faces) faces.insert(faces.end(), f.node.begin(), f.node.end());
    result.topology["unit_nodes"] = flat(ends);
    result.topology["unit_class"] = flat(cls);  // 0 cross, 1 muscle, 2 other
    result.topology["muscles"] = flat(muscles);
    result.topology["faces"] = flat(faces);
  }

  if (r.text("task") == "stable_step") {
    const auto st = fish::largestStableStep(model, s.solver, s.motor, s.schedule, r.real("stable_lo_s"),
                                            r.real("stable_hi_s"), int(r.integer("stable_iterations")));
    result.metrics["max_stable_dt_s"] = {st.dt_s, "s"};
    result.timeseries["time_s"] = {{0.0}, "s"};
    return result;
  }

  fish::RunOptions opt;
  opt.frame_every_steps = int(r.integer("frame_every_steps"));
  const fish::FishRecord rec = fish::runSchedule(model, s.solver, s.motor, s.schedule, opt);

  result.timeseries["time_s"] = {rec.time_s, "s"};
  const int n = rec.frames();
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> c(n), mom(n);
    for (int f = 0; f < n; ++f) c[f] = rec.com_m[3 * f + axis], mom[f] = rec.momentum_kg_m_per_s[3 * f + axis];
    const std::string xyz(1, char('x' + axis));
    result.timeseries["com_" + xyz + "_m"] = {c, "m"};
    result.timeseries["momentum_" + xyz + "_kg_m_per_s"] = {mom, "kg*m/s"};
  }
  result.timeseries["heading_rad"] = {rec.heading_rad, "rad"};
  Tracks& nodes = result.lagrangian["nodes_m"];
  nodes.time_s = rec.time_s;
  nodes.data = rec.nodes_m;
  nodes.points = fish::kNodes;
  nodes.dim = 3;
  Tracks& muscles = result.lagrangian["muscle_rest_m"];
  muscles.time_s = rec.time_s;
  muscles.data = rec.muscle_rest_m;
  muscles.points = fish::kMuscles;
  muscles.dim = 1;

  const fish::SwimMeasures sw = fish::measureSwim(rec, L, r.real("warmup_s"));
  const fish::TurnMeasures tu = fish::measureTurn(rec, s.schedule);
  result.metrics["steps"] = {double(rec.steps), ""};
  result.metrics["speed_body_lengths_per_s"] = {sw.speed_body_lengths_per_s, "1/s"};
  result.metrics["speed_m_per_s"] = {sw.speed_m_per_s, "m/s"};
  result.metrics["forward_distance_m"] = {sw.forward_distance_m, "m"};
  result.metrics["lateral_drift_m"] = {sw.lateral_drift_m, "m"};
  result.metrics["lateral_drift_fraction"] = {sw.lateral_drift_fraction, ""};
  result.metrics["vertical_drift_m"] = {sw.vertical_drift_m, "m"};
  result.metrics["com_travel_m"] = {sw.com_travel_m, "m"};
  result.metrics["com_travel_body_lengths"] = {sw.com_travel_m / L, ""};
  result.metrics["heading_change_deg"] = {tu.found ? tu.heading_change_deg : nan, "deg"};
  result.metrics["turn_path_m"] = {tu.found ? tu.path_m : nan, "m"};
  result.metrics["turn_radius_m"] = {tu.found ? tu.radius_m : nan, "m"};
  result.metrics["turn_radius_body_lengths"] = {tu.found ? tu.radius_m / L : nan, ""};
  result.metrics["momentum_drift_rel"] = {rec.momentum_drift_rel, ""};
  result.metrics["blew_up"] = {rec.blew_up ? 1.0 : 0.0, ""};
  result.metrics["blowup_step"] = {double(rec.blowup_step), ""};
  result.metrics["blowup_time_s"] = {rec.blew_up ? rec.blowup_time_s : -1.0, "s"};
  if (rec.blew_up && r.text("on_blowup") == "fail")
    throw RunFailure("fish blew up at step " + std::to_string(rec.blowup_step) + " (t = " +
                         std::to_string(rec.blowup_time_s) + " s): " + rec.blowup_cause,
                     result);
  return result;
}

}  // namespace creaturelab::kinds
