#include "coupling3d/solid_mobility3.hpp"

#include <cmath>
#include <stdexcept>

#include "rigid/rotation.hpp"

namespace creaturelab::coupling3d {

SolidMobility3::SolidMobility3(const rigid::RigidModel& model, const std::vector<std::string>& held_joints)
    : model_(&model) {
  std::vector<int> held;
  for (const std::string& name : held_joints) {
    const int j = model.findJoint(name);
    if (j < 0) throw std::invalid_argument("coupling3d: held_joints: the model " + model.path() + " has no joint '" + name + "'");
    const rigid::JointInfo info = model.joint(j);
    const int n = info.type == rigid::JointType::free ? 6 : info.type == rigid::JointType::ball ? 3 : 1;
    for (int d = 0; d < n; ++d) held.push_back(info.dof + d);
  }
  setHeldDofs(held);
  com_.assign(static_cast<std::size_t>(model.bodies()), Vec3{});
}

void SolidMobility3::setHeldDofs(const std::vector<int>& dofs) {
  std::vector<bool> held(static_cast<std::size_t>(model_->dofs()), false);
  for (int d : dofs) {
    if (d < 0 || d >= model_->dofs())
      throw std::invalid_argument("coupling3d: held DOF " + std::to_string(d) + " is not in the model " + model_->path());
    held[static_cast<std::size_t>(d)] = true;
  }
  free_.clear();
  for (int d = 0; d < model_->dofs(); ++d)
    if (!held[static_cast<std::size_t>(d)]) free_.push_back(d);
  jac_.assign(static_cast<std::size_t>(model_->bodies()), std::vector<double>(6 * free_.size(), 0.0));
}

void SolidMobility3::update(rigid::RigidData& data) {
  const int nv = model_->dofs(), nf = freeDofs(), nb = model_->bodies();
  for (int b = 1; b < nb; ++b) {
    const double* c = data.bodyComPosition(b);
    com_[static_cast<std::size_t>(b)] = {c[0], c[1], c[2]};
  }
  // J_b's column for DOF d: the body's velocities at a unit velocity of d alone. The angular velocity
  // from two more points: v(c + e_x) − v(c) = ω × e_x = (0, ω_z, −ω_y), v(c + e_y) − v(c) = (−ω_z, 0, ω_x).
  const std::vector<double> qvel(data.qvel(), data.qvel() + nv);
  for (int f = 0; f < nf; ++f) {
    std::fill(data.qvel(), data.qvel() + nv, 0.0);
    data.qvel()[free_[static_cast<std::size_t>(f)]] = 1.0;
    data.kinematics();
    for (int b = 1; b < nb; ++b) {
      const Vec3& c = com_[static_cast<std::size_t>(b)];
      const Vec3 v = data.pointVelocity(b, c);
      const Vec3 vx = data.pointVelocity(b, {c[0] + 1.0, c[1], c[2]});
      const Vec3 vy = data.pointVelocity(b, {c[0], c[1] + 1.0, c[2]});
      const double row[6] = {v[0], v[1], v[2], vy[2] - v[2], -(vx[2] - v[2]), vx[1] - v[1]};
      for (int r = 0; r < 6; ++r) jac_[static_cast<std::size_t>(b)][static_cast<std::size_t>(r * nf + f)] = row[r];
    }
  }
  std::copy(qvel.begin(), qvel.end(), data.qvel());
  data.kinematics();
  // A on the free DOFs, and its Cholesky factor (A is symmetric positive definite: a mass matrix plus
  // non-negative damping).
  data.eulerMatrix(full_);
  factor_.assign(static_cast<std::size_t>(nf * nf), 0.0);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j <= i; ++j) {
      double s = full_[static_cast<std::size_t>(free_[i] * nv + free_[j])];
      for (int k = 0; k < j; ++k) s -= factor_[static_cast<std::size_t>(i * nf + k)] * factor_[static_cast<std::size_t>(j * nf + k)];
      if (i == j) {
        if (!(s > 0)) throw std::invalid_argument("coupling3d: the bodies' mass matrix is singular on the free DOFs");
        factor_[static_cast<std::size_t>(i * nf + i)] = std::sqrt(s);
      } else {
        factor_[static_cast<std::size_t>(i * nf + j)] = s / factor_[static_cast<std::size_t>(j * nf + j)];
      }
    }
}

void SolidMobility3::velocityChange(const std::vector<Vec3>& force_n, const std::vector<Vec3>& torque_n_m, double dt,
                                    std::vector<double>& dv) const {
  const int nf = freeDofs();
  rhs_.assign(static_cast<std::size_t>(nf), 0.0);
  for (std::size_t b = 1; b < jac_.size(); ++b) {
    const double w[6] = {force_n[b][0], force_n[b][1], force_n[b][2], torque_n_m[b][0], torque_n_m[b][1], torque_n_m[b][2]};
    for (int r = 0; r < 6; ++r)
      for (int f = 0; f < nf; ++f) rhs_[static_cast<std::size_t>(f)] += jac_[b][static_cast<std::size_t>(r * nf + f)] * w[r];
  }
  // L Lᵀ Δv = dt rhs.
  dv.assign(static_cast<std::size_t>(nf), 0.0);
  for (int i = 0; i < nf; ++i) {
    double s = dt * rhs_[static_cast<std::size_t>(i)];
    for (int k = 0; k < i; ++k) s -= factor_[static_cast<std::size_t>(i * nf + k)] * dv[static_cast<std::size_t>(k)];
    dv[static_cast<std::size_t>(i)] = s / factor_[static_cast<std::size_t>(i * nf + i)];
  }
  for (int i = nf - 1; i >= 0; --i) {
    double s = dv[static_cast<std::size_t>(i)];
    for (int k = i + 1; k < nf; ++k) s -= factor_[static_cast<std::size_t>(k * nf + i)] * dv[static_cast<std::size_t>(k)];
    dv[static_cast<std::size_t>(i)] = s / factor_[static_cast<std::size_t>(i * nf + i)];
  }
}

void SolidMobility3::bodyVelocity(int body, const std::vector<double>& v, Vec3& linear, Vec3& angular) const {
  const int nf = freeDofs();
  const std::vector<double>& J = jac_[static_cast<std::size_t>(body)];
  double out[6] = {};
  for (int r = 0; r < 6; ++r)
    for (int f = 0; f < nf; ++f) out[r] += J[static_cast<std::size_t>(r * nf + f)] * v[static_cast<std::size_t>(f)];
  linear = {out[0], out[1], out[2]};
  angular = {out[3], out[4], out[5]};
}

void SolidMobility3::apply(rigid::RigidData& data, const std::vector<double>& dv, double dt) const {
  const int nf = freeDofs();
  std::vector<double> full(static_cast<std::size_t>(model_->dofs()), 0.0);
  for (int f = 0; f < nf; ++f) full[static_cast<std::size_t>(free_[static_cast<std::size_t>(f)])] = dv[static_cast<std::size_t>(f)];
  for (int j = 0; j < model_->joints(); ++j) {
    const rigid::JointInfo info = model_->joint(j);
    double* q = data.qpos() + info.qpos;
    const double* d = full.data() + info.dof;
    int linear = 0;
    if (info.type == rigid::JointType::free) linear = 3;
    if (info.type == rigid::JointType::slide || info.type == rigid::JointType::hinge) linear = 1;
    for (int k = 0; k < linear; ++k) q[k] += dt * d[k];
    const bool turned = info.type == rigid::JointType::free || info.type == rigid::JointType::ball;
    const int a = info.type == rigid::JointType::free ? 3 : 0;
    if (turned && (d[a] != 0.0 || d[a + 1] != 0.0 || d[a + 2] != 0.0)) {
      const int o = info.type == rigid::JointType::free ? 3 : 0;
      const rigid::Quat r = rigid::quatRotate({q[o], q[o + 1], q[o + 2], q[o + 3]},
                                              {dt * d[o], dt * d[o + 1], dt * d[o + 2]});
      for (int k = 0; k < 4; ++k) q[o + k] = r[static_cast<std::size_t>(k)];
    }
  }
  for (int d = 0; d < model_->dofs(); ++d) data.qvel()[d] += full[static_cast<std::size_t>(d)];
  data.kinematics();
}

}  // namespace creaturelab::coupling3d
