#pragma once
// What a controller run in the 3-D coupled fluid measures (M. Lentine et al., "Creature Control in a
// Fluid Environment", 2010 §7.1, the driven flyer): per frame the controller's record (frame_series.hpp),
// the controlled and PD-driven angles, the senses followed and the fluid's force on all bodies; at the
// end the mean upward force over whole flap cycles with its standard error. No I/O: the kind copies
// them into its Result.
#include <vector>

#include "control/fluid_controller.hpp"
#include "control/frame_series.hpp"
#include "control/run_measures.hpp"

namespace creaturelab::control {

class FluidRunRecorder3 {
 public:
  FluidRunRecorder3(const rigid::RigidModel& model, const ControllerParams& p);
  // After each frame: its record and the controller's state.
  void record(const FrameRecord& fr, FluidController& controller);

  const SeriesSet& series() const { return series_; }
  // mean_up_force_n (+ _stderr) over the last `force_cycles` flaps of `frames_per_cycle` frames;
  // `markers` and `forcing_iterations_most` as the kind reports them.
  std::vector<NamedValue> measure(int frames_per_cycle, int force_cycles, int markers,
                                  int forcing_iterations_most) const;

 private:
  std::vector<int> pd_qpos_;
  SeriesSet series_;
  FrameSeries common_;  // after series_, which holds its series
  std::vector<double> *body_fx_, *body_fy_, *body_fz_;
  std::vector<std::vector<double>*> angle_, target_, derivative_, sense_, pd_angle_;
};

}  // namespace creaturelab::control
