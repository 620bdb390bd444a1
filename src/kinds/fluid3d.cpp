#include "kinds/fluid3d.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <optional>
#include <utility>

#include "fluid3d/fluid_recorder3.hpp"
#include "fluid3d/fluid_solver3.hpp"
#include "fluid3d/initial_conditions3.hpp"

namespace creaturelab::kinds {
namespace {

// The initial flow with its exact decay (one wavelength across the box), or none at rest.
std::optional<fluid3d::ExactFlow3> exactFlow(const Fluid3dKindParams& q) {
  const double k = 2.0 * std::numbers::pi / q.fluid.domain_x_m, nu = q.fluid.kinematic_viscosity_m2_per_s;
  if (q.initial == "taylor_green") {
    const fluid3d::TaylorGreen3 flow{q.amplitude_m_per_s, k, nu};
    return fluid3d::ExactFlow3{[flow](const std::array<double, 3>& x, double t) { return flow.velocity_m_per_s(x, t); },
                               k, 6.0};
  }
  if (q.initial == "abc") {
    fluid3d::AbcFlow flow;
    flow.a_m_per_s = q.amplitude_m_per_s, flow.b_m_per_s = 0.8 * q.amplitude_m_per_s;
    flow.c_m_per_s = 0.6 * q.amplitude_m_per_s;
    flow.wavenumber_per_m = k, flow.viscosity_m2_per_s = nu;
    return fluid3d::ExactFlow3{[flow](const std::array<double, 3>& x, double t) { return flow.velocity_m_per_s(x, t); },
                               k, 2.0};
  }
  return std::nullopt;
}

// Output frames of a run: the start and every output_interval_s to end_time_s (the last one shorter).
double outputFrames(const Fluid3dKindParams& q) {
  return 1 + std::ceil(q.end_time_s / q.output_interval_s * (1 - 1e-12));
}

// The initial field on the faces, made divergence-free (and the known faces set).
void start(const std::optional<fluid3d::ExactFlow3>& exact, fluid3d::FluidSolver3& solver) {
  if (exact) fluid3d::setFlow(solver.grid(), *exact, 0.0);
  solver.makeDivergenceFree();
}

// The recorded series and planes.
Result recorded(const fluid3d::FluidRecorder3& recorder, const fluid3d::MacGrid3& g) {
  Result result;
  for (const auto& s : recorder.series()) result.timeseries[s.name] = {s.values, s.unit};
  const fluid3d::Slice3& slice = recorder.slice();
  FieldFrames& frames = result.fields;
  frames.nx = slice.columns;
  frames.ny = slice.rows;
  frames.dx_m = frames.dy_m = g.dx_m;
  frames.time_s = recorder.frameTimes();
  for (const auto& f : recorder.fields()) frames.fields[f.name] = {f.values, f.unit};
  return result;
}

// The whole box's cell-centred fields, appended frame by frame in the recorder's names and units
// (Array3 runs x fastest, so each frame is (nz, ny, nx) row-major).
class VolumeFrames {
 public:
  // Room for `expected_frames` frames (at most 1000) from the start: no copies as they arrive.
  VolumeFrames(const fluid3d::MacGrid3& g, double expected_frames) {
    frames_.nx = g.n[0], frames_.ny = g.n[1], frames_.nz = g.n[2];
    frames_.dx_m = frames_.dy_m = frames_.dz_m = g.dx_m;
    const std::size_t cells = std::size_t(g.n[0]) * std::size_t(g.n[1]) * std::size_t(g.n[2]);
    for (const auto& [name, unit] : kNames) frames_.fields[name].data.reserve(cells * std::size_t(std::min(expected_frames, 1000.0)));
  }
  void sample(const fluid3d::FluidSolver3& solver) {
    observables_.update(solver.grid());
    const fluid3d::Array3* arrays[] = {&observables_.cellVelocity_m_per_s(0), &observables_.cellVelocity_m_per_s(1),
                                       &observables_.cellVelocity_m_per_s(2), &solver.grid().pressure_pa,
                                       &observables_.vorticityMagnitude_per_s(), &observables_.q_per_s2()};
    for (std::size_t f = 0; f < std::size(kNames); ++f) {
      Field& field = frames_.fields[kNames[f][0]];
      field.unit = kNames[f][1];
      field.data.insert(field.data.end(), arrays[f]->data(), arrays[f]->data() + arrays[f]->size());
    }
    frames_.time_s.push_back(solver.time_s());
  }
  FieldFrames take() { return std::move(frames_); }

 private:
  static constexpr const char* kNames[6][2] = {{"u_m_per_s", "m/s"},   {"v_m_per_s", "m/s"},
                                               {"w_m_per_s", "m/s"},   {"pressure_pa", "Pa"},
                                               {"vorticity_magnitude_per_s", "1/s"}, {"q_per_s2", "1/s^2"}};
  FieldFrames frames_;
  fluid3d::FlowObservables3 observables_;
};

// The recorded series, with the recorder's plane or the volume (moved out) as the fields.
Result recorded(const fluid3d::FluidRecorder3& recorder, const fluid3d::MacGrid3& g, VolumeFrames* volume) {
  Result result = recorded(recorder, g);
  if (volume) result.fields = volume->take();
  return result;
}

}  // namespace

fluid3d::FluidParams3 Fluid3dKindParams::solverParams() const {
  fluid3d::FluidParams3 f = fluid;
  if (cells > 0) {
    f.cells_x = int(cells);
    f.cells_y = int(std::lround(double(cells) * f.domain_y_m / f.domain_x_m));
    f.cells_z = int(std::lround(double(cells) * f.domain_z_m / f.domain_x_m));
  }
  if (dt_s.is_auto) {
    f.time_step_policy = fluid3d::TimeStepPolicy3::cfl_adaptive;
  } else {
    f.time_step_policy = fluid3d::TimeStepPolicy3::fixed;
    f.fixed_step_s = dt_s.value;
  }
  return f;
}

std::string Fluid3dKindParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  if (std::string err = solverParams().validate(); !err.empty()) return err;
  if (output_interval_s > end_time_s) return "output_interval_s is longer than end_time_s";
  if (initial != "rest") {
    if (fluid.domain_y_m != fluid.domain_x_m || fluid.domain_z_m != fluid.domain_x_m)
      return "initial = \"" + initial + "\" needs a cubic box (domain_y_m = domain_z_m = domain_x_m: one wavelength)";
    for (const fluid3d::AxisBoundary3& b : fluid.boundaries.axis) {
      const bool ok = b.periodic() || (initial == "taylor_green" && b.low == fluid3d::BoundaryType3::free_slip &&
                                       b.high == fluid3d::BoundaryType3::free_slip);
      if (!ok)
        return "initial = \"" + initial + "\" needs periodic sides" +
               (initial == "taylor_green" ? std::string(" (or free_slip on both sides of an axis)") : std::string()) +
               ": its exact decay holds only there";
    }
  }
  return "";
}

Fluid3dKind::Fluid3dKind() {
  metrics_ = {
      {"max_divergence_per_s", "1/s", "largest max|div u| after any step"},
      {"max_divergence_rel", "", "largest max|div u| dx / max|u component| after any step"},
      {"final_kinetic_energy_j", "J", "kinetic energy at the end"},
      {"kinetic_energy_ratio", "", "final over initial kinetic energy"},
      {"steps", "", "time steps taken"},
      {"mean_dt_s", "s", "end_time_s / steps"},
      {"max_cfl", "", "largest CFL number max|u component| dt / dx of any step"},
      {"max_pressure_iterations", "", "most MG-PCG iterations of any step (0: spectral)"},
      {"unconverged_solves", "", "steps whose pressure or viscosity solve stopped above its tolerance"},
      {"velocity_error_linf_m_per_s", "m/s",
       "Taylor-Green (Stokes limit) or ABC only: max |u - u_exact| over the faces at the end"},
      {"velocity_error_rms_m_per_s", "m/s", "Taylor-Green or ABC only: rms |u - u_exact| over the faces at the end"},
      {"effective_viscosity_m2_per_s", "m^2/s",
       "Taylor-Green or ABC only: nu fitted to the energy decay, e^(-6 nu k^2 t) and e^(-2 nu k^2 t)"},
      {"decay_rate_error", "", "Taylor-Green or ABC only: |effective viscosity - nu| / nu"},
      {"inflow_m3_per_s", "m^3/s", "volume flux into the box through its inflow sides at the end"},
      {"outflow_m3_per_s", "m^3/s", "volume flux out of the box through its open sides at the end (net: may be negative)"},
      {"flux_balance_rel", "", "inflow sides only: |outflow - inflow| / inflow at the end (mass conservation)"},
  };
}

std::string Fluid3dKind::doc() const {
  return "3D incompressible Navier-Stokes on a MAC grid (Lentine et al. 2010 §4.1 Eqs. 5-8; Stam 1999), with "
         "inflow sides, vorticity and Q-criterion";
}

// Memory: about 600 B per cell for the solver (seven face and cell arrays, the MG-PCG or spectral
// work arrays, advection scratch, the observables), 6 fields x 8 B per stored frame and plane (or
// volume) cell, and 32 MiB for the process.
CostEstimate Fluid3dKind::estimateCost(const Params& p) const {
  try {
    const Fluid3dKindParams q = readParams<Fluid3dKindParams>(p);
    const fluid3d::FluidParams3 f = q.solverParams();
    const double cells = double(f.cells_x) * double(f.cells_y) * double(f.cells_z);
    const double frames = outputFrames(q);
    const double stored = q.stored_fields == "volume" ? cells : cells / double(std::min({f.cells_x, f.cells_y, f.cells_z}));
    CostEstimate cost;
    cost.memory_bytes = 32.0 * (1 << 20) + cells * 600 + stored * 48 * frames;
    if (!q.dt_s.is_auto) cost.steps = std::ceil(q.end_time_s / q.dt_s.value);
    char detail[160];
    std::snprintf(detail, sizeof detail, "%lld x %lld x %lld cells, %.0f stored %s of 6 fields",
                  (long long)f.cells_x, (long long)f.cells_y, (long long)f.cells_z, frames,
                  q.stored_fields == "volume" ? "volumes" : "planes");
    cost.detail = detail;
    return cost;
  } catch (const std::exception&) {
    return {};
  }
}

Result Fluid3dKind::run(const Params& p) const {
  const Fluid3dKindParams q = readParams<Fluid3dKindParams>(p);
  fluid3d::FluidSolver3 solver(q.solverParams());
  const std::optional<fluid3d::ExactFlow3> exact = exactFlow(q);
  start(exact, solver);
  const int normal = q.slice_normal == "x" ? 0 : q.slice_normal == "y" ? 1 : 2;
  fluid3d::FluidRecorder3 recorder(solver, normal, exact);
  std::optional<VolumeFrames> volume;
  if (q.stored_fields == "volume") volume.emplace(solver.grid(), outputFrames(q));
  VolumeFrames* stored = volume ? &*volume : nullptr;
  try {
    fluid3d::advanceRecorded(solver, q.end_time_s, q.output_interval_s, recorder,
                             [stored](const fluid3d::FluidSolver3& s) {
                               if (stored) stored->sample(s);
                             });
  } catch (const fluid3d::FluidBlowUpError3& e) {
    throw RunFailure(e.what(), recorded(recorder, solver.grid(), stored));
  }
  Result result = recorded(recorder, solver.grid(), stored);
  for (const auto& m : recorder.measure(solver)) result.metrics[m.name] = {m.value, m.unit};
  return result;
}

}  // namespace creaturelab::kinds
