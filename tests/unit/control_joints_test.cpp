// Joints beyond the controlled hinge (Lentine et al. 2010 §2.2, §5): kinematic joints that follow
// a motion pattern under load, PD-driven joints, and ball joints controlled (three axes, each
// differenced and stepped by the strength) and held rigid while another joint is perturbed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "control/controller.hpp"
#include "control/simple_wind.hpp"
#include "control_models.hpp"
#include "rigid/rotation.hpp"

namespace creaturelab::control {
namespace {

class JointsTest : public testing::ScratchDirTest {
 protected:
  JointsTest() : ScratchDirTest("joints") {}
};

rigid::Quat quatAt(const double* q) { return {q[0], q[1], q[2], q[3]}; }

ControllerParams minimiseEffort(const std::string& joint) {
  ControllerParams p;
  p.controlled = {joint};
  p.objectives = {Objective::effort};
  p.senses = {Sense::minimize};
  return p;
}

Pattern sine(double mean, double amplitude, double hz, double phase) {
  Pattern p;
  p.kind = Pattern::Kind::sine;
  p.mean_rad = mean;
  p.amplitude_rad = amplitude;
  p.frequency_hz = hz;
  p.phase_rad = phase;
  return p;
}

TEST_F(JointsTest, PatternsInterpolateAndHold) {
  Pattern t;
  t.kind = Pattern::Kind::table;
  t.time_s = {0.0, 0.5, 1.0};
  t.angle_rad = {0.0, 0.4, -0.2};
  EXPECT_EQ(t.validate(), "");
  EXPECT_DOUBLE_EQ(t.angle(0.25, 9), 0.2);
  EXPECT_DOUBLE_EQ(t.angle(0.75, 9), 0.1);
  EXPECT_DOUBLE_EQ(t.angle(3.0, 9), -0.2);
  EXPECT_DOUBLE_EQ(t.angle(-1.0, 9), 0.0);
  EXPECT_DOUBLE_EQ(t.rate(0.6), -1.2);
  EXPECT_EQ(t.rate(2.0), 0.0);
  Pattern h;
  EXPECT_EQ(h.angle(5, 0.7), 0.7);
  const Pattern s = sine(0.1, 0.3, 2, 0.5);
  EXPECT_NEAR(s.rate(0.2), (s.angle(0.2 + 1e-6, 0) - s.angle(0.2 - 1e-6, 0)) / 2e-6, 1e-6);
  t.time_s = {0.0, 0.5, 0.5};
  EXPECT_NE(t.validate().find("increase"), std::string::npos);
  t.angle_rad.pop_back();
  EXPECT_NE(t.validate().find("differ"), std::string::npos);
}

// A kinematic shoulder swinging through a sine carries the rest of the chain under gravity and a
// 20 m/s wind while the next joint is controlled: at the end of every frame it is on its pattern
// (the servo's own miss before the projection below 1e-9 rad: the load is carried by the servo's
// torques, not by the projection), and it really swings through the amplitude.
TEST_F(JointsTest, KinematicJointTracksItsPatternUnderLoad) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(3)));
  const SimpleWind wind(rigid::geomSurfaces(model, 8), 1.2, constantWind({20, 0, 0}));
  ControllerParams p = minimiseEffort("j1");
  p.kinematic = {"j0"};
  p.kinematic_patterns = {sine(0.3, 0.6, 1.5, 0.0)};
  p.substeps = 3;
  Controller c(model, p, wind);
  double lo = 1e9, hi = -1e9, worst_servo = 0;
  for (int f = 0; f < 45; ++f) {
    const FrameRecord r = c.frame();
    const double q = c.data().qpos()[0];
    EXPECT_LT(std::abs(q - p.kinematic_patterns[0].angle(r.time_s, 0)), 1e-12) << "frame " << f;
    EXPECT_LT(r.kinematic_error_rad, 1e-12);
    worst_servo = std::max(worst_servo, r.servo_residual_rad);
    lo = std::min(lo, q);
    hi = std::max(hi, q);
  }
  EXPECT_LT(worst_servo, 1e-9);
  EXPECT_GT(hi - lo, 1.1);  // 2 x 0.6 rad, sampled at 60 Hz
}

// A PD-driven joint yields to the load: it follows its pattern within a lag that shrinks as the
// gain grows (and does not track it exactly, unlike a kinematic joint).
TEST_F(JointsTest, PdDrivenJointFollowsItsPatternLoosely) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("chain.xml"), testing::chainXml(3)));
  const NoForce none;
  auto worst = [&](double kp) {
    ControllerParams p = minimiseEffort("j0");
    p.pd_driven = {"j2"};
    p.pd_patterns = {sine(0.0, 0.5, 1.0, 0.0)};
    p.pd_kp_n_m_per_rad = kp;
    p.pd_kd_n_m_s_per_rad = 2 * std::sqrt(kp * 0.1);
    p.substeps = 4;
    Controller c(model, p, none);
    double e = 0;
    for (int f = 0; f < 60; ++f) e = std::max(e, c.frame().pd_error_rad);
    return e;
  };
  const double soft = worst(5), stiff = worst(80);
  EXPECT_LT(stiff, 0.15);
  EXPECT_GT(stiff, 1e-4);
  EXPECT_GT(soft, 2 * stiff);
}

// Steady effort of a block on a ball joint under gravity: |r x m g| dt with r = R(q) (0.5, 0, 0),
// i.e. m g dt sqrt(r_x^2 + r_y^2). The central difference on each body axis of the ball
// (q exp(+-delta e_a)) matches this function's derivative along the same rotation.
TEST_F(JointsTest, BallJointDerivativeMatchesAnalyticEffort) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("ball.xml"), testing::ballBlockXml(9.81)));
  const NoForce none;
  ControllerParams p = minimiseEffort("ball");
  p.steady_state = true;
  Controller c(model, p, none);
  ASSERT_EQ(c.controlledDofs(), 3);
  const Vec3 start = {0.3, -0.5, 0.2};
  c.setRotation("ball", start);
  const rigid::Quat q0 = rigid::quatExp(start);
  auto effort = [&](const rigid::Quat& q) {
    // R(q) applied to (0.5, 0, 0): the first column of R times 0.5.
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double rx = 0.5 * (1 - 2 * (y * y + z * z)), ry = 0.5 * 2 * (x * y + w * z);
    return 24 * 9.81 * std::sqrt(rx * rx + ry * ry) * p.frame_s;
  };
  EXPECT_NEAR(c.evaluate(0, 0.0), effort(q0), 1e-9);
  const std::vector<double> g = c.derivatives();
  for (int a = 0; a < 3; ++a) {
    Vec3 e{};
    e[a] = 1e-6;
    const Vec3 m = {-e[0], -e[1], -e[2]};
    const double exact = (effort(rigid::quatRotate(q0, e)) - effort(rigid::quatRotate(q0, m))) / 2e-6;
    EXPECT_NEAR(g[a], exact, 1e-3 * std::abs(exact) + 1e-9) << "axis " << a;
  }
  EXPECT_GT(std::abs(g[0]) + std::abs(g[1]) + std::abs(g[2]), 0.01);
  // §2.1 per axis: one frame moves each axis of the ball by strength x frame against its gradient.
  const rigid::Quat before = quatAt(c.data().qpos());
  const FrameRecord r = c.frame();
  const rigid::Quat after = quatAt(c.data().qpos());
  const Vec3 moved = rigid::quatDifference(before, after);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(moved[a], -(g[a] > 0 ? 1 : -1) * p.strength_rad_per_s * p.frame_s, 1e-12) << "axis " << a;
  EXPECT_LT(r.servo_residual_rad, 1e-9);
}

// §5 with a ball joint outboard: while j0 is perturbed the wrist (ball) is held with it under
// gravity, wind and its own spin, to 1e-9 rad before the projection; left free it would turn.
TEST_F(JointsTest, HeldBallJointStaysHeldUnderLoad) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("wrist.xml"), testing::wristXml()));
  const SimpleWind wind(rigid::geomSurfaces(model, 8), 1.2, constantWind({15, 5, 0}));
  const rigid::Quat bent = rigid::quatExp({0.2, 0.4, -0.3});
  auto start = [&](rigid::RigidData& d) {
    d.qpos()[0] = 0.3;
    std::copy(bent.begin(), bent.end(), d.qpos() + 1);
    d.qvel()[1] = 1.0;
    d.qvel()[2] = -2.0;
    d.kinematics();
  };
  rigid::RigidData d(model);
  start(d);
  Prescribed p;
  p.qpos = {0};
  p.dof = {0};
  p.target = {0.32};
  p.balls = {{1, 1, bent}};
  ServoScratch s;
  const ServoReport r = advanceFrame(d, p, wind, 2, 8, 1e-12, s);
  EXPECT_LT(r.residual_rad, 1e-9);
  EXPECT_EQ(d.qpos()[0], 0.32);
  const rigid::Quat held = quatAt(d.qpos() + 1);
  const Vec3 drift = rigid::quatDifference(bent, held);
  EXPECT_LT(std::abs(drift[0]) + std::abs(drift[1]) + std::abs(drift[2]), 1e-12);
  rigid::RigidData loose(model);
  start(loose);
  p.balls.clear();
  advanceFrame(loose, p, wind, 2, 8, 1e-12, s);
  const Vec3 turned = rigid::quatDifference(bent, quatAt(loose.qpos() + 1));
  EXPECT_GT(std::abs(turned[0]) + std::abs(turned[1]) + std::abs(turned[2]), 1e-3);
  // The controller holds it the same way: its perturbation of j0 leaves the wrist where it was.
  ControllerParams cp;
  cp.controlled = {"j0"};
  cp.objectives = {Objective::drag};
  cp.senses = {Sense::maximize};
  Controller c(model, cp, wind);
  start(c.data());
  c.evaluate(0, 0.01);  // runs on a worker's copy; the servo's residual is checked above
  EXPECT_EQ(c.derivatives().size(), 1u);
}

// Joint ranges (MJCF range): a controlled joint whose objective pulls it past its range stops at
// the range (the servo would otherwise reach any target, §2.2), and so do the derivative's probes. The block hangs down under gravity
// to minimise its effort: a hinge limited to +-0.1 rad ends on 0.1 with no target beyond it (free,
// it turns 20 steps of the strength in 20 frames); a ball limited to 0.1 rad of rotation likewise.
TEST_F(JointsTest, TargetsBeyondAJointsRangeAreClamped) {
  Slot hinge;
  hinge.limited = true;
  hinge.lo = -0.3;
  hinge.hi = 0.2;
  EXPECT_EQ(clampToRange(hinge, 0.25), 0.2);
  EXPECT_EQ(clampToRange(hinge, -0.5), -0.3);
  EXPECT_EQ(clampToRange(hinge, 0.1), 0.1);
  hinge.limited = false;
  EXPECT_EQ(clampToRange(hinge, 0.25), 0.25);
  Slot ball;
  ball.ball = ball.limited = true;
  ball.hi = 0.5;
  const Vec3 r = rigid::quatLog(clampToRange(ball, rigid::quatExp({0.3, -0.6, 0.4})));
  EXPECT_NEAR(std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]), 0.5, 1e-12);
  EXPECT_NEAR(r[0] / r[1], -0.5, 1e-12);  // the axis kept
  EXPECT_NEAR(r[2] / r[1], -2.0 / 3, 1e-12);

  auto limitedXml = [](std::string xml, const std::string& joint, const std::string& range) {
    const std::string tag = "name=\"" + joint + "\"";
    xml.insert(xml.find(tag) + tag.size(), " limited=\"true\" range=\"" + range + "\"");
    return xml;
  };
  const NoForce none;
  double probe_past = 0, probe_on = 0, probe_inside = 0;
  auto hingeRun = [&](const std::string& xml, double& worst_target) {
    const auto model = rigid::RigidModel::load(testing::writeText(file("block.xml"), xml));
    Controller c(model, minimiseEffort("hinge"), none);
    worst_target = 0;
    for (int f = 0; f < 20; ++f) worst_target = std::max(worst_target, c.frame().target_rad[0]);
    probe_past = c.evaluate(0, 0.01);
    probe_on = c.evaluate(0, 0.0);
    probe_inside = c.evaluate(0, -0.01);
    return c.data().qpos()[0];
  };
  double target = 0;
  const std::string block = testing::blockXml(0.1, 9.81);
  EXPECT_NEAR(hingeRun(block, target), 20.0 / 60, 1e-9);
  EXPECT_NEAR(hingeRun(limitedXml(block, "hinge", "-0.1 0.1"), target), 0.1, 1e-12);
  EXPECT_LE(target, 0.1);
  // At the limit the derivative's probe past it stays on it: the objective there is the limit's own.
  EXPECT_EQ(probe_past, probe_on);
  EXPECT_NE(probe_inside, probe_on);

  auto ballRun = [&](const std::string& xml) {
    const auto model = rigid::RigidModel::load(testing::writeText(file("ball.xml"), xml));
    Controller c(model, minimiseEffort("ball"), none);
    double worst = 0;
    for (int f = 0; f < 20; ++f) {
      const std::vector<double> t = c.frame().target_rad;
      worst = std::max(worst, std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]));
    }
    const Vec3 now = rigid::quatLog(quatAt(c.data().qpos()));
    return std::pair{std::sqrt(now[0] * now[0] + now[1] * now[1] + now[2] * now[2]), worst};
  };
  EXPECT_GT(ballRun(testing::ballBlockXml(9.81)).first, 0.3);
  const auto [angle, worst] = ballRun(limitedXml(testing::ballBlockXml(9.81), "ball", "0 0.1"));
  EXPECT_NEAR(angle, 0.1, 1e-9);
  EXPECT_LE(worst, 0.1 + 1e-12);
}

// §5 with a ball joint among the controlled ones: four DOFs on 1, 2 or 3 threads give bitwise
// the same run.
TEST_F(JointsTest, BallJointRunsDoNotDependOnThreads) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("wrist.xml"), testing::wristXml()));
  const SimpleWind wind(rigid::geomSurfaces(model, 8), 1.2, constantWind({12, 4, -2}));
  auto run = [&](int threads) {
    ControllerParams p;
    p.controlled = {"j0", "wrist"};
    p.objectives = {Objective::effort, Objective::drag};
    p.senses = {Sense::minimize, Sense::maximize};
    p.threads = threads;
    Controller c(model, p, wind);
    c.setRotation("wrist", {0.1, -0.3, 0.2});
    std::vector<double> out;
    for (int f = 0; f < 12; ++f) {
      const FrameRecord r = c.frame();
      out.insert(out.end(), r.angle_rad.begin(), r.angle_rad.end());
      out.insert(out.end(), r.derivative.begin(), r.derivative.end());
    }
    return out;
  };
  const auto serial = run(1);
  ASSERT_EQ(serial.size(), 12u * 8u);
  for (int threads : {2, 3}) {
    const auto parallel = run(threads);
    for (std::size_t k = 0; k < serial.size(); ++k) ASSERT_EQ(parallel[k], serial[k]) << threads << " threads, value " << k;
  }
}

TEST_F(JointsTest, ValidationNamesPatternsAndBallWeights) {
  const auto model = rigid::RigidModel::load(testing::writeText(file("wrist.xml"), testing::wristXml()));
  ControllerParams p;
  p.controlled = {"j0", "wrist"};
  p.objectives = {Objective::effort, Objective::effort};
  p.senses = {Sense::minimize, Sense::minimize};
  EXPECT_EQ(p.validate(model), "");
  p.weights = {{1, 0, 0, 0}, {0, 1, 0, 0}};  // one per DOF: wrong, a ball counts once
  EXPECT_NE(p.validate(model).find("a ball joint counts once"), std::string::npos) << p.validate(model);
  p.weights.clear();
  p.controlled = {"j0"};
  p.objectives.pop_back();
  p.senses.pop_back();
  p.kinematic = {"wrist"};
  p.kinematic_patterns = {sine(0, 0.1, 1, 0)};
  EXPECT_NE(p.validate(model).find("kinematic_pattern: joint 'wrist' is a ball joint"), std::string::npos);
  p.kinematic_patterns = {Pattern{}, Pattern{}};
  EXPECT_NE(p.validate(model).find("kinematic_pattern: 2 patterns for 1"), std::string::npos);
  p.kinematic_patterns.clear();
  p.pd_driven = {"wrist"};
  p.pd_patterns = {Pattern{}};
  EXPECT_NE(p.validate(model).find("pd_driven joint 'wrist' is not a hinge"), std::string::npos) << p.validate(model);
}

}  // namespace
}  // namespace creaturelab::control
