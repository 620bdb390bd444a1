// The active-tension muscle, the pulse activation and the pluck measurement, and the
// continuum definition of the bell: refining the chain refines one body, so its
// static shape under a given muscle load and its in-vacuum breathing frequency converge as the
// segments double. Rudolf & Mould 2009 §3.2-3.3.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>
#include <cmath>
#include <vector>

#include "jellyfish/bell_model.hpp"
#include "jellyfish/jellyfish_body.hpp"
#include "jellyfish_stiffness_matrix.hpp"
#include "jellyfish/ringdown.hpp"
#include "support/dense_linalg.hpp"
#include "support/jellyfish_water.hpp"

namespace creaturelab::jellyfish {
namespace {
using test::kWaterViscosity_pa_s;

using Markers = std::vector<fluid::Vec2>;

BellParams activeBell(int segments, double tension_n_per_m2) {
  BellParams p = paperBell();
  p.segments = segments;
  p.muscle_model = MuscleModel::active_tension;
  p.muscle_tension_n_per_m2 = tension_n_per_m2;
  return p;
}

ActivationParams pulse(double duration_s, int cycles) {
  ActivationParams a = paperActivation();
  a.contraction_hz = 1.0;
  a.shape = ActivationShape::pulse;
  a.pulse_duration_s = duration_s;
  a.active_cycles = cycles;
  return a;
}

using testing::stiffnessMatrix;

Eigen::VectorXd forceVector(const JellyfishBody& body, double t, const Markers& x) {
  Markers f(x.size());
  body.forces(t, x, f);
  Eigen::VectorXd out(2 * f.size());
  for (std::size_t i = 0; i < f.size(); ++i) out.segment<2>(2 * long(i)) << f[i].x, f[i].y;
  return out;
}

Markers fromVector(const Eigen::VectorXd& v) {
  Markers x(v.size() / 2);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = {v[2 * long(i)], v[2 * long(i) + 1]};
  return x;
}

Eigen::VectorXd toVector(const Markers& x) {
  Eigen::VectorXd v(2 * x.size());
  for (std::size_t i = 0; i < x.size(); ++i) v.segment<2>(2 * long(i)) << x[i].x, x[i].y;
  return v;
}

// ---- activation -------------------------------------------------------------------------------

// The pulse: sin²(π t / τ) for the first τ of each cycle, zero after; none after active_cycles.
TEST(JellyfishActivation, PulseIsSineSquaredThenZeroAndStopsAfterTheActiveCycles) {
  const BellModel model = buildBell(activeBell(32, 10.0));
  const JellyfishBody body(model, pulse(0.2, 2), kWaterViscosity_pa_s);
  EXPECT_EQ(body.activation(0, 0.0), 0.0);
  EXPECT_NEAR(body.activation(0, 0.1), 1.0, 1e-15);
  EXPECT_NEAR(body.activation(0, 0.05), 0.5, 1e-15);
  EXPECT_EQ(body.activation(0, 0.5), 0.0);
  EXPECT_NEAR(body.activation(0, 1.1), 1.0, 1e-12);  // second cycle
  EXPECT_EQ(body.activation(0, 2.1), 0.0);             // active_cycles = 2
  EXPECT_EQ(body.muscleFactor(0, 2.1), 1.0);
}

// The staggered release (§3.3, Fig. 4 right, for the pulse): every muscle contracts alike; in the
// falling half the muscle at aperture position a runs 1/(1 - s (1 - a)) times faster, so the apex's
// pulse ends at τ/2 + (1 - s) τ/2 and the aperture's at τ; s = 0 is the unstaggered pulse.
TEST(JellyfishActivation, StaggeredPulseReleasesTheApexFirstAndContractsAlike) {
  const BellModel model = buildBell(activeBell(32, 10.0));
  ActivationParams a = pulse(0.4, 0);
  a.pulse_stagger = 0.5;
  const JellyfishBody staggered(model, a, kWaterViscosity_pa_s);
  const JellyfishBody unison(model, pulse(0.4, 0), kWaterViscosity_pa_s);
  int apex = 0, aperture = 0;
  for (int m = 0; m < int(model.muscles.size()); ++m) {
    if (model.muscles[m].aperture_position < model.muscles[apex].aperture_position) apex = m;
    if (model.muscles[m].aperture_position > model.muscles[aperture].aperture_position) aperture = m;
  }
  ASSERT_EQ(model.muscles[aperture].aperture_position, 1.0);
  ASSERT_LT(model.muscles[apex].aperture_position, 0.2);
  for (int m = 0; m < int(model.muscles.size()); ++m)
    for (double t : {0.0, 0.05, 0.1, 0.2, 1.15})
      EXPECT_EQ(staggered.activation(m, t), unison.activation(m, t)) << "muscle " << m << " t " << t;
  for (double t : {0.25, 0.3, 0.35, 0.399})
    EXPECT_NEAR(staggered.activation(aperture, t), unison.activation(aperture, t), 1e-15) << "t " << t;
  const double speed = 1.0 / (1.0 - 0.5 * (1.0 - model.muscles[apex].aperture_position));
  const double apex_end_s = 0.2 + 0.2 / speed;
  EXPECT_NEAR(staggered.activation(apex, 0.2 + 0.1 / speed), 0.5, 1e-12);  // sin²(3π/4)
  EXPECT_GT(staggered.activation(apex, apex_end_s - 1e-3), 0.0);
  EXPECT_EQ(staggered.activation(apex, apex_end_s + 1e-9), 0.0);
  EXPECT_GT(unison.activation(apex, apex_end_s + 1e-9), 0.1);
  for (double t = 0.2; t < 0.4; t += 0.01)  // the apex relaxes first
    EXPECT_LE(staggered.activation(apex, t), staggered.activation(aperture, t) + 1e-15) << "t " << t;
  a.pulse_stagger = 1.0;
  EXPECT_NE(a.validate().find("pulse stagger"), std::string::npos);
}

// The Hermite shape maps the §3.3 curve so that its lowest knot (0.56) is full activation.
TEST(JellyfishActivation, HermiteActivationIsTheCurveScaledToItsLowestKnot) {
  const BellModel model = buildBell(activeBell(32, 10.0));
  ActivationParams a = paperActivation();
  a.expansion = Expansion::unison;
  const JellyfishBody body(model, a, kWaterViscosity_pa_s);
  for (double t : {0.0, 0.1, 0.3 / 0.7, 0.9, 1.2}) {
    const double expected = (1.0 - body.muscleFactor(0, t)) / (1.0 - 0.56);
    EXPECT_NEAR(body.activation(0, t), expected, 1e-15) << "t " << t;
  }
  EXPECT_NEAR(body.activation(0, 0.3 / 0.7), 1.0, 1e-12);
}

// ---- the active-tension muscle ----------------------------------------------------------------

// Each element pulls its two ends together with T_max w a(t), whatever its length; the forces are
// internal (zero sum), and the stiffness is the tension's geometric term, equal to finite
// differences of the force and negative semi-definite (ib/coupling.hpp needs −K ⪰ 0).
TEST(JellyfishActiveTension, PullsWithTheActiveTensionAndItsStiffnessIsTheGeometricTerm) {
  BellModel model = buildBell(activeBell(32, 40.0));
  model.network = springs::Network<2>{};  // the muscle alone
  for (std::size_t i = 0; i < model.rest_positions_m.size(); ++i) model.network.addParticle(1.0, false);
  const JellyfishBody body(model, pulse(0.4, 0), kWaterViscosity_pa_s);
  Markers x = model.rest_positions_m;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = {1.01 * x[i].x + 1e-4 * std::sin(3.0 * i), x[i].y + 1e-4 * std::cos(5.0 * i)};
  const double t = 0.13;
  std::vector<double> tension;
  body.muscleTensions(t, x, tension);
  const Eigen::VectorXd f = forceVector(body, t, x);
  double sx = 0, sy = 0;
  for (std::size_t m = 0; m < model.muscles.size(); ++m) {
    const MuscleSpring& s = model.muscles[m];
    EXPECT_NEAR(tension[m], 40.0 * s.arc_weight_m * body.activation(int(m), t), 1e-15);
    EXPECT_GT(tension[m], 0.0);
  }
  for (long i = 0; i < f.size() / 2; ++i) {
    sx += f[2 * i];
    sy += f[2 * i + 1];
  }
  EXPECT_LT(std::abs(sx) + std::abs(sy), 1e-12 * f.cwiseAbs().maxCoeff());
  // |force| at the aperture element's end is its tension (no other element acts there).
  EXPECT_NEAR(std::hypot(f[0], f[1]), tension[0], 1e-12);

  const Eigen::MatrixXd k = stiffnessMatrix(body, t, x);
  Eigen::MatrixXd fd(k.rows(), k.cols());
  const Eigen::VectorXd x0 = toVector(x);
  const double h = 1e-7;
  for (long c = 0; c < x0.size(); ++c) {
    Eigen::VectorXd xp = x0, xm = x0;
    xp[c] += h;
    xm[c] -= h;
    fd.col(c) = (forceVector(body, t, fromVector(xp)) - forceVector(body, t, fromVector(xm))) / (2 * h);
  }
  EXPECT_LT((k - fd).cwiseAbs().maxCoeff(), 1e-6 * k.cwiseAbs().maxCoeff());
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-14 * k.cwiseAbs().maxCoeff());
  EXPECT_LT(test::symmetricEigenvalues(k).maxCoeff(), 1e-9 * k.cwiseAbs().maxCoeff());
}

// An active tension stores no elastic energy; a relaxed muscle exerts nothing.
TEST(JellyfishActiveTension, StoresNoEnergyAndARelaxedMuscleExertsNothing) {
  const BellModel model = buildBell(activeBell(32, 40.0));
  const JellyfishBody body(model, pulse(0.2, 0), kWaterViscosity_pa_s);
  const Markers& x = model.rest_positions_m;
  EXPECT_LT(body.elasticEnergy(0.1, x), 1e-24);  // rest shape: the bell's springs are at rest
  EXPECT_LT(forceVector(body, 0.5, x).cwiseAbs().maxCoeff(), 1e-12);  // after the pulse
  EXPECT_GT(forceVector(body, 0.1, x).cwiseAbs().maxCoeff(), 0.05);  // T_max w a: 40 x 1.98 mm x 1
}

// ---- ringdown ---------------------------------------------------------------------------------

// A damped cosine e^{−ζ ω t} cos(ω_d t) with known f_n and ζ: the zero crossings and the
// logarithmic decrement give them back.
TEST(JellyfishRingdown, RecoversFrequencyAndDampingOfADampedOscillation) {
  for (double zeta : {0.02, 0.1, 0.3}) {
    const double fn = 1.7, wn = 2 * M_PI * fn, wd = wn * std::sqrt(1 - zeta * zeta);
    std::vector<double> t, d;
    for (int i = 0; i <= 40000; ++i) {
      t.push_back(i * 1e-4);
      d.push_back(-0.3 * std::exp(-zeta * wn * t.back()) * std::cos(wd * t.back()));
    }
    const Ringdown r = measureRingdown(t, d, 1e-4, 8);
    EXPECT_EQ(r.half_periods, 8);
    EXPECT_NEAR(r.damped_hz, wd / (2 * M_PI), 1e-6) << "zeta " << zeta;
    // Extrema of e^{−ζωt} cos sit slightly before the cosine's; the decrement is exact between them.
    EXPECT_NEAR(r.damping_ratio, zeta, 1e-6) << "zeta " << zeta;
    EXPECT_NEAR(r.natural_hz, fn, 1e-5) << "zeta " << zeta;
  }
}

TEST(JellyfishRingdown, NoOscillationGivesNaN) {
  std::vector<double> t, d;
  for (int i = 0; i < 1000; ++i) {
    t.push_back(i * 1e-3);
    d.push_back(-0.3 * std::exp(-5.0 * t.back()));  // overdamped: never crosses
  }
  const Ringdown r = measureRingdown(t, d, 0.1, 4);
  EXPECT_EQ(r.half_periods, 0);
  EXPECT_TRUE(std::isnan(r.damped_hz));
  EXPECT_TRUE(std::isnan(r.natural_hz));
}

// The fit of one damped mode recovers f_n and ζ at the frame rate the kind samples (25 Hz), also
// with a second, faster mode of a third of the amplitude beating in and a slow drift: the case
// where the zero crossings of a real pluck lose half periods under their hysteresis.
TEST(JellyfishRingdown, DampedFitRecoversTheModeUnderABeatAndADrift) {
  for (double zeta : {0.05, 0.15, 0.3}) {
    const double fn = 0.65, wn = 2 * M_PI * fn, wd = wn * std::sqrt(1 - zeta * zeta);
    std::vector<double> t, d, clean;
    for (int i = 0; i <= 150; ++i) {  // 6 s at 25 Hz
      const double s = i / 25.0;
      t.push_back(s);
      clean.push_back(-0.15 * std::exp(-zeta * wn * s) * std::cos(wd * s));
      d.push_back(clean.back() + 0.05 * std::exp(-0.5 * s) * std::sin(2 * M_PI * 2.1 * s) + 0.002 * s);
    }
    const DampedFit exact = fitDampedOscillation(t, clean);
    EXPECT_NEAR(exact.natural_hz, fn, 2e-3 * fn) << "zeta " << zeta;
    EXPECT_NEAR(exact.damping_ratio, zeta, 5e-3) << "zeta " << zeta;
    EXPECT_LT(exact.residual_fraction, 1e-2);
    const DampedFit beaten = fitDampedOscillation(t, d);
    EXPECT_NEAR(beaten.natural_hz, fn, 0.05 * fn) << "zeta " << zeta;
    EXPECT_NEAR(beaten.damping_ratio, zeta, 0.05) << "zeta " << zeta;
    EXPECT_GT(beaten.residual_fraction, exact.residual_fraction);  // the beat is not the mode
  }
  const std::vector<double> few = {0, 1, 2};
  EXPECT_TRUE(std::isnan(fitDampedOscillation(few, few).natural_hz));
}

// ---- continuum convergence -----------------------------------------------------

// Static equilibrium of the bell under a constant active tension, by Newton's method on the body's
// own forces and stiffness (with a tiny shift for the three rigid modes the load does not excite).
double loadedDiameterRatio(int segments) {
  const BellModel model = buildBell(activeBell(segments, 20.0));
  ActivationParams hold = pulse(1.0, 0);  // a = sin²(π t): 1 at t = 0.5
  const JellyfishBody body(model, hold, kWaterViscosity_pa_s);
  Eigen::VectorXd x = toVector(model.rest_positions_m);
  for (int it = 0; it < 60; ++it) {
    const Eigen::VectorXd f = forceVector(body, 0.5, fromVector(x));
    if (f.cwiseAbs().maxCoeff() < 1e-11) break;
    Eigen::MatrixXd a = -stiffnessMatrix(body, 0.5, fromVector(x));
    a.diagonal().array() += 1e-9 * a.diagonal().cwiseAbs().maxCoeff();
    x += test::ldltSolve(a, f);
  }
  EXPECT_LT(forceVector(body, 0.5, fromVector(x)).cwiseAbs().maxCoeff(), 1e-9) << segments << " segments";
  const int n = model.bell_markers - 1;
  return std::hypot(x[2 * n] - x[0], x[2 * n + 1] - x[1]) / model.aperture_width_m;
}

// Lowest mirror-symmetric flexible mode of the bell in vacuum (the breathing mode): K v = −ω² M v
// with the slice's masses (mesoglea of 1000 kg/m³, its thickness times each marker's arc).
double breathingHz(int segments) {
  BellParams p = activeBell(segments, 0.0);
  const BellModel model = buildBell(p);
  const JellyfishBody body(model, pulse(0.2, 0), kWaterViscosity_pa_s);
  const Markers& x = model.rest_positions_m;
  const Eigen::MatrixXd k = -stiffnessMatrix(body, 0.0, x);
  const long n = k.rows();
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  for (int s = 0; s < model.network.springCount(); ++s) {
    const int a = model.network.spring_a[s], b = model.network.spring_b[s];
    const bool tentacle = a >= model.bell_markers || b >= model.bell_markers;
    const double m = 1000.0 * p.thickness_m * (tentacle ? p.tentacle_area_factor : 1.0) * model.network.rest_length_m[s];
    for (int i : {a, b}) mass.segment<2>(2 * i).array() += 0.5 * m;
  }
  // Mirror-symmetric subspace: x-displacements antisymmetric, y symmetric under the mirror.
  std::vector<int> mirror(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      if (std::abs(x[i].x + x[j].x) < 1e-15 && std::abs(x[i].y - x[j].y) < 1e-15) mirror[i] = int(j);
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(n, n);
  int cols = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const int j = mirror[i];
    if (int(i) > j) continue;
    if (int(i) != j) {  // x: u_i = -u_j
      basis(2 * i, cols) = 1;
      basis(2 * j, cols++) = -1;
    }
    basis(2 * i + 1, cols) = 1;  // y: v_i = v_j
    basis(2 * j + 1, cols++) = 1;
  }
  basis.conservativeResize(n, cols);
  const Eigen::MatrixXd ks = basis.transpose() * k * basis;
  const Eigen::MatrixXd ms = basis.transpose() * mass.asDiagonal() * basis;
  // The vertical translation is the one rigid symmetric mode.
  const Eigen::VectorXd w2 = test::generalizedSymmetricEigenvalues(ks, ms);
  EXPECT_LT(std::abs(w2[0]), 1e-6 * w2[1]) << segments << " segments";
  return std::sqrt(w2[1]) / (2 * M_PI);
}

TEST(JellyfishContinuum, StaticShapeUnderLoadConvergesAsSegmentsDouble) {
  const double r32 = loadedDiameterRatio(32), r64 = loadedDiameterRatio(64), r128 = loadedDiameterRatio(128);
  EXPECT_LT(r32, 0.95) << "the load contracts the bell";
  const double e1 = std::abs(r64 - r32), e2 = std::abs(r128 - r64);
  EXPECT_LT(e2, 0.5 * e1) << r32 << " " << r64 << " " << r128;
  EXPECT_LT(e2, 0.01 * (1 - r128)) << r32 << " " << r64 << " " << r128;
}

TEST(JellyfishContinuum, InVacuumBreathingFrequencyConvergesAsSegmentsDouble) {
  const double f32 = breathingHz(32), f64 = breathingHz(64), f128 = breathingHz(128);
  const double e1 = std::abs(f64 - f32), e2 = std::abs(f128 - f64);
  EXPECT_GT(f32, 0.0);
  EXPECT_LT(e2, 0.5 * e1) << f32 << " " << f64 << " " << f128;
  EXPECT_LT(e2, 0.01 * f128) << f32 << " " << f64 << " " << f128;
}

}  // namespace
}  // namespace creaturelab::jellyfish
