// The jellyfish as the immersed boundary sees it (jellyfish/jellyfish_body.hpp; Rudolf & Mould 2009,
// §3.1-3.3): forces of bell, tentacles and the tension-only
// circumferential muscle, their energy and stiffness, checked as properties of the discrete
// operators (equilibrium at rest, momentum and angular momentum, gradient of the energy, finite
// differences of the force) and the muscle timing (Spencer's synaptic delay, §3.1).
#include "jellyfish/jellyfish_body.hpp"
#include "jellyfish_stiffness_matrix.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <stdexcept>
#include <vector>

#include "springs/system.hpp"
#include "support/dense_linalg.hpp"
#include "support/jellyfish_water.hpp"

namespace creaturelab::jellyfish {
namespace {
using test::kWaterViscosity_pa_s;

using Markers = std::vector<fluid::Vec2>;

const BellModel& defaultModel() {
  static const BellModel model = buildBell(paperBell());
  return model;
}

// The default curve contracts over phases [0, 0.3] and expands over [0.3, 1) (jellyfish_params.hpp).
constexpr double kHz = 0.7;
double timeAtPhase(double phase) { return phase / kHz; }

ActivationParams activation(Expansion e = Expansion::staggered, double delay_s = 0.0) {
  ActivationParams a = paperActivation();
  a.contraction_hz = kHz;
  a.expansion = e;
  a.synaptic_delay_s = delay_s;
  return a;
}

Markers forcesAt(const JellyfishBody& body, double t, const Markers& x) {
  Markers f(x.size(), fluid::Vec2{123.0, -456.0});  // garbage: forces() must overwrite, not add
  body.forces(t, x, f);
  return f;
}

double& coord(Markers& x, int c) { return c % 2 == 0 ? x[c / 2].x : x[c / 2].y; }

using testing::stiffnessMatrix;

// Central differences of the forces, column by column.
Eigen::MatrixXd forceJacobianFd(const JellyfishBody& body, double t, const Markers& x, double h) {
  const int n = 2 * static_cast<int>(x.size());
  Eigen::MatrixXd j(n, n);
  for (int c = 0; c < n; ++c) {
    Markers xp = x, xm = x;
    coord(xp, c) += h;
    coord(xm, c) -= h;
    const Markers fp = forcesAt(body, t, xp), fm = forcesAt(body, t, xm);
    for (int r = 0; r < n / 2; ++r) {
      j(2 * r, c) = (fp[r].x - fm[r].x) / (2 * h);
      j(2 * r + 1, c) = (fp[r].y - fm[r].y) / (2 * h);
    }
  }
  return j;
}

// The rest shape with every marker moved by up to `amplitude` in each axis, then rotated by `angle`
// about the origin and shifted: a generic deformed bell.
Markers perturbed(std::mt19937_64& rng, double amplitude, double angle = 0.0) {
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  Markers x = defaultModel().rest_positions_m;
  const double c = std::cos(angle), s = std::sin(angle);
  for (auto& p : x) {
    const fluid::Vec2 q{p.x + u(rng), p.y + u(rng)};
    p = {c * q.x - s * q.y + 0.2, s * q.x + c * q.y + 0.1};
  }
  return x;
}

// ---- equilibrium ------------------------------------------------------------------------------

// At t = 0 the curve is at its relaxed knot (factor 1), so every muscle is at its relaxed length and
// the bell as drawn is in equilibrium: zero force and zero energy. At the end of the contraction
// (phase 0.3, factor 0.56, §3.3) the same shape is pulled: every muscle is in tension and the
// aperture markers are pulled toward the axis (the jet-producing contraction, §3.1).
TEST(JellyfishBody, ForcesVanishAtRestShapeAtTimeZero) {
  const JellyfishBody body(defaultModel(), activation(), kWaterViscosity_pa_s);
  const Markers& x = defaultModel().rest_positions_m;
  for (const auto& f : forcesAt(body, 0.0, x)) {
    EXPECT_LT(std::abs(f.x), 1e-12);
    EXPECT_LT(std::abs(f.y), 1e-12);
  }
  EXPECT_LT(body.elasticEnergy(0.0, x), 1e-24);

  const double t = timeAtPhase(0.3);
  const Markers f = forcesAt(body, t, x);
  const int right = defaultModel().bell_markers - 1;
  EXPECT_GT(f[0].x, 1.0);
  EXPECT_LT(f[right].x, -1.0);
  EXPECT_EQ(f[0].x, -f[right].x);  // symmetric pull on a symmetric bell
  std::vector<double> tension;
  body.muscleTensions(t, x, tension);
  for (std::size_t m = 0; m < tension.size(); ++m) {
    // Hooke: k (L - 0.56 L) = 0.44 E s w for every element (k L = E s w).
    const MuscleSpring& s = defaultModel().muscles[m];
    EXPECT_NEAR(tension[m], 0.44 * 4e5 * paperBell().muscle_section_per_arc * s.arc_weight_m, 1e-9) << "muscle " << m;
  }
  EXPECT_NEAR(
      body.elasticEnergy(t, x),
      0.5 * 0.44 * 0.44 *
          [&] {  // ½ k (0.44 L)² with k L = E s w
            double sum = 0;
            for (const auto& s : defaultModel().muscles)
              sum += 4e5 * paperBell().muscle_section_per_arc * s.arc_weight_m * s.relaxed_length_m;
            return sum;
          }(),
      1e-12);
}

// ---- momentum ---------------------------------------------------------------------------------

// The body's forces are internal (springs act in equal and opposite pairs; a bend's energy depends
// only on the shape): they sum to zero and have zero net torque about any point, for any shape and
// any time, or the bell would push itself without pushing the fluid (Peskin 2002 §5: the elastic
// force density of an immersed body has zero total force and torque).
TEST(JellyfishBody, InternalForcesHaveZeroSumAndZeroTorque) {
  std::mt19937_64 rng(20240517);
  const JellyfishBody staggered(defaultModel(), activation(), kWaterViscosity_pa_s);
  const JellyfishBody delayed(defaultModel(), activation(Expansion::unison, 0.05), kWaterViscosity_pa_s);
  std::uniform_real_distribution<double> time(0.0, 3.0), angle(-M_PI, M_PI);
  for (int trial = 0; trial < 40; ++trial) {
    const Markers x = perturbed(rng, 1.5e-3, angle(rng));
    const double t = time(rng);
    for (const JellyfishBody* body : {&staggered, &delayed}) {
      const Markers f = forcesAt(*body, t, x);
      double fx = 0, fy = 0, torque = 0, force_scale = 0, torque_scale = 0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        fx += f[i].x;
        fy += f[i].y;
        torque += x[i].x * f[i].y - x[i].y * f[i].x;  // about the origin, 0.2 m away from the bell
        force_scale += std::hypot(f[i].x, f[i].y);
        torque_scale += std::hypot(x[i].x, x[i].y) * std::hypot(f[i].x, f[i].y);
      }
      ASSERT_GT(force_scale, 1e-3);
      EXPECT_LT(std::abs(fx), 1e-13 * force_scale) << "trial " << trial;
      EXPECT_LT(std::abs(fy), 1e-13 * force_scale) << "trial " << trial;
      EXPECT_LT(std::abs(torque), 1e-12 * torque_scale) << "trial " << trial;
    }
  }
}

// ---- energy and forces ------------------------------------------------------------------------

// The forces are conservative at fixed time: F = -grad E with E the elastic energy of springs,
// bends and muscles (0.5 k max(0, |l| - r(t))^2 for a muscle: C1, so central differences apply).
// Shapes deformed by up to 1 mm at times across the cycle, where some muscles are slack and some
// taut.
TEST(JellyfishBody, ForcesAreMinusTheGradientOfTheEnergy) {
  std::mt19937_64 rng(7);
  const JellyfishBody body(defaultModel(), activation(), kWaterViscosity_pa_s);
  int slack_seen = 0, taut_seen = 0;
  for (double phase : {0.05, 0.2, 0.3, 0.45, 0.7, 0.95}) {
    const double t = timeAtPhase(phase) + 2.0 / kHz;  // a later cycle
    const Markers x = perturbed(rng, 1e-3, 0.4);
    std::vector<double> tension;
    body.muscleTensions(t, x, tension);
    for (double v : tension) (v > 0 ? taut_seen : slack_seen)++;
    const Markers f = forcesAt(body, t, x);
    double scale = 0;
    for (const auto& v : f) scale = std::max({scale, std::abs(v.x), std::abs(v.y)});
    const double h = 1e-8;
    for (int c = 0; c < 2 * static_cast<int>(x.size()); ++c) {
      Markers xp = x, xm = x;
      coord(xp, c) += h;
      coord(xm, c) -= h;
      const double gradient = (body.elasticEnergy(t, xp) - body.elasticEnergy(t, xm)) / (2 * h);
      const double force = c % 2 == 0 ? f[c / 2].x : f[c / 2].y;
      EXPECT_NEAR(force, -gradient, 1e-6 * scale) << "phase " << phase << " coordinate " << c;
    }
  }
  EXPECT_GT(slack_seen, 0);  // both branches of the tension-only muscle were exercised
  EXPECT_GT(taut_seen, 0);
}

// ---- stiffness --------------------------------------------------------------------------------

// The stiffness is dF/dX (ib/coupling.hpp, step 3), except that, by the coupling's contract, the
// transverse term of a compressed spring and the curvature term of a bent angular spring are dropped
// (so that -dF/dX is positive semi-definite). Where neither applies, i.e. every spring stretched and
// every bend at its rest angle, the triplets must equal central differences of the force. That is
// the drawn bell stretched uniformly by 2 % (angles kept), rotated and shifted, during the
// contraction when no muscle is slack.
TEST(JellyfishBody, StiffnessEqualsFiniteDifferencesWhenNoMuscleIsSlack) {
  const JellyfishBody body(defaultModel(), activation(), kWaterViscosity_pa_s);
  const double c = std::cos(0.3), s = std::sin(0.3);
  Markers x = defaultModel().rest_positions_m;
  for (auto& p : x) p = {1.02 * (c * p.x - s * p.y) + 0.2, 1.02 * (s * p.x + c * p.y) + 0.1};
  for (double phase : {0.1, 0.5}) {  // contracting; expanding with staggered factors
    const double t = timeAtPhase(phase);
    std::vector<double> tension;
    body.muscleTensions(t, x, tension);
    for (double v : tension) ASSERT_GT(v, 0.0) << "phase " << phase;
    const Eigen::MatrixXd k = stiffnessMatrix(body, t, x);
    const Eigen::MatrixXd fd = forceJacobianFd(body, t, x, 1e-7);
    const double scale = k.cwiseAbs().maxCoeff();
    EXPECT_LT((k - fd).cwiseAbs().maxCoeff(), 1e-6 * scale) << "phase " << phase;
  }
}

// The muscle part alone has no clamping (a taut muscle has 1 - r/|l| > 0): for a body made of the
// muscles only, the triplets equal finite differences at any deformed shape while the muscles are
// taut.
TEST(JellyfishBody, MuscleStiffnessEqualsFiniteDifferencesAtAnyTautShape) {
  BellModel muscles_only = defaultModel();
  muscles_only.network = springs::Network<2>{};
  for (std::size_t i = 0; i < muscles_only.rest_positions_m.size(); ++i) muscles_only.network.addParticle(1.0, false);
  const JellyfishBody body(muscles_only, activation(), kWaterViscosity_pa_s);
  std::mt19937_64 rng(99);
  for (int trial = 0; trial < 5; ++trial) {
    const Markers x = perturbed(rng, 1e-3, 1.0 * trial);
    const double t = timeAtPhase(0.25 + 0.02 * trial);
    std::vector<double> tension;
    body.muscleTensions(t, x, tension);
    for (double v : tension) ASSERT_GT(v, 0.0);
    const Eigen::MatrixXd k = stiffnessMatrix(body, t, x);
    const Eigen::MatrixXd fd = forceJacobianFd(body, t, x, 1e-7);
    EXPECT_LT((k - fd).cwiseAbs().maxCoeff(), 1e-6 * k.cwiseAbs().maxCoeff()) << "trial " << trial;
  }
}

// The coupling's contract (ib/coupling.hpp): K = dF/dX as returned is symmetric and -K is positive
// semi-definite for any shape and time, so that m I - dt^2 K is positive definite for the LDLT
// solve of the semi-implicit step.
TEST(JellyfishBody, StiffnessIsSymmetricNegativeSemidefinite) {
  std::mt19937_64 rng(3);
  const JellyfishBody body(defaultModel(), activation(), kWaterViscosity_pa_s);
  std::uniform_real_distribution<double> time(0.0, 2.0);
  for (int trial = 0; trial < 4; ++trial) {
    // Large deformations (up to 3 mm, more than a segment) so that springs are compressed and bends far from rest.
    const Markers x = perturbed(rng, trial < 2 ? 1e-3 : 3e-3, 0.7 * trial);
    const double t = time(rng);
    const Eigen::MatrixXd k = stiffnessMatrix(body, t, x);
    const double scale = k.cwiseAbs().maxCoeff();
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale) << "trial " << trial;
    EXPECT_GT(test::symmetricEigenvalues(-0.5 * (k + k.transpose())).minCoeff(), -1e-10 * scale) << "trial " << trial;
  }
}

// ---- tension-only muscle (§3.1: "The circumferential muscle has no opposing muscle") ------------

// A muscle shorter than its rest length is slack: it exerts no force and adds no stiffness, so the
// body's forces and stiffness are exactly those of the bell's network alone. Here the bell is
// squeezed sideways to half its width at t = 0 (factor 1): every muscle is slack.
TEST(JellyfishBody, SlackMusclesGiveNoForceAndNoStiffness) {
  const BellModel& model = defaultModel();
  const JellyfishBody body(model, activation(), kWaterViscosity_pa_s);
  Markers x = model.rest_positions_m;
  for (auto& p : x) p.x *= 0.5;
  std::vector<double> tension;
  body.muscleTensions(0.0, x, tension);
  for (double v : tension) EXPECT_EQ(v, 0.0);

  const springs::System<2> network(model.network);
  springs::State<2> s = springs::zeroState<2>(model.network.particleCount());
  for (std::size_t i = 0; i < x.size(); ++i) s.x_m.col(static_cast<long>(i)) << x[i].x, x[i].y;
  springs::Points<2> expected;
  network.conservativeForces(s, expected);
  const Markers f = forcesAt(body, 0.0, x);
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(f[i].x, expected(0, long(i))) << "marker " << i;
    EXPECT_EQ(f[i].y, expected(1, long(i))) << "marker " << i;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  network.addStiffnessTriplets(s, 1.0, triplets, /*clamp_compression=*/true);
  const int n = 2 * static_cast<int>(x.size());
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(triplets.begin(), triplets.end());
  EXPECT_EQ((stiffnessMatrix(body, 0.0, x) - Eigen::MatrixXd(k)).cwiseAbs().maxCoeff(), 0.0);
}

// A taut muscle pulls its two markers toward each other with Hooke's tension k (|l| - r) along the
// muscle (and, since the tension is one-sided, a muscle a hair longer than its rest length pulls a
// hair: the force is continuous where the muscle goes slack).
TEST(JellyfishBody, TautMusclePullsWithHookesTension) {
  const BellModel& model = defaultModel();
  const JellyfishBody body(model, activation(Expansion::unison), kWaterViscosity_pa_s);
  const springs::System<2> network(model.network);
  const double t = timeAtPhase(0.3);  // factor 0.56 for every muscle
  const MuscleSpring& m = model.muscles[0];
  for (double excess : {1e-3, 1e-9}) {
    // Aperture markers moved in to 0.56 L + excess: the aperture muscle is barely taut.
    Markers x = model.rest_positions_m;
    const double half = 0.5 * (0.56 * m.relaxed_length_m + excess);
    x[m.a].x = -half;
    x[m.b].x = half;
    springs::State<2> s = springs::zeroState<2>(model.network.particleCount());
    for (std::size_t i = 0; i < x.size(); ++i) s.x_m.col(static_cast<long>(i)) << x[i].x, x[i].y;
    springs::Points<2> passive;
    network.conservativeForces(s, passive);
    const Markers f = forcesAt(body, t, x);
    const double expected = m.stiffness_n_per_m * excess;  // on marker a, toward +x
    EXPECT_NEAR(f[m.a].x - passive(0, m.a), expected, 1e-9 * m.stiffness_n_per_m * 1e-3) << "excess " << excess;
    EXPECT_NEAR(f[m.b].x - passive(0, m.b), -expected, 1e-9 * m.stiffness_n_per_m * 1e-3) << "excess " << excess;
    EXPECT_EQ(f[m.a].y - passive(1, m.a), 0.0);
  }
}

// ---- timing -----------------------------------------------------------------------------------

// Spencer's synaptic delay (§3.1): the impulse reaches pair k (counted from the aperture) k · delay
// later, so pair k's factor is the undelayed pair k's factor shifted in time by k · delay. Measured
// as the moment each pair's rest length crosses 0.78 (halfway) during the contraction, found by
// bisection: the crossings are k · delay apart, and the aperture pair is not delayed at all.
TEST(JellyfishBody, SynapticDelayShiftsEachPairByItsOrder) {
  // 15 elements in the band: the last starts 14 delays late, 0.28 s as in the earlier 8-pair bell
  // at 0.04 s per pair, so that every pair is still expanding at the brackets below.
  const double delay = 0.02;
  for (Expansion e : {Expansion::unison, Expansion::staggered}) {
    const JellyfishBody plain(defaultModel(), activation(e, 0.0), kWaterViscosity_pa_s);
    const JellyfishBody delayed(defaultModel(), activation(e, delay), kWaterViscosity_pa_s);
    const int pairs = static_cast<int>(defaultModel().muscles.size());
    for (int k = 0; k < pairs; ++k) {
      for (int i = 0; i < 50; ++i) {
        const double t = 0.05 * i;
        EXPECT_NEAR(delayed.muscleFactor(k, t), plain.muscleFactor(k, t - k * delay), 1e-15) << "pair " << k;
      }
      // Brackets in the second cycle: from its start (factor > 0.78 for every pair, relaxed or
      // finishing the expansion) to the end of the contraction (0.56), later by k · delay for the
      // delayed body.
      auto crossing = [&](const JellyfishBody& b, double extra) {
        double lo = 1.0 / kHz, hi = 1.0 / kHz + timeAtPhase(0.3) + extra;
        EXPECT_GT(b.muscleFactor(k, lo), 0.78);
        EXPECT_LT(b.muscleFactor(k, hi), 0.78);
        for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
          const double mid = 0.5 * (lo + hi);
          (b.muscleFactor(k, mid) > 0.78 ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
      };
      EXPECT_NEAR(crossing(delayed, k * delay) - crossing(plain, 0.0), k * delay, 1e-11) << "pair " << k;
    }
    for (int i = 0; i < 50; ++i) EXPECT_EQ(delayed.muscleFactor(0, 0.05 * i), plain.muscleFactor(0, 0.05 * i));
  }
}

// Without delay and with unison expansion every pair follows the same curve at every time; with the
// staggered expansion they agree during the contraction and differ during the expansion, the apex
// pairs being more relaxed (§3.3, Fig. 4). The stagger is ignored in unison mode even when set.
TEST(JellyfishBody, UnisonPairsMoveTogetherStaggeredPairsDifferOnlyInExpansion) {
  ActivationParams unison = activation(Expansion::unison);
  unison.stagger = 0.9;
  const JellyfishBody u(defaultModel(), unison, kWaterViscosity_pa_s);
  const JellyfishBody s(defaultModel(), activation(Expansion::staggered), kWaterViscosity_pa_s);
  const int pairs = static_cast<int>(defaultModel().muscles.size());
  for (int i = 0; i < 100; ++i) {
    const double t = 3.0 * i / 100.0;
    for (int k = 1; k < pairs; ++k) EXPECT_EQ(u.muscleFactor(k, t), u.muscleFactor(0, t));
  }
  for (int k = 1; k < pairs; ++k) {
    EXPECT_EQ(s.muscleFactor(k, timeAtPhase(0.2)), s.muscleFactor(0, timeAtPhase(0.2)));
    EXPECT_GT(s.muscleFactor(k, timeAtPhase(0.5)), s.muscleFactor(k - 1, timeAtPhase(0.5)));
  }
}

// Porous tentacles (ib::PorousSlip): every tentacle marker but the root slips, along the chain's unit
// normal, with mobility α / ds (ds half of the two segments beside it, half the last at the tip);
// impermeable chains (α = 0) and the bell have none.
TEST(JellyfishBody, TentacleMarkersArePorousAlongTheirNormal) {
  BellParams p = paperBell();
  p.tentacle_permeability_m = 0.02 * kWaterViscosity_pa_s;  // a Darcy coefficient of 0.02 m/(Pa s)
  const BellModel model = buildBell(p);
  const JellyfishBody body(model, activation(), kWaterViscosity_pa_s);
  std::vector<ib::PorousSlip> slips;
  body.porousSlips(model.rest_positions_m, slips);
  ASSERT_EQ(slips.size(), model.tentacle_markers.size());
  for (const ib::PorousSlip& s : slips) {
    EXPECT_GE(s.marker, model.bell_markers);
    EXPECT_NEAR(std::abs(s.nx), 1.0, 1e-12);  // the chains hang straight down: horizontal normals
    EXPECT_NEAR(s.ny, 0.0, 1e-12);
  }
  const double segment = p.tentacle_length_m / 10;
  EXPECT_NEAR(slips.front().mobility, 0.02 / segment, 1e-9 * 0.02 / segment);
  EXPECT_NEAR(slips[9].mobility, 0.02 / (0.5 * segment), 1e-9 * 0.02 / segment) << "the tip";
  const JellyfishBody solid(buildBell(paperBell()), activation(), kWaterViscosity_pa_s);
  solid.porousSlips(model.rest_positions_m, slips);
  EXPECT_TRUE(slips.empty());
}

// The Darcy coefficient is the permeability over the surrounding fluid's μ: a permeable body without a
// viscosity is refused, and halving μ doubles every slip's mobility.
TEST(JellyfishBody, TentaclePorosityIsPermeabilityOverTheFluidsViscosity) {
  BellParams p = paperBell();
  p.tentacle_permeability_m = 1.7e-3;
  const BellModel model = buildBell(p);
  EXPECT_THROW(JellyfishBody(model, activation(), 0.0), std::invalid_argument);
  EXPECT_NO_THROW(JellyfishBody(buildBell(paperBell()), activation(), 0.0)) << "impermeable: no viscosity needed";
  std::vector<ib::PorousSlip> water, thinner;
  JellyfishBody(model, activation(), kWaterViscosity_pa_s).porousSlips(model.rest_positions_m, water);
  JellyfishBody(model, activation(), 0.5 * kWaterViscosity_pa_s).porousSlips(model.rest_positions_m, thinner);
  ASSERT_EQ(water.size(), thinner.size());
  ASSERT_FALSE(water.empty());
  for (std::size_t i = 0; i < water.size(); ++i) EXPECT_NEAR(thinner[i].mobility, 2 * water[i].mobility, 1e-12 * water[i].mobility);
}

}  // namespace
}  // namespace creaturelab::jellyfish
