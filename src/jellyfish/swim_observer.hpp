#pragma once
// What a jellyfish run measures (the `jellyfish` kind's metrics): a window of whole contraction
// cycles after a warm-up, the distance swum and its spread over the window's cycles, the stroke,
// the muscles' work, and the free decay after the last active cycle (jellyfish/ringdown.hpp).
// The observer watches a Swimmer step by step; it does no I/O.
#include <limits>
#include <vector>

#include "ib/coupling.hpp"
#include "jellyfish/swimmer.hpp"

namespace creaturelab::jellyfish {

// The measured window and what is recorded in it.
struct SwimWindow {
  double warmup_cycles = 1.0;
  double duration_s = 10.0;  // the same for every frequency; per-cycle measures count whole cycles only
  double frame_rate_hz = 25.0;
  bool store_fields = false;
  double field_rate_hz = 10.0;

  template <class V>
  void describe(V& v) {
    v.real("warmup_cycles", warmup_cycles, "", 0, 1000, "cycles before the measured window");
    v.real("duration_s", duration_s, "s", 1e-6, 1e6,
           "measured window, the same for every frequency; compare frequencies by cycle_speed_m_per_s, which counts "
           "whole cycles only");
    v.real("frame_rate_hz", frame_rate_hz, "Hz", 1e-3, 1e4, "series and marker frames");
    v.boolean("store_fields", store_fields, "store vorticity fields (frames × ny × nx) with an XDMF sidecar");
    v.real("field_rate_hz", field_rate_hz, "Hz", 1e-3, 1e4, "field frames per second when store_fields");
  }
};

// Times of a run: warm-up cycles, then the measured window; every time lands on a step.
struct SwimSchedule {
  long warmup_steps = 0;
  long total_steps = 0;
  long work_end_step = 0;   // end of the last whole cycle in the window (muscle work is per whole cycles)
  double whole_cycles = 0;  // whole cycles in the window; 0: shorter than a cycle (work_end_step = total_steps)
  long steps_per_frame = 1;
  long steps_per_field = 0;  // 0: no fields
};

SwimSchedule swimSchedule(const SwimWindow& window, double dt_s, double contraction_hz);

// The measures of one run (names and units as the kind's metrics).
struct SwimMeasures {
  double distance_m = 0;             // centroid's axial (+y) displacement over the window
  double distance_per_cycle_m = 0;   // over the window's whole cycles / their number
  double mean_speed_m_per_s = 0;
  double cycle_speed_m_per_s = 0;
  double whole_cycles = 0;
  double min_diameter_ratio = 0;
  double stroke_amplitude = 0;       // diameter ratio's range over the window's second half
  double ringdown_hz = 0;            // the free decay's (NaN without active_cycles)
  double natural_hz = 0;
  double damping_ratio = 0;
  double mode_residual = 0;
  double lateral_drift_m = 0;
  double forward_travel_m = 0;
  double cycle_distance_spread = 0;
  double cycle_distance_growth = 0;
  double net_fraction = 0;
  double muscle_work_j = 0;          // J/m, by the force on the fluid
  double muscle_work_direct_j = 0;   // J/m, by tension x shortening
  double cost_of_transport = 0;      // J/(kg m)
  double cycles = 0;
  double max_cfl = 0;
  double max_marker_speed_m_per_s = 0;
};

class SwimObserver {
 public:
  // At the start of the run (step 0).
  SwimObserver(const Swimmer& swimmer, const SwimSchedule& plan);
  // After step `step` (1 ..), which returned `report`.
  void afterStep(long step, const Swimmer& swimmer, const ib::CouplingStepReport& report);
  // After the last step.
  SwimMeasures measures(const Swimmer& swimmer) const;

 private:
  bool cycleBoundary(long step) const;

  SwimSchedule plan_;
  double period_steps_ = 0;
  long second_half_step_ = 0;
  long release_step_ = -1;  // the free decay's first step; -1: active every cycle
  SwimmerObservation start_;
  double start_work_ = 0, end_work_ = 0, start_fluid_ = 0, end_fluid_ = 0;
  double min_ratio_ = std::numeric_limits<double>::infinity(), max_cfl_ = 0, max_speed_ = 0;
  double forward_travel_ = 0, last_y_ = 0, cycles_end_y_ = 0;
  double late_min_ = std::numeric_limits<double>::infinity(), late_max_ = -std::numeric_limits<double>::infinity();
  std::vector<double> cycle_start_y_;  // centroid height at each whole cycle's start and end in the window
  std::vector<double> decay_t_, decay_d_;
};

}  // namespace creaturelab::jellyfish
