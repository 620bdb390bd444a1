#include "fluid/fluid_recorder2.hpp"

#include <algorithm>
#include <cmath>

#include "fluid/diagnostics2.hpp"

namespace creaturelab::fluid {

FluidRecorder2::FluidRecorder2(const FluidSolver2& solver)
    : tracers_(int(solver.tracers_m().size())), ke0_(solver.kineticEnergy_joule_per_m()) {
  series_ = {{"time_s", "s", {}}, {"kinetic_energy_j_per_m", "J/m", {}}, {"max_divergence", "1/s", {}}, {"cfl_number", "", {}}};
  fields_ = {{"u_m_per_s", "m/s", {}}, {"v_m_per_s", "m/s", {}}, {"pressure_pa", "Pa", {}}, {"vorticity_per_s", "1/s", {}}};
}

void FluidRecorder2::sample(const FluidSolver2& solver) {
  const double values[] = {solver.time_s(), solver.kineticEnergy_joule_per_m(), solver.maxDivergence_per_s(), last_cfl_};
  for (std::size_t s = 0; s < series_.size(); ++s) series_[s].values.push_back(values[s]);
  const MacGrid2& g = solver.grid();
  velocityAtCentres(g, u_, v_);
  vorticityAtCentres(g, solver.walls(), w_);
  const double* frames[] = {u_.data(), v_.data(), g.pressure_pa.data(), w_.data()};
  for (std::size_t f = 0; f < fields_.size(); ++f)
    fields_[f].values.insert(fields_[f].values.end(), frames[f], frames[f] + g.cellCount());
  if (tracers_ > 0)
    for (const Vec2& m : solver.tracers_m()) tracer_data_.insert(tracer_data_.end(), {m.x, m.y});
}

void FluidRecorder2::step(const FluidStepReport& step, double dx_m) {
  last_cfl_ = step.cfl_number;
  max_cfl_ = std::max(max_cfl_, step.cfl_number);
  max_div_ = std::max(max_div_, step.max_divergence_per_s);
  if (step.max_velocity_component_m_per_s > 0)
    max_div_rel_ = std::max(max_div_rel_, step.max_divergence_per_s * dx_m / step.max_velocity_component_m_per_s);
}

std::vector<core::NamedValue> FluidRecorder2::measure(const FluidSolver2& solver,
                                                      const std::optional<TaylorGreenVortex>& exact) const {
  const double nan = std::nan(""), ke = solver.kineticEnergy_joule_per_m(), t = solver.time_s();
  double linf = nan, rms = nan, nu_eff = nan;
  if (exact) {
    const VelocityError error = taylorGreenError(solver, exact->amplitude_m_per_s);
    linf = error.linf_m_per_s;
    rms = error.rms_m_per_s;
    // KE ~ exp(-2 nu (kx^2 + ky^2) t): twice the velocity decay rate.
    const double k2 = 2.0 * std::pow(M_PI / solver.params().domain_width_m, 2);
    nu_eff = std::log(ke0_ / ke) / (2.0 * k2 * t);
  }
  return {
      {"max_divergence", "1/s", max_div_},
      {"max_divergence_rel", "", max_div_rel_},
      {"final_kinetic_energy_j_per_m", "J/m", ke},
      {"kinetic_energy_ratio", "", ke0_ > 0 ? ke / ke0_ : nan},
      {"steps", "", double(solver.stepsDone())},
      {"mean_dt_s", "s", t / double(std::max(1L, solver.stepsDone()))},
      {"max_cfl", "", max_cfl_},
      {"velocity_error_linf_m_per_s", "m/s", linf},
      {"velocity_error_rms_m_per_s", "m/s", rms},
      {"effective_viscosity_m2_per_s", "m^2/s", nu_eff},
      {"numerical_viscosity_m2_per_s", "m^2/s", nu_eff - solver.params().kinematic_viscosity_m2_per_s},
  };
}

void advanceRecorded(FluidSolver2& solver, double end_s, double interval_s, FluidRecorder2& recorder) {
  recorder.sample(solver);
  for (int next = 1; solver.time_s() < end_s * (1 - 1e-12);) {
    const double t_out = std::min(end_s, next * interval_s);
    const double dt = std::min(solver.nextTimeStep_s(), t_out - solver.time_s());
    recorder.step(solver.step(dt), solver.grid().dx_m);
    if (solver.time_s() >= t_out * (1 - 1e-12)) {
      recorder.sample(solver);
      ++next;
    }
  }
}

VelocityError taylorGreenError(const FluidSolver2& solver, double amplitude) {
  const MacGrid2& g = solver.grid();
  const double nu = solver.params().kinematic_viscosity_m2_per_s, t = solver.time_s();
  double sum2 = 0;
  long n = 0;
  VelocityError out;
  auto visit = [&](double numeric, double exact) {
    const double e = std::fabs(numeric - exact);
    out.linf_m_per_s = std::max(out.linf_m_per_s, e);
    sum2 += e * e;
    ++n;
  };
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i)
      visit(g.u_m_per_s(i, j),
            taylorGreenVelocity_m_per_s(g.uPosition_m(i, j), t, g.width_m(), g.height_m(), amplitude, nu).x);
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      visit(g.v_m_per_s(i, j),
            taylorGreenVelocity_m_per_s(g.vPosition_m(i, j), t, g.width_m(), g.height_m(), amplitude, nu).y);
  out.rms_m_per_s = std::sqrt(sum2 / double(n));
  return out;
}

}  // namespace creaturelab::fluid
