#include "rigid/rigid_data.hpp"

#include <mujoco/mujoco.h>

#include <cmath>
#include <vector>

namespace creaturelab::rigid {

void RigidData::Deleter::operator()(mjData_* d) const { mj_deleteData(d); }

RigidData::RigidData(const RigidModel& model) : model_(&model), data_(mj_makeData(model.raw())) {
  if (!data_) throw RigidError(model.path() + ": MuJoCo could not allocate its data");
  mj_forward(model.raw(), data_.get());
}

RigidState RigidData::save() const {
  const mjModel* m = model_->raw();
  const mjData* d = data_.get();
  RigidState s;
  s.qpos.assign(d->qpos, d->qpos + m->nq);
  s.qvel.assign(d->qvel, d->qvel + m->nv);
  s.warmstart.assign(d->qacc_warmstart, d->qacc_warmstart + m->nv);
  s.time_s = d->time;
  return s;
}

void RigidData::restore(const RigidState& s) {
  const mjModel* m = model_->raw();
  mjData* d = data_.get();
  mju_copy(d->qpos, s.qpos.data(), m->nq);
  mju_copy(d->qvel, s.qvel.data(), m->nv);
  mju_copy(d->qacc_warmstart, s.warmstart.data(), m->nv);
  mju_zero(d->qfrc_applied, m->nv);
  mju_zero(d->xfrc_applied, 6 * m->nbody);
  d->time = s.time_s;
}

void RigidData::reset() {
  mj_resetData(model_->raw(), data_.get());
  mj_forward(model_->raw(), data_.get());
}

double RigidData::time_s() const { return data_->time; }
double* RigidData::qpos() { return data_->qpos; }
const double* RigidData::qpos() const { return data_->qpos; }
double* RigidData::qvel() { return data_->qvel; }
const double* RigidData::qvel() const { return data_->qvel; }
double* RigidData::appliedForces() { return data_->qfrc_applied; }
const double* RigidData::appliedForces() const { return data_->qfrc_applied; }
const double* RigidData::acceleration() const { return data_->qacc; }

void RigidData::kinematics() {
  // mj_fwdPosition normalises the quaternions in qpos in place, which is not idempotent in floating
  // point: the state is put back as it was, so that restore() then kinematics() gives bitwise the
  // saved state (mj_step normalises at its start either way).
  const mjModel* m = model_->raw();
  mjData* d = data_.get();
  qpos_scratch_.assign(d->qpos, d->qpos + m->nq);
  mj_fwdPosition(m, d);
  mj_fwdVelocity(m, d);
  mju_copy(d->qpos, qpos_scratch_.data(), m->nq);
}

void RigidData::freezeShape() {
  const mjModel* m = model_->raw();
  mjData* d = data_.get();
  std::vector<int> root;  // DOFs of the free joints (6 each)
  for (int j = 0; j < m->njnt; ++j)
    if (m->jnt_type[j] == mjJNT_FREE)
      for (int k = 0; k < 6; ++k) root.push_back(m->jnt_dofadr[j] + k);
  if (root.empty()) {
    mju_zero(d->qvel, m->nv);
    return;
  }
  mj_fwdPosition(m, d);  // the mass matrix at this pose
  const int nr = int(root.size());
  std::vector<mjtNum> momentum(m->nv), full(std::size_t(m->nv) * m->nv), block(std::size_t(nr) * nr), v(nr);
  mj_mulM(m, d, momentum.data(), d->qvel);
  mj_fullM(m, full.data(), d->qM);
  // Free trees are independent blocks of M, so one solve over all root DOFs is each tree's.
  for (int r = 0; r < nr; ++r)
    for (int c = 0; c < nr; ++c) block[std::size_t(r) * nr + c] = full[std::size_t(root[r]) * m->nv + root[c]];
  std::vector<mjtNum> rhs(nr);
  for (int r = 0; r < nr; ++r) rhs[r] = momentum[root[r]];
  if (mju_cholFactor(block.data(), nr, mjMINVAL) < nr)
    throw RigidError(model_->path() + ": the free bodies' mass matrix is singular (massless free body?)");
  mju_cholSolve(v.data(), block.data(), rhs.data(), nr);
  mju_zero(d->qvel, m->nv);
  for (int r = 0; r < nr; ++r) d->qvel[root[r]] = v[r];
}

void RigidData::subtreeMomentum(int body, Vec3& linear, Vec3& angular) {
  const mjModel* m = model_->raw();
  mjData* d = data_.get();
  mj_fwdPosition(m, d);
  mj_fwdVelocity(m, d);
  mj_subtreeVel(m, d);
  for (int k = 0; k < 3; ++k) {
    linear[k] = m->body_subtreemass[body] * d->subtree_linvel[3 * body + k];
    angular[k] = d->subtree_angmom[3 * body + k];
  }
}

void RigidData::step() { mj_step(model_->raw(), data_.get()); }

void RigidData::actuatorForcesFor(const double* qacc, double* out) {
  const mjModel* m = model_->raw();
  mjData* d = data_.get();
  // mj_inverse reads qacc from the data; keep the forward acceleration for the caller.
  std::vector<mjtNum> keep(d->qacc, d->qacc + m->nv);
  mju_copy(d->qacc, qacc, m->nv);
  mj_inverse(m, d);
  for (int i = 0; i < m->nv; ++i) out[i] = d->qfrc_inverse[i] - d->qfrc_applied[i];
  mju_copy(d->qacc, keep.data(), m->nv);
}

void RigidData::solveMass(double* x, const double* y, int n) const {
  mj_solveM(model_->raw(), data_.get(), x, y, n);
}

void RigidData::eulerMatrix(std::vector<double>& out) const {
  const mjModel* m = model_->raw();
  out.assign(std::size_t(m->nv) * m->nv, 0.0);
  mj_fullM(m, out.data(), data_->qM);
  for (int i = 0; i < m->nv; ++i) out[std::size_t(i) * m->nv + i] += m->opt.timestep * m->dof_damping[i];
}

void RigidData::applyForceAt(int body, const Vec3& force_n, const Vec3& point_m) {
  const mjtNum torque[3] = {0, 0, 0};
  mj_applyFT(model_->raw(), data_.get(), force_n.data(), torque, point_m.data(), body, data_->qfrc_applied);
}

void RigidData::applyWrenchAt(int body, const Vec3& force_n, const Vec3& torque_n_m, const Vec3& point_m) {
  mj_applyFT(model_->raw(), data_.get(), force_n.data(), torque_n_m.data(), point_m.data(), body, data_->qfrc_applied);
}

Vec3 RigidData::pointVelocity(int body, const Vec3& p) const {
  // cvel is (angular, linear) at the centre of mass of the body's kinematic tree
  // (subtree_com of its root): v(p) = v + w x (p - c).
  const mjModel* m = model_->raw();
  const mjData* d = data_.get();
  const mjtNum* cv = d->cvel + 6 * body;
  const mjtNum* c = d->subtree_com + 3 * m->body_rootid[body];
  const double r[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
  return {cv[3] + cv[1] * r[2] - cv[2] * r[1], cv[4] + cv[2] * r[0] - cv[0] * r[2],
          cv[5] + cv[0] * r[1] - cv[1] * r[0]};
}

const double* RigidData::geomPosition(int geom) const { return data_->geom_xpos + 3 * geom; }
const double* RigidData::geomRotation(int geom) const { return data_->geom_xmat + 9 * geom; }
const double* RigidData::bodyPosition(int body) const { return data_->xpos + 3 * body; }
const double* RigidData::bodyComPosition(int body) const { return data_->xipos + 3 * body; }
const double* RigidData::bodyRotation(int body) const { return data_->xmat + 9 * body; }

const double* RigidData::jointAnchor(int joint) const { return data_->xanchor + 3 * joint; }
const double* RigidData::subtreeCom(int body) const { return data_->subtree_com + 3 * body; }

int RigidData::warnings() const {
  int n = 0;
  for (int k = 0; k < mjNWARNING; ++k) n += data_->warning[k].number;
  return n;
}

bool RigidData::finite() const {
  const mjModel* m = model_->raw();
  for (int i = 0; i < m->nq; ++i)
    if (!std::isfinite(data_->qpos[i])) return false;
  for (int i = 0; i < m->nv; ++i)
    if (!std::isfinite(data_->qvel[i])) return false;
  return true;
}

int RigidData::contacts() const { return data_->ncon; }

}  // namespace creaturelab::rigid
