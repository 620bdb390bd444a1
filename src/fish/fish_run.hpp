#pragma once
// One fish simulated through a controller schedule: the motor controller sets the muscles' rest
// lengths, the solver steps, and the run keeps what the measurements need (centre of mass,
// heading, momentum, node positions). No I/O; the kind turns it into a Result.
#include <string>
#include <vector>

#include "fish/fish_model.hpp"
#include "fish/fish_solver.hpp"
#include "fish/motor.hpp"

namespace creaturelab::fish {

struct RunOptions {
  int frame_every_steps = 1;  // record a frame every this many steps (the first and last always)
};

struct FishRecord {
  // Per frame.
  std::vector<double> time_s;
  std::vector<double> com_m;          // frames x 3
  std::vector<double> heading_rad;    // horizontal heading of the body axis, unwrapped (0 = +x, left > 0)
  std::vector<double> momentum_kg_m_per_s;  // frames x 3: sum m v
  std::vector<double> nodes_m;        // frames x 23 x 3
  std::vector<double> muscle_rest_m;  // frames x 12
  long steps = 0;
  // Failure (blow-up): the step that could not be taken and why.
  bool blew_up = false;
  long blowup_step = -1;
  double blowup_time_s = 0;
  std::string blowup_cause;
  // max over steps of |sum m v - sum m v(0)| / max over steps of sum m |v|.
  double momentum_drift_rel = 0;
  double momentum_scale_kg_m_per_s = 0;  // the denominator
  int frames() const { return int(time_s.size()); }
};

// Horizontal heading of the fish: from the middle of ring 2 to the snout, atan2(dy, dx).
double headingRad(const NodeMatrix& x);
Eigen::Vector3d centreOfMass(const FishModel& fish, const NodeMatrix& x);

// Runs the whole schedule from the fish at rest (or until a blow-up, which is recorded, not thrown).
FishRecord runSchedule(const FishModel& fish, const SolverParams& solver, const MotorParams& motor,
                       const std::vector<ScheduleItem>& schedule, const RunOptions& options);

// The largest step at which the schedule runs to its end without a blow-up, by bisection on a log
// scale between lo_s and hi_s (the answer is lo_s if even that fails, hi_s if that passes).
// Stability need not be monotone in the step: the bisection reports the boundary it brackets.
struct StableStep {
  double dt_s = 0;
  std::string first_failure;  // the cause at the smallest failing step tried
};
StableStep largestStableStep(const FishModel& fish, SolverParams solver, const MotorParams& motor,
                             const std::vector<ScheduleItem>& schedule, double lo_s, double hi_s, int iterations);

}  // namespace creaturelab::fish
