#include "fit/spline_store.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "core/text.hpp"
#include "fit/fit_error.hpp"
#include "fit/params_fragment.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "jellyfish/contraction_curve.hpp"

namespace creaturelab::fit {
namespace fs = std::filesystem;

namespace {

void writeContents(const io::Group& root, const Profile& profile, const SplineFitOptions& o,
                   const SplineFitResult& r, const SplineFitContext& c) {
  const int k = static_cast<int>(r.phases.size());
  for (const auto& [name, value] : c.attributes) io::setAttr(root, name, value);
  io::setAttr(root, "data_source", c.data_source);
  io::setAttr(root, "period_s", o.period_s);
  io::setAttr(root, "period_source", c.period_source);
  io::setAttr(root, "phase_origin_s", o.phase_origin_s);
  io::setAttr(root, "loss", lossName(o.loss));
  io::setAttr(root, "loss_scale", o.loss_scale);
  io::setAttr(root, "lower_value", o.lower_value);
  io::setAttr(root, "upper_value", o.upper_value);
  io::setAttr(root, "knots", k);
  io::setAttr(root, "samples", r.samples);
  io::setAttr(root, "converged", r.converged);
  io::setAttr(root, "iterations", r.iterations);
  io::setAttr(root, "solver_report", r.solver_report);
  io::setAttr(root, "covariance_message", r.covariance_message);

  const io::Group knots = root.createGroup("knots");
  io::writeVector(knots, "phase", r.phases);
  io::writeVector(knots, "value", r.values);
  io::writeVector(knots, "tangent", r.tangents);
  io::setAttr(io::writeVector(knots, "value_sigma", r.value_sigma), "doc", "1-sigma, sqrt of the covariance diagonal");
  io::setAttr(io::writeVector(knots, "tangent_sigma", r.tangent_sigma), "unit", "1/cycle");
  io::writeColumn(knots, "value_at_bound", r.value_at_bound, std::identity{});
  io::writeVector(knots, "start_value", r.start_values);
  io::writeVector(knots, "start_tangent", r.start_tangents);

  std::vector<double> cov = r.covariance;
  if (cov.empty()) cov.assign(4 * k * k, std::nan(""));
  const io::Dataset cd = io::writeArray(root, "covariance", cov.data(), {hsize_t(2 * k), hsize_t(2 * k)});
  io::setAttr(cd, "order", "value_0..value_{K-1}, tangent_0..tangent_{K-1}");
  io::writeScalar(root, "residual_rms", r.residual_rms);
  io::writeScalar(root, "weighted_residual_rms", r.weighted_residual_rms);
  io::writeScalar(root, "sigma_unit_weight", r.sigma_unit_weight);

  const io::Group data = root.createGroup("data");
  std::vector<double> phase, weight, fitted, residual;
  for (int i = 0; i < profile.size(); ++i) {
    const double ph = jellyfish::wrapPhase((profile.time_s[i] - o.phase_origin_s) / o.period_s);
    phase.push_back(ph);
    weight.push_back(profile.weightAt(i));
    fitted.push_back(r.curve(ph));
    residual.push_back(fitted.back() - profile.value[i]);
  }
  io::setAttr(io::writeVector(data, "time_s", profile.time_s), "unit", "s");
  io::writeVector(data, "phase", phase);
  io::writeVector(data, "value", profile.value);
  io::writeVector(data, "weight", weight);
  io::writeVector(data, "fitted", fitted);
  io::writeVector(data, "residual", residual);

  const io::Group curve = root.createGroup("curve");
  std::vector<double> cp, cv;
  for (int i = 0; i <= 500; ++i) {
    cp.push_back(i / 500.0);
    cv.push_back(r.curve(cp.back()));
  }
  io::writeVector(curve, "phase", cp);
  io::writeVector(curve, "value", cv);
}

}  // namespace

std::string splineParamsFragment(const SplineFitResult& r, const SplineFitContext& c) {
  const std::string comment = "Contraction curve fitted by `creaturelab fit spline` to " + c.data_source +
                              "\n(period " + c.period_source + "; residual_rms " +
                              core::formatNumber(r.residual_rms) +
                              ").\nAppend to an experiment file without a [params] table, or copy the lines into it.";
  return paramsFragment(knotParams(r.phases, r.values, r.tangents), comment);
}

void writeSplineFit(const std::string& dir, const Profile& profile, const SplineFitOptions& o,
                    const SplineFitResult& r, const SplineFitContext& c) {
  fs::create_directories(dir);
  const fs::path final_path = fs::path(dir) / "spline_fit.h5";
  const fs::path tmp_path = fs::path(dir) / "spline_fit.h5.tmp";
  {
    io::File file = io::File::create(tmp_path);
    writeContents(file.root(), profile, o, r, c);
    file.close();  // every handle opened in writeContents is closed by now
  }
  fs::rename(tmp_path, final_path);

  try {
    io::writeFileAtomically(fs::path(dir) / "params.toml", splineParamsFragment(r, c));
  } catch (const std::runtime_error& e) {
    throw FitError(e.what());
  }
}

}  // namespace creaturelab::fit
