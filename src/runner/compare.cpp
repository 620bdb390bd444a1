#include "runner/compare.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/text.hpp"

namespace creaturelab::runner {

Tolerance Baseline::toleranceFor(const std::string& metric) const {
  if (auto it = tolerances.find(metric); it != tolerances.end()) return it->second;
  if (auto it = tolerances.find("default"); it != tolerances.end()) return it->second;
  return {};
}

namespace {
// JSON has no NaN or infinity: those are stored as the strings "nan", "inf", "-inf" (a strand
// that never settled has a NaN settling time).
nlohmann::json number(double x) {
  if (std::isfinite(x)) return x;
  return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
}

double numberFrom(const nlohmann::json& v) {
  if (v.is_null()) return std::nan("");
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "inf") return HUGE_VAL;
    if (s == "-inf") return -HUGE_VAL;
    if (s == "nan") return std::nan("");
    throw std::runtime_error("metric value \"" + s + "\" is not a number, \"nan\", \"inf\" or \"-inf\"");
  }
  return v.get<double>();
}
}  // namespace

nlohmann::json baselineToJson(const Baseline& b) {
  nlohmann::json j;
  j["experiment"] = b.experiment;
  j["overrides"] = b.overrides;
  for (const auto& [name, t] : b.tolerances) j["tolerances"][name] = {{"rtol", t.rtol}, {"atol", t.atol}};
  j["points"] = nlohmann::json::array();
  for (const auto& row : b.table.rows) {
    nlohmann::json p = {{"index", row.index}, {"label", row.label}, {"status", row.status}};
    p["metrics"] = nlohmann::json::object();
    for (const auto& [name, v] : row.metrics) p["metrics"][name] = number(v);
    j["points"].push_back(p);
  }
  return j;
}

Baseline baselineFromJson(const nlohmann::json& j, const std::string& source) {
  try {
    Baseline b;
    b.experiment = j.at("experiment").get<std::string>();
    if (j.contains("overrides")) b.overrides = j.at("overrides").get<std::vector<std::string>>();
    if (j.contains("tolerances"))
      for (const auto& [name, t] : j.at("tolerances").items())
        b.tolerances[name] = {t.value("rtol", 0.0), t.value("atol", 0.0)};
    for (const auto& p : j.at("points")) {
      Row row;
      row.index = p.at("index").get<int>();
      row.label = p.value("label", "");
      row.status = p.value("status", "ok");
      for (const auto& [name, v] : p.at("metrics").items())
        row.metrics[name] = numberFrom(v);
      b.table.rows.push_back(std::move(row));
    }
    return b;
  } catch (const std::exception& e) {
    throw std::runtime_error(source + ": not a creaturelab baseline: " + e.what());
  }
}

bool Comparison::passed() const {
  for (const auto& r : rows)
    if (!r.within) return false;
  return true;
}

Comparison compareTables(const Table& run, const Baseline& baseline) {
  Comparison out;
  for (const auto& ref : baseline.table.rows) {
    const Row* got = nullptr;
    for (const auto& r : run.rows)
      if (r.index == ref.index) got = &r;
    for (const auto& [metric, expected] : ref.metrics) {
      Difference d{ref.index, ref.label, metric, std::nan(""), expected, baseline.toleranceFor(metric), false, ""};
      if (!got || got->status == "missing") d.note = "point missing from the run";
      else if (got->status != ref.status) d.note = "status " + got->status + ", baseline " + ref.status;
      else if (auto it = got->metrics.find(metric); it == got->metrics.end()) d.note = "metric missing from the run";
      else {
        d.got = it->second;
        if (!std::isfinite(expected) || !std::isfinite(d.got)) {
          d.within = (std::isnan(expected) && std::isnan(d.got)) || d.got == expected;
        } else {
          d.within = std::fabs(d.got - expected) <= d.tolerance.atol + d.tolerance.rtol * std::fabs(expected);
        }
      }
      out.rows.push_back(d);
    }
  }
  return out;
}

std::string formatComparison(const Comparison& c, bool only_failures) {
  std::ostringstream s;
  char line[512];
  std::snprintf(line, sizeof line, "%-5s %-24s %-26s %-14s %-14s %-10s %-16s %s\n", "point", "label", "metric", "got",
                "baseline", "rel diff", "tolerance", "");
  s << line;
  int shown = 0;
  for (const auto& d : c.rows) {
    if (only_failures && d.within) continue;
    ++shown;
    const double rel = std::fabs(d.got - d.expected) / std::max(std::fabs(d.expected), 1e-300);
    const std::string tol = "r" + core::formatNumber(d.tolerance.rtol) + " a" + core::formatNumber(d.tolerance.atol);
    std::snprintf(line, sizeof line, "%-5d %-24.24s %-26.26s %-14.7g %-14.7g %-10.2e %-16s %s\n", d.point, d.label.c_str(),
                  d.metric.c_str(), d.got, d.expected, rel, tol.c_str(),
                  d.within ? "ok" : ("OUTSIDE " + d.note).c_str());
    s << line;
  }
  if (only_failures && shown == 0) s << "(all " << c.rows.size() << " values within tolerance)\n";
  return s.str();
}

}  // namespace creaturelab::runner
