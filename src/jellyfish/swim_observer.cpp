#include "jellyfish/swim_observer.hpp"

#include <algorithm>
#include <cmath>

#include "jellyfish/ringdown.hpp"

namespace creaturelab::jellyfish {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The distances of the window's whole cycles, from the heights at successive cycle starts.
std::vector<double> cycleDistances(const std::vector<double>& start_y) {
  std::vector<double> d;
  for (std::size_t k = 0; k + 1 < start_y.size(); ++k) d.push_back(start_y[k + 1] - start_y[k]);
  return d;
}

// Standard error of the mean of the cycles' distances, relative to the window's distance per cycle.
double cycleSpread(const std::vector<double>& d, double per_cycle) {
  if (d.size() < 2) return kNaN;
  double mean = 0, var = 0;
  for (double v : d) mean += v / double(d.size());
  for (double v : d) var += (v - mean) * (v - mean) / double(d.size() - 1);
  return std::sqrt(var / double(d.size())) / std::abs(per_cycle);
}

// The least-squares line through the cycles' distances against the cycle's index, from the first
// cycle of the window to the last, relative to the window's distance per cycle. A window shorter than
// the viscous time D² / ν (32 s for the 4 cm bell at the default ν) shows a trend rather than a
// scatter, which cycleSpread alone would read as noise.
double cycleGrowth(const std::vector<double>& d, double per_cycle) {
  if (d.size() < 2) return kNaN;
  const double n = double(d.size()), mid = 0.5 * (n - 1);
  double mean = 0, sxy = 0, sxx = 0;
  for (double v : d) mean += v / n;
  for (std::size_t k = 0; k < d.size(); ++k) {
    sxy += (double(k) - mid) * (d[k] - mean);
    sxx += (double(k) - mid) * (double(k) - mid);
  }
  return sxy / sxx * (n - 1) / std::abs(per_cycle);
}

}  // namespace

SwimSchedule swimSchedule(const SwimWindow& w, double dt, double hz) {
  SwimSchedule s;
  s.warmup_steps = std::lround(w.warmup_cycles / hz / dt);
  s.total_steps = s.warmup_steps + std::lround(w.duration_s / dt);
  const double whole_cycles = std::floor(w.duration_s * hz + 1e-9);
  s.whole_cycles = whole_cycles;
  s.work_end_step = whole_cycles >= 1 ? s.warmup_steps + std::lround(whole_cycles / hz / dt) : s.total_steps;
  s.work_end_step = std::min(s.work_end_step, s.total_steps);
  s.steps_per_frame = std::max(1L, std::lround(1.0 / (w.frame_rate_hz * dt)));
  if (w.store_fields) s.steps_per_field = std::max(1L, std::lround(1.0 / (w.field_rate_hz * dt)));
  return s;
}

SwimObserver::SwimObserver(const Swimmer& swimmer, const SwimSchedule& plan) : plan_(plan) {
  const ActivationParams& a = swimmer.config().activation;
  const double dt = swimmer.config().dt_s;
  period_steps_ = 1.0 / (a.contraction_hz * dt);
  // Stroke amplitude over the window's second half; the free decay after the last active cycle.
  second_half_step_ = plan.warmup_steps + (plan.total_steps - plan.warmup_steps) / 2;
  // The activation ends with the last active cycle's pulse (pulse shape) or with the cycle (hermite).
  const double last_cycle_s = (a.active_cycles - 1) / a.contraction_hz;
  const double release_s =
      last_cycle_s + (a.shape == ActivationShape::pulse ? a.pulse_duration_s : 1.0 / a.contraction_hz);
  release_step_ = a.active_cycles > 0 ? std::lround(release_s / dt) : -1;
  if (plan.warmup_steps == 0) start_ = swimmer.observe();
  last_y_ = swimmer.observe().centroid_m.y;
  if (cycleBoundary(0)) cycle_start_y_.push_back(last_y_);
}

bool SwimObserver::cycleBoundary(long step) const {
  const double k = double(step - plan_.warmup_steps) / period_steps_;
  return step >= plan_.warmup_steps && step <= plan_.work_end_step &&
         step - plan_.warmup_steps == std::lround(std::round(k) * period_steps_);
}

void SwimObserver::afterStep(long step, const Swimmer& swimmer, const ib::CouplingStepReport& report) {
  max_cfl_ = std::max(max_cfl_, report.fluid.cfl_number);
  max_speed_ = std::max(max_speed_, report.max_marker_speed_m_per_s);
  const auto o = swimmer.observe();
  if (step == plan_.warmup_steps) {
    start_ = o;
    start_work_ = swimmer.muscleWork_j_per_m();
    start_fluid_ = swimmer.fluidWork_j_per_m();
  }
  if (step == plan_.work_end_step) {
    cycles_end_y_ = o.centroid_m.y;
    end_work_ = swimmer.muscleWork_j_per_m();
    end_fluid_ = swimmer.fluidWork_j_per_m();
  }
  if (step > plan_.warmup_steps) {
    min_ratio_ = std::min(min_ratio_, o.diameter_ratio);
    forward_travel_ += std::max(0.0, o.centroid_m.y - last_y_);
  }
  last_y_ = o.centroid_m.y;
  if (cycleBoundary(step)) cycle_start_y_.push_back(o.centroid_m.y);
  if (step > second_half_step_) {
    late_min_ = std::min(late_min_, o.diameter_ratio);
    late_max_ = std::max(late_max_, o.diameter_ratio);
  }
  if (release_step_ >= 0 && step >= release_step_) {
    decay_t_.push_back(o.time_s);
    decay_d_.push_back(o.diameter_ratio - 1.0);
  }
}

SwimMeasures SwimObserver::measures(const Swimmer& swimmer) const {
  const double dt = swimmer.config().dt_s, hz = swimmer.config().activation.contraction_hz;
  const auto end = swimmer.observe();
  const double duration = (plan_.total_steps - plan_.warmup_steps) * dt;
  const double distance = end.centroid_m.y - start_.centroid_m.y;
  const double cycles = duration * hz;
  // Work is counted over whole cycles, so that the two work measures compare like with like
  // (over whole cycles the elastic energy stored, far larger than one cycle's work, nearly cancels).
  // A window that ends part way through a cycle adds that part's surge or slide to distance_m (see
  // duration_s), so the per-cycle measures count the whole cycles only. A window shorter than one
  // cycle counts all of itself, work and distance alike.
  const double work_cycles = plan_.whole_cycles;
  const double work_distance = work_cycles >= 1 ? cycles_end_y_ - start_.centroid_m.y : distance;
  const double per_cycle = work_cycles >= 1 ? work_distance / work_cycles : distance / cycles;
  const double fluid_work = end_fluid_ - start_fluid_;
  const double bell_mass = swimmer.config().fluid.density_kg_per_m3 * swimmer.body().model().bell_area_m2;
  SwimMeasures m;
  m.distance_m = distance;
  m.distance_per_cycle_m = per_cycle;
  m.mean_speed_m_per_s = distance / duration;
  m.cycle_speed_m_per_s = per_cycle * hz;
  m.whole_cycles = work_cycles;
  m.min_diameter_ratio = min_ratio_;
  m.stroke_amplitude = late_max_ - late_min_;
  // Two estimates of the free decay (jellyfish/ringdown.hpp): zero crossings of the first two periods
  // after release, with a hysteresis of a fifth of the last extremum (ringdown_hz), and a fit of one
  // damped mode to the whole decay at the frame rate (natural_hz, damping_ratio): the crossings lose
  // a half period whenever a higher mode beating in the tail keeps the signal under the hysteresis.
  const Ringdown ring = measureRingdown(decay_t_, decay_d_, 0.2, 4);
  std::vector<double> frame_t, frame_d;
  for (std::size_t i = 0; i < decay_t_.size(); i += std::size_t(std::max(1L, plan_.steps_per_frame)))
    frame_t.push_back(decay_t_[i]), frame_d.push_back(decay_d_[i]);
  const DampedFit fit = fitDampedOscillation(frame_t, frame_d);
  const bool released = release_step_ >= 0;
  m.ringdown_hz = released ? ring.damped_hz : kNaN;
  m.natural_hz = released ? fit.natural_hz : kNaN;
  m.damping_ratio = released ? fit.damping_ratio : kNaN;
  m.mode_residual = released ? fit.residual_fraction : kNaN;
  m.lateral_drift_m = end.centroid_m.x - start_.centroid_m.x;
  m.forward_travel_m = forward_travel_;
  const std::vector<double> cycle_distances = cycleDistances(cycle_start_y_);
  m.cycle_distance_spread = cycleSpread(cycle_distances, per_cycle);
  m.cycle_distance_growth = cycleGrowth(cycle_distances, per_cycle);
  m.net_fraction = forward_travel_ > 0 ? distance / forward_travel_ : kNaN;
  m.muscle_work_j = fluid_work;
  m.muscle_work_direct_j = end_work_ - start_work_;
  m.cost_of_transport = work_distance > 0 ? fluid_work / (bell_mass * work_distance) : kNaN;
  m.cycles = cycles;
  m.max_cfl = max_cfl_;
  m.max_marker_speed_m_per_s = max_speed_;
  m.markers = double(swimmer.markers_m().size());
  m.kernel_cells = double(swimmer.config().coupling.kernel_scale);
  m.segment_cells = swimmer.body().model().segment_m / swimmer.fluid().grid().dx_m;
  m.steps = double(plan_.total_steps);
  return m;
}

}  // namespace creaturelab::jellyfish
