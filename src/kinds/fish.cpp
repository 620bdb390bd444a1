#include "kinds/fish.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "fish/fish_measure.hpp"
#include "fish/fish_modes.hpp"
#include "fish/fish_run.hpp"
#include "fish/skin.hpp"
#include "fish/swim_mc.hpp"
#include "kinds/fish_render.hpp"
#include "render/mesh_export.hpp"
#include "render/pov_scene.hpp"

namespace creaturelab::kinds {
namespace {

const char* kSpec = "X. Tu, Artificial Animals for Computer Animation, PhD thesis 1996; docs/fish-spec.md";

std::vector<std::int64_t> flat(const std::vector<int>& v) { return {v.begin(), v.end()}; }

// The skin on every recorded frame (quality metrics), stored and exported on export_frames of them.
void addSkin(const FishKindParams& q, const FishSetup& s, const fish::FishModel& model, const fish::FishRecord& rec,
             Result& result) {
  fish::FishSkin skin(model, s.skin);
  const int around = int(q.skin_samples_around), along = int(q.skin_samples_along);
  fish::SkinMesh mesh;
  skin.mesh(around, along, mesh);
  result.metrics["skin_rest_inward"] = {double(fish::checkOutward(mesh).inward), ""};
  Tracks& rest_net = result.lagrangian["skin_rest_control_points_m"];  // the undeformed net (coupling figure)
  rest_net.time_s = {0.0};
  for (const auto& p : skin.controlPoints()) rest_net.data.insert(rest_net.data.end(), {p.x(), p.y(), p.z()});
  rest_net.points = int(skin.controlPoints().size());
  rest_net.dim = 3;
  const int n = rec.frames();
  // The exported frames: export_frames evenly spaced over [export_start_s, end].
  std::vector<int> exported;
  int first = 0;
  while (first < n - 1 && rec.time_s[first] < q.export_start_s - 1e-9) ++first;
  const int count = std::min<int>(int(q.export_frames), n - first);
  for (int k = 0; k < count; ++k)
    exported.push_back(count > 1 ? first + int(std::lround(double(k) * (n - 1 - first) / (count - 1))) : n - 1);
  double creases = 0, worst = 1, gap = 0, inward = 0;
  struct SkinFrame {
    double time_s;
    render::TriangleMesh mesh;
  };
  std::vector<SkinFrame> frames;
  Tracks& net = result.lagrangian["skin_control_points_m"];
  Tracks& vertices = result.lagrangian["skin_vertices_m"];
  size_t next = 0;
  for (int f = 0; f < n; ++f) {
    fish::NodeMatrix x;
    for (int k = 0; k < fish::kNodes; ++k)
      for (int d = 0; d < 3; ++d) x(k, d) = rec.nodes_m[(size_t(f) * fish::kNodes + k) * 3 + d];
    skin.update(x);
    skin.mesh(around, along, mesh);
    const fish::FoldCheck fold = fish::checkOutward(mesh);
    creases += fold.creases;
    inward = std::max(inward, double(fold.inward));
    worst = std::min(worst, fold.worst_neighbour_cosine);
    gap = std::max(gap, fish::seamGapM(mesh));
    if (next < exported.size() && exported[next] == f) {
      ++next;
      net.time_s.push_back(rec.time_s[f]);
      for (const auto& p : skin.controlPoints()) net.data.insert(net.data.end(), {p.x(), p.y(), p.z()});
      vertices.time_s.push_back(rec.time_s[f]);
      for (const auto& p : mesh.positions) vertices.data.insert(vertices.data.end(), {p.x(), p.y(), p.z()});
      frames.push_back({rec.time_s[f], fishRenderMesh(mesh)});
    }
  }
  net.points = int(skin.controlPoints().size());
  net.dim = 3;
  vertices.points = int(mesh.positions.size());
  vertices.dim = 3;
  std::vector<std::int64_t> tris;
  for (const auto& t : mesh.triangles) tris.insert(tris.end(), t.begin(), t.end());
  result.topology["skin_triangles"] = tris;
  // The runner writes one /lagrangian/time_s (all frames): the skin tracks' frames are these indices into it.
  result.topology["skin_frames"] = std::vector<std::int64_t>(exported.begin(), exported.end());
  result.topology["skin_body_triangles"] = {mesh.body_triangles};
  result.metrics["skin_creases"] = {creases, ""};
  result.metrics["skin_inward_max"] = {inward, ""};
  result.metrics["skin_worst_neighbour_cosine"] = {worst, ""};
  result.metrics["skin_seam_gap_m"] = {gap, "m"};

  // Artifacts: the animation, OBJ frames and POV-Ray scenes (rendered by analysis/plot_fish.py).
  auto bytes = [](const std::string& text) { return std::vector<std::uint8_t>(text.begin(), text.end()); };
  render::GltfAnimation animation(fishSkinLook());
  for (const auto& frame : frames) animation.addFrame(frame.time_s, frame.mesh);
  result.artifacts["skin.glb"] = animation.glb("fish");
  char name[64];
  for (size_t k = 0; k < frames.size(); ++k) {
    std::snprintf(name, sizeof name, "skin_%03zu.obj", k);
    result.artifacts[name] = bytes(render::objText(frames[k].mesh, "fish", "t = " + std::to_string(frames[k].time_s) + " s"));
  }
  const int pov = std::min<int>(int(q.pov_frames), int(frames.size()));
  for (int k = 0; k < pov; ++k) {
    const size_t i = pov > 1 ? size_t(std::lround(double(k) * (frames.size() - 1) / (pov - 1))) : frames.size() - 1;
    render::Vec3 centre;
    const double nv = double(frames[i].mesh.positions.size());
    for (const auto& p : frames[i].mesh.positions) centre = {centre.x + p.x / nv, centre.y + p.y / nv, centre.z + p.z / nv};
    std::snprintf(name, sizeof name, "skin_%03d.pov", k);
    result.artifacts[name] =
        bytes(render::povSeaScene(frames[i].mesh, centre, model.body_length_m, "t = " + std::to_string(frames[i].time_s) + " s"));
  }
}

}  // namespace

FishSetup FishKindParams::setup() const {
  FishSetup s;
  if (shape == "reimplementation") {
    s.geometry = fish::reimplementationGeometry();
    s.geometry.body_length_m = geometry.body_length_m;
  } else {
    s.geometry = geometry;
  }
  s.units = units;
  s.solver = solver;
  s.motor = motor;
  s.motor.swim.bothAsAnterior();
  if (auto e = s.motor.validate(); !e.empty()) throw std::invalid_argument(e);
  s.skin = skin_params;
  if (auto e = s.skin.validate(); !e.empty()) throw std::invalid_argument(e);
  for (const std::string& e : {s.geometry.validate(), s.units.validate(), s.solver.validate()})
    if (!e.empty()) throw std::invalid_argument(e);
  try {
    s.schedule = fish::parseSchedule(schedule);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("schedule: ") + e.what());
  }
  return s;
}

std::string FishKindParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  try {
    setup();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  if (!(stable_lo_s < stable_hi_s)) return "stable_lo_s must be below stable_hi_s";
  return "";
}

FishKind::FishKind() {
  metrics_ = {
      {"fish_length_m", "m", "snout to tail (= body_length_m)"},
      {"mass_kg", "kg", "total mass"},
      {"steps", "", "steps taken"},
      {"speed_body_lengths_per_s", "1/s", "centre-of-mass speed from warmup_s to the end, in body lengths per second"},
      {"speed_m_per_s", "m/s", "the same in metres per second"},
      {"forward_distance_m", "m", "centre-of-mass displacement along the initial heading (+x) over the run"},
      {"lateral_drift_m", "m", "|sideways displacement| of the centre of mass over the run"},
      {"lateral_drift_fraction", "", "lateral_drift_m / forward_distance_m"},
      {"settled_heading_change_deg", "deg",
       "direction of travel over the first swim period after warmup_s against the last one (left > 0): curvature of the settled path"},
      {"settled_lateral_drift_fraction", "",
       "sideways displacement from warmup_s to the end, perpendicular to the travel direction of the first period after warmup_s, over the distance"},
      {"vertical_drift_m", "m", "|vertical displacement| of the centre of mass"},
      {"com_travel_m", "m", "|com(end) - com(0)|"},
      {"com_travel_body_lengths", "", "com_travel_m / body length"},
      {"heading_change_deg", "deg", "heading change over the first turn item (left > 0)"},
      {"turn_path_m", "m", "centre-of-mass path over the first turn item"},
      {"turn_radius_m", "m", "turn_path_m / |heading change|"},
      {"turn_radius_body_lengths", "", "turn_radius_m / body length"},
      {"travel_heading_change_deg", "deg",
       "from a swimming start: change of the centre of mass's direction of travel, one swim period before the first non-swim item against the swim period right after it (left > 0)"},
      {"travel_turn_path_m", "m", "centre-of-mass path over that item"},
      {"travel_turn_radius_body_lengths", "", "travel_turn_path_m / |travel_heading_change| / body length"},
      {"swim_mc_knob", "", "swim-MC: the knob s (alpha = s, r = s r_max) chosen for swim_speed_body_lengths_per_s (NaN if not asked)"},
      {"swim_mc_speed_ratio", "", "swim-MC: the measured speed over swim_speed_body_lengths_per_s (NaN if not asked)"},
      {"swim_mc_slowest_body_lengths_per_s", "1/s", "swim-MC: the slowest calibrated speed (the lower end of its claimed range)"},
      {"swim_mc_fastest_body_lengths_per_s", "1/s", "swim-MC: the fastest calibrated speed (s = 1)"},
      {"swim_period_s", "s", "the swim-MC's period (from alpha, r, the stroke and the reference step)"},
      {"lowest_lateral_mode_hz", "Hz", "the undeformed body's lowest sideways bending mode in air (fish_modes.hpp)"},
      {"stroke_frequency_over_mode", "", "1 / swim_period_s over lowest_lateral_mode_hz: above about 1 the body's inertia filters the gait"},
      {"stride_body_lengths", "", "speed_body_lengths_per_s x swim_period_s: body lengths travelled per swim cycle"},
      {"spring_limit_dt_s", "s", "2 / w_max of the body at rest: the symplectic-Euler limit of its stiffest mode"},
      {"momentum_drift_rel", "", "max |sum m v - sum m v(0)| / max sum m |v| over the run (conserved when water_mu = 0)"},
      {"blew_up", "", "1 if the run stopped at a blow-up (on_blowup = record)"},
      {"blowup_step", "", "the step that blew up, -1 if none"},
      {"blowup_time_s", "s", "its time, -1 if none"},
      {"max_stable_dt_s", "s", "stable_step: the largest step that survives the schedule"},
      {"school_count", "", "fish simulated (= school_size)"},
      {"school_fish_steps", "", "steps summed over the school (steps per second: this / the point's wall_time_s attribute)"},
      {"school_mean_speed_body_lengths_per_s", "1/s", "mean speed over the school"},
      {"school_blowups", "", "fish of the school that blew up"},
      {"skin_rest_inward", "", "skin: body triangles pointing into the body on the undeformed skin"},
      {"skin_inward_max", "",
       "skin: most body triangles on one frame pointing into their section (a section-ellipse test; near the zero-thickness caudal edge it misjudges)"},
      {"skin_creases", "", "skin: neighbouring triangles more than 90 degrees apart, summed over all frames (fold-overs)"},
      {"skin_worst_neighbour_cosine", "", "skin: smallest cosine between neighbouring triangles' normals over all frames"},
      {"skin_seam_gap_m", "m", "skin: largest distance between the two halves along the midlines and the tail edge, over all frames"},
  };
}

std::string FishKind::doc() const {
  return std::string("Tu's artificial fish: 23 masses, 91 Voigt units, semi-implicit Euler, swim/turn motor controllers (") +
         kSpec + ")";
}

CostEstimate FishKind::estimateCost(const Params& p) const {
  try {
    const FishKindParams q = readParams<FishKindParams>(p);
    const FishSetup s = q.setup();
    const double steps = std::ceil(fish::scheduleDurationS(s.schedule) / s.solver.dt_s);
    CostEstimate c;
    const double runs =
        q.task == "stable_step" ? double(q.stable_iterations + 2) : double(q.school_size);
    c.steps = steps * runs;
    c.memory_bytes = 8.0 * (1 << 20) + steps / double(q.frame_every_steps) * 8.0 * (fish::kNodes * 3 + 30);
    c.detail = std::to_string(long(steps)) + " steps of " + std::to_string(s.solver.dt_s) + " s" +
               (runs > 1 ? " x " + std::to_string(long(runs)) + " runs (or fish)" : "");
    return c;
  } catch (const std::exception&) {
    return {};
  }
}

namespace {

// The swim-MC's speed map (swim_mc.hpp) and the swim command it gives for the wanted speed, with the
// map's range and the knob as metrics; a speed outside the map fails the point.
fish::SwimCommand swimCommandForSpeed(const FishKindParams& q, const FishSetup& s, const fish::FishModel& model,
                                      Result& result) {
  const fish::SpeedMap map = fish::calibrateSwimMC(model, s.solver, s.motor, q.swim_mc_swim_s, q.warmup_s,
                                                   q.swim_mc_slowest_knob, int(q.swim_mc_levels));
  std::string error;
  const double knob = fish::knobForSpeed(map, q.swim_speed_body_lengths_per_s, error);
  result.metrics["swim_mc_slowest_body_lengths_per_s"] = {map.speed_body_lengths_per_s.front(), "1/s"};
  result.metrics["swim_mc_fastest_body_lengths_per_s"] = {map.speed_body_lengths_per_s.back(), "1/s"};
  if (!error.empty()) throw RunFailure("swim_speed_body_lengths_per_s: " + error, result);
  result.metrics["swim_mc_knob"] = {knob, ""};
  return fish::swimCommandForKnob(knob, s.motor.r_max);
}

// The model's measures (length, mass, rest modes against the stroke), NaN for the metrics this run
// may not reach, and its topology: unit ends and classes, muscles (unit, segment, side), faces.
void addModel(const fish::FishModel& model, const fish::MotorParams& motor, Result& result) {
  const double nan = std::nan("");
  result.metrics["fish_length_m"] = {model.body_length_m, "m"};
  result.metrics["mass_kg"] = {model.totalMassKg(), "kg"};
  const fish::RestModes modes = fish::restModes(model);
  result.metrics["lowest_lateral_mode_hz"] = {modes.lowest_lateral_hz, "Hz"};
  result.metrics["spring_limit_dt_s"] = {2.0 / modes.highest_rad_per_s, "s"};
  result.metrics["stroke_frequency_over_mode"] = {1.0 / fish::swimPeriodS(motor) / modes.lowest_lateral_hz, ""};
  for (const char* m : {"max_stable_dt_s"}) result.metrics[m] = {nan, "s"};
  for (const char* m : {"skin_rest_inward", "skin_inward_max", "skin_creases", "skin_worst_neighbour_cosine"})
    result.metrics[m] = {nan, ""};
  result.metrics["skin_seam_gap_m"] = {nan, "m"};

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

// task = stable_step: the largest step that survives the schedule, and no run recorded.
void addStableStep(const FishKindParams& q, const FishSetup& s, const fish::FishModel& model, Result& result) {
  const auto st = fish::largestStableStep(model, s.solver, s.motor, s.schedule, q.stable_lo_s, q.stable_hi_s,
                                          int(q.stable_iterations));
  result.metrics["max_stable_dt_s"] = {st.dt_s, "s"};
  for (const char* m : {"school_count", "school_fish_steps", "school_mean_speed_body_lengths_per_s", "school_blowups"})
    result.metrics[m] = {std::nan(""), ""};
  result.timeseries["time_s"] = {{0.0}, "s"};
}

// The recorded run: centre of mass, momentum and heading per frame; nodes and muscle rest lengths.
void addRecord(const fish::FishRecord& rec, Result& result) {
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
}

// The swim, turn and travel-turn measures of the recorded run (fish_measure.hpp), and its health.
void addSwimMeasures(const FishKindParams& q, const FishSetup& s, double L, const fish::FishRecord& rec,
                     Result& result) {
  const double nan = std::nan("");
  const double period = fish::swimPeriodS(s.motor);
  const fish::SwimMeasures sw = fish::measureSwim(rec, L, q.warmup_s, period);
  const fish::TurnMeasures tu = fish::measureTurn(rec, s.schedule);
  auto& m = result.metrics;
  m["steps"] = {double(rec.steps), ""};
  m["speed_body_lengths_per_s"] = {sw.speed_body_lengths_per_s, "1/s"};
  m["speed_m_per_s"] = {sw.speed_m_per_s, "m/s"};
  if (const double want = q.swim_speed_body_lengths_per_s; want > 0)
    m["swim_mc_speed_ratio"] = {sw.speed_body_lengths_per_s / want, ""};
  m["forward_distance_m"] = {sw.forward_distance_m, "m"};
  m["lateral_drift_m"] = {sw.lateral_drift_m, "m"};
  m["lateral_drift_fraction"] = {sw.lateral_drift_fraction, ""};
  m["vertical_drift_m"] = {sw.vertical_drift_m, "m"};
  m["settled_heading_change_deg"] = {sw.settled_heading_change_deg, "deg"};
  m["settled_lateral_drift_fraction"] = {sw.settled_lateral_drift_fraction, ""};
  m["com_travel_m"] = {sw.com_travel_m, "m"};
  m["com_travel_body_lengths"] = {sw.com_travel_m / L, ""};
  m["heading_change_deg"] = {tu.found ? tu.heading_change_deg : nan, "deg"};
  m["turn_path_m"] = {tu.found ? tu.path_m : nan, "m"};
  m["turn_radius_m"] = {tu.found ? tu.radius_m : nan, "m"};
  m["turn_radius_body_lengths"] = {tu.found ? tu.radius_m / L : nan, ""};
  const fish::TravelTurn tt = fish::measureTravelTurn(rec, s.schedule, period);
  m["swim_period_s"] = {period, "s"};
  m["stride_body_lengths"] = {sw.speed_body_lengths_per_s * period, ""};
  m["travel_heading_change_deg"] = {tt.found ? tt.heading_change_deg : nan, "deg"};
  m["travel_turn_path_m"] = {tt.found ? tt.path_m : nan, "m"};
  m["travel_turn_radius_body_lengths"] = {tt.found ? tt.radius_m / L : nan, ""};
  m["momentum_drift_rel"] = {rec.momentum_drift_rel, ""};
  m["blew_up"] = {rec.blew_up ? 1.0 : 0.0, ""};
  m["blowup_step"] = {double(rec.blowup_step), ""};
  m["blowup_time_s"] = {rec.blew_up ? rec.blowup_time_s : -1.0, "s"};
}

// The school: independent fish, each its own solver and controller, stepped one after the other
// (the thesis animates up to 5; the speed goal is 1,000 in real time). Only counted, not recorded.
void addSchool(const FishKindParams& q, const FishSetup& s, const fish::FishModel& model, const fish::FishRecord& rec,
               Result& result) {
  const double L = model.body_length_m;
  const long school = long(q.school_size);
  double speed_sum = result.metrics["speed_body_lengths_per_s"].value, fish_steps = double(rec.steps),
         school_blowups = rec.blew_up;
  fish::RunOptions quiet;
  quiet.frame_every_steps = 20;  // enough frames for measureSwim, little recording
  for (long k = 1; k < school; ++k) {
    fish::MotorParams mk = s.motor;
    const double scale = 1.0 - 0.05 * double(k % 5);
    mk.swim.amplitude_anterior *= scale;
    mk.swim.amplitude_posterior *= scale;
    const fish::FishRecord other = fish::runSchedule(model, s.solver, mk, s.schedule, quiet);
    fish_steps += double(other.steps);
    school_blowups += other.blew_up;
    speed_sum += fish::measureSwim(other, L, q.warmup_s).speed_body_lengths_per_s;
  }
  result.metrics["school_count"] = {double(school), ""};
  result.metrics["school_fish_steps"] = {fish_steps, ""};
  result.metrics["school_mean_speed_body_lengths_per_s"] = {speed_sum / double(school), "1/s"};
  result.metrics["school_blowups"] = {school_blowups, ""};
}

}  // namespace

Result FishKind::run(const Params& p) const {
  const FishKindParams q = readParams<FishKindParams>(p);
  FishSetup s = q.setup();
  const fish::FishModel model = fish::buildFish(s.geometry, s.units);
  Result result;
  for (const char* m : {"swim_mc_knob", "swim_mc_speed_ratio"}) result.metrics[m] = {std::nan(""), ""};
  for (const char* m : {"swim_mc_slowest_body_lengths_per_s", "swim_mc_fastest_body_lengths_per_s"})
    result.metrics[m] = {std::nan(""), "1/s"};
  if (q.swim_speed_body_lengths_per_s > 0) s.motor.swim = swimCommandForSpeed(q, s, model, result);
  addModel(model, s.motor, result);
  if (q.task == "stable_step") {
    addStableStep(q, s, model, result);
    return result;
  }
  fish::RunOptions opt;
  opt.frame_every_steps = int(q.frame_every_steps);
  const fish::FishRecord rec = fish::runSchedule(model, s.solver, s.motor, s.schedule, opt);
  addRecord(rec, result);
  addSwimMeasures(q, s, model.body_length_m, rec, result);
  addSchool(q, s, model, rec, result);
  if (q.skin) addSkin(q, s, model, rec, result);
  if (rec.blew_up && q.on_blowup == "fail")
    throw RunFailure("fish blew up at step " + std::to_string(rec.blowup_step) + " (t = " +
                         std::to_string(rec.blowup_time_s) + " s): " + rec.blowup_cause,
                     result);
  return result;
}

}  // namespace creaturelab::kinds
