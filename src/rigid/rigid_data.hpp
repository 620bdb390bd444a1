#pragma once
// Simulation data for one RigidModel (mjData behind RAII): one per thread, never shared. Every
// operation the controller needs from MuJoCo is here, named for what it does, so that src/control/
// stays free of MuJoCo's headers (DESIGN.md layers).
#include <memory>
#include <vector>

#include "rigid/rigid_model.hpp"

struct mjData_;

namespace creaturelab::rigid {

// Everything that decides the next step: positions, velocities, time, and the constraint
// solver's warm start (restoring it too keeps a re-run from a snapshot bitwise identical).
struct RigidState {
  std::vector<double> qpos, qvel, warmstart;
  double time_s = 0;
};

// A body's spatial velocity: angular (rad/s) and linear (m/s) at `point_m`, world frame.
struct BodyVelocity {
  Vec3 angular{}, linear{};
  Vec3 point_m{};
};

class RigidData {
 public:
  explicit RigidData(const RigidModel& model);
  RigidData(const RigidData&) = delete;
  RigidData& operator=(const RigidData&) = delete;
  RigidData(RigidData&&) = default;
  RigidData& operator=(RigidData&&) = default;

  const RigidModel& model() const { return *model_; }

  RigidState save() const;
  void restore(const RigidState& s);
  // Back to the model's reference configuration (qpos0, zero velocity).
  void reset();

  double time_s() const;
  double* qpos();
  const double* qpos() const;
  double* qvel();
  const double* qvel() const;
  // Generalized forces applied this step (external-force stages write here).
  double* appliedForces();
  const double* appliedForces() const;
  const double* acceleration() const;  // qacc of the last forward/step

  // Stage: positions and velocities of bodies and geoms from qpos, qvel (no dynamics); qpos itself
  // is left bit for bit as it was.
  void kinematics();
  // Lentine et al. 2010 §3.3: the creature's shape
  // frozen, i.e. every relative joint velocity set to zero, "treating the entire creature ... as a
  // unified rigid body ... in a way that conserves both linear and angular momentum". A tree
  // rooted to the world (no free joint) comes to rest; a tree with a free root keeps the rigid
  // velocity v_R of its free joint that carries the same generalized momentum along the root's
  // DOFs, M_RR v_R = (M qvel)_R, which is its total linear momentum and its angular momentum
  // about the root (the root DOFs move every body of the tree rigidly). Positions are not changed.
  void freezeShape();
  // Momentum of `body` and everything outboard of it: linear (kg m/s) and angular about the
  // subtree's centre of mass (kg m^2/s), world frame, at the current qpos, qvel.
  void subtreeMomentum(int body, Vec3& linear, Vec3& angular);
  // One MuJoCo step (forward dynamics + semi-implicit Euler) with the applied forces as they are.
  void step();
  // Inverse dynamics: generalized forces that produce the accelerations `qacc` (size nv) at the
  // current state, with everything applied: writes the forces the actuators must add, i.e.
  // MuJoCo's qfrc_inverse minus the applied forces (qfrc_inverse = qfrc_applied + J' xfrc + actuators).
  void actuatorForcesFor(const double* qacc, double* out);
  // x = M^-1 y for n columns of length nv, with M factorised at the last step's start.
  void solveMass(double* x, const double* y, int n) const;
  // The dense nv x nv matrix of the last Euler step, M + h D (MuJoCo's Euler integrator treats
  // joint damping D implicitly), row-major into out (resized).
  void eulerMatrix(std::vector<double>& out) const;

  // Adds a force (N) acting at a world point (m) on `body` to the applied generalized forces.
  void applyForceAt(int body, const Vec3& force_n, const Vec3& point_m);
  // Adds a force (N) at a world point (m) plus a couple (N m) acting on `body`.
  void applyWrenchAt(int body, const Vec3& force_n, const Vec3& torque_n_m, const Vec3& point_m);
  // Body velocity at its subtree root's centre of mass (use pointVelocity for a point).
  Vec3 pointVelocity(int body, const Vec3& point_m) const;

  // Geom pose: position (m) and rotation matrix (row-major, columns are the geom's axes).
  const double* geomPosition(int geom) const;
  const double* geomRotation(int geom) const;
  const double* bodyPosition(int body) const;    // body frame origin
  const double* bodyComPosition(int body) const; // body centre of mass
  const double* bodyRotation(int body) const;
  const double* jointAnchor(int joint) const;      // world position of a joint's anchor
  const double* subtreeCom(int body) const;        // centre of mass of a body and all outboard of it

  // Warnings MuJoCo raised (bad qacc, too many contacts, ...), summed over kinds; and whether
  // every position and velocity is finite.
  int warnings() const;
  bool finite() const;
  int contacts() const;

 private:
  struct Deleter {
    void operator()(mjData_* d) const;
  };
  const RigidModel* model_;
  std::unique_ptr<mjData_, Deleter> data_;
  std::vector<double> qpos_scratch_;  // kinematics(): qpos before MuJoCo normalises it
};

}  // namespace creaturelab::rigid
