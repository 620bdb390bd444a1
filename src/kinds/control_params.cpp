#include "kinds/control_params.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace creaturelab::kinds {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

double number(const std::string& text, const std::string& what) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw std::invalid_argument(what + ": '" + text + "' is not a number");
  return v;
}

std::vector<double> numbers(const std::string& text, const std::string& what) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string word;
  while (in >> word) out.push_back(number(word, what));
  return out;
}

// "joint = pattern; joint = pattern" for the joints of `joints`; the others hold.
std::vector<control::Pattern> patternsFor(const std::string& text, const std::vector<std::string>& joints,
                                          const std::string& key, const std::string& list_key) {
  std::vector<control::Pattern> out(joints.size());
  std::vector<char> given(joints.size(), 0);
  for (const auto& item : splitList(text, ';')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument(key + ": '" + item + "' is not joint = pattern");
    const std::string joint = trim(item.substr(0, eq));
    std::size_t k = 0;
    while (k < joints.size() && joints[k] != joint) ++k;
    if (k == joints.size()) throw std::invalid_argument(key + ": joint '" + joint + "' is not in " + list_key);
    if (given[k]) throw std::invalid_argument(key + ": joint '" + joint + "' has two patterns");
    given[k] = 1;
    out[k] = parsePattern(trim(item.substr(eq + 1)), key + " (" + joint + ")");
  }
  return out;
}

}  // namespace

std::vector<std::string> splitList(const std::string& s, char sep) {
  std::vector<std::string> out;
  if (trim(s).empty()) return out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, sep)) out.push_back(trim(item));
  return out;
}

rigid::RigidModel ControllerSettings::loadModel() const {
  auto model = rigid::RigidModel::load(model_file);
  model.setGravity({0, 0, -gravity_m_per_s2});
  model.setTimestep(frame_s / double(substeps));
  return model;
}

control::Pattern parsePattern(const std::string& text, const std::string& key) {
  control::Pattern p;
  if (text == "hold") return p;
  const auto open = text.find('(');
  const std::string kind = trim(text.substr(0, open));
  if (open == std::string::npos || text.back() != ')' || (kind != "sine" && kind != "table"))
    throw std::invalid_argument(key + ": '" + text +
                                "' is not hold | sine(mean_deg, amplitude_deg, frequency_hz, phase_deg) | "
                                "table(t_s angle_deg, ...)");
  const std::string inside = text.substr(open + 1, text.size() - open - 2);
  if (kind == "sine") {
    std::vector<double> v;
    for (const auto& x : splitList(inside, ',')) v.push_back(number(x, key));
    if (v.size() != 4)
      throw std::invalid_argument(key + ": sine takes 4 numbers (mean_deg, amplitude_deg, frequency_hz, phase_deg), got " +
                                  std::to_string(v.size()));
    p.kind = control::Pattern::Kind::sine;
    p.mean_rad = v[0] * kRad;
    p.amplitude_rad = v[1] * kRad;
    p.frequency_hz = v[2];
    p.phase_rad = v[3] * kRad;
  } else {
    p.kind = control::Pattern::Kind::table;
    for (const auto& point : splitList(inside, ',')) {
      const std::vector<double> v = numbers(point, key);
      if (v.size() != 2)
        throw std::invalid_argument(key + ": table point '" + point + "' is not 't_s angle_deg' (two numbers)");
      p.time_s.push_back(v[0]);
      p.angle_rad.push_back(v[1] * kRad);
    }
  }
  if (auto e = p.validate(); !e.empty()) throw std::invalid_argument(key + ": " + e);
  return p;
}

control::ControllerParams ControllerSettings::controllerParams() const {
  control::ControllerParams p;
  p.controlled = splitList(controlled, ',');
  p.kinematic = splitList(kinematic, ',');
  p.kinematic_patterns = patternsFor(kinematic_pattern, p.kinematic, "kinematic_pattern", "kinematic");
  p.pd_driven = splitList(pd_driven, ',');
  p.pd_patterns = patternsFor(pd_pattern, p.pd_driven, "pd_pattern", "pd_driven");
  p.pd_kp_n_m_per_rad = pd_kp_n_m_per_rad;
  p.pd_kd_n_m_s_per_rad = pd_kd_n_m_s_per_rad;
  for (const auto& o : splitList(objectives, ',')) {
    if (o == "effort") p.objectives.push_back(control::Objective::effort);
    else if (o == "drag") p.objectives.push_back(control::Objective::drag);
    else if (o == "drag_along") p.objectives.push_back(control::Objective::drag_along);
    else throw std::invalid_argument("objectives: '" + o + "' is not one of effort | drag | drag_along");
  }
  for (const auto& s : splitList(senses, ',')) {
    if (s == "min") p.senses.push_back(control::Sense::minimize);
    else if (s == "max") p.senses.push_back(control::Sense::maximize);
    else throw std::invalid_argument("senses: '" + s + "' is not min or max");
  }
  for (const auto& row : splitList(weights, ';')) {
    std::vector<double> w;
    for (const auto& x : splitList(row, ',')) w.push_back(number(x, "weights"));
    p.weights.push_back(w);
  }
  p.drag_direction = {drag_direction_x, drag_direction_y, drag_direction_z};
  p.frame_s = frame_s;
  p.substeps = int(substeps);
  p.strength_rad_per_s = strength_rad_per_s;
  p.delta_rad = delta_rad;
  p.one_sided = one_sided;
  p.search_every_frames = int(search_every_frames);
  p.rigidify_outboard = rigidify_outboard;
  p.threads = int(threads);
  return p;
}

double ControllerSettings::coupledStepsPerFrame(double steps_per_evaluation) const {
  if (strength_rad_per_s <= 0) return double(substeps);
  const double joints = double(splitList(controlled, ',').size());
  return double(substeps) + 2 * joints * steps_per_evaluation / double(search_every_frames);
}

std::vector<InitialPose> ControllerSettings::initialPoses() const {
  std::vector<InitialPose> out;
  for (const auto& item : splitList(initial_deg, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("initial_deg: '" + item + "' is not joint=degrees");
    InitialPose pose{trim(item.substr(0, eq)), numbers(item.substr(eq + 1), "initial_deg")};
    if (pose.deg.size() != 1 && pose.deg.size() != 3)
      throw std::invalid_argument("initial_deg: '" + item + "' needs one angle (hinge) or three (ball rotation vector)");
    out.push_back(pose);
  }
  return out;
}

std::string ControllerSettings::checkInitialPoses(const rigid::RigidModel& model, bool hinges_only) const {
  for (const auto& pose : initialPoses()) {
    const int id = model.findJoint(pose.joint);
    if (id < 0) return "initial_deg: joint '" + pose.joint + "' is not in the model " + model.path();
    const auto type = model.joint(id).type;
    if (type == rigid::JointType::free) return "initial_deg: joint '" + pose.joint + "' is a free joint";
    if (hinges_only && pose.deg.size() != 1)
      return "initial_deg: '" + pose.joint + "' needs one angle (hinges only in the planar fluid)";
    if ((type == rigid::JointType::ball) != (pose.deg.size() == 3))
      return "initial_deg: joint '" + pose.joint + "' takes " +
             (type == rigid::JointType::ball ? "three numbers (a ball)" : "one angle");
  }
  return "";
}

std::vector<control::StrokeFollow> parseStrokeSense(const std::string& text,
                                                    const std::vector<std::string>& controlled) {
  const auto entries = splitList(text, ',');
  if (entries.empty()) return {};
  std::vector<control::StrokeFollow> out(controlled.size());
  for (const auto& e : entries) {
    const auto eq = e.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument("stroke_sense: '" + e + "' is not 'controlled_joint = [+|-]inboard_joint'");
    const std::string joint = trim(e.substr(0, eq));
    std::string follow = trim(e.substr(eq + 1));
    double sign = 1.0;
    if (!follow.empty() && (follow[0] == '-' || follow[0] == '+')) {
      sign = follow[0] == '-' ? -1.0 : 1.0;
      follow = trim(follow.substr(1));
    }
    std::size_t k = 0;
    while (k < controlled.size() && controlled[k] != joint) ++k;
    if (k == controlled.size() || follow.empty())
      throw std::invalid_argument("stroke_sense: '" + e + "': the left side must be a controlled joint, the right an inboard joint");
    out[k] = {follow, sign};
  }
  return out;
}

int framesPerCycle(double period_s, double frame_s) {
  const double n = period_s / frame_s;
  if (n < 1 || std::abs(n - std::round(n)) > 1e-6)
    throw std::invalid_argument("flap_period_s: " + std::to_string(period_s) + " s is not a whole number of frames of " +
                                std::to_string(frame_s) + " s");
  return int(std::round(n));
}

void addSeries(Result& result, const control::SeriesSet& series) {
  for (const auto& s : series.all()) result.timeseries[s.name] = {s.values, s.unit};
}

void addMetrics(Result& result, const std::vector<control::NamedValue>& values) {
  for (const auto& v : values) result.metrics[v.name] = {v.value, v.unit};
}

}  // namespace creaturelab::kinds
