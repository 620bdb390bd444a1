#pragma once
// The creature controller of Lentine et al. 2010 (§2,
// Fig. 1): every frame,
//   (b) for each controlled joint i (independently, in parallel, §5):
//       (d) move joint i by +delta and by -delta over one frame with the target servo, the bodies
//           outboard of it held rigid with it (§5), the other prescribed joints held;
//       (e) evaluate joint i's objective in each configuration (§2.3, §3);
//       (f) derivative g_i = (J_i(+delta) - J_i(-delta)) / (2 delta) (§2.1, Fig. 3);
//       (g) steepest descent with the fixed step of the creature's strength: the target moves by
//           strength x frame against the gradient (with it to maximise) (§2.1);
//   (a, c) advance the creature one frame towards those targets under all external forces.
// A hinge is one DOF; a ball joint three, the rotations about its body's own axes (q * exp(+-delta
// e_a), the body frame MuJoCo's ball velocities live in), each differenced and stepped on its own:
// the steepest-descent direction per DOF is -sign(g), so every DOF (each ball axis) moves by the
// strength's step. Kinematic joints follow their patterns exactly, PD-driven ones are pulled
// towards theirs (§2.2); both go on doing so while a controlled joint is perturbed, unless they
// lie outboard of it, where they are held rigid with it (§5).
#include <memory>
#include <vector>

#include "control/controller_params.hpp"
#include "control/force_model.hpp"
#include "control/objectives.hpp"
#include "control/prescription.hpp"
#include "control/target_servo.hpp"
#include "fluid/worker_pool.hpp"

namespace creaturelab::control {

struct FrameRecord {
  double time_s = 0;
  // Per controlled DOF (a ball joint's three: the components of its rotation vector log(q), rad):
  std::vector<double> angle_rad;    // after the frame
  std::vector<double> target_rad;   // the servo's targets for the frame (PD targets, §2.2)
  std::vector<double> derivative;   // dJ_i/dq used for the frame's direction (per rad)
  // Per controlled joint:
  std::vector<double> objective;    // J_i = sum_j w_ij F_j after the frame
  JointMeasures measures;           // effort, drag per joint after the frame
  double servo_residual_rad = 0;    // largest servo residual before projection (this frame)
  bool searched = false;            // derivatives re-evaluated this frame (search_every_frames)
  double kinematic_error_rad = 0;   // largest |q - pattern(t)| of the kinematic joints after the frame
  double pd_error_rad = 0;          // largest |q - pattern(t)| of the PD-driven joints after the frame
};

class Controller {
 public:
  // `model` (with its time step set to frame_s / substeps by the caller) and `force` must outlive
  // the controller; p must pass p.validate(model).
  Controller(const rigid::RigidModel& model, ControllerParams p, const ForceModel& force);
  ~Controller();

  // Sets a hinge's angle, or a ball joint's rotation (vector, rad, from the identity), before the
  // first frame; kinematic and PD joints holding a pose hold this one.
  void setAngle(const std::string& joint, double rad);
  void setRotation(const std::string& joint, const Vec3& rotation_rad);
  FrameRecord frame();

  rigid::RigidData& data() { return main_; }
  const ControllerParams& params() const { return p_; }
  // The objective of the joint owning controlled DOF `dof` at `offset` rad from the current pose
  // along that DOF, as the derivative sees it (rigidified, held, one frame of the servo): for tests.
  double evaluate(int dof, double offset_rad);
  // Per-DOF derivatives at the current state (evaluated in parallel).
  std::vector<double> derivatives();
  int controlledDofs() const { return int(pres_.dof_joint.size()); }
  // The measures at the current state (steady_state as configured), without changing it.
  JointMeasures measureNow();
  int evaluationsPerFrame() const { return 2 * controlledDofs(); }

 private:
  struct Worker;
  double evaluate(Worker& w, const rigid::RigidState& start, int dof, double offset_rad);

  const rigid::RigidModel& model_;
  ControllerParams p_;
  const ForceModel& force_;
  ObjectiveLayout layout_;
  rigid::RigidData main_;
  Prescription pres_;                     // the frame's targets live in pres_.prescribed
  std::vector<double> direction_;         // -1, 0, +1 per controlled DOF
  std::vector<double> derivative_;
  std::unique_ptr<fluid::WorkerPool> pool_;
  std::vector<std::unique_ptr<Worker>> workers_;  // one per pool part
  ServoScratch main_servo_;
  long frame_ = 0;
};

}  // namespace creaturelab::control
