#pragma once
// A MuJoCo model behind RAII: loaded from an MJCF file, read-only afterwards so that
// any number of threads can step their own RigidData against it. Errors name the file and carry
// MuJoCo's own message. The controller (src/control/) knows MuJoCo only through this face.
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

struct mjModel_;

namespace creaturelab::rigid {

using Vec3 = std::array<double, 3>;

// A model that cannot be loaded, a name it does not have, a MuJoCo error while stepping.
class RigidError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class JointType { free, ball, slide, hinge };

struct JointInfo {
  std::string name;
  JointType type = JointType::hinge;
  int qpos = 0;   // address in qpos
  int dof = 0;    // address in qvel
  int body = 0;   // the body the joint moves (with everything outboard of it)
  // MJCF range (MuJoCo's jnt_limited, jnt_range): a hinge's angle (rad) or a slide's position (m)
  // stays within [range_lo, range_hi]; a ball joint's rotation angle from its reference within
  // range_hi (rad; MuJoCo requires range_lo = 0). Without a range both are 0.
  bool limited = false;
  double range_lo = 0, range_hi = 0;
};

class RigidModel {
 public:
  // Loads an MJCF file; throws RigidError "FILE: MuJoCo's message" when it cannot.
  static RigidModel load(const std::string& path);

  int bodies() const;
  int joints() const;
  int dofs() const;       // nv
  int positions() const;  // nq
  int geoms() const;
  double timestep_s() const;
  Vec3 gravity_m_per_s2() const;

  // Joint id by name; -1 when the model has none.
  int findJoint(const std::string& name) const;
  JointInfo joint(int id) const;
  std::string bodyName(int body) const;
  int bodyParent(int body) const;
  double bodyMass_kg(int body) const;
  // True when `body` is `ancestor` or lies outboard of it (in its subtree).
  bool inSubtree(int body, int ancestor) const;
  double subtreeMass_kg(int body) const;
  // MJCF armature of a DOF (kg or kg m^2): inertia added to the DOF alone.
  double dofArmature(int dof) const;
  // MuJoCo's geom type number (2 sphere, 3 capsule, 4 ellipsoid, 5 cylinder, 6 box, 7 mesh) and
  // size parameters (half-sizes; capsule: radius, half-length).
  int geomType(int geom) const;
  Vec3 geomSize(int geom) const;
  int geomBody(int geom) const;
  // The joint's reference angle (qpos0) at its qpos address.
  double referencePosition(int qpos) const;

  // Replaces gravity and the time step (the experiment's choice over the file's).
  void setGravity(const Vec3& g_m_per_s2);
  void setTimestep(double dt_s);

  const std::string& path() const { return path_; }
  const mjModel_* raw() const { return model_.get(); }

 private:
  struct Deleter {
    void operator()(mjModel_* m) const;
  };
  std::unique_ptr<mjModel_, Deleter> model_;
  std::string path_;
};

// Installs handlers so that MuJoCo's warnings are counted in its data (never printed, never
// written to MUJOCO_LOG.TXT) and its errors throw RigidError instead of ending the process.
// Called by RigidModel::load; idempotent.
void installMujocoHandlers();

std::string mujocoVersion();

}  // namespace creaturelab::rigid
