#include "kinds/fluid.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

#include "fluid/fluid_recorder2.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::kinds {
namespace {

// The initial field, made divergence-free, and the tracers on their lattice.
void start(const FluidKindParams& q, fluid::FluidSolver2& solver) {
  fluid::MacGrid2& grid = solver.grid();
  if (q.initial == "taylor_green") {
    fluid::setTaylorGreen(grid, {q.amplitude_m_per_s});
  } else if (q.initial == "vortex_pair") {
    fluid::VortexPair pair;
    pair.circulation_m2_per_s = q.circulation_m2_per_s;
    pair.centre_y_fraction = q.vortex_height_fraction;
    fluid::setVortexPair(grid, pair);
  } else if (q.initial == "shear_layer") {
    fluid::ShearLayer layer;
    layer.speed_m_per_s = q.amplitude_m_per_s;
    fluid::setShearLayer(grid, layer);
  } else {
    fluid::setRest(grid);
  }
  solver.makeDivergenceFree();
  const int n = int(q.tracers_per_side);
  const double L = q.fluid.domain_width_m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) solver.tracers_m().push_back({(i + 0.5) * L / n, (j + 0.5) * L / n});
}

// The recorded series, field frames and tracers.
Result recorded(const fluid::FluidRecorder2& recorder, const fluid::MacGrid2& g) {
  Result result;
  for (const auto& s : recorder.series()) result.timeseries[s.name] = {s.values, s.unit};
  FieldFrames& frames = result.fields;
  frames.nx = g.nx;
  frames.ny = g.ny;
  frames.dx_m = frames.dy_m = g.dx_m;
  frames.time_s = recorder.frameTimes();
  for (const auto& f : recorder.fields()) frames.fields[f.name] = {f.values, f.unit};
  Tracks& tracers = result.lagrangian["tracers_m"];
  tracers.points = recorder.tracers();
  tracers.dim = 2;
  if (tracers.points > 0) tracers.time_s = recorder.frameTimes();
  tracers.data = recorder.tracerData();
  return result;
}

}  // namespace

fluid::FluidParams FluidKindParams::solverParams() const {
  fluid::FluidParams f = fluid;
  f.makeSquare();
  if (dt_s.is_auto) {
    f.time_step_policy = fluid::TimeStepPolicy::cfl_adaptive;
  } else {
    f.time_step_policy = fluid::TimeStepPolicy::fixed;
    f.fixed_step_s = dt_s.value;
  }
  return f;
}

std::string FluidKindParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  if (std::string err = solverParams().validate(); !err.empty()) return err;
  if (output_interval_s > end_time_s) return "output_interval_s is longer than end_time_s";
  return "";
}

FluidKind::FluidKind() {
  metrics_ = {
      {"max_divergence", "1/s", "largest max|div u| after any step"},
      {"max_divergence_rel", "", "largest max|div u| dx / max|u| after any step"},
      {"final_kinetic_energy_j_per_m", "J/m", "kinetic energy per metre of depth at the end"},
      {"kinetic_energy_ratio", "", "final over initial kinetic energy"},
      {"steps", "", "time steps taken"},
      {"mean_dt_s", "s", "end_time_s / steps"},
      {"max_cfl", "", "largest CFL number max(|u|,|v|) dt / dx of any step"},
      {"velocity_error_linf_m_per_s", "m/s", "Taylor-Green only: max |u - u_exact| over faces at the end"},
      {"velocity_error_rms_m_per_s", "m/s", "Taylor-Green only: rms |u - u_exact| over faces at the end"},
      {"effective_viscosity_m2_per_s", "m^2/s", "Taylor-Green only: nu fitted to the energy decay, e^(-2 nu k^2 t)"},
      {"numerical_viscosity_m2_per_s", "m^2/s", "Taylor-Green only: effective minus physical viscosity"},
  };
}

std::string FluidKind::doc() const {
  return "2D incompressible Navier-Stokes on a MAC grid (Rudolf & Mould 2009 §3.2 Eq. 1; Stam 1999)";
}

// Memory: about 280 B per cell for the solver (its arrays, the pressure solver, the HDF5 write), 4 fields
// x 8 B = 32 B per cell and stored frame (40 taken), and 32 MiB for the process; an upper bound on the
// peak resident set of `creaturelab run`.
CostEstimate FluidKind::estimateCost(const Params& p) const {
  try {
    const FluidKindParams q = readParams<FluidKindParams>(p);
    const double cells = double(q.fluid.cells_x) * double(q.fluid.cells_x);
    const double frames = 1 + std::ceil(q.end_time_s / q.output_interval_s * (1 - 1e-12));
    const double tracers = double(q.tracers_per_side) * double(q.tracers_per_side);
    CostEstimate cost;
    cost.memory_bytes = 32.0 * (1 << 20) + cells * (280 + 40 * frames) + tracers * 16 * frames;
    char detail[160];
    std::snprintf(detail, sizeof detail, "%lld^2 cells, %.0f stored frames of 4 fields", (long long)q.fluid.cells_x,
                  frames);
    cost.detail = detail;
    return cost;
  } catch (const std::exception&) {
    return {};
  }
}

Result FluidKind::run(const Params& p) const {
  const FluidKindParams q = readParams<FluidKindParams>(p);
  fluid::FluidSolver2 solver(q.solverParams());
  start(q, solver);
  fluid::FluidRecorder2 recorder(solver);
  try {
    fluid::advanceRecorded(solver, q.end_time_s, q.output_interval_s, recorder);
  } catch (const fluid::FluidBlowUpError& e) {
    throw RunFailure(e.what(), recorded(recorder, solver.grid()));
  }
  Result result = recorded(recorder, solver.grid());
  std::optional<fluid::TaylorGreenVortex> exact;  // the solution its error is measured against
  if (q.initial == "taylor_green") exact = fluid::TaylorGreenVortex{q.amplitude_m_per_s};
  for (const auto& m : recorder.measure(solver, exact)) result.metrics[m.name] = {m.value, m.unit};
  return result;
}

}  // namespace creaturelab::kinds
