#pragma once
// The bodies' side of the coupled solve (rigid_fluid_coupling3.hpp, Forcing3::coupled): how MuJoCo's
// generalised velocities answer forces on the bodies within one step. With A = M + h D the matrix of
// MuJoCo's Euler step (joint damping implicit; rigid::RigidData::eulerMatrix) restricted to the free
// DOFs (every DOF but the held joints'), and per body b the Jacobian J_b (6 × free DOFs) of its
// centre-of-mass velocity and angular velocity, a wrench (F_b, T_b) per body held for dt changes the
// velocities by
//   Δv = dt A⁻¹ Σ_b J_bᵀ (F_b, T_b),
// exact for the articulated tree (no contacts, no constraints). A is factorised by a dense Cholesky
// (nv is small), J_b probed column by column from data's point velocities. No I/O.
#include <string>
#include <vector>

#include "coupling3d/transfer3.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::coupling3d {

class SolidMobility3 {
 public:
  /// Throws std::invalid_argument naming a held joint the model does not have.
  SolidMobility3(const rigid::RigidModel& model, const std::vector<std::string>& held_joints);

  /// Replaces the held DOFs (MuJoCo's qvel indices; the constructor's held joints' included only if listed);
  /// throws std::invalid_argument for an index out of range.
  void setHeldDofs(const std::vector<int>& dofs);

  /// Jacobians and the factor at data's pose and velocities (kinematics done). data's velocities are
  /// probed and put back (its kinematics recomputed: the same as before).
  void update(rigid::RigidData& data);
  /// Δv (free DOFs) = dt A⁻¹ Σ_b J_bᵀ (force_n[b], torque_n_m[b]) (torque about body b's centre of mass).
  void velocityChange(const std::vector<Vec3>& force_n, const std::vector<Vec3>& torque_n_m, double dt_s,
                      std::vector<double>& dv) const;
  /// Body b's centre-of-mass velocity and angular velocity (world) for the free-DOF velocities v.
  void bodyVelocity(int body, const std::vector<double>& v, Vec3& linear, Vec3& angular) const;
  /// data's velocities += Δv and positions += dt Δv (quaternions rotated in the body frame, as MuJoCo
  /// integrates them), then its kinematics.
  void apply(rigid::RigidData& data, const std::vector<double>& dv, double dt_s) const;

  int freeDofs() const { return static_cast<int>(free_.size()); }
  /// Body b's centre of mass at the last update (m, world).
  const Vec3& bodyPoint_m(int body) const { return com_[static_cast<std::size_t>(body)]; }

 private:
  const rigid::RigidModel* model_;
  std::vector<int> free_;                  // the free DOFs, ascending
  std::vector<std::vector<double>> jac_;   // per body: 6 rows × free DOFs, row-major (linear, angular)
  std::vector<Vec3> com_;
  std::vector<double> factor_;             // Cholesky factor L of A (row-major, lower)
  std::vector<double> full_;
  mutable std::vector<double> rhs_;
};

}  // namespace creaturelab::coupling3d
