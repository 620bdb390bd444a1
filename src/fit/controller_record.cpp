#include "fit/controller_record.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/sha256.hpp"
#include "core/text.hpp"
#include "fit/fit_error.hpp"
#include "fit/params_fragment.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "jellyfish/contraction_curve.hpp"
#include "jellyfish/jellyfish_params.hpp"

namespace creaturelab::fit {
namespace fs = std::filesystem;
namespace {

std::string specSha(const ControllerSpec& spec) { return core::sha256Hex(spec.source_text); }

// One row of `columns` values per record: its vector `field`.
template <class Record>
void writeMatrix(const io::Group& g, const std::string& name, const std::vector<Record>& records,
                 std::vector<double> Record::*field, std::size_t columns) {
  std::vector<double> flat;
  for (const auto& r : records) flat.insert(flat.end(), (r.*field).begin(), (r.*field).end());
  io::writeArray(g, name, flat.data(), {hsize_t(records.size()), hsize_t(columns)});
}

void writeMetrics(const io::Group& g, const std::map<std::string, double>& metrics) {
  for (const auto& [name, v] : metrics) io::writeScalar(g, name, v);
}

// The header, the tuned parameters, the evaluations and the history: common to both writers.
void writeBody(const io::Group& root, const ControllerSpec& spec, const std::vector<Evaluation>& evaluations,
               const std::vector<IterationRecord>& history, const ControllerRecordInfo& info) {
  for (const auto& [name, value] : info.attributes) io::setAttr(root, name, value);
  io::setAttr(root, "title", spec.title);
  io::setAttr(root, "kind", spec.kind);
  io::setAttr(root, "spec_path", spec.path);
  io::setAttr(root, "spec_sha256", specSha(spec));
  io::setAttr(root, "spec_text", spec.source_text);
  io::setAttr(root, "objective_type", spec.objective.type == ObjectiveType::maximise ? "maximise" : "target");
  io::setAttr(root, "objective_metric", spec.objective.metric);

  const std::size_t n = spec.tuned.size();
  const io::Group tuned = root.createGroup("tuned");
  io::writeColumn(tuned, "name", spec.tuned, &TunedParam::name);
  io::writeColumn(tuned, "unit", spec.tuned, &TunedParam::unit);
  io::writeColumn(tuned, "lower", spec.tuned, &TunedParam::lower);
  io::writeColumn(tuned, "upper", spec.tuned, &TunedParam::upper);
  io::writeColumn(tuned, "step", spec.tuned, &TunedParam::step);
  io::writeColumn(tuned, "start", spec.tuned, &TunedParam::start);

  const io::Group ev = root.createGroup("evaluations");
  writeMatrix(ev, "x", evaluations, &Evaluation::x, n);
  io::writeColumn(ev, "ok", evaluations, &Evaluation::ok);
  io::writeColumn(ev, "cost", evaluations, &Evaluation::cost);
  io::setAttr(io::writeColumn(ev, "wall_s", evaluations, &Evaluation::wall_s), "unit", "s");
  io::writeColumn(ev, "message", evaluations, &Evaluation::message);
  std::set<std::string> metric_names;
  for (const auto& e : evaluations)
    for (const auto& [name, v] : e.metrics) metric_names.insert(name);
  const io::Group metrics = ev.createGroup("metrics");
  for (const auto& name : metric_names)
    io::writeColumn(metrics, name, evaluations, [&](const Evaluation& e) {
      auto it = e.metrics.find(name);
      return it == e.metrics.end() ? std::nan("") : it->second;
    });

  const io::Group h = root.createGroup("history");
  io::writeColumn(h, "iteration", history, &IterationRecord::iteration);
  io::writeColumn(h, "accepted", history, &IterationRecord::accepted);
  io::writeColumn(h, "cost", history, &IterationRecord::cost);
  io::writeColumn(h, "objective", history, &IterationRecord::objective);
  io::writeColumn(h, "gradient_max_norm", history, &IterationRecord::gradient_max_norm);
  io::writeColumn(h, "step_norm", history, &IterationRecord::step_norm);
  io::writeColumn(h, "evaluations", history, &IterationRecord::evaluations);
  writeMatrix(h, "x", history, &IterationRecord::x, n);
}

void writeRun(const io::Group& g, const kinds::Result& run) {
  const io::Group ts = g.createGroup("timeseries");
  for (const auto& [name, s] : run.timeseries) io::setAttr(io::writeVector(ts, name, s.values), "unit", s.unit);
}

// The jellyfish's muscle factor over one period for the aperture spring (which follows the curve as
// written) and the apex spring (whose expansion is staggered), from the run's parameters.
void writeCurve(const io::Group& g, const kinds::Params& p) {
  kinds::ParamReader r(p);
  std::vector<jellyfish::Knot> knots;
  for (int k = 0; k < int(r.integer("contraction_knots")); ++k) {
    const std::string s = "knot" + std::to_string(k) + "_";
    knots.push_back({r.real(s + "phase"), r.real(s + "value"), r.real(s + "tangent")});
  }
  const double stagger = r.text("expansion") == "unison" ? 0.0 : r.real("stagger");
  const jellyfish::ExpansionWindow window = jellyfish::expansionWindow(knots);
  std::vector<double> phase, aperture, apex;
  for (int i = 0; i <= 400; ++i) {
    phase.push_back(i / 400.0);
    aperture.push_back(jellyfish::muscleFactor(knots, phase.back(), window, stagger, 1.0));
    apex.push_back(jellyfish::muscleFactor(knots, phase.back(), window, stagger, 0.0));
  }
  const io::Group c = g.createGroup("curve");
  io::writeVector(c, "phase", phase);
  io::writeVector(c, "aperture", aperture);
  io::writeVector(c, "apex", apex);
}

template <typename Body>
void writeWhole(const std::string& dir, Body&& body) {
  fs::create_directories(dir);
  const fs::path tmp = recordPath(dir) + ".tmp";
  {
    io::File file = io::File::create(tmp);
    body(file.root());
    file.close();
  }
  fs::rename(tmp, recordPath(dir));
}

}  // namespace

std::string recordPath(const std::string& dir) { return (fs::path(dir) / "controller_fit.h5").string(); }

void writeControllerRecord(const std::string& dir, const ControllerSpec& spec, const ControllerFitState& state,
                           const ControllerRecordInfo& info) {
  static const std::vector<IterationRecord> no_history;
  writeWhole(dir, [&](const io::Group& root) {
    writeBody(root, spec, *state.evaluations, state.history ? *state.history : no_history, info);
    io::setAttr(root, "complete", false);
    io::setAttr(root, "new_runs", state.new_runs);
    io::setAttr(root, "reused_runs", state.reused_runs);
  });
}

void writeControllerResult(const std::string& dir, const ControllerSpec& spec, const ControllerFitResult& result,
                           const kinds::Result& start_run, const kinds::Result& fitted_run,
                           const ControllerRecordInfo& info) {
  writeWhole(dir, [&](const io::Group& root) {
    writeBody(root, spec, result.evaluations, result.history, info);
    io::setAttr(root, "complete", true);
    io::setAttr(root, "new_runs", result.new_runs);
    io::setAttr(root, "reused_runs", result.reused_runs);
    io::setAttr(root, "converged", result.converged);
    io::setAttr(root, "termination", result.termination);
    io::setAttr(root, "solver_report", result.solver_report);
    const io::Group res = root.createGroup("result");
    io::writeVector(res, "x_start", result.x_start);
    io::writeVector(res, "x_fitted", result.x_fitted);
    io::writeScalar(res, "cost_start", result.start.cost);
    io::writeScalar(res, "cost_fitted", result.fitted.cost);
    writeMetrics(res.createGroup("start_metrics"), result.start.metrics);
    writeMetrics(res.createGroup("fitted_metrics"), result.fitted.metrics);
    const io::Group start = root.createGroup("start"), fitted = root.createGroup("fitted");
    writeRun(start, start_run);
    writeRun(fitted, fitted_run);
    if (spec.kind == "jellyfish") {
      writeCurve(start, spec.paramsAt(result.x_start));
      writeCurve(fitted, spec.paramsAt(result.x_fitted));
    }
  });
  try {
    io::writeFileAtomically(fs::path(dir) / "params.toml", controllerParamsFragment(spec, result.x_fitted));
  } catch (const std::runtime_error& e) {
    throw FitError(e.what());
  }
}

std::vector<Evaluation> readControllerEvaluations(const std::string& dir, const ControllerSpec& spec) {
  const std::string path = recordPath(dir);
  std::vector<Evaluation> out;
  try {
    const io::File file = io::File::openReadOnly(path);
    const io::Group root = file.root();
    if (!io::hasAttr(root, "spec_sha256") || io::getAttrString(root, "spec_sha256") != specSha(spec))
      throw FitError(path + ": the record was made from another version of " + spec.path +
                     " (its SHA-256 differs); use --force to start over");
    const io::Group ev = root.openGroup("evaluations");
    const auto shape = io::datasetShape(ev, "x");
    const std::size_t n = spec.tuned.size();
    if (shape.size() != 2 || shape[1] != n) throw FitError(path + ": /evaluations/x does not have " + std::to_string(n) + " columns");
    const auto x = io::readArrayDouble(ev, "x");
    const auto ok = io::readVectorInt8(ev, "ok");
    const auto cost = io::readVectorDouble(ev, "cost");
    const auto wall = io::readVectorDouble(ev, "wall_s");
    const auto message = io::readVectorString(ev, "message");
    const io::Group mg = ev.openGroup("metrics");
    std::map<std::string, std::vector<double>> metrics;
    for (const auto& name : mg.childNames()) metrics[name] = io::readVectorDouble(mg, name);
    for (std::size_t i = 0; i < shape[0]; ++i) {
      Evaluation e;
      e.x.assign(x.begin() + i * n, x.begin() + (i + 1) * n);
      e.ok = ok[i] != 0;
      e.cost = cost[i];
      e.wall_s = wall[i];
      e.message = message[i];
      if (e.ok)
        for (const auto& [name, column] : metrics) e.metrics[name] = column[i];
      out.push_back(std::move(e));
    }
  } catch (const io::Hdf5Error& e) {
    throw FitError(path + ": cannot read the record: " + e.what());
  }
  return out;
}

std::string controllerParamsFragment(const ControllerSpec& spec, const std::vector<double>& x) {
  std::vector<std::pair<std::string, kinds::Value>> params;
  for (const auto& [name, value] : spec.overrides) {
    bool tuned = false;
    for (const auto& t : spec.tuned) tuned = tuned || t.name == name;
    if (!tuned) params.emplace_back(name, value);
  }
  for (std::size_t i = 0; i < spec.tuned.size(); ++i) params.emplace_back(spec.tuned[i].name, kinds::Value(x[i]));
  return paramsFragment(params, "Controller fitted by `creaturelab fit controller " + spec.path + "` (" + spec.title +
                                    ").\nThe file's [params] and the tuned values; append to an experiment file "
                                    "without a [params] table.");
}

}  // namespace creaturelab::fit
