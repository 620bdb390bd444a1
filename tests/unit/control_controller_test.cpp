// The controller (Lentine et al. 2010 §2, §5): derivative of a known objective, the strength
// limit, the servo reaching targets under load with outboard joints rigidified, determinism
// across thread counts, parameter validation.
#include <gtest/gtest.h>

#include <cmath>

#include "control/controller.hpp"
#include "control/simple_wind.hpp"
#include "control_models.hpp"

namespace creaturelab::control {
namespace {

class ControllerTest : public testing::ScratchDirTest {
 protected:
  ControllerTest() : ScratchDirTest("controller") {}
  ControllerParams one(Objective o, Sense s) {
    ControllerParams p;
    p.controlled = {"hinge"};
    p.objectives = {o};
    p.senses = {s};
    return p;
  }
};

// Steady drag |F_d| = 2 rho U^2 sqrt(sin^4 + t^2 cos^4) (control_wind_test.cpp): the central
// difference over +-0.01 rad matches its derivative to O(delta^2).
TEST_F(ControllerTest, CentralDifferenceMatchesAnalyticDerivative) {
  const double t = 0.1, U = 10, rho = 1.2, theta = 0.4;
  const auto model = rigid::RigidModel::load(testing::writeText(file("block.xml"), testing::blockXml(t, 0)));
  const SimpleWind wind(rigid::geomSurfaces(model, 12), rho, constantWind({U, 0, 0}));
  ControllerParams p = one(Objective::drag, Sense::minimize);
  p.steady_state = true;
  Controller c(model, p, wind);
  c.setAngle("hinge", theta);
  auto drag = [&](double x) {
    const double s = std::sin(x), co = std::cos(x);
    return 2 * rho * U * U * std::sqrt(s * s * s * s + t * t * co * co * co * co);
  };
  EXPECT_NEAR(c.evaluate(0, 0.0), drag(theta), 1e-9);
  const double exact = (drag(theta + 1e-6) - drag(theta - 1e-6)) / 2e-6;
  const double g = c.derivatives()[0];
  EXPECT_NEAR(g, exact, 1e-3 * std::abs(exact));
  // One-sided differences are biased by the curvature (§2.1): O(delta), visibly worse.
  p.one_sided = true;
  Controller forward(model, p, wind);
  forward.setAngle("hinge", theta);
  EXPECT_GT(std::abs(forward.derivatives()[0] - exact), 10 * std::abs(g - exact));
}

// Effort holding a block still under gravity (steady): |m g (L/2) cos theta| x frame (Eq. 1).
TEST_F(ControllerTest, EffortIsTheHoldingImpulse) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("block.xml"), testing::blockXml(0.02, 9.81)));
  const NoForce none;
  ControllerParams p = one(Objective::effort, Sense::minimize);
  p.steady_state = true;
  Controller c(model, p, none);
  c.setAngle("hinge", 0.3);
  const JointMeasures m = c.measureNow();
  EXPECT_NEAR(m.effort_n_m_s[0], 24 * 9.81 * 0.5 * std::cos(0.3) * p.frame_s, 1e-9);
}

// §2.1: each frame the joint moves by exactly strength x frame, against the gradient.
TEST_F(ControllerTest, StepIsLimitedByStrength) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("block.xml"), testing::blockXml(0.02, 9.81)));
  const SimpleWind wind(rigid::geomSurfaces(model, 12), 1.2, constantWind({10, 0, 0}));
  ControllerParams p = one(Objective::effort, Sense::minimize);
  p.strength_rad_per_s = 0.7;
  Controller c(model, p, wind);
  c.setAngle("hinge", 0.2);  // tip below the horizontal: effort falls as it hangs lower
  double before = 0.2;
  for (int f = 0; f < 5; ++f) {
    const FrameRecord r = c.frame();
    EXPECT_NEAR(r.angle_rad[0] - before, 0.7 * p.frame_s, 1e-12) << "frame " << f;
    EXPECT_LT(r.derivative[0], 0);
    before = r.angle_rad[0];
  }
}

// The servo lands a prescribed joint on its target in one step under gravity and wind, holding
// the outboard joint rigid (§5) and leaving a free one to the dynamics; Newton converges so that
// the projection afterwards removes less than 1e-9 rad.
TEST_F(ControllerTest, ServoReachesTargetsUnderLoadWithOutboardRigidified) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(3)));
  rigid::RigidData d(model);
  const SimpleWind wind(rigid::geomSurfaces(model, 12), 1.2, constantWind({20, 0, 0}));
  d.qpos()[0] = 0.5;
  d.qpos()[1] = -0.4;
  d.qpos()[2] = 0.2;
  d.qvel()[2] = 1.0;
  d.kinematics();
  Prescribed p;
  p.qpos = {0, 1};
  p.dof = {0, 1};
  p.target = {0.52, -0.4};  // j0 perturbed, j1 held with it
  ServoScratch s;
  const ServoReport r = advanceFrame(d, p, wind, 1, 8, 1e-12, s);
  EXPECT_LT(r.residual_rad, 1e-9);
  EXPECT_EQ(d.qpos()[0], 0.52);
  EXPECT_EQ(d.qpos()[1], -0.4);
  EXPECT_NE(d.qpos()[2], 0.2);  // the free joint moved under gravity and its own velocity
  // Without the servo, gravity alone would have moved j0 (the load is real).
  rigid::RigidData free(model);
  free.qpos()[0] = 0.5;
  free.qpos()[1] = -0.4;
  free.kinematics();
  for (int k = 0; k < 5; ++k) free.step();
  EXPECT_GT(free.qpos()[0] - 0.5, 1e-3);
}

// §5 with several joints: per-DOF evaluations in parallel give bitwise the same run for any
// thread count.
TEST_F(ControllerTest, ThreadsDoNotChangeResults) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(4)));
  const SimpleWind wind(rigid::geomSurfaces(model, 8), 1.2, constantWind({8, 0, 3}));
  auto run = [&](int threads) {
    ControllerParams p;
    p.controlled = {"j0", "j1", "j2"};
    p.objectives = {Objective::effort, Objective::effort, Objective::drag};
    p.senses = {Sense::minimize, Sense::minimize, Sense::maximize};
    p.weights = {{1, 0.5, 0}, {0, 1, 0}, {0, 0, 1}};
    p.threads = threads;
    Controller c(model, p, wind);
    c.setAngle("j0", 0.4);
    std::vector<double> out;
    for (int f = 0; f < 15; ++f) {
      const FrameRecord r = c.frame();
      out.insert(out.end(), r.angle_rad.begin(), r.angle_rad.end());
      out.insert(out.end(), r.derivative.begin(), r.derivative.end());
    }
    out.push_back(c.data().qpos()[3]);
    return out;
  };
  const auto serial = run(1);
  for (int threads : {2, 3}) {
    const auto parallel = run(threads);
    ASSERT_EQ(parallel.size(), serial.size());
    for (std::size_t k = 0; k < serial.size(); ++k) ASSERT_EQ(parallel[k], serial[k]) << threads << " threads, value " << k;
  }
}

// §3.3 for a free creature: the steady-state drag of a creature drifting rigidly with the wind is
// zero (its shape frozen, its momentum kept); zeroing every velocity, right for a creature rooted
// in a stationary object, would stop it in the wind. With the fin also swinging, the frozen
// creature still drifts (momentum kept), so its drag stays far below the stopped creature's.
TEST_F(ControllerTest, SteadyStateOfAFreeCreatureKeepsItsDrift) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("free.xml"), testing::freeCreatureXml()));
  const double U = 10;
  const SimpleWind wind(rigid::geomSurfaces(model, 8), 1.2, constantWind({U, 0, 0}));
  ControllerParams p = one(Objective::drag, Sense::minimize);
  p.controlled = {"fin"};
  p.steady_state = true;
  Controller c(model, p, wind);
  c.setAngle("fin", 0.5);
  c.data().qvel()[0] = U;
  EXPECT_LT(c.measureNow().drag_n[0], 1e-12);
  c.data().qvel()[12] = 3.0;  // the fin swinging: relative velocity, zeroed with momentum kept
  const double drifting = c.measureNow().drag_n[0];
  c.data().qvel()[0] = 0;
  c.data().qvel()[12] = 0;
  const double stopped = c.measureNow().drag_n[0];
  EXPECT_GT(stopped, 1.0);
  EXPECT_LT(drifting, 0.05 * stopped);
}

TEST_F(ControllerTest, ValidationNamesWhatIsWrong) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(2)));
  ControllerParams p;
  p.controlled = {"j0", "elbow"};
  p.objectives = {Objective::effort, Objective::effort};
  p.senses = {Sense::minimize, Sense::minimize};
  EXPECT_NE(p.validate(model).find("'elbow'"), std::string::npos);
  p.controlled = {"j0", "j1"};
  EXPECT_EQ(p.validate(model), "");
  p.weights = {{1, 0}, {0, 1, 0}};
  EXPECT_NE(p.validate(model).find("weights: row 2"), std::string::npos);
  p.weights.clear();
  p.strength_rad_per_s = -1;
  EXPECT_NE(p.validate(model).find("strength"), std::string::npos);
  p.strength_rad_per_s = 1;
  p.delta_rad = 0;
  EXPECT_NE(p.validate(model).find("delta_rad"), std::string::npos);
  // The controller refuses them too, before it reads the model by name.
  const NoForce none;
  p.delta_rad = 0.01;
  p.controlled = {"j0", "elbow"};
  EXPECT_THROW(Controller(model, p, none), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::control
