#include "cli/fit_commands.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/text.hpp"
#include "fit/controller_fit.hpp"
#include "fit/controller_record.hpp"
#include "fit/controller_spec.hpp"
#include "fit/params_fragment.hpp"
#include "fit/period.hpp"
#include "fit/profile_io.hpp"
#include "fit/spline_fit.hpp"
#include "fit/spline_store.hpp"
#include "runner/store.hpp"

namespace creaturelab::cli {
namespace fs = std::filesystem;
using core::formatNumber;

namespace {

std::vector<double> parseList(const std::string& text, const std::string& option) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size())
      throw fit::FitError(option + " " + text + ": '" + item + "' is not a number (expected a comma-separated list)");
    out.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string joined(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ", ") + formatNumber(x);
  return s;
}

// Checks the fitted [params] against the jellyfish kind, as `creaturelab run` would: "" if accepted.
std::string checkWithKind(const std::vector<std::pair<std::string, kinds::Value>>& params,
                          const kinds::Registry& registry) {
  const kinds::Kind* kind = registry.find("jellyfish");
  if (!kind) return "";
  kinds::Params given;
  for (const auto& [name, value] : params) {
    for (const auto& spec : kind->params())
      if (spec.name == name)
        if (std::string e = kinds::checkValue(spec, value); !e.empty()) return name + ": expected " + e;
    given[name] = value;
  }
  return kind->validate(kinds::withDefaults(*kind, given));
}

// The numeric options of `fit spline`, checked before anything is read or written.
void checkSplineOptions(const FitSplineArgs& a) {
  const auto finite = [](const char* option, double v) {
    if (!std::isfinite(v)) throw fit::FitError(std::string(option) + " " + formatNumber(v) + ": expected a finite number");
  };
  if (a.knots && *a.knots < 1) throw fit::FitError("--knots " + std::to_string(*a.knots) + ": expected at least 1");
  if (a.period_s && !(std::isfinite(*a.period_s) && *a.period_s > 0))
    throw fit::FitError("--period " + formatNumber(*a.period_s) + ": expected a positive number of seconds");
  if (!(std::isfinite(a.loss_scale) && a.loss_scale > 0))
    throw fit::FitError("--loss-scale " + formatNumber(a.loss_scale) + ": expected a positive number");
  finite("--lower", a.lower);
  finite("--upper", a.upper);
  finite("--phase-origin", a.phase_origin_s);
  if (std::isnan(a.from_s)) throw fit::FitError("--from nan: expected a time in s");
}

}  // namespace

int fitSpline(const FitSplineArgs& a) {
  checkSplineOptions(a);
  const std::string out = a.out.empty() ? "results/runs/fit/" + fs::path(a.data).stem().string() + "_spline" : a.out;
  if (fs::exists(fs::symlink_status(out)) && !a.force)
    throw fit::FitError(out + " exists: pass --force to replace the fit there, or another --out");
  // --- read
  fit::Profile profile;
  std::string source = a.data, period_source;
  std::optional<double> hz;
  const std::string ext = fs::path(a.data).extension().string();
  if (ext == ".csv" || ext == ".txt") {
    profile = fit::readProfileCsv(a.data);
  } else if (ext == ".h5" || ext == ".hdf5" || fs::is_directory(a.data)) {
    fit::Hdf5ProfileSource s;
    s.value_dataset = a.dataset;
    s.time_dataset = a.time_dataset;
    s.weight_dataset = a.weight_dataset;
    s.point = a.point;
    auto h = fit::readProfileHdf5(a.data, s);
    profile = std::move(h.profile);
    source = profile.source;
    hz = h.contraction_hz;
  } else {
    throw fit::FitError(a.data + ": expected a .csv file, an .h5 point file or a run folder");
  }
  if (std::string e = fit::checkSamples(profile); !e.empty()) throw fit::FitError(e);
  profile = fit::dropBefore(profile, a.from_s);
  if (profile.size() == 0) throw fit::FitError(a.data + ": no samples at or after --from " + formatNumber(a.from_s) + " s");

  // --- options
  fit::SplineFitOptions o;
  if (!a.phases.empty()) {
    o.knot_phases = parseList(a.phases, "--phases");
    if (a.knots && *a.knots != int(o.knot_phases.size()))
      throw fit::FitError("--knots " + std::to_string(*a.knots) + " but --phases lists " +
                          std::to_string(o.knot_phases.size()) + " phases");
  } else {
    o.knot_phases = fit::evenPhases(a.knots.value_or(4));
  }
  if (!fit::parseLoss(a.loss, o.loss)) throw fit::FitError("--loss " + a.loss + ": expected none | huber | cauchy");
  o.loss_scale = a.loss_scale;
  o.lower_value = a.lower;
  o.upper_value = a.upper;
  o.phase_origin_s = a.phase_origin_s;
  if (!a.start_values.empty()) o.start_values = parseList(a.start_values, "--start-values");
  if (a.period_s) {
    o.period_s = *a.period_s;
    period_source = "--period";
  } else if (hz && *hz > 0) {
    o.period_s = 1.0 / *hz;
    period_source = "1 / contraction_hz of the point";
  } else {
    const fit::PeriodDetection d = fit::detectPeriod(profile);
    if (!d.error.empty()) throw fit::FitError(profile.source + ": " + d.error);
    o.period_s = d.period_s;
    period_source = "detected (YIN, mismatch " + formatNumber(d.mismatch) + ")";
  }

  // --- fit (checks everything first) and write
  const fit::SplineFitResult r = fit::fitSpline(profile, o);
  fit::SplineFitContext ctx{source, period_source, {}};
  for (const auto& [k, v] : runner::collectProvenance()) ctx.attributes[k] = v;
  ctx.attributes["finished"] = core::isoTimeUtcNow();
  fit::writeSplineFit(out, profile, o, r, ctx);

  std::printf("%s: %d samples, period %s s (%s), %d knots, loss %s\n", source.c_str(), r.samples,
              formatNumber(o.period_s).c_str(), period_source.c_str(), int(r.phases.size()), a.loss.c_str());
  std::printf("  %-6s %-10s %-30s %s\n", "knot", "phase", "value ± 1σ", "tangent ± 1σ (1/cycle)");
  for (std::size_t k = 0; k < r.phases.size(); ++k) {
    char v[64], t[64];
    std::snprintf(v, sizeof v, "%.6f ± %.2g%s", r.values[k], r.value_sigma[k], r.value_at_bound[k] ? " (bound)" : "");
    std::snprintf(t, sizeof t, "%.5f ± %.2g", r.tangents[k], r.tangent_sigma[k]);
    std::printf("  %-6zu %-10.6g %-28s %s\n", k, r.phases[k], v, t);
  }
  std::printf("  residual_rms %.3g; %s%s\n", r.residual_rms, r.converged ? "converged" : "NOT converged",
              r.covariance_message.empty() ? "" : ("; " + r.covariance_message).c_str());
  std::printf("wrote %s/spline_fit.h5 and %s/params.toml\n", out.c_str(), out.c_str());
  const kinds::Registry registry = kinds::defaultRegistry();
  if (std::string e = checkWithKind(fit::knotParams(r.phases, r.values, r.tangents), registry); !e.empty())
    std::fprintf(stderr, "warning: the jellyfish kind would not accept params.toml: %s\n", e.c_str());
  return r.converged ? 0 : 1;
}

int fitController(const FitControllerArgs& a, const kinds::Registry& registry) {
  const fit::ControllerSpec spec = fit::loadControllerSpec(a.file, registry);
  const kinds::Kind& kind = *registry.find(spec.kind);
  const std::string out = a.out.empty() ? "results/runs/fit/" + spec.stem : a.out;
  const bool exists = fs::exists(fit::recordPath(out));
  if (a.resume && a.force) throw fit::FitError("--resume and --force exclude each other");
  if (exists && !a.resume && !a.force)
    throw fit::FitError(fit::recordPath(out) + " exists: --resume to continue that fit or --force to start over");

  fit::ControllerFitOptions o;
  o.jobs = a.jobs;
  if (exists && a.resume) o.recorded = fit::readControllerEvaluations(out, spec);
  if (exists && a.force) fs::remove(fit::recordPath(out));

  fit::ControllerRecordInfo info;
  for (const auto& [k, v] : runner::collectProvenance()) info.attributes[k] = v;
  info.attributes["started"] = core::isoTimeUtcNow();
  o.on_batch = [&](const fit::ControllerFitState& s) { fit::writeControllerRecord(out, spec, s, info); };
  const std::string metric = spec.objective.metric;
  o.on_iteration = [&](const fit::IterationRecord& r) {
    std::fprintf(stderr, "iteration %d%s: %s %s (cost %s), %d evaluations; x = [%s]\n", r.iteration,
                 r.accepted ? "" : " (step rejected)",
                 spec.objective.type == fit::ObjectiveType::maximise ? metric.c_str() : "cost",
                 formatNumber(r.objective).c_str(), formatNumber(r.cost).c_str(), r.evaluations, joined(r.x).c_str());
  };
  std::fprintf(stderr, "fitting %zu parameter(s) of %s (%s); %zu recorded evaluation(s) to reuse\n",
               spec.tuned.size(), spec.kind.c_str(), spec.path.c_str(), o.recorded.size());

  const auto t0 = std::chrono::steady_clock::now();
  const fit::ControllerFitResult r = fit::fitController(spec, kind, o);
  const double fit_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto runs = fit::runPoints(spec, kind, {r.x_start, r.x_fitted}, a.jobs);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  info.attributes["finished"] = core::isoTimeUtcNow();
  info.attributes["wall_time_s"] = formatNumber(wall_s);
  fit::writeControllerResult(out, spec, r, runs[0], runs[1], info);

  std::printf("%s: %d iteration(s); %s\n", spec.path.c_str(), r.history.empty() ? 0 : r.history.back().iteration,
              r.termination.c_str());
  std::printf("  %-28s %-14s %-14s\n", "parameter", "start", "fitted");
  for (std::size_t i = 0; i < spec.tuned.size(); ++i)
    std::printf("  %-28s %-14.6g %-14.6g\n", spec.tuned[i].name.c_str(), r.x_start[i], r.x_fitted[i]);
  for (const std::string& m : {spec.objective.metric, spec.objective.least}) {
    if (m.empty() || !r.start.metrics.count(m) || !r.fitted.metrics.count(m)) continue;
    const double s = r.start.metrics.at(m), f = r.fitted.metrics.at(m);
    std::printf("  %-28s %-14.6g %-14.6g (%+.1f%%)\n", m.c_str(), s, f, 100 * (f - s) / std::fabs(s));
  }
  std::printf("  %d new run(s), %d reused from the record; fit %.1f s, with the final two runs %.1f s\n", r.new_runs,
              r.reused_runs, fit_s, wall_s);
  std::printf("wrote %s and %s/params.toml\n", fit::recordPath(out).c_str(), out.c_str());
  return 0;
}

}  // namespace creaturelab::cli
