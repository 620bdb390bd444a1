#pragma once
// What a run of the fluid alone records and measures (the fluid kind's; Rudolf & Mould 2009 §3.2,
// Eq. 1): at every output time the series (time, kinetic energy, largest divergence, the last step's
// CFL number), cell-centred frames of u, v, pressure and vorticity, and the tracers; over the steps
// the largest divergence (absolute and relative to the largest velocity) and CFL number; at the end,
// for a Taylor-Green vortex, the error against the exact solution and the viscosity the energy decay
// implies. No I/O: the kind copies them into its Result.
#include <optional>
#include <vector>

#include "core/named_measure.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::fluid {

class FluidRecorder2 {
 public:
  // Starts from the solver's state (its initial kinetic energy and tracer count); samples nothing yet.
  explicit FluidRecorder2(const FluidSolver2& solver);

  // One output frame of the current state.
  void sample(const FluidSolver2& solver);
  // After each step: its report; dx_m, the grid's cell size.
  void step(const FluidStepReport& report, double dx_m);

  // time_s, kinetic_energy_j_per_m, max_divergence, cfl_number: one value per frame.
  const std::vector<core::NamedSeries>& series() const { return series_; }
  // u_m_per_s, v_m_per_s, pressure_pa, vorticity_per_s at the cell centres: frames x ny x nx each.
  const std::vector<core::NamedSeries>& fields() const { return fields_; }
  const std::vector<double>& frameTimes() const { return series_[0].values; }
  // The tracers at the frames, frames x tracers x 2 (empty without tracers).
  int tracers() const { return tracers_; }
  const std::vector<double>& tracerData() const { return tracer_data_; }

  // At the end: max_divergence, max_divergence_rel, final_kinetic_energy_j_per_m, kinetic_energy_ratio,
  // steps, mean_dt_s, max_cfl; and velocity_error_linf_m_per_s, velocity_error_rms_m_per_s,
  // effective_viscosity_m2_per_s, numerical_viscosity_m2_per_s against `exact` (NaN without one).
  std::vector<core::NamedValue> measure(const FluidSolver2& solver,
                                        const std::optional<TaylorGreenVortex>& exact) const;

 private:
  int tracers_;
  double ke0_;
  double max_div_ = 0, max_div_rel_ = 0, max_cfl_ = 0, last_cfl_ = 0;
  std::vector<core::NamedSeries> series_, fields_;
  std::vector<double> tracer_data_;
  Array2 u_, v_, w_;
};

// Steps `solver` to end_s, each step shortened to land exactly on the next multiple of interval_s (so
// every frame is at its nominal time), and samples there; samples the start first. Throws what
// FluidSolver2::step throws (FluidBlowUpError), the recorder holding the frames before it.
void advanceRecorded(FluidSolver2& solver, double end_s, double interval_s, FluidRecorder2& recorder);

// Largest and root-mean-square difference from the exact Taylor-Green velocity over every face.
struct VelocityError {
  double linf_m_per_s = 0;
  double rms_m_per_s = 0;
};
VelocityError taylorGreenError(const FluidSolver2& solver, double amplitude_m_per_s);

}  // namespace creaturelab::fluid
