#include "runner/checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>
#include <variant>

#include <boost/math/distributions/students_t.hpp>

#include "core/text.hpp"

namespace creaturelab::runner {
namespace {

// A check's outcome before it is measured: its name, type and what it expects.
CheckOutcome outcome(const CheckSpec& c, std::string expected, bool passed = false) {
  CheckOutcome out;
  out.name = c.name;
  out.type = c.type;
  out.expected = std::move(expected);
  out.passed = passed;
  return out;
}

// Six significant digits: enough to read a check, short enough for a table.
std::string formatNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

bool matches(const Row& row, const Where& where) {
  for (const auto& [key, value] : where) {
    if (key == "label") {
      if (!sameValue(kinds::Value(row.label), value)) return false;
      continue;
    }
    auto it = row.columns.find(key);
    if (it == row.columns.end() || !sameValue(it->second, value)) return false;
  }
  return true;
}

std::string range(double lo, double hi) { return "[" + formatNumber(lo) + ", " + formatNumber(hi) + "]"; }

std::string describeWhere(const Where& where) {
  std::string out;
  for (const auto& [k, v] : where) out += (out.empty() ? "" : ", ") + k + "=" + kinds::describeValue(v);
  return out;
}

// The selected rows, or the reason they cannot be used (a failed or missing point, no match).
std::vector<const Row*> select(const Table& table, const Where& where, const std::string& metric, std::string& problem) {
  std::vector<const Row*> rows;
  for (const auto& row : table.rows) {
    if (!matches(row, where)) continue;
    if (row.status != "ok") {
      problem = "point " + std::to_string(row.index) + " " + row.status + (row.message.empty() ? "" : ": " + row.message);
      return {};
    }
    auto it = row.metrics.find(metric);
    if (it == row.metrics.end() || !std::isfinite(it->second)) {
      problem = "point " + std::to_string(row.index) + " has no finite " + metric;
      return {};
    }
    rows.push_back(&row);
  }
  if (rows.empty() && problem.empty()) problem = "no point matches " + (where.empty() ? "" : describeWhere(where));
  return rows;
}

CheckOutcome extremum(const CheckSpec& c, const Table& table, const std::vector<const Row*>& rows, bool is_max) {
  CheckOutcome out = outcome(c, "");
  const Row* best = rows.front();
  for (const Row* r : rows) {
    double v = r->metrics.at(c.metric), b = best->metrics.at(c.metric);
    if (is_max ? v > b : v < b) best = r;
  }
  const kinds::Value& at = best->columns.at(c.axis);
  out.got = c.axis + "=" + kinds::describeValue(at) + " (" + c.metric + "=" + formatNumber(best->metrics.at(c.metric)) + ")";
  if (c.expect_choice) {
    out.expected = c.axis + "=\"" + *c.expect_choice + "\"";
    out.passed = sameValue(at, kinds::Value(*c.expect_choice));
  } else if (c.relative_to.empty()) {
    out.expected = c.axis + " in " + range(c.expect_lo, c.expect_hi);
    const double x = numericValue(at);
    out.passed = x >= c.expect_lo && x <= c.expect_hi;
  } else {
    out.expected = c.axis + " / " + c.relative_metric + "(" + describeWhere(c.relative_to) + ") in " +
                   range(c.expect_lo, c.expect_hi);
    std::string problem;
    const auto reference = select(table, c.relative_to, c.relative_metric, problem);
    if (!problem.empty()) {
      out.got += "; " + problem;
      return out;
    }
    double mean = 0;
    for (const Row* r : reference) mean += r->metrics.at(c.relative_metric) / double(reference.size());
    const double ratio = numericValue(at) / mean;
    out.got += " = " + formatNumber(ratio) + " x " + c.relative_metric + " " + formatNumber(mean);
    out.passed = std::isfinite(ratio) && ratio >= c.expect_lo && ratio <= c.expect_hi;
  }
  return out;
}

// A row's standard error of its value (uncertainty metric); NaN when the row has none.
double standardError(const Row& row, const std::string& metric) {
  auto it = row.metrics.find(metric);
  return it == row.metrics.end() ? std::nan("") : it->second;
}

// A row's degrees of freedom: its samples parameter less one; NaN when the row has no such column.
double degreesOfFreedom(const Row& row, const std::string& samples) {
  auto it = row.columns.find(samples);
  if (it == row.columns.end()) return std::nan("");
  if (const auto* n = std::get_if<std::int64_t>(&it->second)) return double(*n) - 1;
  return std::nan("");
}

// Sets the outcome's verdict and appends " +- s" (s the standard error) and the 95% interval to its got text.
void judge(CheckOutcome& out, const CheckSpec& c, double value, double standard_error, double dof) {
  const Verdict v = intervalVerdict(value, standard_error, dof, c.expect_lo, c.expect_hi);
  out.passed = v == Verdict::pass;
  out.inconclusive = v == Verdict::inconclusive;
  out.got += " +- " + formatNumber(standard_error);
  const double half = intervalHalfWidth(standard_error, dof);
  if (!std::isfinite(standard_error)) return;
  const std::string dof_text = formatNumber(std::round(dof * 10) / 10) + " dof";
  if (std::isfinite(half))
    out.got += " (95%, " + dof_text + ": " + range(value - half, value + half) + ")";
  else
    out.got += " (no interval: " + dof_text + ")";
}

CheckOutcome inRange(const CheckSpec& c, const std::vector<const Row*>& rows) {
  double lo = rows.front()->metrics.at(c.metric), hi = lo;
  for (const Row* r : rows) {
    lo = std::min(lo, r->metrics.at(c.metric));
    hi = std::max(hi, r->metrics.at(c.metric));
  }
  CheckOutcome out = outcome(c, c.metric + " in " + range(c.expect_lo, c.expect_hi));
  out.got = rows.size() == 1 ? formatNumber(lo) : range(lo, hi) + " over " + std::to_string(rows.size()) + " points";
  out.passed = lo >= c.expect_lo && hi <= c.expect_hi;
  if (c.uncertainty.empty()) return out;
  if (rows.size() == 1) {
    judge(out, c, lo, standardError(*rows.front(), c.uncertainty), degreesOfFreedom(*rows.front(), c.samples));
    return out;
  }
  // Over several points: every interval inside passes, any wholly outside fails, else inconclusive.
  bool any_fail = false, all_pass = true;
  double most = 0;
  for (const Row* r : rows) {
    const double s = standardError(*r, c.uncertainty);
    most = std::isfinite(s) && std::isfinite(most) ? std::max(most, s) : std::nan("");
    const Verdict v = intervalVerdict(r->metrics.at(c.metric), s, degreesOfFreedom(*r, c.samples), c.expect_lo, c.expect_hi);
    any_fail = any_fail || v == Verdict::fail;
    all_pass = all_pass && v == Verdict::pass;
  }
  out.passed = !any_fail && all_pass;
  out.inconclusive = !any_fail && !all_pass;
  out.got += ", standard errors up to " + formatNumber(most);
  return out;
}

CheckOutcome monotonic(const CheckSpec& c, std::vector<const Row*> rows) {
  std::stable_sort(rows.begin(), rows.end(), [&](const Row* a, const Row* b) {
    return numericValue(a->columns.at(c.axis)) < numericValue(b->columns.at(c.axis));
  });
  CheckOutcome out = outcome(c, c.metric + (c.strict ? " strictly " : " ") + c.direction + " in " + c.axis, true);
  std::ostringstream got;
  for (size_t i = 0; i < rows.size(); ++i) {
    const double v = rows[i]->metrics.at(c.metric);
    got << (i ? ", " : "") << formatNumber(v);
    if (i == 0) continue;
    const double prev = rows[i - 1]->metrics.at(c.metric);
    const bool up = c.strict ? v > prev : v >= prev, down = c.strict ? v < prev : v <= prev;
    if (c.direction == "increasing" ? !up : !down) out.passed = false;
  }
  out.got = got.str();
  if (rows.size() < 2) {
    out.passed = false;
    out.got = "fewer than 2 points";
  }
  return out;
}

// Observed order of convergence: p in metric ~ C * axis^-p (e.g. an error against cells per
// side), the least-squares slope of log(metric) against log(axis), negated.
CheckOutcome order(const CheckSpec& c, const std::vector<const Row*>& rows) {
  CheckOutcome out = outcome(c, "order of " + c.metric + " in " + c.axis + " in " + range(c.expect_lo, c.expect_hi));
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(rows.size());
  for (const Row* r : rows) {
    const double x = std::log(numericValue(r->columns.at(c.axis))), y = std::log(r->metrics.at(c.metric));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double denom = n * sxx - sx * sx;
  if (rows.size() < 2 || !(denom > 0)) {
    out.got = "needs two or more distinct positive axis values";
    return out;
  }
  const double p = -(n * sxy - sx * sy) / denom;
  out.got = formatNumber(p) + " over " + std::to_string(rows.size()) + " points";
  out.passed = std::isfinite(p) && p >= c.expect_lo && p <= c.expect_hi;
  return out;
}

}  // namespace

double intervalHalfWidth(double standard_error, double dof) {
  if (!std::isfinite(standard_error) || standard_error < 0) return std::nan("");
  if (standard_error == 0) return 0;
  if (!(dof > 0) || !std::isfinite(dof)) return std::nan("");
  const boost::math::students_t_distribution<double> t(dof);
  return boost::math::quantile(boost::math::complement(t, 0.025)) * standard_error;
}

double welchDegreesOfFreedom(double error_a, double dof_a, double error_b, double dof_b) {
  const double a2 = error_a * error_a, b2 = error_b * error_b;
  if (a2 == 0) return dof_b;
  if (b2 == 0) return dof_a;
  return (a2 + b2) * (a2 + b2) / (a2 * a2 / dof_a + b2 * b2 / dof_b);
}

Verdict intervalVerdict(double value, double standard_error, double dof, double lo, double hi) {
  if (!std::isfinite(value)) return Verdict::fail;
  const double half = intervalHalfWidth(standard_error, dof);
  if (!std::isfinite(half)) return Verdict::inconclusive;
  const double a = value - half, b = value + half;
  if (a >= lo && b <= hi) return Verdict::pass;
  if (b < lo || a > hi) return Verdict::fail;
  return Verdict::inconclusive;
}

namespace {
CheckOutcome evaluateOne(const CheckSpec& c, const Table& table) {
  std::string problem;
  if (c.type == "ratio" || c.type == "difference") {
    // difference: numerator - denominator, for a comparison whose reference may be near zero or
    // negative (a creature that barely moves without its controller), where a ratio means nothing.
    const bool ratio = c.type == "ratio";
    const std::string& num_metric = c.numerator_metric.empty() ? c.metric : c.numerator_metric;
    const std::string& den_metric = c.denominator_metric.empty() ? c.metric : c.denominator_metric;
    const std::string op = ratio ? " / " : " - ";
    const std::string what = (num_metric == den_metric ? c.metric + (ratio ? " ratio" : " difference")
                                                       : num_metric + op + den_metric) +
                             (c.numerator_base.empty() && c.denominator_base.empty() ? ""
                              : c.base_difference                                  ? " (each less its base)"
                                                                                   : " (each relative to its base)");
    CheckOutcome out = outcome(c, what + " in " + range(c.expect_lo, c.expect_hi));
    auto num = select(table, c.numerator, num_metric, problem);
    auto den = problem.empty() ? select(table, c.denominator, den_metric, problem) : std::vector<const Row*>{};
    if (!problem.empty()) {
      out.got = problem;
      return out;
    }
    if (num.size() != 1 || den.size() != 1) {
      out.got = "numerator and denominator must each select one point (got " + std::to_string(num.size()) + " and " +
                std::to_string(den.size()) + ")";
      return out;
    }
    // With a base selection a side is relative to another point: metric(side) / metric(base), or
    // metric(side) - metric(base) with base_relation = "difference".
    auto side = [&](const Row* row, const std::string& metric, const Where& base) {
      const double v = row->metrics.at(metric);
      if (base.empty()) return v;
      auto b = select(table, base, metric, problem);
      if (b.size() != 1) {
        if (problem.empty()) problem = "a base selection must select one point";
        return std::nan("");
      }
      const double base_value = b[0]->metrics.at(metric);
      return c.base_difference ? v - base_value : v / base_value;
    };
    const double n = side(num[0], num_metric, c.numerator_base);
    const double d = side(den[0], den_metric, c.denominator_base);
    const double r = ratio ? n / d : n - d;
    if (!problem.empty()) {
      out.got = problem;
      return out;
    }
    out.got = formatNumber(r);
    out.passed = std::isfinite(r) && r >= c.expect_lo && r <= c.expect_hi;
    if (!c.uncertainty.empty()) {
      // Independent sides: a ratio's relative errors and a difference's errors add in quadrature, their
      // degrees of freedom by Welch and Satterthwaite.
      const double sn = standardError(*num[0], c.uncertainty), sd = standardError(*den[0], c.uncertainty);
      const double en = ratio ? sn / n : sn, ed = ratio ? sd / d : sd;
      const double dof = welchDegreesOfFreedom(en, degreesOfFreedom(*num[0], c.samples), ed,
                                               degreesOfFreedom(*den[0], c.samples));
      judge(out, c, r, ratio ? std::abs(r) * std::hypot(en, ed) : std::hypot(en, ed), dof);
    }
    return out;
  }
  auto rows = select(table, c.where, c.metric, problem);
  if (!problem.empty()) {
    CheckOutcome out = outcome(c, "");
    out.got = problem;
    return out;
  }
  if (c.type == "argmax") return extremum(c, table, rows, true);
  if (c.type == "argmin") return extremum(c, table, rows, false);
  if (c.type == "range") return inRange(c, rows);
  if (c.type == "order") return order(c, rows);
  return monotonic(c, rows);
}
}  // namespace

CheckOutcome evaluateCheck(const CheckSpec& c, const Table& table) {
  CheckOutcome out = evaluateOne(c, table);
  out.known_deviation = c.known_deviation;
  return out;
}

void checkSelections(const Experiment& experiment, const std::vector<Point>& points) {
  // The rows the sweep will have, without metrics: enough to match selections against.
  const auto columns = sweepColumns(experiment);
  std::vector<Row> rows;
  for (const auto& p : points) {
    Row row;
    row.index = p.index;
    row.label = p.label;
    for (const auto& c : columns) row.columns[c] = p.params.at(c);
    rows.push_back(std::move(row));
  }
  // The distinct values a key takes over the sweep, for the message.
  auto valuesOf = [&](const std::string& key) {
    std::vector<std::string> values;
    for (const auto& row : rows) {
      const std::string v =
          key == "label" ? kinds::describeValue(kinds::Value(row.label)) : kinds::describeValue(row.columns.at(key));
      if (std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
    }
    std::string out;
    for (size_t i = 0; i < values.size() && i < 12; ++i) out += (i ? ", " : "") + values[i];
    return values.size() > 12 ? out + ", ..." : out;
  };
  for (const auto& c : experiment.checks) {
    const std::pair<const char*, const Where*> selections[] = {{"where", &c.where},
                                                               {"numerator", &c.numerator},
                                                               {"denominator", &c.denominator},
                                                               {"numerator_base", &c.numerator_base},
                                                               {"denominator_base", &c.denominator_base},
                                                               {"relative_to", &c.relative_to}};
    for (const auto& [field, where] : selections) {
      if (where->empty()) continue;
      const Where& wanted = *where;  // clang 14 cannot capture a structured binding in a lambda
      if (std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return matches(r, wanted); })) continue;
      const std::string head =
          experiment.path + ": check '" + c.name + "': " + field + " = {" + describeWhere(*where) + "}";
      for (const auto& [key, value] : *where) {
        if (key != "label" && !std::count(columns.begin(), columns.end(), key))
          throw ExperimentError(head + ": no point has the key '" + key + "'");
        const Where one{{key, value}};
        if (std::none_of(rows.begin(), rows.end(), [&](const Row& r) { return matches(r, one); }))
          throw ExperimentError(head + ": no point has " + key + " = " + kinds::describeValue(value) + " (" +
                                (key == "label" && experiment.cases.empty()
                                     ? std::string("the file has no [[case]] labels")
                                     : key + " takes " + valuesOf(key)) +
                                ")");
      }
      throw ExperimentError(head + ": no point has these values together");
    }
  }
}

std::vector<CheckOutcome> evaluateChecks(const std::vector<CheckSpec>& checks, const Table& table) {
  std::vector<CheckOutcome> out;
  for (const auto& c : checks) out.push_back(evaluateCheck(c, table));
  return out;
}

std::string formatCheckTable(const std::vector<CheckOutcome>& outcomes) {
  size_t w_name = 5, w_exp = 8, w_status = 6;
  for (const auto& o : outcomes) {
    w_name = std::max(w_name, o.name.size());
    w_exp = std::max(w_exp, o.expected.size());
    if (o.inconclusive) w_status = 14;
  }
  std::ostringstream s;
  auto pad = [](const std::string& t, size_t w) { return t + std::string(w > t.size() ? w - t.size() : 0, ' '); };
  s << pad("check", w_name) << "  " << pad("pass", w_status) << pad("expected", w_exp) << "  got\n";
  for (const auto& o : outcomes) {
    const char* status = o.passed ? "ok" : o.inconclusive ? "inconclusive" : o.known_deviation.empty() ? "FAIL" : "KNOWN";
    s << pad(o.name, w_name) << "  " << pad(status, w_status) << pad(o.expected, w_exp) << "  " << o.got << "\n";
  }
  for (const auto& o : outcomes)
    if (o.inconclusive)
      s << "inconclusive: '" << o.name << "': its value's 95% interval holds a bound of " << o.expected
        << " (not counted in the exit code; a longer run decides)\n";
  for (const auto& o : outcomes) {
    if (o.known_deviation.empty() || o.inconclusive) continue;
    if (o.passed)
      s << "note: '" << o.name << "' is marked as a known deviation but passed this time\n";
    else
      s << "KNOWN: '" << o.name << "' fails as expected (not counted in the exit code): " << o.known_deviation << "\n";
  }
  return s.str();
}

}  // namespace creaturelab::runner

