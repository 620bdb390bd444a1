#include "fluid3d/fluid_recorder3.hpp"

#include <algorithm>
#include <cmath>

namespace creaturelab::fluid3d {
namespace recorder3_detail {

// Volume flux into the box through its inflow sides and out through its open sides (m³/s).
std::array<double, 2> boundaryFluxes_m3_per_s(const MacGrid3& g) {
  double in = 0.0, out = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (g.periodic(a)) continue;
    const AxisBoundary3& b = g.boundaries.axis[a];
    const Array3& u = g.velocity_m_per_s[a];
    for (const bool high : {false, true}) {
      const BoundaryType3 type = high ? b.high : b.low;
      if (type != BoundaryType3::open && type != BoundaryType3::inflow) continue;
      const int m = high ? g.n[a] : 0;
      double sum = 0.0;  // along +axis
      for (int k = 0; k < u.nz(); ++k)
        for (int j = 0; j < u.ny(); ++j)
          for (int i = 0; i < u.nx(); ++i)
            if ((a == 0 ? i : a == 1 ? j : k) == m) sum += u(i, j, k);
      const double outward = (high ? sum : -sum) * g.dx_m * g.dx_m;
      if (type == BoundaryType3::inflow) in -= outward;
      else out += outward;
    }
  }
  return {in, out};
}

}  // namespace recorder3_detail

FluidRecorder3::FluidRecorder3(const FluidSolver3& solver, int slice_normal_axis, std::optional<ExactFlow3> exact)
    : exact_(std::move(exact)), ke0_(solver.kineticEnergy_joule()) {
  const MacGrid3& g = solver.grid();
  slice_.normal_axis = slice_normal_axis;
  slice_.axes = slice_normal_axis == 0 ? std::array<int, 2>{1, 2}
                : slice_normal_axis == 1 ? std::array<int, 2>{0, 2}
                                         : std::array<int, 2>{0, 1};
  slice_.layer = g.n[slice_normal_axis] / 2;
  slice_.columns = g.n[slice_.axes[0]], slice_.rows = g.n[slice_.axes[1]];
  slice_.position_m = (slice_.layer + 0.5) * g.dx_m;
  series_ = {{"time_s", "s", {}},
             {"kinetic_energy_j", "J", {}},
             {"max_divergence_per_s", "1/s", {}},
             {"max_vorticity_per_s", "1/s", {}},
             {"cfl_number", "", {}}};
  if (exact_) {
    series_.push_back({"kinetic_energy_error_rel", "", {}});
    series_.push_back({"velocity_error_linf_m_per_s", "m/s", {}});
  }
  fields_ = {{"u_m_per_s", "m/s", {}},           {"v_m_per_s", "m/s", {}}, {"w_m_per_s", "m/s", {}},
             {"pressure_pa", "Pa", {}},          {"vorticity_magnitude_per_s", "1/s", {}},
             {"q_per_s2", "1/s^2", {}}};
}

void FluidRecorder3::sample(const FluidSolver3& solver) {
  const MacGrid3& g = solver.grid();
  observables_.update(g);
  const Array3& vort = observables_.vorticityMagnitude_per_s();
  const double ke = solver.kineticEnergy_joule(), t = solver.time_s();
  std::vector<double> values = {t, ke, solver.maxDivergence_per_s(),
                                *std::max_element(vort.data(), vort.data() + vort.size()), last_cfl_};
  if (exact_) {
    const double nu = solver.params().kinematic_viscosity_m2_per_s, k = exact_->wavenumber_per_m;
    const double expected = ke0_ * std::exp(-exact_->energy_decay_per_nu_k2 * nu * k * k * t);
    values.push_back(ke / expected - 1.0);
    values.push_back(velocityError(g, *exact_, t).linf_m_per_s);
  }
  for (std::size_t s = 0; s < series_.size(); ++s) series_[s].values.push_back(values[s]);
  const Array3* planes[] = {&observables_.cellVelocity_m_per_s(0), &observables_.cellVelocity_m_per_s(1),
                            &observables_.cellVelocity_m_per_s(2), &g.pressure_pa, &vort, &observables_.q_per_s2()};
  for (std::size_t f = 0; f < fields_.size(); ++f) {
    std::vector<double>& out = fields_[f].values;
    for (int r = 0; r < slice_.rows; ++r)
      for (int c = 0; c < slice_.columns; ++c) {
        int m[3];
        m[slice_.normal_axis] = slice_.layer, m[slice_.axes[0]] = c, m[slice_.axes[1]] = r;
        out.push_back((*planes[f])(m[0], m[1], m[2]));
      }
  }
}

void FluidRecorder3::step(const FluidStepReport3& report, const FluidSolver3& solver) {
  last_cfl_ = report.cfl_number;
  max_cfl_ = std::max(max_cfl_, report.cfl_number);
  max_pressure_iterations_ = std::max(max_pressure_iterations_, report.pressure.iterations);
  if (!report.pressure.converged || !report.viscosity.converged) ++unconverged_;
  const double div = solver.maxDivergence_per_s(), speed = solver.maxVelocityComponent_m_per_s();
  max_div_ = std::max(max_div_, div);
  if (speed > 0) max_div_rel_ = std::max(max_div_rel_, div * solver.grid().dx_m / speed);
}

std::vector<core::NamedValue> FluidRecorder3::measure(const FluidSolver3& solver) const {
  const double nan = std::nan(""), ke = solver.kineticEnergy_joule(), t = solver.time_s();
  const double nu = solver.params().kinematic_viscosity_m2_per_s;
  double linf = nan, rms = nan, nu_eff = nan;
  const std::array<double, 2> flux = recorder3_detail::boundaryFluxes_m3_per_s(solver.grid());
  if (exact_ && t > 0) {
    const VelocityError3 error = velocityError(solver.grid(), *exact_, t);
    linf = error.linf_m_per_s, rms = error.rms_m_per_s;
    const double k = exact_->wavenumber_per_m;
    nu_eff = std::log(ke0_ / ke) / (exact_->energy_decay_per_nu_k2 * k * k * t);
  }
  return {
      {"max_divergence_per_s", "1/s", max_div_},
      {"max_divergence_rel", "", max_div_rel_},
      {"final_kinetic_energy_j", "J", ke},
      {"kinetic_energy_ratio", "", ke0_ > 0 ? ke / ke0_ : nan},
      {"steps", "", double(solver.stepsDone())},
      {"mean_dt_s", "s", t / double(std::max(1L, solver.stepsDone()))},
      {"max_cfl", "", max_cfl_},
      {"max_pressure_iterations", "", double(max_pressure_iterations_)},
      {"unconverged_solves", "", double(unconverged_)},
      {"velocity_error_linf_m_per_s", "m/s", linf},
      {"velocity_error_rms_m_per_s", "m/s", rms},
      {"effective_viscosity_m2_per_s", "m^2/s", nu_eff},
      {"decay_rate_error", "", nu > 0 ? std::fabs(nu_eff - nu) / nu : nan},
      {"inflow_m3_per_s", "m^3/s", flux[0]},
      {"outflow_m3_per_s", "m^3/s", flux[1]},
      {"flux_balance_rel", "", flux[0] > 0 ? std::fabs(flux[1] - flux[0]) / flux[0] : nan},
  };
}

VelocityError3 velocityError(const MacGrid3& g, const ExactFlow3& exact, double t_s) {
  VelocityError3 out;
  double sum2 = 0.0;
  long count = 0;
  for (int a = 0; a < 3; ++a) {
    const Array3& u = g.velocity_m_per_s[a];
    for (int k = 0; k < u.nz(); ++k)
      for (int j = 0; j < u.ny(); ++j)
        for (int i = 0; i < u.nx(); ++i) {
          const double e = std::fabs(u(i, j, k) - exact.velocity_m_per_s(g.facePosition_m(a, i, j, k), t_s)[a]);
          out.linf_m_per_s = std::max(out.linf_m_per_s, e);
          sum2 += e * e;
          ++count;
        }
  }
  out.rms_m_per_s = std::sqrt(sum2 / double(std::max(1L, count)));
  return out;
}

void advanceRecorded(FluidSolver3& solver, double end_s, double interval_s, FluidRecorder3& recorder,
                     const std::function<void(const FluidSolver3&)>& on_frame) {
  const auto frame = [&] {
    recorder.sample(solver);
    if (on_frame) on_frame(solver);
  };
  frame();
  for (int next = 1; solver.time_s() < end_s * (1 - 1e-12);) {
    const double t_out = std::min(end_s, next * interval_s);
    const double dt = std::min(solver.nextTimeStep_s(), t_out - solver.time_s());
    recorder.step(solver.step(dt), solver);
    if (solver.time_s() >= t_out * (1 - 1e-12)) {
      frame();
      ++next;
    }
  }
}

}  // namespace creaturelab::fluid3d
