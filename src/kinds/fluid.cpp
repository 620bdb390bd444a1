#include "kinds/fluid.hpp"

#include <cmath>
#include <cstdio>

#include "fluid/diagnostics2.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::kinds {
namespace {

const std::vector<std::string> kWalls = {"free_slip", "no_slip", "moving", "open"};
const char* kSides[] = {"left", "right", "bottom", "top"};

fluid::FluidParams solverParams(const ParamReader& r) {
  fluid::FluidParams f;
  f.domain_width_m = f.domain_height_m = r.real("domain_m");
  f.cells_x = f.cells_y = int(r.integer("cells"));
  f.density_kg_per_m3 = r.real("density_kg_per_m3");
  f.kinematic_viscosity_m2_per_s = r.real("kinematic_viscosity_m2_per_s");
  fluid::Wall* walls[] = {&f.walls.left, &f.walls.right, &f.walls.bottom, &f.walls.top};
  for (int k = 0; k < 4; ++k) {
    const std::string side = kSides[k];
    walls[k]->type = *fluid::parse_wall_type(r.text("wall_" + side));
    walls[k]->tangential_velocity_m_per_s = r.real("wall_" + side + "_velocity_m_per_s");
  }
  f.advection = *fluid::parse_advection_scheme(r.text("advection"));
  f.pressure_solver = *fluid::parse_pressure_solver_type(r.text("pressure_solver"));
  f.viscosity_solver = *fluid::parse_viscosity_solver_type(r.text("viscosity_solver"));
  if (r.isAuto("dt_s")) {
    f.time_step_policy = fluid::TimeStepPolicy::cfl_adaptive;
  } else {
    f.time_step_policy = fluid::TimeStepPolicy::fixed;
    f.fixed_step_s = r.real("dt_s");
  }
  f.cfl_safety_factor = r.real("cfl_safety_factor");
  f.max_step_s = r.real("max_step_s");
  f.body_acceleration_x_m_per_s2 = r.real("body_acceleration_x_m_per_s2");
  f.body_acceleration_y_m_per_s2 = r.real("body_acceleration_y_m_per_s2");
  return f;
}

void setInitial(const ParamReader& r, fluid::MacGrid2& grid) {
  const std::string& init = r.text("initial");
  if (init == "taylor_green") {
    fluid::set_taylor_green(grid, {r.real("amplitude_m_per_s")});
  } else if (init == "vortex_pair") {
    fluid::VortexPair pair;
    pair.circulation_m2_per_s = r.real("circulation_m2_per_s");
    pair.centre_y_fraction = r.real("vortex_height_fraction");
    fluid::set_vortex_pair(grid, pair);
  } else if (init == "shear_layer") {
    fluid::ShearLayer layer;
    layer.speed_m_per_s = r.real("amplitude_m_per_s");
    fluid::set_shear_layer(grid, layer);
  } else {
    fluid::set_rest(grid);
  }
}

// Cell-centred u, v, pressure and vorticity of the current state, appended as one frame.
void appendFrame(const fluid::FluidSolver2& solver, FieldFrames& frames, fluid::Array2& u, fluid::Array2& v,
                 fluid::Array2& w) {
  const auto& g = solver.grid();
  fluid::velocity_at_centres(g, u, v);
  fluid::vorticity_at_centres(g, solver.walls(), w);
  frames.time_s.push_back(solver.time_s());
  auto add = [&](const std::string& name, const double* data, const char* unit) {
    Field& f = frames.fields[name];
    f.unit = unit;
    f.data.insert(f.data.end(), data, data + g.cell_count());
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
            fluid::taylor_green_velocity_m_per_s(g.u_position_m(i, j), t, g.width_m(), g.height_m(), amplitude, nu).x);
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      visit(g.v_m_per_s(i, j),
            fluid::taylor_green_velocity_m_per_s(g.v_position_m(i, j), t, g.width_m(), g.height_m(), amplitude, nu).y);
  rms = std::sqrt(sum2 / double(n));
}

}  // namespace

FluidKind::FluidKind() {
  params_ = {
      real("domain_m", 0.4, "m", 1e-6, 1e6, "side of the square box; default ten 40 mm bell diameters (Rudolf & Mould Fig. 12)"),
      integer("cells", 100, 4, 4096, "cells per side (Rudolf & Mould Fig. 12: 100)"),
      real("density_kg_per_m3", 1000.0, "kg/m^3", 1e-6, 1e6, "fluid density (paper: '1' without units, read as g/cm^3)"),
      real("kinematic_viscosity_m2_per_s", 1.304e-6, "m^2/s", 0, 1e3,
           "nu (paper: 1.304e-3, read as Pa s, water at 10 C, over 1000 kg/m^3)"),
  };
  for (const char* side : kSides) {
    params_.push_back(choice(std::string("wall_") + side, "free_slip", kWalls,
                             std::string(side) + " wall: free_slip (the paper's), no_slip, moving, open (p = 0)"));
    params_.push_back(real(std::string("wall_") + side + "_velocity_m_per_s", 0.0, "m/s", -1e3, 1e3,
                           std::string("tangential velocity of the ") + side + " wall when moving"));
  }
  const std::vector<ParamSpec> rest = {
      choice("advection", "semi_lagrangian", {"semi_lagrangian", "maccormack", "upwind2_rk2"},
             "semi_lagrangian (Stam 1999, linear interpolation), maccormack (limited, second order) or upwind2_rk2 "
             "(Fromm upwind + Heun, second order, CFL <= 0.5)"),
      choice("pressure_solver", "fast_direct", {"fast_direct", "pcg"},
             "exact projection: transform + tridiagonal (uniform box) or MIC(0)-PCG to 1e-10"),
      choice("viscosity_solver", "iterative", {"iterative", "fast_direct"},
             "implicit viscosity: iterative sweeps (fast for water-like nu dt / dx^2) or the fast direct solve "
             "(exact; faster for very viscous fluids)"),
      realOrAuto("dt_s", "s", 1e-9, 10, "fixed step, or \"auto\": CFL-adaptive with cfl_safety_factor and max_step_s"),
      real("cfl_safety_factor", 0.5, "", 1e-6, 10, "fraction of the CFL limit dx / max|u| (paper used 0.001 with the bell)"),
      real("max_step_s", 0.01, "s", 1e-9, 10, "largest adaptive step (paper §4: instability near 0.01 s)"),
      real("end_time_s", 1.0, "s", 1e-9, 1e6, "simulated time"),
      real("output_interval_s", 0.1, "s", 1e-9, 1e6, "interval between stored fields and series samples"),
      choice("initial", "rest", {"rest", "taylor_green", "vortex_pair", "shear_layer"}, "initial velocity field"),
      real("amplitude_m_per_s", 1.0, "m/s", 0, 1e3, "Taylor-Green amplitude, or the shear layer's speed"),
      real("circulation_m2_per_s", 1e-3, "m^2/s", 0, 1e3, "circulation of each vortex of the pair"),
      real("vortex_height_fraction", 0.6, "", 0, 1, "starting height of the pair, fraction of the box"),
      real("body_acceleration_x_m_per_s2", 0.0, "m/s^2", -1e4, 1e4, "uniform body force per unit mass, x"),
      real("body_acceleration_y_m_per_s2", 0.0, "m/s^2", -1e4, 1e4, "uniform body force per unit mass, y (gravity: -9.81)"),
      integer("tracers_per_side", 0, 0, 1000, "passive tracers on an n x n lattice (paper Fig. 6), 0 = none"),
  };
  params_.insert(params_.end(), rest.begin(), rest.end());
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

std::string FluidKind::validate(const Params& p) const {
  ParamReader r(p);
  if (std::string err = solverParams(r).validate(); !err.empty()) return err;
  if (r.real("output_interval_s") > r.real("end_time_s")) return "output_interval_s is longer than end_time_s";
  return "";
}

// Memory: about 280 B per cell for the solver (its arrays, the pressure solver, the HDF5 write), 4 fields
// x 8 B = 32 B per cell and stored frame (40 taken), and 32 MiB for the process; an upper bound on the
// peak resident set of `creaturelab run`.
CostEstimate FluidKind::estimateCost(const Params& p) const {
  try {
    ParamReader r(p);
    const double cells = double(r.integer("cells")) * double(r.integer("cells"));
    const double frames = 1 + std::ceil(r.real("end_time_s") / r.real("output_interval_s") * (1 - 1e-12));
    const double tracers = double(r.integer("tracers_per_side")) * double(r.integer("tracers_per_side"));
    CostEstimate cost;
    cost.memory_bytes = 32.0 * (1 << 20) + cells * (280 + 40 * frames) + tracers * 16 * frames;
    char detail[160];
    std::snprintf(detail, sizeof detail, "%lld^2 cells, %.0f stored frames of 4 fields", (long long)r.integer("cells"),
                  frames);
    cost.detail = detail;
    return cost;
  } catch (const std::exception&) {
    return {};
  }
}

Result FluidKind::run(const Params& p) const {
  ParamReader r(p);
  fluid::FluidSolver2 solver(solverParams(r));
  setInitial(r, solver.grid());
  solver.make_divergence_free();
  if (const int n = int(r.integer("tracers_per_side")); n > 0) {
    const double L = r.real("domain_m");
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
    energy.values.push_back(solver.kinetic_energy_joule_per_m());
    divergence.values.push_back(solver.max_divergence_per_s());
    cfl.values.push_back(last_cfl);
    appendFrame(solver, frames, u, v, w);
    if (tracers.points > 0) {
      tracers.time_s.push_back(solver.time_s());
      for (const auto& q : solver.tracers_m()) tracers.data.insert(tracers.data.end(), {q.x, q.y});
    }
  };

  const double end = r.real("end_time_s"), every = r.real("output_interval_s");
  const double ke0 = solver.kinetic_energy_joule_per_m();
  sample();
  int next_output = 1;
  try {
    while (solver.time_s() < end * (1 - 1e-12)) {
      // Steps end exactly on output times so every frame is at its nominal time.
      const double t_out = std::min(end, next_output * every);
      const double dt = std::min(solver.next_time_step_s(), t_out - solver.time_s());
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
  result.metrics["final_kinetic_energy_j_per_m"] = {solver.kinetic_energy_joule_per_m(), "J/m"};
  result.metrics["kinetic_energy_ratio"] = {ke0 > 0 ? solver.kinetic_energy_joule_per_m() / ke0 : nan, ""};
  result.metrics["steps"] = {double(solver.steps_done()), ""};
  result.metrics["mean_dt_s"] = {solver.time_s() / double(std::max(1L, solver.steps_done())), "s"};
  result.metrics["max_cfl"] = {max_cfl, ""};
  double linf = nan, rms = nan, nu_eff = nan;
  if (r.text("initial") == "taylor_green") {
    taylorGreenError(solver, r.real("amplitude_m_per_s"), linf, rms);
    // KE ~ exp(-2 nu (kx^2 + ky^2) t): twice the velocity decay rate.
    const double k2 = 2.0 * std::pow(M_PI / r.real("domain_m"), 2);
    nu_eff = std::log(ke0 / solver.kinetic_energy_joule_per_m()) / (2.0 * k2 * solver.time_s());
  }
  result.metrics["velocity_error_linf_m_per_s"] = {linf, "m/s"};
  result.metrics["velocity_error_rms_m_per_s"] = {rms, "m/s"};
  result.metrics["effective_viscosity_m2_per_s"] = {nu_eff, "m^2/s"};
  result.metrics["numerical_viscosity_m2_per_s"] = {nu_eff - r.real("kinematic_viscosity_m2_per_s"), "m^2/s"};
  return result;
}

}  // namespace creaturelab::kinds
