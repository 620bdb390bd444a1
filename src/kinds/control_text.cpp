#include "kinds/control_text.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace creaturelab::kinds::control_text {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  if (trim(s).empty()) return out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, sep)) out.push_back(trim(item));
  return out;
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

rigid::RigidModel loadModel(const ParamReader& r) {
  auto model = rigid::RigidModel::load(r.text("model_file"));
  model.setGravity({0, 0, -r.real("gravity_m_per_s2")});
  model.setTimestep(r.real("frame_s") / double(r.integer("substeps")));
  return model;
}

control::ControllerParams controllerParams(const ParamReader& r) {
  control::ControllerParams p;
  p.controlled = split(r.text("controlled"), ',');
  p.kinematic = split(r.text("kinematic"), ',');
  for (const auto& o : split(r.text("objectives"), ',')) {
    if (o == "effort") p.objectives.push_back(control::Objective::effort);
    else if (o == "drag") p.objectives.push_back(control::Objective::drag);
    else if (o == "drag_along") p.objectives.push_back(control::Objective::drag_along);
    else throw std::invalid_argument("objectives: '" + o + "' is not one of effort | drag | drag_along");
  }
  for (const auto& s : split(r.text("senses"), ',')) {
    if (s == "min") p.senses.push_back(control::Sense::minimize);
    else if (s == "max") p.senses.push_back(control::Sense::maximize);
    else throw std::invalid_argument("senses: '" + s + "' is not min or max");
  }
  for (const auto& row : split(r.text("weights"), ';')) {
    std::vector<double> w;
    for (const auto& x : split(row, ',')) w.push_back(number(x, "weights"));
    p.weights.push_back(w);
  }
  p.drag_direction = {r.real("drag_direction_x"), r.real("drag_direction_y"), r.real("drag_direction_z")};
  p.frame_s = r.real("frame_s");
  p.substeps = int(r.integer("substeps"));
  p.strength_rad_per_s = r.real("strength_rad_per_s");
  p.delta_rad = r.real("delta_rad");
  p.one_sided = r.boolean("one_sided");
  p.search_every_frames = int(r.integer("search_every_frames"));
  p.rigidify_outboard = r.boolean("rigidify_outboard");
  p.threads = int(r.integer("threads"));
  return p;
}

std::vector<std::pair<std::string, double>> initialAngles(const ParamReader& r) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& item : split(r.text("initial_deg"), ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("initial_deg: '" + item + "' is not joint=degrees");
    out.push_back({trim(item.substr(0, eq)), number(trim(item.substr(eq + 1)), "initial_deg")});
  }
  return out;
}

double lineAngleDeg(const control::Vec3& a, const control::Vec3& b) {
  auto norm = [](const control::Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  const double c = std::abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (norm(a) * norm(b));
  return std::acos(std::min(1.0, c)) * 180.0 / std::numbers::pi;
}

double convergedFrame(const std::vector<std::vector<double>>& angles_deg, double tol_deg, int tail) {
  long first = 0;
  for (const auto& a : angles_deg) {
    const int n = int(a.size());
    const int t = std::min(tail, n);
    double mean = 0;
    for (int k = n - t; k < n; ++k) mean += a[k] / t;
    long f = n;
    while (f > 0 && std::abs(a[f - 1] - mean) <= tol_deg) --f;
    first = std::max(first, f == n ? long(n) + 1 : f + 1);  // frames count from 1
  }
  return double(first);
}

}  // namespace creaturelab::kinds::control_text
