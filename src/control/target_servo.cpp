#include "control/target_servo.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace creaturelab::control {

namespace {

rigid::Quat readQuat(const double* q) { return {q[0], q[1], q[2], q[3]}; }

// Stage 1b: PD torques towards each pattern at the substep's end (§2.2).
void addPdTorques(rigid::RigidData& data, const std::vector<PdDrive>& pd, double t_end_s, double* f) {
  for (const PdDrive& d : pd) {
    const double goal = d.pattern ? d.pattern->angle(t_end_s, d.hold_rad) : d.hold_rad;
    const double rate = d.pattern ? d.pattern->rate(t_end_s) : 0.0;
    f[d.dof] += d.kp_n_m_per_rad * (goal - data.qpos()[d.qpos]) + d.kd_n_m_s_per_rad * (rate - data.qvel()[d.dof]);
  }
}

// Residuals of every prescribed DOF against its goal (ball: the body-frame rotation vector from
// where it is to its goal, the coordinates its three dofs move in); the largest magnitude.
double residuals(const rigid::RigidData& data, const Prescribed& p, const ServoScratch& s, std::vector<double>& r,
                 const std::vector<double>& goal) {
  const int ns = int(p.qpos.size());
  double worst = 0;
  for (int k = 0; k < ns; ++k) {
    r[k] = goal[k] - data.qpos()[p.qpos[k]];
    worst = std::max(worst, std::abs(r[k]));
  }
  for (std::size_t b = 0; b < p.balls.size(); ++b) {
    const rigid::Vec3 d = rigid::quatDifference(readQuat(data.qpos() + p.balls[b].qpos), s.ball_goal[b]);
    for (int a = 0; a < 3; ++a) r[ns + 3 * b + a] = d[a];
    worst = std::max(worst, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
  }
  return worst;
}

}  // namespace

ServoReport advanceFrame(rigid::RigidData& data, const Prescribed& p, const ForceModel& force, int substeps,
                         int max_iterations, double tolerance_rad, ServoScratch& s, bool project) {
  const int nv = data.model().dofs();
  const int ns = int(p.qpos.size());
  const int np = ns + 3 * int(p.balls.size());  // unknown torques
  const double h = data.model().timestep_s();
  ServoReport report;
  s.start.resize(ns);
  for (int k = 0; k < ns; ++k) s.start[k] = data.qpos()[p.qpos[k]];
  s.ball_start.resize(p.balls.size());
  s.ball_goal.resize(p.balls.size());
  for (std::size_t b = 0; b < p.balls.size(); ++b) s.ball_start[b] = readQuat(data.qpos() + p.balls[b].qpos);
  s.unknown_dof.assign(p.dof.begin(), p.dof.end());
  for (const auto& b : p.balls)
    for (int a = 0; a < 3; ++a) s.unknown_dof.push_back(b.dof + a);
  std::vector<double>& goal = s.goal;
  goal.resize(ns);
  const int warnings_before = data.warnings();

  for (int sub = 1; sub <= substeps; ++sub) {
    // Stage 1: external forces at the substep's start (explicit), PD torques.
    data.kinematics();
    std::fill(data.appliedForces(), data.appliedForces() + nv, 0.0);
    force.apply(data, s.body_force_n);
    const double t_end = data.time_s() + h;  // as mj_step advances it
    addPdTorques(data, p.pd, t_end, data.appliedForces());
    s.base_force.assign(data.appliedForces(), data.appliedForces() + nv);
    const rigid::RigidState state = data.save();

    // Stage 2: Newton on the prescribed torques so that each joint lands on its goal.
    const double share = double(sub) / substeps;
    for (int k = 0; k < ns; ++k) {
      const Pattern* pat = p.pattern.empty() ? nullptr : p.pattern[k];
      goal[k] = pat ? pat->angle(t_end, p.target[k]) : s.start[k] + share * (p.target[k] - s.start[k]);
    }
    for (std::size_t b = 0; b < p.balls.size(); ++b) {
      const rigid::Vec3 whole = rigid::quatDifference(s.ball_start[b], p.balls[b].target);
      s.ball_goal[b] = rigid::quatRotate(s.ball_start[b], {share * whole[0], share * whole[1], share * whole[2]});
    }
    s.tau.assign(np, 0.0);
    s.residual.assign(np, 0.0);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    double worst = 0;
    int it = 0;
    for (;; ++it) {
      data.restore(state);
      double* f = data.appliedForces();
      std::copy(s.base_force.begin(), s.base_force.end(), f);
      for (int k = 0; k < np; ++k) f[s.unknown_dof[k]] += s.tau[k];
      data.step();
      worst = residuals(data, p, s, s.residual, goal);
      if (np == 0 || worst <= tolerance_rad || it >= max_iterations || !std::isfinite(worst)) break;
      if (it == 0) {
        // Jacobian h^2 [(M + h D)^-1]_PP of the Euler step (damping implicit), with M at the
        // substep's start: exact without contacts for hinges, to first order in the rotation for
        // a ball (whose qvel is the body-frame angular velocity the residual is measured in).
        data.eulerMatrix(s.jacobian);
        const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> A(
            s.jacobian.data(), nv, nv);
        Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nv, np);
        for (int c = 0; c < np; ++c) rhs(s.unknown_dof[c], c) = 1.0;
        const Eigen::MatrixXd cols = Eigen::MatrixXd(A).ldlt().solve(rhs);
        Eigen::MatrixXd J(np, np);
        for (int c = 0; c < np; ++c)
          for (int r = 0; r < np; ++r) J(r, c) = h * h * cols(s.unknown_dof[r], c);
        lu.compute(J);
      }
      const Eigen::VectorXd dtau = lu.solve(Eigen::Map<const Eigen::VectorXd>(s.residual.data(), np));
      for (int k = 0; k < np; ++k) s.tau[k] += dtau[k];
    }
    report.iterations = std::max(report.iterations, it + 1);
    report.residual_rad = std::max(report.residual_rad, worst);
    if (!data.finite() || !std::isfinite(worst))
      throw std::runtime_error("the rigid bodies diverged (positions or velocities not finite) at t = " +
                               std::to_string(data.time_s()) + " s");
    // Stage 3: projection of the residual (post-stabilisation, §2.2).
    if (!project) continue;
    for (int k = 0; k < ns; ++k) data.qpos()[p.qpos[k]] = goal[k];
    for (std::size_t b = 0; b < p.balls.size(); ++b)
      std::copy(s.ball_goal[b].begin(), s.ball_goal[b].end(), data.qpos() + p.balls[b].qpos);
  }
  if (data.warnings() > warnings_before)
    throw std::runtime_error("MuJoCo warned of a bad state (singular inertia, bad acceleration or too many contacts) "
                             "near t = " + std::to_string(data.time_s()) + " s");
  return report;
}

}  // namespace creaturelab::control
