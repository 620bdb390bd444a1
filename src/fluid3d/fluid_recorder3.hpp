#pragma once
// What a run of the 3-D fluid alone records and measures (the fluid3d kind's): at every output time
// the series (time, kinetic energy, largest divergence and vorticity, the last step's CFL number,
// and against an exact flow its kinetic-energy and velocity errors), and a plane through the box's
// centre of cell-centred u, v, w, pressure, vorticity magnitude and Q (vorticity3.hpp); over the steps
// the largest divergence and CFL number and the pressure solve's work; at the end the errors against
// the exact flow and the viscosity the energy decay implies. No I/O: the kind copies them out.

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "core/named_measure.hpp"
#include "fluid3d/fluid_solver3.hpp"
#include "fluid3d/vorticity3.hpp"

namespace creaturelab::fluid3d {

/// A flow the run is compared with: its velocity, and its kinetic energy's decay
/// KE(t) = KE(0) exp(−energy_decay_per_nu_k2 · ν k² t) (Taylor–Green 6, ABC 2).
struct ExactFlow3 {
  std::function<std::array<double, 3>(const std::array<double, 3>&, double)> velocity_m_per_s;
  double wavenumber_per_m = 1.0;
  double energy_decay_per_nu_k2 = 0.0;
};

/// The recorded plane: the layer of cells at index n/2 along `normal_axis`; its rows run along the
/// other two axes in order (for normal y: columns x, rows z).
struct Slice3 {
  int normal_axis = 1;
  int layer = 0;
  std::array<int, 2> axes{0, 2};  ///< the plane's column and row axes
  int columns = 0, rows = 0;
  double position_m = 0.0;  ///< centre of the layer along the normal
};

class FluidRecorder3 {
 public:
  /// Starts from the solver's state (its initial kinetic energy); samples nothing yet.
  FluidRecorder3(const FluidSolver3& solver, int slice_normal_axis, std::optional<ExactFlow3> exact);

  /// One output frame of the current state.
  void sample(const FluidSolver3& solver);
  /// After each step: its report.
  void step(const FluidStepReport3& report, const FluidSolver3& solver);

  /// time_s, kinetic_energy_j, max_divergence_per_s, max_vorticity_per_s, cfl_number, and with an exact
  /// flow kinetic_energy_error_rel and velocity_error_linf_m_per_s: one value per frame.
  const std::vector<core::NamedSeries>& series() const { return series_; }
  /// u_m_per_s, v_m_per_s, w_m_per_s, pressure_pa, vorticity_magnitude_per_s, q_per_s2 on the slice:
  /// frames × rows × columns each.
  const std::vector<core::NamedSeries>& fields() const { return fields_; }
  const std::vector<double>& frameTimes() const { return series_[0].values; }
  const Slice3& slice() const { return slice_; }

  /// At the end: max_divergence_per_s, max_divergence_rel, final_kinetic_energy_j, kinetic_energy_ratio,
  /// steps, mean_dt_s, max_cfl, max_pressure_iterations, unconverged_solves; and against the exact flow
  /// (NaN without one) velocity_error_linf_m_per_s, velocity_error_rms_m_per_s,
  /// effective_viscosity_m2_per_s, decay_rate_error; the volume fluxes at the end, in through the inflow
  /// sides (inflow_m3_per_s) and out through the open ones (outflow_m3_per_s), and
  /// flux_balance_rel = |out − in| / in (NaN without inflow).
  std::vector<core::NamedValue> measure(const FluidSolver3& solver) const;

 private:
  std::optional<ExactFlow3> exact_;
  Slice3 slice_;
  double ke0_;
  double max_div_ = 0, max_div_rel_ = 0, max_cfl_ = 0, last_cfl_ = 0;
  int max_pressure_iterations_ = 0;
  long unconverged_ = 0;
  std::vector<core::NamedSeries> series_, fields_;
  FlowObservables3 observables_;
};

/// Largest and root-mean-square difference from the exact velocity over every face.
struct VelocityError3 {
  double linf_m_per_s = 0.0;
  double rms_m_per_s = 0.0;
};
VelocityError3 velocityError(const MacGrid3& grid, const ExactFlow3& exact, double t_s);

/// Steps `solver` to end_s, each step shortened to land exactly on the next multiple of interval_s,
/// and samples there; samples the start first. Throws what FluidSolver3::step throws
/// (FluidBlowUpError3), the recorder holding the frames before it. `on_frame`, when given, is
/// called with the solver at every frame the recorder samples (e.g. to copy out the whole box).
void advanceRecorded(FluidSolver3& solver, double end_s, double interval_s, FluidRecorder3& recorder,
                     const std::function<void(const FluidSolver3&)>& on_frame = {});

}  // namespace creaturelab::fluid3d
