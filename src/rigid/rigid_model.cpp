#include "rigid/rigid_model.hpp"

#include <mujoco/mujoco.h>

#include <mutex>

namespace creaturelab::rigid {

namespace {
// MuJoCo's warning hook: the counters in mjData::warning already record every warning (the
// controller reads them), so the message itself is dropped rather than printed by a solver.
void quietWarning(const char*) {}
// MuJoCo's error hook must not return (the default ends the process); throwing lets the point
// fail with the message instead. MuJoCo is compiled with unwind tables on Debian's x86-64.
void throwingError(const char* message) { throw RigidError(std::string("MuJoCo: ") + message); }
}  // namespace

void installMujocoHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_warning = quietWarning;
    mju_user_error = throwingError;
  });
}

std::string mujocoVersion() { return mj_versionString(); }

void RigidModel::Deleter::operator()(mjModel_* m) const { mj_deleteModel(m); }

RigidModel RigidModel::load(const std::string& path) {
  installMujocoHandlers();
  char error[1024] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  if (m == nullptr) {
    // MuJoCo's message may span lines; an error is one line on the console.
    std::string message = error[0] ? error : "MuJoCo could not load the model";
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    while (!message.empty() && message.back() == ' ') message.pop_back();
    throw RigidError(path + ": " + message);
  }
  RigidModel out;
  out.model_.reset(m);
  out.path_ = path;
  return out;
}

int RigidModel::bodies() const { return model_->nbody; }
int RigidModel::joints() const { return model_->njnt; }
int RigidModel::dofs() const { return model_->nv; }
int RigidModel::positions() const { return model_->nq; }
int RigidModel::geoms() const { return model_->ngeom; }
double RigidModel::timestep_s() const { return model_->opt.timestep; }
Vec3 RigidModel::gravity_m_per_s2() const { return {model_->opt.gravity[0], model_->opt.gravity[1], model_->opt.gravity[2]}; }

int RigidModel::findJoint(const std::string& name) const { return mj_name2id(model_.get(), mjOBJ_JOINT, name.c_str()); }

JointInfo RigidModel::joint(int id) const {
  const mjModel* m = model_.get();
  JointInfo j;
  const char* name = mj_id2name(m, mjOBJ_JOINT, id);
  j.name = name ? name : "";
  switch (m->jnt_type[id]) {
    case mjJNT_FREE: j.type = JointType::free; break;
    case mjJNT_BALL: j.type = JointType::ball; break;
    case mjJNT_SLIDE: j.type = JointType::slide; break;
    default: j.type = JointType::hinge; break;
  }
  j.qpos = m->jnt_qposadr[id];
  j.dof = m->jnt_dofadr[id];
  j.body = m->jnt_bodyid[id];
  j.limited = m->jnt_limited[id] != 0;
  if (j.limited) {
    j.range_lo = m->jnt_range[2 * id];
    j.range_hi = m->jnt_range[2 * id + 1];
  }
  return j;
}

std::string RigidModel::bodyName(int body) const {
  const char* name = mj_id2name(model_.get(), mjOBJ_BODY, body);
  return name ? name : "";
}

int RigidModel::bodyParent(int body) const { return model_->body_parentid[body]; }
double RigidModel::bodyMass_kg(int body) const { return model_->body_mass[body]; }
double RigidModel::dofArmature(int dof) const { return model_->dof_armature[dof]; }

bool RigidModel::inSubtree(int body, int ancestor) const {
  for (int b = body;; b = model_->body_parentid[b]) {
    if (b == ancestor) return true;
    if (b == 0) return false;
  }
}

double RigidModel::subtreeMass_kg(int body) const { return model_->body_subtreemass[body]; }
int RigidModel::geomType(int geom) const { return model_->geom_type[geom]; }
Vec3 RigidModel::geomSize(int geom) const {
  const mjtNum* s = model_->geom_size + 3 * geom;
  return {s[0], s[1], s[2]};
}
int RigidModel::geomBody(int geom) const { return model_->geom_bodyid[geom]; }

double RigidModel::referencePosition(int qpos) const { return model_->qpos0[qpos]; }

void RigidModel::setGravity(const Vec3& g) {
  for (int k = 0; k < 3; ++k) model_->opt.gravity[k] = g[k];
}

void RigidModel::setTimestep(double dt_s) { model_->opt.timestep = dt_s; }

}  // namespace creaturelab::rigid
