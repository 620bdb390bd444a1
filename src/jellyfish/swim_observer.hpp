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

// The measures of one run: each declared once, beside its field, with its name, unit and doc (the
// `jellyfish` kind's metrics; v.metric(name, field, unit, doc)).
struct SwimMeasures {
  double distance_m = 0;
  double distance_per_cycle_m = 0;
  double mean_speed_m_per_s = 0;
  double cycle_speed_m_per_s = 0;
  double whole_cycles = 0;
  double min_diameter_ratio = 0;
  double stroke_amplitude = 0;
  double ringdown_hz = 0;
  double natural_hz = 0;
  double damping_ratio = 0;
  double mode_residual = 0;
  double lateral_drift_m = 0;
  double forward_travel_m = 0;
  double net_fraction = 0;
  double cycle_distance_spread = 0;
  double cycle_distance_growth = 0;
  double muscle_work_j = 0;
  double muscle_work_direct_j = 0;
  double cost_of_transport = 0;
  double cycles = 0;
  double max_cfl = 0;
  double max_marker_speed_m_per_s = 0;
  double markers = 0;
  double kernel_cells = 0;
  double segment_cells = 0;
  double steps = 0;

  template <class V>
  void describe(V& v) {
    v.metric("distance_m", distance_m, "m",
             "axial (+y) displacement of the bell's centroid over the measured window");
    v.metric("distance_per_cycle_m", distance_per_cycle_m, "m",
             "displacement over the window's whole cycles / their number (distance_m / cycles when the window has "
             "less than one): a window that ends part way through a cycle would add that part's surge or slide");
    v.metric("mean_speed_m_per_s", mean_speed_m_per_s, "m/s", "distance_m / duration_s");
    v.metric("cycle_speed_m_per_s", cycle_speed_m_per_s, "m/s",
             "distance_per_cycle_m x contraction_hz: the mean speed over the window's whole cycles, the measure of "
             "Fig. 5's 'distance in a given time' that does not depend on where the window cuts the last cycle");
    v.metric("whole_cycles", whole_cycles, "",
             "whole contraction cycles in the window (distance_per_cycle_m, the work measures)");
    v.metric("min_diameter_ratio", min_diameter_ratio, "", "smallest aperture width / drawn width in the window");
    v.metric("stroke_amplitude", stroke_amplitude, "",
             "largest minus smallest diameter ratio over the second half of the window (the frequency response's "
             "amplitude, once the start-up has died away)");
    v.metric("ringdown_hz", ringdown_hz, "Hz",
             "active_cycles > 0: damped frequency of the diameter's free decay after the last active cycle (zero "
             "crossings of ratio - 1); NaN without two half periods");
    v.metric("natural_hz", natural_hz, "Hz",
             "active_cycles > 0: the bell-water natural frequency f_n from a fit of one damped mode to the whole "
             "free decay, sqrt(sigma^2 + omega^2) / 2 pi (jellyfish/ringdown.hpp)");
    v.metric("damping_ratio", damping_ratio, "", "the same fit's sigma / sqrt(sigma^2 + omega^2)");
    v.metric("mode_residual", mode_residual, "",
             "rms residual of that fit over the decay's rms: how much of the decay is not one mode");
    v.metric("lateral_drift_m", lateral_drift_m, "m", "x displacement of the centroid over the window");
    v.metric("forward_travel_m", forward_travel_m, "m",
             "sum of the centroid's upward steps over the window: the bell surges forward on each contraction and "
             "slides back on each re-expansion, and distance_m is what is left of the surge");
    v.metric("net_fraction", net_fraction, "",
             "distance_m / forward_travel_m: near 1 a stroke that keeps its surge; small, a nearly reciprocal one, "
             "whose distance is a small difference of two large excursions and converges slowly in the grid");
    v.metric("cycle_distance_spread", cycle_distance_spread, "",
             "standard error of the mean distance per whole cycle in the window over distance_per_cycle_m (sample "
             "deviation of the cycles' distances / sqrt(cycles)): how far the window is from periodic. Whether that "
             "is a scatter or a start-up trend, see cycle_distance_growth; a steady trend is deterministic and a "
             "grid study compares it like any other number. NaN with fewer than two whole cycles");
    v.metric("cycle_distance_growth", cycle_distance_growth, "",
             "least-squares line through the whole cycles' distances against their order, its rise from the "
             "window's first cycle to its last over distance_per_cycle_m: positive while the bell still gains "
             "speed, negative while the surge of its first strokes fades. NaN with fewer than two whole cycles");
    v.metric("muscle_work_j", muscle_work_j, "J/m",
             "muscles' net work over the whole cycles of the window, per metre of depth: the work the body did on "
             "the fluid, sum F . dX (the body has no internal dissipation, so over periodic cycles the muscles' "
             "work goes to the fluid); converged in dt");
    v.metric("muscle_work_direct_j", muscle_work_direct_j, "J/m",
             "the same from -sum T dr (tension x rest-length shortening): adds the semi-implicit step's damping of "
             "the stiff muscle, which falls in proportion to dt");
    v.metric("cost_of_transport", cost_of_transport, "J/(kg m)",
             "muscle_work_j / (bell mass per metre x distance over those whole cycles); NaN if that distance <= 0");
    v.metric("cycles", cycles, "", "contraction cycles in the measured window");
    v.metric("max_cfl", max_cfl, "", "largest max(|u|,|v|) dt / dx of any step");
    v.metric("max_marker_speed_m_per_s", max_marker_speed_m_per_s, "m/s", "largest marker speed of any step");
    v.metric("markers", markers, "", "immersed-boundary markers (bell + tentacles)");
    v.metric("kernel_cells", kernel_cells, "",
             "the kernel's stretch: its radius in units of its own reach in cells (1 = the grid's kernel)");
    v.metric("segment_cells", segment_cells, "",
             "drawn bell segment length in fluid cells (bell_segments = 0 keeps it <= marker_spacing_cells)");
    v.metric("steps", steps, "", "coupled steps taken");
  }
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
