#include "kinds/oscillator.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/text.hpp"
#include "kinds/damped_oscillator.hpp"
#include "kinds/spring_run.hpp"
#include "springs/network.hpp"
#include "springs/simulate.hpp"
#include "springs/stability.hpp"

namespace creaturelab::kinds {

OscillatorKind::OscillatorKind() {
  metrics_ = {
      {"omega_dt", "rad", "natural frequency times step, against each integrator's stability bound"},
      {"dt_used_s", "s", "the step used"},
      {"max_abs_error_m", "m", "largest |x_numeric - x_exact| over the run"},
      {"final_abs_error_m", "m", "|x_numeric - x_exact| at the end"},
      {"final_energy_ratio", "", "numeric / exact mechanical energy at the end"},
  };
}

std::string OscillatorKind::doc() const {
  return "damped mass on a spring beside its closed form (thesis Eq. 4.12); sweep integrator and dt_s";
}

std::string OscillatorParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  if (!dt_s.is_auto && dt_s.value > end_time_s)
    return "dt_s (" + core::formatNumber(dt_s.value) + " s) is longer than end_time_s (" +
           core::formatNumber(end_time_s) + " s)";
  return "";
}

namespace {

// The oscillator as the spring-mass engine runs it: a pinned anchor and the bob on one spring, the
// bob displaced and moving as the closed form starts, every step recorded.
struct OscillatorSetup {
  static constexpr double kRestM = 1.0;  // arbitrary: only the displacement from rest enters the closed form
  static constexpr int kBob = 1;
  springs::Network<2> net;
  springs::State<2> state;
  springs::SimulationOptions opt;
};

OscillatorSetup oscillatorSetup(const OscillatorParams& q) {
  const DampedOscillator& exact = q.body;
  OscillatorSetup s;
  const int anchor = s.net.addParticle(exact.mass_kg, true);
  const int bob = s.net.addParticle(exact.mass_kg, false);
  s.net.addSpring(anchor, bob, OscillatorSetup::kRestM, exact.stiffness_n_per_m);
  s.net.drag_ns_per_m = exact.damping_ns_per_m;
  s.state.x_m = springs::Points<2>::Zero(2, 2);
  s.state.v_m_per_s = springs::Points<2>::Zero(2, 2);
  s.state.x_m(0, bob) = OscillatorSetup::kRestM + exact.x0_m;
  s.state.v_m_per_s(0, bob) = exact.v0_m_per_s;
  s.opt.integrator = parseIntegratorOrThrow(q.integrator);
  s.opt.end_time_s = q.end_time_s;
  const double omega = springs::estimateOmegaMaxRadPerS(s.net, s.state);
  s.opt.dt_s = q.dt_s.is_auto ? springs::autoStepS(s.opt.integrator, omega, exact.zeta()) : q.dt_s.value;
  s.opt.frame_interval_s = s.opt.dt_s;  // record every step: the error is read step by step
  s.opt.runaway_factor = 1e6;
  return s;
}

// Each step against the closed form: the series (in the Result as they grow, so a failed run keeps
// them), the largest error, and at the end the metrics.
class ErrorTrack {
 public:
  ErrorTrack(const DampedOscillator& exact, Result& result)
      : exact_(exact),
        time_(result.timeseries["time_s"] = {{}, "s"}),
        x_num_(result.timeseries["x_m"] = {{}, "m"}),
        x_ex_(result.timeseries["x_exact_m"] = {{}, "m"}),
        err_(result.timeseries["error_m"] = {{}, "m"}),
        energy_(result.timeseries["energy_j"] = {{}, "J"}) {}

  void operator()(int, double t, const springs::State<2>& s) {
    double xe = 0, ve = 0;
    exact_.at(t, xe, ve);
    const double xn = s.x_m(0, OscillatorSetup::kBob) - OscillatorSetup::kRestM;
    time_.values.push_back(t);
    x_num_.values.push_back(xn);
    x_ex_.values.push_back(xe);
    err_.values.push_back(xn - xe);
    energy_.values.push_back(exact_.energy(xn, s.v_m_per_s(0, OscillatorSetup::kBob)));
    max_err_ = std::max(max_err_, std::fabs(xn - xe));
    v_exact_end_ = ve;
    v_num_end_ = s.v_m_per_s(0, OscillatorSetup::kBob);
  }

  void addMetrics(double dt_used_s, Result& result) const {
    const double x_exact_end = x_ex_.values.back(), x_num_end = x_num_.values.back();
    result.metrics["omega_dt"] = {exact_.omega0() * dt_used_s, "rad"};
    result.metrics["dt_used_s"] = {dt_used_s, "s"};
    result.metrics["max_abs_error_m"] = {max_err_, "m"};
    result.metrics["final_abs_error_m"] = {std::fabs(x_num_end - x_exact_end), "m"};
    result.metrics["final_energy_ratio"] = {
        exact_.energy(x_num_end, v_num_end_) / exact_.energy(x_exact_end, v_exact_end_), ""};
  }

 private:
  const DampedOscillator& exact_;
  Series &time_, &x_num_, &x_ex_, &err_, &energy_;
  double max_err_ = 0, v_exact_end_ = 0, v_num_end_ = 0;
};

}  // namespace

Result OscillatorKind::run(const Params& p) const {
  const OscillatorParams q = readParams<OscillatorParams>(p);
  OscillatorSetup setup = oscillatorSetup(q);
  Result result;
  ErrorTrack track(q.body, result);
  springs::System<2> system(std::move(setup.net));
  const auto summary = runOrFail(system, setup.state, setup.opt, std::ref(track), result);
  track.addMetrics(summary.dt_used_s, result);
  return result;
}

}  // namespace creaturelab::kinds
