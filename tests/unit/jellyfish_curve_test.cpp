// The muscle activation curve of Rudolf & Mould 2009 §3.3
// and Fig. 4 (jellyfish/contraction_curve.hpp), and the parameter checks of jellyfish_params.hpp.
//
// hermiteCurve: interpolation of knot values and tangents, C1 continuity (also across the wrap at
// phase 1), periodicity, and differentiability with respect to the knots through a non-double
// value type (ceres::Jet when available, else a small dual number). muscleFactor: the staggered
// expansion is a re-timing of the expansion only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#if __has_include(<ceres/jet.h>)
#include <ceres/jet.h>
#define CL_HAVE_CERES_JET 1
#endif

#include "jellyfish/contraction_curve.hpp"
#include "jellyfish/jellyfish_params.hpp"

namespace creaturelab::jellyfish {
namespace {

// A curve with four knots, none at phase 0 (so phase 0/1 lies inside the wrapped segment
// 0.8 -> 1.1), uneven segment widths and non-zero tangents: every term of the Hermite basis counts.
const std::vector<double> kPhases = {0.1, 0.35, 0.6, 0.8};
const std::vector<double> kValues = {0.95, 0.6, 0.7, 1.0};
const std::vector<double> kTangents = {-1.0, 0.5, 2.0, -0.3};

double curve(double phase) {
  return hermiteCurve<double>(std::span<const double>(kPhases), kValues.data(), kTangents.data(), phase);
}

// The same curve with a knot at phase 0, so that the wrap coincides with a knot.
const std::vector<double> kPhases0 = {0.0, 0.3, 0.55};
const std::vector<double> kValues0 = {1.0, 0.56, 0.8};
const std::vector<double> kTangents0 = {0.4, 0.0, 1.5};

double curve0(double phase) {
  return hermiteCurve<double>(std::span<const double>(kPhases0), kValues0.data(), kTangents0.data(), phase);
}

double centralDifference(double (*f)(double), double p, double h) { return (f(p + h) - f(p - h)) / (2 * h); }

// Cubic Hermite interpolation: the curve passes through each knot's value (the h00/h01 basis is
// 1/0 at the segment ends).
TEST(JellyfishCurve, PassesThroughKnotValues) {
  for (std::size_t k = 0; k < kPhases.size(); ++k) EXPECT_NEAR(curve(kPhases[k]), kValues[k], 1e-15) << "knot " << k;
  for (std::size_t k = 0; k < kPhases0.size(); ++k)
    EXPECT_NEAR(curve0(kPhases0[k]), kValues0[k], 1e-15) << "knot " << k;
}

// ... and has each knot's tangent d value / d phase there, from both sides, so it is C1 at every
// knot. The central difference across a knot is only first order in h (the second derivative
// jumps at a knot: the spline is C1, not C2), error ~ h |f''(p+) - f''(p-)| / 4 ~ 1e-5 here; the
// one-sided second-order differences (-3 f(p) + 4 f(p + h) - f(p + 2h)) / 2h (and the mirror one)
// stay inside one segment and give the tangent to ~ h^2 times the third derivative.
double rightSlope(double (*f)(double), double p, double h) {
  return (-3 * f(p) + 4 * f(p + h) - f(p + 2 * h)) / (2 * h);
}
double leftSlope(double (*f)(double), double p, double h) { return (3 * f(p) - 4 * f(p - h) + f(p - 2 * h)) / (2 * h); }

TEST(JellyfishCurve, HasKnotTangentsAndIsC1AtKnots) {
  for (auto [f, phases, tangents] :
       {std::tuple{&curve, &kPhases, &kTangents}, std::tuple{&curve0, &kPhases0, &kTangents0}}) {
    for (std::size_t k = 0; k < phases->size(); ++k) {
      const double p = (*phases)[k], tangent = (*tangents)[k];
      EXPECT_NEAR(centralDifference(f, p, 1e-6), tangent, 1e-4) << "knot " << k;
      EXPECT_NEAR(rightSlope(f, p, 1e-5), tangent, 1e-6) << "right of knot " << k;
      EXPECT_NEAR(leftSlope(f, p, 1e-5), tangent, 1e-6) << "left of knot " << k;
    }
  }
  // Between knots the curve is a cubic: there the central difference is second order.
  const double mid = 0.5 * (kPhases[1] + kPhases[2]);
  EXPECT_NEAR(centralDifference(curve, mid, 1e-5), rightSlope(curve, mid, 1e-5), 1e-6);
}

// C1 across the wrap at phase 1, where the last segment hands over to the first: value and slope
// just below phase 1 continue into those just above phase 0. For the curve without a knot at 0
// the wrap is inside the segment 0.8 -> 1.1 and must be invisible; for the curve with one it is
// the knot's value and tangent.
TEST(JellyfishCurve, IsC1AcrossTheWrapAtPhaseOne) {
  const double h = 1e-5;
  for (auto f : {&curve, &curve0}) {
    EXPECT_NEAR(f(1.0 - 1e-12), f(0.0), 1e-10);
    EXPECT_NEAR(leftSlope(f, 1.0, h), rightSlope(f, 0.0, h), 1e-6);  // f(1.0) wraps to f(0)
    EXPECT_NEAR(leftSlope(f, 0.0, h), rightSlope(f, 0.0, h), 1e-6);  // negative phases wrap too
  }
  EXPECT_NEAR(rightSlope(curve0, 0.0, h), kTangents0[0], 1e-6);
  EXPECT_NEAR(leftSlope(curve0, 1.0, h), kTangents0[0], 1e-6);
  // Inside the wrapped segment 0.8 -> 1.1 of `curve`, phase 0 is s = 2/3 of the way: the value
  // there is the Hermite blend of knots 3 and 0 (width 0.3), written out.
  const double s = 0.2 / 0.3, w = 0.3;
  const double expected = (2 * s * s * s - 3 * s * s + 1) * kValues[3] +
                          (s * s * s - 2 * s * s + s) * w * kTangents[3] + (-2 * s * s * s + 3 * s * s) * kValues[0] +
                          (s * s * s - s * s) * w * kTangents[0];
  EXPECT_NEAR(curve(0.0), expected, 1e-14);
}

// Periodicity: the activation repeats every cycle (§3.3, "a cyclical pattern"): any whole number
// of periods added to the phase, including negative phases (times before t = 0), gives the same
// value, to the round-off of wrapping.
TEST(JellyfishCurve, IsPeriodic) {
  for (int i = 0; i < 97; ++i) {
    const double p = i / 97.0;
    for (int n : {-3, -1, 1, 2, 7}) EXPECT_NEAR(curve(p + n), curve(p), 1e-13) << "phase " << p << " + " << n;
  }
  // A phase a hair below 0 wraps to just below 1, never to exactly 1 (the segment search needs [0, 1)).
  EXPECT_LT(wrapPhase(-1e-18), 1.0);
  EXPECT_GE(wrapPhase(-1e-18), 0.0);
  EXPECT_NEAR(curve(-1e-18), curve(0.0), 1e-15);
}

// A curve with a single knot is a constant (its one segment runs from the knot to itself one
// period later); this is the degenerate case the code mentions.
TEST(JellyfishCurve, SingleKnotIsConstant) {
  const std::vector<double> phase = {0.4};
  const double value = 0.8, tangent = 0.0;
  for (double p : {0.0, 0.2, 0.4, 0.7, 0.999})
    EXPECT_NEAR(hermiteCurve<double>(std::span<const double>(phase), &value, &tangent, p), 0.8, 1e-15);
}

// ---- non-double value types -------------------------------------------------------------------

// A minimal forward-mode dual number: the header promises only that T supports double * T and
// T + T, which is what Ceres' Jet and this struct share.
struct Dual {
  double a = 0, d = 0;  // value, derivative
};
Dual operator*(double s, Dual x) { return {s * x.a, s * x.d}; }
Dual operator+(Dual x, Dual y) { return {x.a + y.a, x.d + y.d}; }

// The curve is linear in the knot values and tangents, so d curve / d value_k is the Hermite basis
// function of knot k: 1 at knot k's phase and 0 at every other knot (cardinal property). A central
// difference of the double curve matches the dual derivative at arbitrary phases. This is what a
// Ceres fit of the knots (issue "Fitting with Ceres") relies on.
TEST(JellyfishCurve, DualNumberDerivativeMatchesFiniteDifference) {
  const int count = static_cast<int>(kPhases.size());
  for (int k = 0; k < count; ++k) {
    for (bool wrt_tangent : {false, true}) {
      std::vector<Dual> values(count), tangents(count);
      for (int i = 0; i < count; ++i) {
        values[i] = {kValues[i], (!wrt_tangent && i == k) ? 1.0 : 0.0};
        tangents[i] = {kTangents[i], (wrt_tangent && i == k) ? 1.0 : 0.0};
      }
      for (int i = 0; i <= 40; ++i) {
        const double p = -0.3 + 1.6 * i / 40.0;
        const Dual c = hermiteCurve<Dual>(std::span<const double>(kPhases), values.data(), tangents.data(), p);
        EXPECT_EQ(c.a, curve(p));  // the value part runs the same double operations
        const double h = 1e-6;
        std::vector<double> vp = kValues, vm = kValues, tp = kTangents, tm = kTangents;
        (wrt_tangent ? tp : vp)[k] += h;
        (wrt_tangent ? tm : vm)[k] -= h;
        const double fd = (hermiteCurve<double>(std::span<const double>(kPhases), vp.data(), tp.data(), p) -
                           hermiteCurve<double>(std::span<const double>(kPhases), vm.data(), tm.data(), p)) /
                          (2 * h);
        EXPECT_NEAR(c.d, fd, 1e-9) << "knot " << k << (wrt_tangent ? " tangent" : " value") << " at phase " << p;
      }
      // Cardinal property at the knots.
      for (int j = 0; j < count; ++j) {
        const Dual c = hermiteCurve<Dual>(std::span<const double>(kPhases), values.data(), tangents.data(), kPhases[j]);
        EXPECT_NEAR(c.d, (!wrt_tangent && j == k) ? 1.0 : 0.0, 1e-15) << "knot " << k << " at knot " << j;
      }
    }
  }
}

#ifdef CL_HAVE_CERES_JET
// The same with ceres::Jet, the type the fitting issue will use: all 8 partial derivatives at
// once, each matching a central difference.
TEST(JellyfishCurve, CeresJetDerivativesMatchFiniteDifferences) {
  using Jet = ceres::Jet<double, 8>;
  const int count = static_cast<int>(kPhases.size());
  std::vector<Jet> values(count), tangents(count);
  for (int i = 0; i < count; ++i) {
    values[i] = Jet(kValues[i], i);
    tangents[i] = Jet(kTangents[i], count + i);
  }
  for (int i = 0; i <= 25; ++i) {
    const double p = 1.3 * i / 25.0;
    const Jet c = hermiteCurve<Jet>(std::span<const double>(kPhases), values.data(), tangents.data(), p);
    EXPECT_EQ(c.a, curve(p));
    for (int k = 0; k < 2 * count; ++k) {
      const double h = 1e-6;
      std::vector<double> vp = kValues, vm = kValues, tp = kTangents, tm = kTangents;
      (k < count ? vp : tp)[k % count] += h;
      (k < count ? vm : tm)[k % count] -= h;
      const double fd = (hermiteCurve<double>(std::span<const double>(kPhases), vp.data(), tp.data(), p) -
                         hermiteCurve<double>(std::span<const double>(kPhases), vm.data(), tm.data(), p)) /
                        (2 * h);
      EXPECT_NEAR(c.v[k], fd, 1e-9) << "parameter " << k << " at phase " << p;
    }
  }
}
#endif

// ---- muscleFactor: staggered expansion (§3.3, Fig. 4 right) -------------------------------------

const ActivationParams kDefaults = paperActivation();

double factor(double phase, double stagger, double position) {
  return muscleFactor(kDefaults.knots, phase, expansionWindow(kDefaults.knots), stagger, position);
}

double defaultCurve(double phase) {
  std::vector<double> p, v, t;
  for (const Knot& k : kDefaults.knots) {
    p.push_back(k.phase);
    v.push_back(k.value);
    t.push_back(k.tangent);
  }
  return hermiteCurve<double>(std::span<const double>(p), v.data(), t.data(), phase);
}

// The default curve is the paper's normalisation: 1 relaxed, 0.56 fully contracted (§3.3, Fig. 3),
// and it stays inside [0.56, 1] all cycle (zero slopes at both extremes).
TEST(JellyfishMuscleFactor, DefaultCurveSpansThePapersRange) {
  EXPECT_EQ(expansionWindow(kDefaults.knots).start_phase, 0.3);
  EXPECT_EQ(expansionWindow(kDefaults.knots).end_phase, 0.0);
  double low = 2, high = -1;
  for (int i = 0; i < 1000; ++i) {
    low = std::min(low, defaultCurve(i / 1000.0));
    high = std::max(high, defaultCurve(i / 1000.0));
  }
  EXPECT_NEAR(low, 0.56, 1e-12);
  EXPECT_NEAR(high, 1.0, 1e-12);
}

// "unison" expansion (§3.3): stagger 0 gives every spring the curve as written, whatever its
// position between apex and aperture.
TEST(JellyfishMuscleFactor, ZeroStaggerIsTheCurve) {
  for (int i = 0; i < 200; ++i) {
    const double p = i / 200.0;
    for (double position : {0.0, 0.3, 1.0}) EXPECT_NEAR(factor(p, 0.0, position), defaultCurve(p), 1e-15) << p;
  }
}

// The aperture spring (position 1) expands slowest, i.e. follows the curve as written, for any
// stagger.
TEST(JellyfishMuscleFactor, ApertureSpringIsTheCurveForAnyStagger) {
  for (double stagger : {0.2, 0.5, 0.9})
    for (int i = 0; i < 200; ++i) EXPECT_NEAR(factor(i / 200.0, stagger, 1.0), defaultCurve(i / 200.0), 1e-15);
}

// Springs near the apex expand faster (§3.3: "springs close to the aperture expand more slowly than
// those closer to the apex"): the apex spring (position 0) replays the expansion at speed
// 1/(1 − stagger), reaches the relaxed value 1 at phase c + (1 − c)(1 − stagger) (c = 0.3, the end of
// the contraction) and holds it until the cycle ends; a spring at position a is the aperture curve
// re-timed by 1/(1 − stagger (1 − a)). During the expansion the factor decreases from apex to aperture.
TEST(JellyfishMuscleFactor, ApexSpringReachesRelaxedEarlierAndHolds) {
  const double stagger = 0.5, c = 0.3;
  const double done = c + (1 - c) * (1 - stagger);  // 0.65
  for (int i = 0; i < 100; ++i) {
    const double p = done + (1 - done) * i / 100.0;
    EXPECT_NEAR(factor(p, stagger, 0.0), 1.0, 1e-12) << "phase " << p;
  }
  EXPECT_LT(factor(done - 0.05, stagger, 0.0), 1.0 - 1e-4);  // not before
  EXPECT_LT(factor(0.99, stagger, 1.0), 1.0);                // the aperture spring is still expanding
  for (double position : {0.0, 0.25, 0.5, 0.75}) {
    const double speed = 1.0 / (1.0 - stagger * (1.0 - position));
    for (int i = 1; i < 20; ++i) {
      const double since = (1 - c) / speed * i / 20.0;  // before this spring finishes
      EXPECT_NEAR(factor(c + since, stagger, position), defaultCurve(c + since * speed), 1e-12)
          << "position " << position << " phase " << c + since;
    }
  }
  for (int i = 1; i < 70; ++i) {
    const double p = c + 0.01 * i;
    double previous = 2;
    for (double position : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const double f = factor(p, stagger, position);
      EXPECT_LE(f, previous + 1e-15) << "phase " << p << " position " << position;
      previous = f;
    }
  }
}

// The stagger changes the expansion only: from phase 0 to the end of the contraction every spring
// follows the same curve, bit for bit, and at the contracted knot all springs hold 0.56.
TEST(JellyfishMuscleFactor, ContractionIsUnchangedByStagger) {
  for (int i = 0; i < 300; ++i) {
    const double p = 0.3 * i / 300.0;
    for (double stagger : {0.3, 0.5, 0.9})
      for (double position : {0.0, 0.4, 1.0}) EXPECT_EQ(factor(p, stagger, position), factor(p, 0.0, 1.0)) << p;
  }
  for (double position : {0.0, 0.4, 1.0}) EXPECT_NEAR(factor(0.3, 0.9, position), 0.56, 1e-15);
}

// The staggered factor is continuous in phase for every spring, also at the end of the
// contraction, where the speed-up starts, and across the period: a jump in a rest length would be
// an impulse on the bell.
TEST(JellyfishMuscleFactor, StaggeredFactorIsContinuous) {
  for (double position : {0.0, 0.5, 1.0}) {
    const double n = 20000;
    for (int i = 0; i < n; ++i) {
      const double p = i / n;
      EXPECT_NEAR(factor(p + 1 / n, 0.5, position), factor(p, 0.5, position), 2e-3) << p;
    }
  }
}

// The same re-timing property for activation curves whose period does not start at the relaxed
// knot. Knots are free parameters (fitted by `creaturelab fit spline`), and validate() accepts
// these curves, so the stagger must still change the expansion only (from the smallest knot to the
// largest, cyclically): outside that stretch every spring follows the curve as written, and the
// apex spring holds the relaxed (largest) value once it has finished expanding.
TEST(JellyfishMuscleFactor, StaggerOnlyRetimesTheExpansionWhereverThePeriodStarts) {
  // (0) the default curve (passes: the earlier tests); (1) the default curve shifted by 0.1 in phase;
  // (2) the same rotated so that the contracted knot is at phase 0.
  const std::vector<std::vector<Knot>> curves = {
      kDefaults.knots, {{0.1, 1.0, 0.0}, {0.4, 0.56, 0.0}}, {{0.0, 0.56, 0.0}, {0.7, 1.0, 0.0}}};
  for (std::size_t which = 0; which < curves.size(); ++which) {
    const auto& knots = curves[which];
    ActivationParams a = paperActivation();
    a.knots = knots;
    ASSERT_EQ(a.validate(), "") << "curve " << which;
    const Knot relaxed =
        *std::max_element(knots.begin(), knots.end(), [](auto x, auto y) { return x.value < y.value; });
    const Knot contracted =
        *std::min_element(knots.begin(), knots.end(), [](auto x, auto y) { return x.value < y.value; });
    const ExpansionWindow cp = expansionWindow(knots);
    // The contraction: from the relaxed knot to the contracted knot (cyclically), 0.3 of a period.
    int contraction_mismatches = 0, hold_mismatches = 0;
    std::string first_contraction, first_hold;
    for (int i = 1; i < 30; ++i) {
      const double p = relaxed.phase + 0.3 * i / 30.0;
      const double apex = muscleFactor(knots, p, cp, 0.5, 0.0), aperture = muscleFactor(knots, p, cp, 0.0, 1.0);
      if (std::abs(apex - aperture) > 1e-12 && contraction_mismatches++ == 0)
        first_contraction =
            "phase " + std::to_string(p) + ": apex " + std::to_string(apex) + ", curve " + std::to_string(aperture);
    }
    // The apex spring at stagger 0.5 expands in 0.35 of a period, then holds the relaxed value
    // until the next contraction starts at the relaxed knot.
    for (int i = 1; i < 30; ++i) {
      const double p = contracted.phase + 0.35 + 0.34 * i / 30.0;
      const double apex = muscleFactor(knots, p, cp, 0.5, 0.0);
      if (std::abs(apex - relaxed.value) > 1e-12 && hold_mismatches++ == 0)
        first_hold = "phase " + std::to_string(p) + ": apex " + std::to_string(apex) + ", relaxed " +
                     std::to_string(relaxed.value);
    }
    EXPECT_EQ(contraction_mismatches, 0) << "curve " << which << ": the stagger changed the contraction, first at "
                                         << first_contraction;
    EXPECT_EQ(hold_mismatches, 0) << "curve " << which << ": the apex spring does not hold the relaxed value, first at "
                                  << first_hold;
  }
}

// ---- validate() of the parameters -------------------------------------------------------------

bool mentions(const std::string& message, const std::string& words) { return message.find(words) != std::string::npos; }

// The defaults are usable (validate returns "").
TEST(JellyfishParams, DefaultsAreValid) {
  EXPECT_EQ(ActivationParams{}.validate(), "");
  EXPECT_EQ(BellParams{}.validate(), "");
  EXPECT_EQ(paperActivation().validate(), "");
  EXPECT_EQ(paperBell().validate(), "");
}

// Each bad activation input gives a message naming the problem (STYLE.md: validate() says what is
// wrong in words a user understands).
TEST(JellyfishParams, ActivationProblemsAreNamed) {
  auto message = [](auto edit) {
    ActivationParams a = paperActivation();
    edit(a);
    return a.validate();
  };
  EXPECT_TRUE(mentions(message([](auto& a) {
                         a.knots = {{0.0, 1, 0}, {0.5, 0.6, 0}, {0.4, 0.7, 0}};
                       }),
                       "knot phases must increase: knot 2 is not after knot 1"));
  EXPECT_TRUE(mentions(message([](auto& a) { a.knots = {{0.0, 1, 0}, {0.0, 0.6, 0}}; }), "knot phases must increase"));
  EXPECT_TRUE(mentions(message([](auto& a) {
                         a.knots = {{0.0, 1, 0}, {1.0, 0.6, 0}};
                       }),
                       "knot 1 phase must be in [0, 1)"));
  EXPECT_TRUE(mentions(message([](auto& a) { a.knots.clear(); }), "needs 1 to 16 knots"));
  EXPECT_TRUE(mentions(message([](auto& a) { a.knots.assign(17, Knot{}); }), "needs 1 to 16 knots"));
  EXPECT_TRUE(mentions(message([](auto& a) { a.knots[1].tangent = std::nan(""); }), "knot 1 is not finite"));
  EXPECT_TRUE(mentions(message([](auto& a) { a.stagger = 1.0; }), "stagger must be in [0, 1)"));
  EXPECT_TRUE(mentions(message([](auto& a) { a.stagger = -0.1; }), "stagger must be in [0, 1)"));
  EXPECT_TRUE(mentions(message([](auto& a) { a.contraction_hz = 0; }), "contraction frequency must be > 0"));
  EXPECT_TRUE(mentions(message([](auto& a) { a.synaptic_delay_s = -1e-3; }), "synaptic delay must be >= 0"));
  // Steep tangents make the Hermite segment overshoot below zero: a rest length that vanishes.
  const std::string overshoot = message([](auto& a) { a.knots = {{0.0, 1.0, -30.0}, {0.3, 0.56, 0.0}}; });
  EXPECT_TRUE(mentions(overshoot, "overshoot")) << overshoot;
  // Two problems at once: both are named, joined by "; ".
  const std::string two = message([](auto& a) {
    a.stagger = 2;
    a.contraction_hz = -1;
  });
  EXPECT_TRUE(mentions(two, "stagger") && mentions(two, "frequency") && mentions(two, "; ")) << two;
}

// Each bad bell input gives a message naming the problem.
TEST(JellyfishParams, BellProblemsAreNamed) {
  auto message = [](auto edit) {
    BellParams b = paperBell();
    edit(b);
    return b.validate();
  };
  EXPECT_TRUE(mentions(message([](auto& b) { b.segments = 31; }), "segments must be even and at least 8, got 31"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.segments = 6; }), "segments must be even and at least 8, got 6"));
  // The muscle band may not reach the apex (an element from the apex to itself).
  EXPECT_TRUE(mentions(message([](auto& b) { b.muscle_band_fraction = 1.0; }), "cannot reach the apex"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.muscle_band_fraction = 0.0; }), "muscle band fraction must be in (0, 1)"));
  EXPECT_EQ(message([](auto& b) { b.muscle_band_fraction = 0.99; }), "");
  EXPECT_TRUE(
      mentions(message([](auto& b) { b.thickness_m = 0.03; }), "thickness must be less than half its diameter"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.height_m = 0.003; }), "thickness must be less than its height"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.diameter_m = -1; }), "diameter must be > 0"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.bell_modulus_pa = 0; }), "bell modulus must be > 0"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.muscle_modulus_pa = std::nan(""); }), "muscle modulus must be > 0"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.bending_rigidity_n_m = -1; }), "bending rigidity must be >= 0"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.muscle_section_per_arc = 0; }), "muscle section per arc must be > 0"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.muscle_tension_n_per_m2 = -1; }), "muscle tension must be >= 0"));
  EXPECT_TRUE(mentions(message([](auto& b) { b.tentacle_length_m = 0; }), "tentacle length must be > 0"));
  EXPECT_EQ(message([](auto& b) {
              b.tentacles = false;
              b.tentacle_length_m = 0;
            }),
            "");
}

}  // namespace
}  // namespace creaturelab::jellyfish
