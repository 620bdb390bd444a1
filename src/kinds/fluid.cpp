#include "kinds/fluid.hpp"

#include <cmath>
#include <cstdio>

#include "fluid/diagnostics2.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::kinds {
namespace {

void setInitial(const FluidKindParams& q, fluid::MacGrid2& grid) {
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
}

// Cell-centred u, v, pressure and vorticity of the current state, appended as one frame.
void appendFrame(const fluid::FluidSolver2& solver, FieldFrames& frames, fluid::Array2& u, fluid::Array2& v,
                 fluid::Array2& w) {
  const auto& g = solver.grid();
  fluid::velocityAtCentres(g, u, v);
  fluid::vorticityAtCentres(g, solver.walls(), w);
  frames.time_s.push_back(solver.time_s());
  auto add = [&](const std::string& name, const double* data, const char* unit) {
    Field& f = frames.fields[name];
    f.unit = unit;
    f.data.insert(f.data.end(), data, data + g.cellCount());
  };
  add("u_m_per_s", u.data(), "m/s");
  add("v_m_per_s", v.data(), "m/s");
  add("pressure_pa", g.pressure_pa.data(), "Pa");
  add("vorticity_per_s", w.data(), "1/s");
}

// Largest and root-mean-square difference from the exact Taylor-Green velocity on every face.
void taylorGreenError(const fluid::FluidSolver2& solver, double amplitude, double& linf, double& rms) {
  const auto& g = solver.grid();
  const double nu = solver.params().kinematic_viscosity_m2_per_s, t = solver.time_s();
  double sum2 = 0;
  long n = 0;
  linf = 0;
  auto visit = [&](double numeric, double exact) {
    const double e = std::fabs(numeric - exact);
    linf = std::max(linf, e);
    sum2 += e * e;
    ++n;
  };
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i)
      visit(g.u_m_per_s(i, j),
            fluid::taylorGreenVelocity_m_per_s(g.uPosition_m(i, j), t, g.width_m(), g.height_m(), amplitude, nu).x);
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      visit(g.v_m_per_s(i, j),
            fluid::taylorGreenVelocity_m_per_s(g.vPosition_m(i, j), t, g.width_m(), g.height_m(), amplitude, nu).y);
  rms = std::sqrt(sum2 / double(n));
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
  setInitial(q, solver.grid());
  solver.makeDivergenceFree();
  if (const int n = int(q.tracers_per_side); n > 0) {
    const double L = q.fluid.domain_width_m;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) solver.tracers_m().push_back({(i + 0.5) * L / n, (j + 0.5) * L / n});
  }

  Result result;
  FieldFrames& frames = result.fields;
  const auto& g = solver.grid();
  frames.nx = g.nx;
  frames.ny = g.ny;
  frames.dx_m = frames.dy_m = g.dx_m;
  fluid::Array2 u, v, w;
  auto& time = result.timeseries["time_s"] = {{}, "s"};
  auto& energy = result.timeseries["kinetic_energy_j_per_m"] = {{}, "J/m"};
  auto& divergence = result.timeseries["max_divergence"] = {{}, "1/s"};
  auto& cfl = result.timeseries["cfl_number"] = {{}, ""};
  Tracks& tracers = result.lagrangian["tracers_m"];
  tracers.points = int(solver.tracers_m().size());
  tracers.dim = 2;
  double max_div = 0, max_div_rel = 0, max_cfl = 0, last_cfl = 0;
  auto sample = [&] {
    time.values.push_back(solver.time_s());
    energy.values.push_back(solver.kineticEnergy_joule_per_m());
    divergence.values.push_back(solver.maxDivergence_per_s());
    cfl.values.push_back(last_cfl);
    appendFrame(solver, frames, u, v, w);
    if (tracers.points > 0) {
      tracers.time_s.push_back(solver.time_s());
      for (const auto& m : solver.tracers_m()) tracers.data.insert(tracers.data.end(), {m.x, m.y});
    }
  };

  const double end = q.end_time_s, every = q.output_interval_s;
  const double ke0 = solver.kineticEnergy_joule_per_m();
  sample();
  int next_output = 1;
  try {
    while (solver.time_s() < end * (1 - 1e-12)) {
      // Steps end exactly on output times so every frame is at its nominal time.
      const double t_out = std::min(end, next_output * every);
      const double dt = std::min(solver.nextTimeStep_s(), t_out - solver.time_s());
      const fluid::FluidStepReport step = solver.step(dt);
      last_cfl = step.cfl_number;
      max_cfl = std::max(max_cfl, step.cfl_number);
      max_div = std::max(max_div, step.max_divergence_per_s);
      if (step.max_velocity_component_m_per_s > 0)
        max_div_rel = std::max(max_div_rel, step.max_divergence_per_s * g.dx_m / step.max_velocity_component_m_per_s);
      if (solver.time_s() >= t_out * (1 - 1e-12)) {
        sample();
        ++next_output;
      }
    }
  } catch (const fluid::FluidBlowUpError& e) {
    throw RunFailure(e.what(), result);
  }

  const double nan = std::nan("");
  result.metrics["max_divergence"] = {max_div, "1/s"};
  result.metrics["max_divergence_rel"] = {max_div_rel, ""};
  result.metrics["final_kinetic_energy_j_per_m"] = {solver.kineticEnergy_joule_per_m(), "J/m"};
  result.metrics["kinetic_energy_ratio"] = {ke0 > 0 ? solver.kineticEnergy_joule_per_m() / ke0 : nan, ""};
  result.metrics["steps"] = {double(solver.stepsDone()), ""};
  result.metrics["mean_dt_s"] = {solver.time_s() / double(std::max(1L, solver.stepsDone())), "s"};
  result.metrics["max_cfl"] = {max_cfl, ""};
  double linf = nan, rms = nan, nu_eff = nan;
  if (q.initial == "taylor_green") {
    taylorGreenError(solver, q.amplitude_m_per_s, linf, rms);
    // KE ~ exp(-2 nu (kx^2 + ky^2) t): twice the velocity decay rate.
    const double k2 = 2.0 * std::pow(M_PI / q.fluid.domain_width_m, 2);
    nu_eff = std::log(ke0 / solver.kineticEnergy_joule_per_m()) / (2.0 * k2 * solver.time_s());
  }
  result.metrics["velocity_error_linf_m_per_s"] = {linf, "m/s"};
  result.metrics["velocity_error_rms_m_per_s"] = {rms, "m/s"};
  result.metrics["effective_viscosity_m2_per_s"] = {nu_eff, "m^2/s"};
  result.metrics["numerical_viscosity_m2_per_s"] = {nu_eff - q.fluid.kinematic_viscosity_m2_per_s, "m^2/s"};
  return result;
}

}  // namespace creaturelab::kinds
