#include "control/target_servo.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace creaturelab::control {

ServoReport advanceFrame(rigid::RigidData& data, const Prescribed& p, const ForceModel& force, int substeps,
                         int max_iterations, double tolerance_rad, ServoScratch& s) {
  const int nv = data.model().dofs();
  const int np = int(p.dof.size());
  const double h = data.model().timestep_s();
  ServoReport report;
  s.start.resize(np);
  for (int k = 0; k < np; ++k) s.start[k] = data.qpos()[p.qpos[k]];
  const int warnings_before = data.warnings();

  for (int sub = 1; sub <= substeps; ++sub) {
    // Stage 1: external forces at the substep's start (explicit).
    data.kinematics();
    std::fill(data.appliedForces(), data.appliedForces() + nv, 0.0);
    force.apply(data, s.body_force_n);
    s.base_force.assign(data.appliedForces(), data.appliedForces() + nv);
    const rigid::RigidState state = data.save();

    // Stage 2: Newton on the prescribed torques so that each angle lands on its share.
    const double share = double(sub) / substeps;
    s.tau.assign(np, 0.0);
    s.residual.assign(np, 0.0);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    double worst = 0;
    int it = 0;
    for (;; ++it) {
      data.restore(state);
      double* f = data.appliedForces();
      std::copy(s.base_force.begin(), s.base_force.end(), f);
      for (int k = 0; k < np; ++k) f[p.dof[k]] += s.tau[k];
      data.step();
      worst = 0;
      for (int k = 0; k < np; ++k) {
        const double goal = s.start[k] + share * (p.target[k] - s.start[k]);
        s.residual[k] = goal - data.qpos()[p.qpos[k]];
        worst = std::max(worst, std::abs(s.residual[k]));
      }
      if (np == 0 || worst <= tolerance_rad || it >= max_iterations || !std::isfinite(worst)) break;
      if (it == 0) {
        // Jacobian h^2 [(M + h D)^-1]_PP of the Euler step (damping implicit), with M at the
        // substep's start: exact without contacts.
        data.eulerMatrix(s.jacobian);
        const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> A(
            s.jacobian.data(), nv, nv);
        Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nv, np);
        for (int c = 0; c < np; ++c) rhs(p.dof[c], c) = 1.0;
        const Eigen::MatrixXd cols = Eigen::MatrixXd(A).ldlt().solve(rhs);
        Eigen::MatrixXd J(np, np);
        for (int c = 0; c < np; ++c)
          for (int r = 0; r < np; ++r) J(r, c) = h * h * cols(p.dof[r], c);
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
    for (int k = 0; k < np; ++k) data.qpos()[p.qpos[k]] += s.residual[k];
  }
  if (data.warnings() > warnings_before)
    throw std::runtime_error("MuJoCo warned of a bad state (singular inertia, bad acceleration or too many contacts) "
                             "near t = " + std::to_string(data.time_s()) + " s");
  return report;
}

}  // namespace creaturelab::control
