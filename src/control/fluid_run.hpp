#pragma once
// What a controller run in the coupled fluid measures (M. Lentine et al., "Creature Control in a
// Fluid Environment", 2010 §4, §6, §7): per frame the controller's record, the fluid's force per
// joint and on all bodies (§7.1's lift), the senses followed, the PD-driven angles and the first
// joint's line against the stream; every k frames the outline markers and the vorticity; at the end
// the means over the last frames or whole flap cycles. No I/O: the kind copies them into its Result.
#include <cstdint>
#include <vector>

#include "control/fluid_controller.hpp"
#include "control/frame_series.hpp"
#include "control/run_measures.hpp"

namespace creaturelab::control {

// The outline markers (world x, z, m) at the recorded frames, and the body of each.
struct MarkerFrames {
  std::vector<double> time_s;
  std::vector<double> data;  // frames x markers x 2
  std::vector<std::int64_t> body;
  int points = 0;
};

// The fluid's vorticity at cell centres (1/s) at the recorded frames, on the box's grid.
struct VorticityFrames {
  std::vector<double> time_s;
  std::vector<double> data;  // frames x ny x nx
  int nx = 0, ny = 0;
  double dx_m = 0, origin_x_m = 0, origin_z_m = 0;  // origin: the box's lower-left corner, world
};

class FluidRunRecorder {
 public:
  // `origin_*_m`: world position of the fluid box's lower-left corner. `field_every_frames` > 0
  // records markers and vorticity now and after every k-th frame.
  FluidRunRecorder(const rigid::RigidModel& model, const ControllerParams& p, FluidController& controller,
                   double origin_x_m, double origin_z_m, long field_every_frames);

  // Markers and vorticity now, if fields are recorded (after the flow has developed).
  void start(FluidController& controller);
  // After each frame: its record and the controller's state.
  void record(const FrameRecord& fr, FluidController& controller);

  const SeriesSet& series() const { return series_; }
  const MarkerFrames& markers() const { return markers_; }
  const VorticityFrames& vorticity() const { return vorticity_; }
  // Means over the last `average_frames`; mean_up_force_n over the last `force_cycles` flaps of
  // `frames_per_cycle` frames (0: over the last average_frames); `tolerance_deg` for the converged
  // frame (Fig. 2); `forcing_iterations_most` the controller's.
  std::vector<NamedValue> measure(int average_frames, double tolerance_deg, int frames_per_cycle, int force_cycles,
                                  int forcing_iterations_most) const;

 private:
  void recordField(FluidController& controller);

  std::vector<int> pd_qpos_;
  int j0_id_ = -1, j0_body_ = -1;
  long field_every_ = 0, frame_ = 0;
  SeriesSet series_;
  FrameSeries common_;  // after series_, which holds its series
  std::vector<double> *flow_, *body_fx_, *body_fz_;
  std::vector<std::vector<double>*> angle_, target_, derivative_, fx_, fz_, sense_, pd_angle_;
  std::vector<Vec3> lines_;  // per frame: anchor -> centre of mass of the first joint's bodies
  MarkerFrames markers_;
  VorticityFrames vorticity_;
  double max_cells_ = 0;
};

}  // namespace creaturelab::control
