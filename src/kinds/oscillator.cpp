#include "kinds/oscillator.hpp"

#include <cmath>

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

Result OscillatorKind::run(const Params& p) const {
  const OscillatorParams q = readParams<OscillatorParams>(p);
  const DampedOscillator& exact = q.body;
  const double rest_m = 1.0;  // arbitrary: only the displacement from rest enters the closed form

  springs::Network<2> net;
  const int anchor = net.addParticle(exact.mass_kg, true);
  const int bob = net.addParticle(exact.mass_kg, false);
  net.addSpring(anchor, bob, rest_m, exact.stiffness_n_per_m);
  net.drag_ns_per_m = exact.damping_ns_per_m;
  springs::State<2> state;
  state.x_m = springs::Points<2>::Zero(2, 2);
  state.v_m_per_s = springs::Points<2>::Zero(2, 2);
  state.x_m(0, bob) = rest_m + exact.x0_m;
  state.v_m_per_s(0, bob) = exact.v0_m_per_s;

  springs::SimulationOptions opt;
  opt.integrator = parseIntegratorOrThrow(q.integrator);
  opt.end_time_s = q.end_time_s;
  const double omega = springs::estimateOmegaMaxRadPerS(net, state);
  opt.dt_s = q.dt_s.is_auto ? springs::autoStepS(opt.integrator, omega, exact.zeta()) : q.dt_s.value;
  opt.frame_interval_s = opt.dt_s;  // record every step: the error is read step by step
  opt.runaway_factor = 1e6;

  Result result;
  auto& time = result.timeseries["time_s"] = {{}, "s"};
  auto& x_num = result.timeseries["x_m"] = {{}, "m"};
  auto& x_ex = result.timeseries["x_exact_m"] = {{}, "m"};
  auto& err = result.timeseries["error_m"] = {{}, "m"};
  auto& energy = result.timeseries["energy_j"] = {{}, "J"};
  double max_err = 0, v_exact_end = 0, v_num_end = 0;
  auto record = [&](int, double t, const springs::State<2>& s) {
    double xe = 0, ve = 0;
    exact.at(t, xe, ve);
    const double xn = s.x_m(0, bob) - rest_m;
    time.values.push_back(t);
    x_num.values.push_back(xn);
    x_ex.values.push_back(xe);
    err.values.push_back(xn - xe);
    energy.values.push_back(exact.energy(xn, s.v_m_per_s(0, bob)));
    max_err = std::max(max_err, std::fabs(xn - xe));
    v_exact_end = ve;
    v_num_end = s.v_m_per_s(0, bob);
  };

  springs::System<2> system(std::move(net));
  const auto summary = runOrFail(system, state, opt, record, result);
  const double x_exact_end = x_ex.values.back(), x_num_end = x_num.values.back();
  result.metrics["omega_dt"] = {exact.omega0() * summary.dt_used_s, "rad"};
  result.metrics["dt_used_s"] = {summary.dt_used_s, "s"};
  result.metrics["max_abs_error_m"] = {max_err, "m"};
  result.metrics["final_abs_error_m"] = {std::fabs(x_num_end - x_exact_end), "m"};
  result.metrics["final_energy_ratio"] = {exact.energy(x_num_end, v_num_end) / exact.energy(x_exact_end, v_exact_end), ""};
  return result;
}

}  // namespace creaturelab::kinds
