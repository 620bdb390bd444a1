// Fitting the contraction curve to a simulated jellyfish (Rudolf & Mould 2009 §3.3): the bell's
// aperture width follows its muscles' rest-length curve closely, so a spline fitted to the
// diameter_ratio series of a short run recovers the shape of the curve that drove it; the series
// of the driving curve itself (aperture_muscle_factor) gives back its knots exactly.
//
// "Shape", numerically, for the fitted curve f against the driving curve c over one period
// (400 phases). The amplitude is the bell's (its compliance and the fluid's load decide how far it
// follows the muscle), so shape is compared scale-free: correlation(f, c) >= 0.95; the phase of
// f's minimum (the end of the bell's contraction) lags c's (0.3) by 0 to 0.06 of a cycle; f's
// range is 0.7 to 1.3 times c's (0.44); and the curves, each rescaled to [0, 1], differ by at
// most 0.25 anywhere. One run on the paper's 100² grid: a warm-up cycle and 3 cycles at 0.7 Hz.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>

#include "core/text.hpp"
#include "fit/spline_fit.hpp"
#include "jellyfish/contraction_curve.hpp"
#include "kinds/kind.hpp"

namespace creaturelab::fit {
namespace {

const kinds::Result& shortRun() {
  static const kinds::Result result = [] {
    const kinds::Registry registry = kinds::defaultRegistry();
    const kinds::Kind& kind = *registry.find("jellyfish");
    // The paper's model: the rest-length muscle, whose curve prescribes the stroke, on a bell with
    // Fig. 12's angular stiffness read per joint of the 32-segment chain. The diameter then follows
    // the driving curve, which is what the fits below recover (the kind's default active-tension
    // bell, soft and driven by a tension, does not follow it).
    // The setting below is pinned, not the kind's defaults: the Hermite curve, hat kernel, 2 mm cells in
    // the 0.4 m box, the force before the advection in a box 1.5 times as tall, the force at the step's
    // end, the viscous solve to 1e-10.
    kinds::Params p = kinds::withDefaults(kind, {{"muscle_model", kinds::Value(std::string("rest_length"))},
                                                 {"bending_rigidity_n_m", kinds::Value(2.352e-3)},
                                                 {"activation_shape", kinds::Value(std::string("hermite"))},
                                                 {"kinematic_viscosity_m2_per_s", 1.304e-5},
                                                 {"kernel", kinds::Value(std::string("bilinear"))},
                                                 {"domain_m", 0.4},
                                                 {"cells", std::int64_t(200)},
                                                 {"dt_s", 0.00125},
                                                 {"bell_segments", std::int64_t(0)},
                                                 {"force_stage", kinds::Value(std::string("before_advection"))},
                                                 {"box_aspect", 1.5},
                                                 {"start_y_fraction", 0.2},
                                                 {"implicit_theta", 1.0},
                                                 {"viscosity_tolerance", 1e-10}});
    p["duration_s"] = 3 / 0.7;
    return kind.run(p);
  }();
  return result;
}

Profile series(const std::string& name) {
  Profile p;
  p.source = name;
  p.time_s = shortRun().timeseries.at("time_s").values;
  p.value = shortRun().timeseries.at(name).values;
  return p;
}

SplineFitOptions at07Hz(std::vector<double> phases) {
  SplineFitOptions o;
  o.knot_phases = std::move(phases);
  o.period_s = 1 / 0.7;
  return o;
}

// The default curve of jellyfish_params.hpp: (0, 1, 0), (0.3, 0.56, 0).
double driving(double phase) {
  static const double phases[] = {0.0, 0.3}, values[] = {1.0, 0.56}, tangents[] = {0.0, 0.0};
  return jellyfish::hermiteCurve<double>(std::span<const double>(phases), values, tangents, phase);
}

TEST(FitJellyfish, DrivingCurveSeriesGivesBackItsKnots) {
  const SplineFitResult r = fitSpline(series("aperture_muscle_factor"), at07Hz({0.0, 0.3}));
  EXPECT_NEAR(r.values[0], 1.0, 1e-12);
  EXPECT_NEAR(r.values[1], 0.56, 1e-12);
  EXPECT_NEAR(r.tangents[0], 0.0, 1e-10);
  EXPECT_NEAR(r.tangents[1], 0.0, 1e-10);
  EXPECT_LT(r.residual_rms, 1e-12);
  RecordProperty("knot_errors", core::formatNumber(r.values[0] - 1.0) + " " + core::formatNumber(r.values[1] - 0.56) +
                                    " " + core::formatNumber(r.tangents[0]) + " " + core::formatNumber(r.tangents[1]));
}

TEST(FitJellyfish, DiameterRatioRecoversTheShapeOfTheDrivingCurve) {
  const SplineFitResult r = fitSpline(series("diameter_ratio"), at07Hz(evenPhases(4)));
  ASSERT_TRUE(r.converged) << r.solver_report;
  const int n = 400;
  std::vector<double> f(n), c(n);
  for (int i = 0; i < n; ++i) f[i] = r.curve(double(i) / n), c[i] = driving(double(i) / n);
  double mf = 0, mc = 0;
  for (int i = 0; i < n; ++i) mf += f[i] / n, mc += c[i] / n;
  double sfc = 0, sff = 0, scc = 0;
  for (int i = 0; i < n; ++i)
    sfc += (f[i] - mf) * (c[i] - mc), sff += (f[i] - mf) * (f[i] - mf), scc += (c[i] - mc) * (c[i] - mc);
  const double correlation = sfc / std::sqrt(sff * scc);
  const auto [f_lo, f_hi] = std::minmax_element(f.begin(), f.end());
  const auto [c_lo, c_hi] = std::minmax_element(c.begin(), c.end());
  const double lag = double(f_lo - f.begin()) / n - double(c_lo - c.begin()) / n;
  const double range_ratio = (*f_hi - *f_lo) / (*c_hi - *c_lo);
  double rescaled_diff = 0;
  for (int i = 0; i < n; ++i)
    rescaled_diff = std::max(rescaled_diff, std::fabs((f[i] - *f_lo) / (*f_hi - *f_lo) - (c[i] - *c_lo) / (*c_hi - *c_lo)));
  RecordProperty("correlation", std::to_string(correlation));
  RecordProperty("lag_cycles", std::to_string(lag));
  RecordProperty("range_ratio", std::to_string(range_ratio));
  RecordProperty("rescaled_max_difference", std::to_string(rescaled_diff));
  RecordProperty("residual_rms", std::to_string(r.residual_rms));
  EXPECT_GE(correlation, 0.95);
  EXPECT_GE(lag, 0.0);
  EXPECT_LE(lag, 0.06);
  EXPECT_GE(range_ratio, 0.7);
  EXPECT_LE(range_ratio, 1.3);
  EXPECT_LE(rescaled_diff, 0.25);
}

}  // namespace
}  // namespace creaturelab::fit
