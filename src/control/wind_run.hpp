#pragma once
// What a controller run under gravity and simple wind measures (M. Lentine et al., "Creature
// Control in a Fluid Environment", 2010 §2-3, Figs. 2, 4, 6): per frame the controller's record,
// the geoms' frames for drawing and the first controlled joint's load line; at the end the means
// over the last frames. No I/O: the kind copies series, frames and values into its Result.
#include <cstdint>
#include <memory>
#include <vector>

#include "control/controller.hpp"
#include "control/frame_series.hpp"
#include "control/run_measures.hpp"

namespace creaturelab::control {

// Geom frames for drawing: per frame and geom the centre and the three axis tips scaled by the
// half-extents (4 points of 3 coordinates, m), with each geom's MuJoCo type and body.
struct GeomFrames {
  std::vector<double> time_s;
  std::vector<double> data;  // frames x (4 x geoms) x 3
  std::vector<std::int64_t> type, body;
  int points = 0;
};

class WindRunRecorder {
 public:
  // `model` and `force` must outlive the recorder; `wind_m_per_s` the constant wind (flow angle),
  // `gravity_m_per_s2` along -z (the net force's weight). Records the geoms' first frame from
  // `controller`'s state.
  WindRunRecorder(const rigid::RigidModel& model, const ControllerParams& p, const ForceModel& force,
                  const Vec3& wind_m_per_s, double gravity_m_per_s2, Controller& controller);
  ~WindRunRecorder();

  // After each frame: its record and the controller's state (whose kinematics it updates).
  void record(const FrameRecord& fr, Controller& controller);

  const SeriesSet& series() const { return series_; }
  const GeomFrames& geoms() const { return geoms_; }
  // Means over the last `average_frames` (the strength-limited step chatters by one step about an
  // optimum) and the run's extremes; `tolerance_deg` for the converged frame (Fig. 2).
  std::vector<NamedValue> measure(int average_frames, double tolerance_deg, int triangles) const;

 private:
  void recordGeoms(const rigid::RigidData& d, double time_s);
  void recordLoad(rigid::RigidData& d);

  const rigid::RigidModel& model_;
  ControllerParams p_;
  Vec3 wind_;
  double gravity_ = 0, mass_ = 0;
  int j0_id_ = -1, j0_body_ = -1;
  std::unique_ptr<Controller> probe_;  // steady state, one thread: the net force at zero velocity
  SeriesSet series_;
  FrameSeries common_;  // after series_, which holds its series
  GeomFrames geoms_;
  std::vector<std::vector<double>*> angle_, target_, derivative_;
  std::vector<double> *flow_, *load_, *lean_, *force_lean_, *offset_, *arm_length_;
  std::vector<double> arm_x_, arm_y_, arm_z_, net_x_, net_y_, net_z_;
  double max_kinematic_ = 0, max_pd_ = 0;
  int max_contacts_ = 0;
};

}  // namespace creaturelab::control
