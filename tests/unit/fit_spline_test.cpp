// Fitting the periodic Hermite contraction curve (fit/spline_fit.hpp; Rudolf & Mould 2009 §3.3):
// exact recovery from noiseless samples, honest uncertainty from noisy ones (a statistical
// statement over many seeds), robust losses against outliers, period detection, and every bad
// input rejected with a message before fitting.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <span>
#include <toml++/toml.h>

#include "core/rng.hpp"
#include "core/text.hpp"
#include "fit/params_fragment.hpp"
#include "fit/period.hpp"
#include "fit/profile_io.hpp"
#include "fit/spline_fit.hpp"
#include "fit/spline_store.hpp"
#include "jellyfish/contraction_curve.hpp"
#include "kinds/kind.hpp"
#include "runner/experiment.hpp"
#include "scratch_dir_test.hpp"

namespace creaturelab::fit {
namespace {

// A curve with every Hermite term active: uneven knot spacing, non-zero tangents, one value on
// the lower bound 0.56 (the paper's full contraction) and one on the upper bound 1.
const std::vector<double> kPhases = {0.0, 0.3, 0.55, 0.8};
const std::vector<double> kValues = {1.0, 0.56, 0.74, 0.93};
const std::vector<double> kTangents = {-0.4, 0.3, 1.1, 0.9};
constexpr double kPeriod = 1.0 / 0.7;

double truth(double phase, const std::vector<double>& values = kValues) {
  return jellyfish::hermiteCurve<double>(std::span<const double>(kPhases), values.data(), kTangents.data(), phase);
}

// n samples over `periods` periods at an incommensurate step (distinct phases), plus seeded noise.
Profile synthetic(int n, double periods, double noise = 0, std::uint64_t seed = 0,
                  const std::vector<double>& values = kValues) {
  Profile p;
  p.source = "synthetic";
  constexpr auto kNoise = core::purposeId("tests.fit.noise");
  for (int i = 0; i < n; ++i) {
    const double t = periods * kPeriod * i / (n - 1);
    p.time_s.push_back(t);
    p.value.push_back(truth(t / kPeriod, values) + noise * core::normal(seed, kNoise, std::uint64_t(i)));
  }
  return p;
}

SplineFitOptions options() {
  SplineFitOptions o;
  o.knot_phases = kPhases;
  o.period_s = kPeriod;
  return o;
}

// The model is linear in the knots, so noiseless data determine them to rounding, also where
// the truth sits on a bound.
TEST(FitSpline, RecoversKnotsFromNoiselessProfileTo1e8) {
  const SplineFitResult r = fitSpline(synthetic(400, 2.5), options());
  ASSERT_TRUE(r.converged) << r.solver_report;
  double value_error = 0, tangent_error = 0;
  for (std::size_t k = 0; k < kPhases.size(); ++k) {
    EXPECT_NEAR(r.values[k], kValues[k], 1e-8) << "knot " << k;
    EXPECT_NEAR(r.tangents[k], kTangents[k], 1e-8) << "knot " << k;
    value_error = std::max(value_error, std::fabs(r.values[k] - kValues[k]));
    tangent_error = std::max(tangent_error, std::fabs(r.tangents[k] - kTangents[k]));
  }
  RecordProperty("max_value_error", core::formatNumber(value_error));
  RecordProperty("max_tangent_error", core::formatNumber(tangent_error));
  EXPECT_LT(r.residual_rms, 1e-10);
  EXPECT_TRUE(r.value_at_bound[0]);
  EXPECT_TRUE(r.value_at_bound[1]);
  EXPECT_FALSE(r.value_at_bound[2]);
}

// Coverage. With Gaussian noise σ = 0.01, over 40 seeds × 8 parameters (truth strictly inside the
// bounds, so the bounded estimate is the unbounded one), the truth must lie within the reported
// 1σ about 68.3% of the time and within 2σ about 95.4%. Limits: 1σ in [0.60, 0.77], 2σ in
// [0.90, 0.99] (binomial sd for 320 draws ≈ 0.026 and 0.012; the 8 parameters of one seed are
// correlated, so wider than 3 sd). A covariance left unscaled by σ̂² (σ ≈ 1e-4 here) or doubled
// fails them. The scatter of the estimates over the seeds must also match the mean reported σ.
TEST(FitSpline, ReportedUncertaintyCoversTheTruthAtTheStatedRate) {
  const std::vector<double> inside = {0.95, 0.62, 0.74, 0.88};
  const int seeds = 40, k = int(kPhases.size());
  int within1 = 0, within2 = 0, total = 0;
  std::vector<double> sum_err2(2 * k, 0.0), sum_sigma(2 * k, 0.0);
  for (int seed = 1; seed <= seeds; ++seed) {
    const SplineFitResult r = fitSpline(synthetic(240, 2.0, 0.01, std::uint64_t(seed), inside), options());
    ASSERT_TRUE(r.covariance_message.empty()) << r.covariance_message;
    for (int i = 0; i < 2 * k; ++i) {
      const double est = i < k ? r.values[i] : r.tangents[i - k];
      const double tru = i < k ? inside[i] : kTangents[i - k];
      const double sigma = i < k ? r.value_sigma[i] : r.tangent_sigma[i - k];
      ASSERT_GT(sigma, 0);
      within1 += std::fabs(est - tru) <= sigma;
      within2 += std::fabs(est - tru) <= 2 * sigma;
      ++total;
      sum_err2[i] += (est - tru) * (est - tru);
      sum_sigma[i] += sigma;
    }
  }
  const double c1 = double(within1) / total, c2 = double(within2) / total;
  RecordProperty("coverage_1sigma", std::to_string(c1));
  RecordProperty("coverage_2sigma", std::to_string(c2));
  EXPECT_GE(c1, 0.60);
  EXPECT_LE(c1, 0.77);
  EXPECT_GE(c2, 0.90);
  EXPECT_LE(c2, 0.99);
  for (int i = 0; i < 2 * k; ++i) {
    const double rms = std::sqrt(sum_err2[i] / seeds), mean_sigma = sum_sigma[i] / seeds;
    EXPECT_GT(rms / mean_sigma, 0.7) << "parameter " << i;
    EXPECT_LT(rms / mean_sigma, 1.4) << "parameter " << i;
  }
}

// 5% of the samples pushed 0.2 up (a mis-tracked frame): Huber and Cauchy losses of scale 0.02
// keep the knots near the truth; plain least squares is pulled away.
TEST(FitSpline, RobustLossesResistOutliers) {
  const std::vector<double> inside = {0.95, 0.62, 0.74, 0.88};
  Profile p = synthetic(300, 2.0, 0.005, 7, inside);
  for (int i = 0; i < p.size(); i += 20) p.value[i] += 0.2;
  auto worst = [&](Loss loss) {
    SplineFitOptions o = options();
    o.loss = loss;
    o.loss_scale = 0.02;
    const SplineFitResult r = fitSpline(p, o);
    double e = 0;
    for (std::size_t k = 0; k < inside.size(); ++k) e = std::max(e, std::fabs(r.values[k] - inside[k]));
    return e;
  };
  const double plain = worst(Loss::none), huber = worst(Loss::huber), cauchy = worst(Loss::cauchy);
  EXPECT_GT(plain, 0.01);
  EXPECT_LT(huber, plain / 3);
  EXPECT_LT(cauchy, plain / 5);
  EXPECT_LT(cauchy, 0.005);
}

TEST(FitSpline, WeightsOfZeroDropSamples) {
  Profile p = synthetic(300, 2.0);
  p.weight.assign(p.size(), 1.0);
  for (int i = 0; i < p.size(); i += 10) p.value[i] = 0.0, p.weight[i] = 0.0;
  const SplineFitResult r = fitSpline(p, options());
  for (std::size_t k = 0; k < kPhases.size(); ++k) EXPECT_NEAR(r.values[k], kValues[k], 1e-8);
}

// YIN on 3.5 periods of the curve, noiseless and with noise 0.01, at an uneven sampling step.
TEST(FitPeriod, DetectsThePeriodOfTheCurve) {
  for (double noise : {0.0, 0.01}) {
    Profile p = synthetic(350, 3.5, noise, 3);
    const PeriodDetection d = detectPeriod(p);
    ASSERT_TRUE(d.error.empty()) << d.error;
    EXPECT_NEAR(d.period_s, kPeriod, 2e-3 * kPeriod) << "noise " << noise;
  }
  const PeriodDetection short_one = detectPeriod(synthetic(100, 1.5));
  EXPECT_NE(short_one.error.find("two periods"), std::string::npos) << short_one.error;
}

// --- bad input: each rejected before fitting, with a message naming the problem

std::string fitError(const Profile& p, const SplineFitOptions& o) {
  try {
    fitSpline(p, o);
  } catch (const FitError& e) {
    return e.what();
  }
  return "";
}

TEST(FitSplineBadInput, TooFewSamples) {
  EXPECT_NE(fitError(synthetic(12, 2.0), options()).find("too few samples"), std::string::npos);
  // Enough in total but one segment (0.3 -> 0.55) nearly empty.
  Profile p = synthetic(400, 1.0);
  Profile holes;
  for (int i = 0; i < p.size(); ++i) {
    const double ph = p.time_s[i] / kPeriod;
    if (ph > 0.3 && ph < 0.549) continue;
    holes.time_s.push_back(p.time_s[i]), holes.value.push_back(p.value[i]);
  }
  EXPECT_NE(fitError(holes, options()).find("between knot phases 0.3 and 0.55"), std::string::npos)
      << fitError(holes, options());
}

TEST(FitSplineBadInput, TimeAxisShorterThanOnePeriod) {
  const std::string e = fitError(synthetic(200, 0.8), options());
  EXPECT_NE(e.find("less than one period"), std::string::npos) << e;
}

TEST(FitSplineBadInput, NaNSamples) {
  Profile p = synthetic(200, 2.0);
  p.value[17] = std::nan("");
  const std::string e = fitError(p, options());
  EXPECT_NE(e.find("sample 17 is not finite"), std::string::npos) << e;
}

TEST(FitSplineBadInput, BoundsExcludingTheStart) {
  SplineFitOptions o = options();
  o.start_values = {1.0, 0.5, 0.8, 0.9};
  std::string e = fitError(synthetic(200, 2.0), o);
  EXPECT_NE(e.find("exclude the start value 0.5 of knot 1"), std::string::npos) << e;
  o.start_values.clear();
  o.lower_value = 0.9, o.upper_value = 0.8;
  e = fitError(synthetic(200, 2.0), o);
  EXPECT_NE(e.find("lower < upper"), std::string::npos) << e;
}

TEST(FitSplineBadInput, KnotPhasesAndCounts) {
  SplineFitOptions o = options();
  o.knot_phases = {0.0, 0.5, 0.4};
  EXPECT_NE(fitError(synthetic(200, 2.0), o).find("must increase"), std::string::npos);
  o.knot_phases = evenPhases(7);
  EXPECT_NE(fitError(synthetic(200, 2.0), o).find("1 to 6 knots"), std::string::npos);
  o.knot_phases = {0.0, 1.0};
  EXPECT_NE(fitError(synthetic(200, 2.0), o).find("outside [0, 1)"), std::string::npos);
}

class FitCsvTest : public testing::ScratchDirTest {
 protected:
  FitCsvTest() : ScratchDirTest("fit_csv") {}
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(file(name)) << text;
    return file(name).string();
  }
  std::string readError(const std::string& path) {
    try {
      readProfileCsv(path);
    } catch (const FitError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(FitCsvTest, ReadsHeaderValuesAndWeights) {
  const Profile p = readProfileCsv(write("a.csv", "# comment\ntime_s, value, weight\n0, 1.0, 1\n\n0.5, 0.8, 2\n"));
  ASSERT_EQ(p.size(), 2);
  EXPECT_EQ(p.time_s[1], 0.5);
  EXPECT_EQ(p.value[1], 0.8);
  EXPECT_EQ(p.weight[1], 2.0);
}

TEST_F(FitCsvTest, RejectsMissingHeaderNaNRowsAndBadFields) {
  EXPECT_NE(readError(write("h.csv", "0,1\n1,0.9\n")).find("h.csv:1: expected a header row"), std::string::npos);
  EXPECT_NE(readError(write("n.csv", "time_s,value\n0,1\n0.1,nan\n")).find("n.csv:3: value is nan: remove the row"),
            std::string::npos)
      << readError(file("n.csv").string());
  EXPECT_NE(readError(write("c.csv", "time_s,value\n0,1,3\n")).find("c.csv:2: 3 columns"), std::string::npos);
  EXPECT_NE(readError(write("x.csv", "time_s,value\n0,abc\n")).find("'abc' is not a number"), std::string::npos);
  EXPECT_NE(readError(file("missing.csv").string()).find("cannot open"), std::string::npos);
}

// The fragment is valid TOML, round-trips every number exactly and is accepted by the runner
// as the [params] of a jellyfish experiment (appended to a file without its own [params]).
TEST_F(FitCsvTest, ParamsFragmentIsAcceptedByTheJellyfishKind) {
  const SplineFitResult r = fitSpline(synthetic(400, 2.5), options());
  const SplineFitContext ctx{"synthetic", "--period", {}};
  writeSplineFit(dir_.string(), synthetic(400, 2.5), options(), r, ctx);
  std::ifstream in(file("params.toml"));
  const std::string fragment((std::istreambuf_iterator<char>(in)), {});
  const toml::table t = toml::parse(fragment);
  EXPECT_EQ(t["params"]["contraction_knots"].value<std::int64_t>(), 4);
  EXPECT_EQ(t["params"]["knot2_tangent"].value<double>(), r.tangents[2]);
  const kinds::Registry registry = kinds::defaultRegistry();
  const std::string experiment = "kind = \"jellyfish\"\ntitle = \"fitted\"\n" + fragment + "cells = 50\n";
  const runner::Experiment e = runner::loadExperimentText(experiment, "fitted.toml", {}, registry);
  const auto points = runner::expandPoints(e, *registry.find("jellyfish"));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(std::get<double>(points[0].params.at("knot1_value")), r.values[1]);
  EXPECT_EQ(std::get<std::int64_t>(points[0].params.at("cells")), 50);
}

}  // namespace
}  // namespace creaturelab::fit
