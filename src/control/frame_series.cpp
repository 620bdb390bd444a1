#include "control/frame_series.hpp"

#include <algorithm>

namespace creaturelab::control {

FrameSeries::FrameSeries(SeriesSet& series, const std::vector<std::string>& controlled) {
  time_ = &series.add("time_s", "s");
  residual_ = &series.add("servo_residual_rad", "rad");
  for (const auto& j : controlled) {
    objective_.push_back(&series.add("objective_" + j, ""));
    effort_.push_back(&series.add("effort_n_m_s_" + j, "N m s"));
    torque_.push_back(&series.add("torque_n_m_" + j, "N m"));
    drag_.push_back(&series.add("drag_n_" + j, "N"));
    drag_along_.push_back(&series.add("drag_along_n_" + j, "N"));
  }
}

void FrameSeries::record(const FrameRecord& fr) {
  time_->push_back(fr.time_s);
  residual_->push_back(fr.servo_residual_rad);
  max_residual_ = std::max(max_residual_, fr.servo_residual_rad);
  for (std::size_t i = 0; i < objective_.size(); ++i) {
    objective_[i]->push_back(fr.objective[i]);
    effort_[i]->push_back(fr.measures.effort_n_m_s[i]);
    torque_[i]->push_back(fr.measures.torque_n_m[i]);
    drag_[i]->push_back(fr.measures.drag_n[i]);
    drag_along_[i]->push_back(fr.measures.drag_along_n[i]);
  }
}

}  // namespace creaturelab::control
