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
  params_ = {
      real("mass_kg", 1.0, "kg", 1e-12, 1e6, "oscillating mass"),
      real("stiffness_n_per_m", 4.0 * M_PI * M_PI, "N/m", 1e-12, 1e12, "spring constant k (default: 1 Hz with 1 kg)"),
      real("damping_ns_per_m", 0.1, "N*s/m", 0, 1e12, "viscous drag c (thesis Eq. 4.7), 0 = undamped"),
      real("x0_m", 0.1, "m", -1e3, 1e3, "initial displacement from rest"),
      real("v0_m_per_s", 0.0, "m/s", -1e3, 1e3, "initial velocity"),
      choice("integrator", "rk4", {"euler", "symplectic_euler", "rk4", "implicit_euler"},
             "time integrator (thesis §4.2.1; rk4 is the thesis's choice, Eq. 4.16-4.19)"),
      realOrAuto("dt_s", "s", 1e-9, 10, "time step; \"auto\" = half the integrator's stability limit"),
      real("end_time_s", 10.0, "s", 1e-6, 1e5, "simulated time"),
  };
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

std::string OscillatorKind::validate(const Params& p) const {
  ParamReader r(p);
  if (!r.isAuto("dt_s") && r.real("dt_s") > r.real("end_time_s"))
    return "dt_s (" + core::formatNumber(r.real("dt_s")) + " s) is longer than end_time_s (" +
           core::formatNumber(r.real("end_time_s")) + " s)";
  return "";
}

Result OscillatorKind::run(const Params& p) const {
  ParamReader r(p);
  const DampedOscillator exact{r.real("mass_kg"), r.real("stiffness_n_per_m"), r.real("damping_ns_per_m"),
                               r.real("x0_m"), r.real("v0_m_per_s")};
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
  opt.integrator = parseIntegratorOrThrow(r.text("integrator"));
  opt.end_time_s = r.real("end_time_s");
  const double omega = springs::estimateOmegaMaxRadPerS(net, state);
  opt.dt_s = r.isAuto("dt_s") ? springs::autoStepS(opt.integrator, omega, exact.zeta()) : r.real("dt_s");
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
