#pragma once
// The per-frame series every controller run records, in wind and in the fluid alike (M. Lentine et
// al., "Creature Control in a Fluid Environment", 2010): the time, the servo's miss before its
// projection (§2.2), and per controlled joint its objective J_i (§5), effort (Eq. 1), torque and
// drag (Eqs. 3, 4). No I/O: the recorders hand the series on to the kinds.
#include <string>
#include <vector>

#include "control/controller.hpp"
#include "control/run_measures.hpp"

namespace creaturelab::control {

class FrameSeries {
 public:
  // Adds the series to `series` (which must outlive this), one set per name in `controlled`.
  FrameSeries(SeriesSet& series, const std::vector<std::string>& controlled);
  void record(const FrameRecord& fr);

  int frames() const { return int(time_->size()); }
  double maxResidualRad() const { return max_residual_; }
  // Per controlled joint i, its values so far.
  const std::vector<double>& objective(int i) const { return *objective_[i]; }
  const std::vector<double>& effort(int i) const { return *effort_[i]; }
  const std::vector<double>& torque(int i) const { return *torque_[i]; }
  const std::vector<double>& drag(int i) const { return *drag_[i]; }
  const std::vector<double>& dragAlong(int i) const { return *drag_along_[i]; }

 private:
  std::vector<double> *time_, *residual_;
  std::vector<std::vector<double>*> objective_, effort_, torque_, drag_, drag_along_;
  double max_residual_ = 0;
};

}  // namespace creaturelab::control
