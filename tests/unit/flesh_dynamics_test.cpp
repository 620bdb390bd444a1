// The flesh's backward Euler step (flesh/flesh.hpp): on a held skeleton its energy never grows and
// decays with damping; on a free skeleton flesh and bodies together keep their linear momentum; stiff
// springs at a large step stay bounded; it follows a skeleton that MuJoCo turns, closer as the binding
// stiffens, by the analytic lag. CPU time of each TEST in its comment (Release).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "control_models.hpp"
#include "flesh/flesh.hpp"
#include "flesh_models.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::flesh {
namespace {

class FleshDynamicsTest : public testing::ScratchDirTest {
 protected:
  FleshDynamicsTest() : ScratchDirTest("flesh_dynamics") {}
  rigid::RigidModel load(const std::string& xml) {
    return rigid::RigidModel::load(testing::writeText(file("model.xml"), xml));
  }
};

// A deterministic disturbance: every vertex displaced by up to `dx` and moving at up to `v`.
void disturb(Flesh& flesh, double dx_m, double v_m_per_s) {
  Eigen::Matrix3Xd x = flesh.positions_m(), v = flesh.velocities_m_per_s();
  for (int i = 0; i < flesh.vertices(); ++i)
    for (int d = 0; d < 3; ++d) {
      x(d, i) += dx_m * std::sin(1.3 * i + 2.1 * d);
      v(d, i) += v_m_per_s * std::cos(0.7 * i + 1.7 * d);
    }
  flesh.setState(x, v);
}

double energy(const Flesh& flesh, const rigid::RigidData& skeleton) {
  return flesh.kineticEnergy_j() + flesh.stretchEnergy_j() + flesh.bindingEnergy_j(skeleton);
}

// Backward Euler dissipates: with no damping at all the total energy (kinetic + stretch + binding)
// never grows from one step to the next; the springs' damping takes more. 60 steps of 1/600 s each
// way, about 0.1 s of CPU.
TEST_F(FleshDynamicsTest, EnergyDoesNotGrowOnAHeldSkeleton) {
  const auto model = load(testing::heldSphereXml(0.1));
  std::vector<double> left;  // the energy's fraction left after 0.1 s
  for (const bool damped : {false, true}) {
    FleshParams p;
    if (!damped) p.stretch_damping_ratio = p.binding_damping_ratio = 0;
    Flesh flesh(model, p);
    rigid::RigidData skeleton(model);
    flesh.placeOnSkeleton(skeleton);
    disturb(flesh, 0.003, 0.2);
    const double e0 = energy(flesh, skeleton);
    double last = e0;
    for (int k = 0; k < 60; ++k) {
      flesh.step(skeleton, 1.0 / 600);
      ASSERT_TRUE(flesh.lastStep().cg_converged);
      const double e = energy(flesh, skeleton);
      EXPECT_LE(e, last * (1 + 1e-12)) << "step " << k << (damped ? " damped" : " undamped");
      last = e;
    }
    left.push_back(last / e0);
  }
  EXPECT_LT(left[1], 0.5 * left[0]);
}

// With a free skeleton in the solve the flesh and the bone together are one backward Euler system:
// without damping the energy of both (the sphere's kinetic energy 1/2 m v^2 + 1/2 (2/5 m r^2) w^2 from
// MuJoCo's velocities) never grows from one step to the next. 100 steps, about 0.05 s of CPU.
TEST_F(FleshDynamicsTest, EnergyDoesNotGrowWithAFreeSkeleton) {
  const double r = 0.1, m = 2.0;
  const auto model = load(testing::freeSphereXml(r, m));
  FleshParams p;
  p.stretch_damping_ratio = p.binding_damping_ratio = 0;
  p.binding_hz = 30;
  Flesh flesh(model, p);
  rigid::RigidData skeleton(model);
  flesh.placeOnSkeleton(skeleton);
  disturb(flesh, 0.003, 0.3);
  auto total = [&] {
    const double* u = skeleton.qvel();
    const double bone = 0.5 * m * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) +
                        0.5 * 0.4 * m * r * r * (u[3] * u[3] + u[4] * u[4] + u[5] * u[5]);
    skeleton.kinematics();
    return bone + energy(flesh, skeleton);
  };
  const double e0 = total();
  double last = e0, bone_speed = 0;
  for (int k = 0; k < 100; ++k) {
    flesh.step(skeleton, model.timestep_s());
    skeleton.step();
    std::fill(skeleton.appliedForces(), skeleton.appliedForces() + model.dofs(), 0.0);
    const double e = total();
    EXPECT_LE(e, last * (1 + 1e-12)) << "step " << k;
    last = e;
    bone_speed = std::max(bone_speed, std::abs(skeleton.qvel()[3]));
  }
  EXPECT_GT(bone_speed, 1e-3);  // the bone turned under its flesh
}

// The internal springs pass momentum between flesh and bodies and nowhere else: the total linear
// momentum (flesh + a free MuJoCo body) is conserved to round-off (1e-12 of the flesh's scale) over
// 100 steps of a disturbed flesh. (A jointed free tree is left out: MuJoCo's own Euler step does not
// conserve its momentum exactly, the mass matrix changing with the shape over the step.)
// About 0.1 s of CPU.
TEST_F(FleshDynamicsTest, FleshAndFreeSkeletonConserveLinearMomentum) {
  const auto model = load(testing::freeSphereXml(0.1, 2.0));
  FleshParams p;
  p.cg_tolerance = 1e-13;
  Flesh flesh(model, p);
  rigid::RigidData skeleton(model);
  flesh.placeOnSkeleton(skeleton);
  disturb(flesh, 0.003, 0.3);
  flesh.setState(flesh.positions_m(), flesh.velocities_m_per_s().colwise() + Eigen::Vector3d(0.2, 0.0, -0.1));
  auto total = [&]() -> Eigen::Vector3d {
    skeleton.kinematics();
    rigid::Vec3 linear{}, angular{};
    skeleton.subtreeMomentum(1, linear, angular);
    return Eigen::Vector3d(linear[0], linear[1], linear[2]) + flesh.linearMomentum_kg_m_per_s();
  };
  const Eigen::Vector3d p0 = total();
  const double scale = flesh.mesh().mass_kg.sum() * 0.3;  // kg m/s: the flesh's momentum scale
  ASSERT_GT(p0.norm(), 1e-3 * scale);
  const double h = model.timestep_s();
  double drift = 0, body_speed = 0;
  for (int k = 0; k < 100; ++k) {
    flesh.step(skeleton, h);
    skeleton.step();
    std::fill(skeleton.appliedForces(), skeleton.appliedForces() + model.dofs(), 0.0);
    drift = std::max(drift, (total() - p0).norm());
    body_speed = std::max(body_speed, std::abs(skeleton.qvel()[0]));
  }
  EXPECT_GT(body_speed, 1e-3);  // the skeleton was pushed by its flesh
  EXPECT_LT(drift, 1e-12 * scale);
}

// The fluid's hook: forces added to externalForces_n() before each step act once and are cleared; a
// uniform push F on every vertex of a free sphere's flesh changes the total linear momentum by
// h sum F per step (to round-off) and, through the binding, carries the bone along: after 0.5 s the
// sphere moves at the common acceleration sum F / (flesh + bone mass) times t, within 2%. 50 steps,
// about 0.05 s of CPU.
TEST_F(FleshDynamicsTest, ExternalForcesPushFleshAndBoneTogether) {
  const auto model = load(testing::freeSphereXml(0.1, 2.0));
  Flesh flesh(model);
  rigid::RigidData skeleton(model);
  flesh.placeOnSkeleton(skeleton);
  const double h = model.timestep_s(), push_n = 0.01;
  const int steps = 50;
  for (int k = 0; k < steps; ++k) {
    flesh.externalForces_n().row(0).array() += push_n;
    flesh.step(skeleton, h);
    EXPECT_EQ(flesh.externalForces_n().cwiseAbs().maxCoeff(), 0.0);
    skeleton.step();
    std::fill(skeleton.appliedForces(), skeleton.appliedForces() + model.dofs(), 0.0);
  }
  rigid::Vec3 linear{}, angular{};
  skeleton.subtreeMomentum(1, linear, angular);
  const double total_push = steps * h * push_n * flesh.vertices();  // N s
  EXPECT_NEAR(linear[0] + flesh.linearMomentum_kg_m_per_s()[0], total_push, 1e-12 * total_push);
  const double together = total_push / (flesh.mesh().mass_kg.sum() + model.bodyMass_kg(1));  // m/s
  EXPECT_NEAR(skeleton.qvel()[0], together, 0.02 * together);
}

// Stiff springs at a large step (Baraff & Witkin's point): a flesh of 1 GPa bound at 1 kHz, stepped at
// 50 ms (the binding's omega h = 314, far beyond explicit Euler's 2), without damping, stays bounded
// and loses energy. About 0.05 s of CPU.
TEST_F(FleshDynamicsTest, StiffSpringsAtALargeStepStayStable) {
  const auto model = load(testing::heldSphereXml(0.1));
  FleshParams p;
  p.youngs_modulus_pa = 1e9;
  p.binding_hz = 1000;
  p.stretch_damping_ratio = p.binding_damping_ratio = 0;
  Flesh flesh(model, p);
  rigid::RigidData skeleton(model);
  flesh.placeOnSkeleton(skeleton);
  disturb(flesh, 0.001, 0.1);
  const double e0 = energy(flesh, skeleton);
  for (int k = 0; k < 20; ++k) flesh.step(skeleton, 0.05);
  EXPECT_TRUE(flesh.positions_m().allFinite());
  EXPECT_LT(energy(flesh, skeleton), e0);
  EXPECT_LT((flesh.positions_m() - flesh.mesh().rest_m).cwiseAbs().maxCoeff(), 0.001);
}

// The flesh follows a capsule that MuJoCo spins at Omega = 2 pi rad/s about z. In the steady turn a
// vertex at radius R, bound at omega = 2 pi f with damping ratio zeta (edge springs made negligible),
// sits off its anchor by |d| = Omega^2 R / sqrt(a^2 + b^2), a = omega^2 - Omega^2, b = 2 zeta omega Omega
// (the binding supplies the centripetal force; the damping turns d backwards). The largest distance
// from a vertex to its anchor after 1 s matches that to backward Euler's first-order error (measured
// about 1.1 omega h; allowed 1.5 omega h) at 5, 10 and 20 Hz, so it falls more than threefold per
// doubling of the binding frequency. About 0.1 s of CPU.
TEST_F(FleshDynamicsTest, FollowsASpinningSkeletonWithTheAnalyticLag) {
  const auto model = load(testing::spinnerXml());
  const double omega_spin = 2 * std::numbers::pi, h = model.timestep_s();
  std::vector<double> errors;
  for (const double hz : {5.0, 10.0, 20.0}) {
    FleshParams p;
    p.slices = 8;  // a coarse flesh: the lag is per vertex
    p.youngs_modulus_pa = 1e-6;
    p.binding_damping_ratio = 1.0;
    p.binding_hz = hz;
    Flesh flesh(model, p);
    rigid::RigidData skeleton(model);
    skeleton.qvel()[0] = omega_spin;
    flesh.placeOnSkeleton(skeleton);
    double reach = 0;
    for (int i = 0; i < flesh.vertices(); ++i) reach = std::max(reach, flesh.positions_m().col(i).head<2>().norm());
    for (int k = 0; k < 500; ++k) {
      flesh.step(skeleton, h);
      skeleton.step();
      std::fill(skeleton.appliedForces(), skeleton.appliedForces() + model.dofs(), 0.0);
    }
    const Eigen::Matrix3Xd x = flesh.positions_m();
    flesh.placeOnSkeleton(skeleton);  // the anchors
    const double error = (x - flesh.positions_m()).colwise().norm().maxCoeff();
    const double w = 2 * std::numbers::pi * hz, spin = skeleton.qvel()[0];
    const double a = w * w - spin * spin, b = 2 * p.binding_damping_ratio * w * spin;
    const double lag = spin * spin * reach / std::hypot(a, b);
    EXPECT_GT(error, 0.95 * lag) << hz << " Hz";
    EXPECT_LT(error, (1 + 1.5 * w * h) * lag) << hz << " Hz";
    errors.push_back(error);
  }
  EXPECT_GT(errors[0] / errors[1], 3.0);
  EXPECT_GT(errors[1] / errors[2], 3.0);
}

// The skeleton in the implicit solve is what keeps stiff binding on light bones stable: a free 2 kg
// sphere under 1.4 kg of flesh bound at 100 Hz, stepped at 10 ms (omega h = 6.3), stays at the
// disturbance's speeds with it and blows up without it (FleshParams::implicit_skeleton = false, the
// bodies getting the reactions explicitly). 100 steps each, about 0.1 s of CPU.
TEST_F(FleshDynamicsTest, SkeletonInTheSolveKeepsStiffBindingStable) {
  const auto model = load(testing::freeSphereXml(0.1, 2.0));
  for (const bool implicit : {true, false}) {
    FleshParams p;
    p.binding_hz = 100;
    p.implicit_skeleton = implicit;
    Flesh flesh(model, p);
    rigid::RigidData skeleton(model);
    flesh.placeOnSkeleton(skeleton);
    disturb(flesh, 0.0, 0.1);
    double speed = 0;
    for (int k = 0; k < 100 && std::isfinite(speed); ++k) {
      flesh.step(skeleton, model.timestep_s());
      skeleton.step();
      std::fill(skeleton.appliedForces(), skeleton.appliedForces() + model.dofs(), 0.0);
      speed = flesh.velocities_m_per_s().colwise().norm().maxCoeff();
      for (int j = 0; j < model.dofs(); ++j) speed = std::max(speed, std::abs(skeleton.qvel()[j]));
    }
    if (implicit) EXPECT_LT(speed, 0.2);
    else EXPECT_FALSE(speed < 1e3) << "explicit reactions stayed bounded: " << speed;
  }
}

TEST_F(FleshDynamicsTest, BadStateAndStepAreErrors) {
  const auto model = load(testing::heldSphereXml(0.1));
  Flesh flesh(model);
  rigid::RigidData skeleton(model);
  EXPECT_THROW(flesh.setState(Eigen::Matrix3Xd::Zero(3, 2), Eigen::Matrix3Xd::Zero(3, 2)), std::invalid_argument);
  Eigen::Matrix3Xd x = flesh.positions_m();
  x(0, 0) = NAN;
  EXPECT_THROW(flesh.setState(x, flesh.velocities_m_per_s()), std::invalid_argument);
  EXPECT_THROW(flesh.step(skeleton, 0.0), std::invalid_argument);
  const auto other = load(testing::freeCreatureXml(0.1, 2.0));
  rigid::RigidData other_skeleton(other);
  EXPECT_THROW(flesh.step(other_skeleton, 0.01), std::invalid_argument);
  flesh.externalForces_n().resize(3, 1);
  EXPECT_THROW(flesh.step(skeleton, 0.01), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::flesh
