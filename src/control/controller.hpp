#pragma once
// The creature controller of Lentine et al. 2010 (seeds/creature-control-lentine-2010.txt §2,
// Fig. 1): every frame,
//   (b) for each controlled joint i (independently, in parallel, §5):
//       (d) move joint i by +delta and by -delta over one frame with the target servo, the bodies
//           outboard of it held rigid with it (§5), the other prescribed joints held;
//       (e) evaluate joint i's objective in each configuration (§2.3, §3);
//       (f) derivative g_i = (J_i(+delta) - J_i(-delta)) / (2 delta) (§2.1, Fig. 3);
//       (g) steepest descent with the fixed step of the creature's strength: the target moves by
//           strength x frame against the gradient (with it to maximise) (§2.1);
//   (a, c) advance the creature one frame towards those targets under all external forces.
// With one DOF per joint the normalised steepest-descent direction of joint i is -sign(g_i).
#include <memory>
#include <vector>

#include "control/controller_params.hpp"
#include "control/force_model.hpp"
#include "control/objectives.hpp"
#include "control/target_servo.hpp"
#include "fluid/worker_pool.hpp"

namespace creaturelab::control {

struct FrameRecord {
  double time_s = 0;
  std::vector<double> angle_rad;    // controlled joints after the frame
  std::vector<double> target_rad;   // the servo's targets for the frame (PD targets, §2.2)
  std::vector<double> derivative;   // dJ_i/dq_i used for the frame's direction (per rad)
  std::vector<double> objective;    // J_i = sum_j w_ij F_j after the frame
  JointMeasures measures;           // effort, drag per joint after the frame
  double servo_residual_rad = 0;    // largest servo residual before projection (this frame)
  bool searched = false;            // derivatives re-evaluated this frame (search_every_frames)
};

class Controller {
 public:
  // `model` (with its time step set to frame_s / substeps by the caller) and `force` must outlive
  // the controller; p must pass validate(p, model).
  Controller(const rigid::RigidModel& model, ControllerParams p, const ForceModel& force);
  ~Controller();

  // Sets a controlled or kinematic joint's angle before the first frame.
  void setAngle(const std::string& joint, double rad);
  FrameRecord frame();

  rigid::RigidData& data() { return main_; }
  const ControllerParams& params() const { return p_; }
  // Joint i's objective at `offset` rad from its current angle, as the derivative sees it
  // (rigidified, held, one frame of the servo): for tests of the derivative.
  double evaluate(int joint, double offset_rad);
  // Per-DOF derivatives at the current state (evaluated in parallel).
  std::vector<double> derivatives();
  // The measures at the current state (steady_state as configured), without changing it.
  JointMeasures measureNow();
  int evaluationsPerFrame() const { return 2 * int(p_.controlled.size()); }

 private:
  struct Worker;
  double evaluate(Worker& w, const rigid::RigidState& start, int joint, double offset_rad);

  const rigid::RigidModel& model_;
  ControllerParams p_;
  const ForceModel& force_;
  ObjectiveLayout layout_;
  rigid::RigidData main_;
  Prescribed prescribed_;                 // controlled joints first (in order), then kinematic
  std::vector<std::vector<int>> holds_;   // per controlled joint: passive hinge/slide joints outboard
  std::vector<double> kinematic_rad_;     // held angles of the kinematic joints
  std::vector<double> direction_;         // -1, 0, +1 per controlled joint
  std::vector<double> derivative_;
  std::unique_ptr<fluid::WorkerPool> pool_;
  std::vector<std::unique_ptr<Worker>> workers_;  // one per pool part
  ServoScratch main_servo_;
  long frame_ = 0;
};

}  // namespace creaturelab::control
