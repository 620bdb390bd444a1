// The fish's body and its semi-implicit step (spec §1-2; Tu 1996 ch. 4): topology counts, outward
// faces, one step against a step computed by hand, momentum in air, mirror symmetry, the water
// force's properties, blow-up detection.
#include <gtest/gtest.h>

#include <cmath>


#include "fish/fish_modes.hpp"
#include "fish/fish_run.hpp"
#include "fish/fish_solver.hpp"

#include "fish_test_settings.hpp"
#include "support/dense_linalg.hpp"

namespace creaturelab::fish {
namespace {

FishModel defaultFish() { return testFish(); }

TEST(FishModel, CountsMatchTheThesis) {
  const FishModel f = defaultFish();
  EXPECT_EQ(f.network.particleCount(), 23);
  EXPECT_EQ(f.network.springCount(), 91);
  int muscles = 0, cross = 0;
  for (auto c : f.unit_class) muscles += c == UnitClass::muscle, cross += c == UnitClass::cross;
  EXPECT_EQ(muscles, 12);
  EXPECT_EQ(cross, 10 + 32 + 4);  // 2 per ring, 2 per face of the 4 ring gaps, 2 on each side face of the tail ([reimpl])
  // 3 segments x 2 sides x 2 muscles
  int count[3][2] = {};
  for (const Muscle& m : f.muscles) ++count[m.segment][m.side];
  for (auto& seg : count) {
    EXPECT_EQ(seg[0], 2);
    EXPECT_EQ(seg[1], 2);
  }
  // [reimpl] masses: 97.3 units of 1.1 kg
  EXPECT_NEAR(f.totalMassKg(), 97.3 * 1.1, 1e-12);
}

TEST(FishModel, FacesPointOutwardAndTheLeftIsLeft) {
  const FishModel f = defaultFish();
  const NodeMatrix& x = f.rest_positions_m;
  double area = 0;
  for (const Face& face : f.faces) {
    const FaceFrame fr = faceNormal(x, face);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : face.node) c += x.row(n).transpose() / 4;
    EXPECT_GT(fr.normal.dot(c - Eigen::Vector3d(c.x(), 0, 0)), 0) << "segment " << face.segment;
    area += fr.area_m2;
  }
  EXPECT_GT(area, 0);
  for (const Muscle& m : f.muscles) {  // left muscles have y > 0
    const int a = f.network.spring_a[m.unit];
    EXPECT_EQ(x(a, 1) > 0, m.side == 0);
  }
}

// One semi-implicit step from rest with one muscle shortened and no water. Only that unit has a
// force, so only its two nodes move, and A restricted to them is
//   [mi/dt + dt n, -dt n; -dt n, mj/dt + dt n],   right-hand side (n r, -n r),
// n = c (|r| - l') / |r|. Momentum gives vj = -mi vi / mj; the first row then gives
//   vi = n r / (mi/dt + dt n (1 + mi/mj)).
TEST(FishSolver, OneStepMatchesTheStepByHand) {
  const FishModel f = defaultFish();
  SolverParams p = testSolver();
  p.water.mu = 0;
  p.dt_s = 0.055;
  FishSolver solver(f, p);
  FishState s = restState(f);
  const Muscle m = f.muscles[4];
  const int e = m.unit, i = f.network.spring_a[e], j = f.network.spring_b[e];
  const double l0 = f.network.rest_length_m[e];
  s.rest_m[e] = 0.8 * l0;
  ASSERT_EQ(solver.step(s).status, StepStatus::ok);

  const double mi = f.network.mass_kg[i], mj = f.network.mass_kg[j], dt = p.dt_s;
  const Eigen::RowVector3d r = f.rest_positions_m.row(j) - f.rest_positions_m.row(i);
  const double n = f.network.stiffness_n_per_m[e] * (r.norm() - 0.8 * l0) / r.norm();
  const Eigen::RowVector3d vi = n * r / (mi / dt + dt * n * (1 + mi / mj));
  const Eigen::RowVector3d vj = -mi / mj * vi;
  EXPECT_GT(vi.norm(), 1e-3);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(s.v_m_per_s(i, d), vi[d], 1e-14) << d;
    EXPECT_NEAR(s.v_m_per_s(j, d), vj[d], 1e-14) << d;
  }
  for (int k = 0; k < kNodes; ++k) {
    if (k == i || k == j) continue;
    EXPECT_LT(s.v_m_per_s.row(k).norm(), 1e-15) << k;
  }
  EXPECT_TRUE(((s.x_m - f.rest_positions_m) - dt * s.v_m_per_s).norm() < 1e-15);
  EXPECT_DOUBLE_EQ(s.time_s, dt);
}

// The explicit schemes: V+ = V + dt F/m; forward Euler moves with the old velocity, symplectic with the new.
TEST(FishSolver, ExplicitStepsByHand) {
  const FishModel f = defaultFish();
  for (Scheme scheme : {Scheme::explicit_euler, Scheme::symplectic_euler}) {
    SolverParams p = testSolver();
    p.scheme = scheme;
    FishSolver solver(f, p);
    FishState s = restState(f);
    s.v_m_per_s.setZero();
    s.v_m_per_s(3, 1) = 0.01;
    const int e = f.muscles[0].unit;
    s.rest_m[e] *= 0.9;
    FishState before = s;
    solver.unitForces(before);
    solver.waterForce(before);
    const NodeMatrix force = solver.unitForceSum() + solver.waterForceN();
    ASSERT_EQ(solver.step(s).status, StepStatus::ok);
    for (int k = 0; k < kNodes; ++k) {
      const Eigen::RowVector3d v = before.v_m_per_s.row(k) + p.dt_s * force.row(k) / f.network.mass_kg[k];
      EXPECT_LT((s.v_m_per_s.row(k) - v).norm(), 1e-15);
      const Eigen::RowVector3d moved = scheme == Scheme::explicit_euler ? before.v_m_per_s.row(k) : v;
      EXPECT_LT((s.x_m.row(k) - before.x_m.row(k) - p.dt_s * moved).norm(), 1e-15);
    }
  }
}

// K's rows sum to zero, so A 1 = (M/dt) 1; A is symmetric and positive definite at rest.
TEST(FishSolver, MatrixRowsSumToTheMassTerm) {
  const FishModel f = defaultFish();
  FishSolver solver(f, testSolver());
  FishState s = restState(f);
  for (int k = 0; k < kMuscles; k += 3) s.rest_m[f.muscles[k].unit] *= 0.85;
  s.v_m_per_s.setConstant(0.01);
  s.v_m_per_s(4, 2) = -0.2;
  solver.unitForces(s);
  solver.assemble();
  const auto& a = solver.matrix();
  EXPECT_LT((a - a.transpose()).norm(), 1e-13 * a.norm());
  const Eigen::Matrix<double, kNodes, 1> ones = Eigen::Matrix<double, kNodes, 1>::Ones();
  for (int i = 0; i < kNodes; ++i) EXPECT_NEAR((a * ones)[i], f.network.mass_kg[i] / solver.params().dt_s, 1e-12);
  EXPECT_GT(test::symmetricEigenvalues(a).minCoeff(), 0);
  // Sum G = 0 (pairs of opposite forces).
  EXPECT_LT(solver.unitForceSum().colwise().sum().norm(), 1e-13);
}

// With mu = 0 (air) sum m v is conserved: here from a fish thrown with a momentum and spun, its
// muscles swimming, for 250 steps.
TEST(FishSolver, MomentumConservedInAir) {
  const FishModel f = defaultFish();
  SolverParams p = testSolver();
  p.water.mu = 0;
  FishSolver solver(f, p);
  MotorController motor(f, testMotor(), parseSchedule("swim 30"));
  FishState s = restState(f);
  for (int k = 0; k < kNodes; ++k) s.v_m_per_s.row(k) << 0.3, 0.1 * f.rest_positions_m(k, 2), -0.05 * f.rest_positions_m(k, 1);
  auto momentum = [&] {
    Eigen::RowVector3d q = Eigen::RowVector3d::Zero();
    for (int k = 0; k < kNodes; ++k) q += f.network.mass_kg[k] * s.v_m_per_s.row(k);
    return q;
  };
  const Eigen::RowVector3d p0 = momentum();
  for (int n = 0; n < 250; ++n) {  // it flails and folds a unit at step 291 (the thesis's failure in air)
    motor.apply(s.time_s, p.dt_s, s.rest_m);
    ASSERT_EQ(solver.step(s).status, StepStatus::ok) << n;
  }
  EXPECT_LT((momentum() - p0).norm(), 1e-12 * p0.norm());
  // and the muscles did move the body
  EXPECT_GT((s.x_m - f.rest_positions_m).rowwise().norm().maxCoeff(), 0.01);
}

// The body is mirror-symmetric (y -> -y): a left turn from rest and its mirror image (the mirror
// switch swaps left and right in every controller, the swim that runs through the turn too) are
// mirror images.
TEST(FishSolver, LeftAndRightTurnsMirror) {
  const FishModel f = defaultFish();
  // node k's mirror image: ring node (0 UL, 1 LL, 2 LR, 3 UR) -> (3, 2, 1, 0)
  auto mirror = [](int k) {
    if (k == 0 || k > 20) return k;
    const int ring = (k - 1) / 4, q = (k - 1) % 4;
    return 1 + 4 * ring + (3 - q);
  };
  SolverParams p = testSolver();
  p.dt_s = 0.02;
  MotorParams mirrored = testMotor();
  mirrored.mirror = true;
  const FishRecord left = runSchedule(f, p, testMotor(), parseSchedule("left 6"), {});
  const FishRecord right = runSchedule(f, p, mirrored, parseSchedule("left 6"), {});
  ASSERT_FALSE(left.blew_up);
  ASSERT_EQ(left.frames(), right.frames());
  const int last = left.frames() - 1;
  double scale = 0, worst = 0;
  for (int k = 0; k < kNodes; ++k) {
    const double* a = &left.nodes_m[(last * kNodes + k) * 3];
    const double* b = &right.nodes_m[(last * kNodes + mirror(k)) * 3];
    worst = std::max({worst, std::fabs(a[0] - b[0]), std::fabs(a[1] + b[1]), std::fabs(a[2] - b[2])});
    scale = std::max(scale, std::fabs(a[1]));
  }
  EXPECT_LT(worst, 1e-12 * 2.0);
  EXPECT_GT(std::fabs(left.heading_rad[last]), 1e-3);
  EXPECT_NEAR(left.heading_rad[last], -right.heading_rad[last], 1e-12);
  // a straight swim stays in its horizontal plane: the body is also symmetric top to bottom
  const FishRecord swim = runSchedule(f, p, testMotor(), parseSchedule("swim 10"), {});
  EXPECT_LT(std::fabs(swim.com_m[3 * (swim.frames() - 1) + 2] - swim.com_m[2]), 1e-12);
}

// Similarity (why the spec's numbers, not our 2 m size, set the speed in body lengths per second):
// (a) time: stiffness x k^2, damping x k, linear water mu x k, step and reference step / k, durations
//     / k give the same positions at times / k, so the speed in body lengths per second scales as
//     sqrt(c / m) at a fixed gait; (b) length: every length x lambda with the linear water mu /
//     lambda^2 gives positions x lambda at the same times, so our 2 m fish in mu = 100 is the
//     reimplementation's 26-unit fish in mu = 100 / 13^2: the size maps onto mu, nothing else;
//     (c) with the quadratic law mu / lambda^3.
TEST(FishSolver, SimilarityInTimeAndLength) {
  auto runLast = [](const FishGeometry& g, const UnitParams& u, const SolverParams& sp, const MotorParams& mp,
                    const std::string& schedule) {
    const FishModel f = buildFish(g, u);
    const FishRecord r = runSchedule(f, sp, mp, parseSchedule(schedule), {});
    EXPECT_FALSE(r.blew_up);
    return std::vector<double>(r.nodes_m.end() - 3 * kNodes, r.nodes_m.end());
  };
  FishGeometry g = testBody();
  UnitParams u = testUnits();
  SolverParams sp = testSolver();
  sp.dt_s = 0.02;
  MotorParams mp = testMotor();
  mp.swim = {1.0, 0.01, 1.0, 0.01};
  const auto base = runLast(g, u, sp, mp, "swim 6; left 3");
  double scale = 0;
  for (double v : base) scale = std::max(scale, std::fabs(v));
  {  // (a) k = 3
    const double k = 3;
    UnitParams uk = u;
    uk.stiffness_cross_n_per_m *= k * k, uk.stiffness_other_n_per_m *= k * k, uk.stiffness_muscle_n_per_m *= k * k;
    uk.damping_ns_per_m *= k;
    SolverParams sk = sp;
    sk.dt_s /= k, sk.water.mu *= k;
    MotorParams mk = mp;
    mk.reference_step_s /= k;
    const auto fast = runLast(g, uk, sk, mk, "swim 2; left 1");
    double worst = 0;
    for (size_t i = 0; i < base.size(); ++i) worst = std::max(worst, std::fabs(fast[i] - base[i]));
    EXPECT_LT(worst, 1e-9 * scale);
  }
  {  // (b) lambda = 13: the reimplementation's 26-unit fish
    const double lambda = 13;
    FishGeometry gl = g;
    gl.body_length_m *= lambda;
    SolverParams sl = sp;
    sl.water.mu /= lambda * lambda;
    const auto big = runLast(gl, u, sl, mp, "swim 6; left 3");
    double worst = 0;
    for (size_t i = 0; i < base.size(); ++i) worst = std::max(worst, std::fabs(big[i] / lambda - base[i]));
    EXPECT_LT(worst, 1e-9 * scale);
  }
  {  // (c) the quadratic law: mu / lambda^3 (the reimplementation's mu = 1 on 26 units is 2197 on 2 m)
    const double lambda = 13;
    SolverParams sq = sp;
    sq.water.law = WaterLaw::quadratic;
    sq.water.mu = 2197;
    const auto small = runLast(g, u, sq, mp, "swim 6; left 3");
    FishGeometry gl = g;
    gl.body_length_m *= lambda;
    sq.water.mu = 1;
    const auto big = runLast(gl, u, sq, mp, "swim 6; left 3");
    double worst = 0, size = 0;
    for (size_t i = 0; i < small.size(); ++i)
      worst = std::max(worst, std::fabs(big[i] / lambda - small[i])), size = std::max(size, std::fabs(small[i]));
    EXPECT_LT(worst, 1e-9 * size);
  }
}

// The rest modes: six rigid-body modes skipped; frequencies independent of the size, doubled by four
// times the stiffness; the reimplementation's shape has its own, similar lowest sideways mode.
TEST(FishModes, ScaleAsTheSpringMassSystem) {
  const RestModes base = restModes(defaultFish());
  EXPECT_GT(base.lowest_lateral_hz, 0.05);
  EXPECT_LT(base.lowest_lateral_hz, 1.0);
  EXPECT_GT(base.highest_rad_per_s, 2 * M_PI * base.lowest_lateral_hz);
  FishGeometry big = testBody();
  big.body_length_m = 26;
  UnitParams stiff = testUnits();
  stiff.stiffness_cross_n_per_m *= 4, stiff.stiffness_other_n_per_m *= 4, stiff.stiffness_muscle_n_per_m *= 4;
  EXPECT_NEAR(restModes(buildFish(big, testUnits())).lowest_lateral_hz, base.lowest_lateral_hz, 1e-9 * base.lowest_lateral_hz);
  EXPECT_NEAR(restModes(buildFish(testBody(), stiff)).lowest_lateral_hz, 2 * base.lowest_lateral_hz, 1e-9 * base.lowest_lateral_hz);
  EXPECT_NEAR(restModes(buildFish(testBody(), stiff)).highest_rad_per_s, 2 * base.highest_rad_per_s, 1e-9 * base.highest_rad_per_s);
  FishGeometry their_shape = reimplementationGeometry();
  their_shape.body_length_m = 1.0;
  const RestModes theirs = restModes(buildFish(their_shape, testUnits()));
  EXPECT_GT(theirs.lowest_lateral_hz, 0.5 * base.lowest_lateral_hz);
  EXPECT_LT(theirs.lowest_lateral_hz, 2.0 * base.lowest_lateral_hz);
}

// The tangent step (not the spec's; stability comparison): in air it conserves sum m v (its
// matrix's block columns sum to zero), and at a small step it follows the spec's step to O(dt^2)
// per step (both are first-order Euler steps of the same equations).
TEST(FishSolver, TangentStepConservesMomentumAndFollowsTheSpecStep) {
  const FishModel f = defaultFish();
  FishState s0 = restState(f);
  for (int k = 0; k < kNodes; ++k) s0.v_m_per_s.row(k) << 0.3, 0.1 * f.rest_positions_m(k, 2), -0.05 * f.rest_positions_m(k, 1);
  for (int e = 0; e < kUnits; ++e) s0.rest_m[e] *= 0.9 + 0.02 * (e % 7);
  SolverParams p = testSolver();
  p.water.mu = 0;
  p.scheme = Scheme::tangent_implicit;
  FishState s = s0;
  FishSolver tangent(f, p);
  auto momentum = [&](const FishState& st) {
    Eigen::RowVector3d q = Eigen::RowVector3d::Zero();
    for (int k = 0; k < kNodes; ++k) q += f.network.mass_kg[k] * st.v_m_per_s.row(k);
    return q;
  };
  for (int n = 0; n < 50; ++n) ASSERT_EQ(tangent.step(s).status, StepStatus::ok) << n;
  EXPECT_LT((momentum(s) - momentum(s0)).norm(), 1e-12 * momentum(s0).norm());
  double diff[2];
  for (int k = 0; k < 2; ++k) {
    SolverParams q = p;
    q.water.mu = 100;
    q.dt_s = k == 0 ? 2e-4 : 1e-4;
    FishState a = s0, b = s0;
    FishSolver ta(f, q);
    q.scheme = Scheme::semi_implicit;
    FishSolver sa(f, q);
    ASSERT_EQ(ta.step(a).status, StepStatus::ok);
    ASSERT_EQ(sa.step(b).status, StepStatus::ok);
    diff[k] = (a.v_m_per_s - b.v_m_per_s).norm();
  }
  EXPECT_GT(diff[0], 0);
  EXPECT_NEAR(diff[0] / diff[1], 4.0, 0.2);  // the difference is O(dt^2)
}

// Water force: none when the fish moves with the water; opposes a translation; linear in speed for
// the linear law and quadratic for the quadratic one; pushing only (reversing v never flips a face's sign).
TEST(WaterForce, Properties) {
  const FishModel f = defaultFish();
  const NodeMatrix& x = f.rest_positions_m;
  NodeMatrix v;
  for (int k = 0; k < kNodes; ++k) v.row(k) << 0.2, 0.1, -0.05;
  auto total = [&](const WaterParams& w, const NodeMatrix& vel) {
    NodeMatrix force = NodeMatrix::Zero();
    addWaterForce(f, w, x, vel, force);
    return Eigen::Vector3d(force.colwise().sum().transpose());
  };
  WaterParams w = testSolver().water;
  w.mu = 50;
  w.law = WaterLaw::linear;
  w.current_m_per_s = Eigen::Vector3d(0.2, 0.1, -0.05);
  EXPECT_EQ(total(w, v).norm(), 0.0);
  w.current_m_per_s.setZero();
  const Eigen::Vector3d f1 = total(w, v), f2 = total(w, 2 * v);
  EXPECT_LT(f1.dot(v.row(0).transpose()), 0);
  EXPECT_LT((f2 - 2 * f1).norm(), 1e-12 * f1.norm());
  w.law = WaterLaw::quadratic;
  const Eigen::Vector3d q1 = total(w, v), q2 = total(w, 2 * v);
  EXPECT_LT((q2 - 4 * q1).norm(), 1e-12 * q1.norm());
  // by hand, for the linear law: the faces that move into the water, -mu A (n . v) n each
  w.law = WaterLaw::linear;
  Eigen::Vector3d expect = Eigen::Vector3d::Zero();
  for (const Face& face : f.faces) {
    const FaceFrame fr = faceNormal(x, face);
    const double push = fr.normal.dot(v.row(0).transpose());
    if (push > 0) expect -= w.mu * fr.area_m2 * push * fr.normal;
  }
  EXPECT_LT((total(w, v) - expect).norm(), 1e-12 * expect.norm());
}

TEST(FishSolver, BlowUpIsDetectedAndNamed) {
  const FishModel f = defaultFish();
  SolverParams p = testSolver();
  p.water.mu = 0;
  FishSolver solver(f, p);
  FishState s = restState(f);
  s.v_m_per_s(21, 1) = 1e3;  // a tail tip flung sideways: its units overstretch in one step
  const FishState before = s;
  const StepReport r = solver.step(s);
  EXPECT_EQ(r.status, StepStatus::overstretched);
  EXPECT_NE(r.cause.find("unit"), std::string::npos);
  EXPECT_EQ(s.x_m, before.x_m);  // the last good state is kept
  s.v_m_per_s(3, 0) = std::nan("");
  EXPECT_EQ(solver.step(s).status, StepStatus::non_finite);
  // a unit compressed hard at a huge step makes M/dt + dt K indefinite
  SolverParams big = p;
  big.dt_s = 50;
  FishSolver coarse(f, big);
  FishState c = restState(f);
  for (int e = 0; e < kUnits; ++e) c.rest_m[e] *= 3.0;  // every unit pushes: n < 0
  EXPECT_EQ(coarse.step(c).status, StepStatus::not_positive_definite);
  // the air run of the thesis: full amplitude, fast, blows up and says when
  SolverParams air = p;
  MotorParams flail = testMotor();
  flail.swim = {1.0, 0.008, 1.0, 0.008};
  const FishRecord rec = runSchedule(f, air, flail, parseSchedule("swim 60"), {});
  EXPECT_TRUE(rec.blew_up);
  EXPECT_GT(rec.blowup_step, 1);
  EXPECT_FALSE(rec.blowup_cause.empty());
}

TEST(FishParams, BadInputNamesTheParameter) {
  SolverParams p = testSolver();
  p.dt_s = 0;
  EXPECT_NE(p.validate().find("dt_s"), std::string::npos);
  UnitParams u = testUnits();
  u.mass_units[2] = -1;
  EXPECT_NE(u.validate().find("mass"), std::string::npos);
  EXPECT_THROW(buildFish(testBody(), u), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::fish
