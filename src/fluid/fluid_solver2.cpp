#include "fluid/fluid_solver2.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "fluid/boundary2.hpp"
#include "fluid/diagnostics2.hpp"
#include "fluid/fast_diffusion2.hpp"
#include "fluid/tracers2.hpp"

namespace creaturelab::fluid {
namespace {

std::string blowUpMessage(long step, double time_s, double dt_s, double max_speed, double limit, double cfl) {
  std::ostringstream out;
  out << "fluid solver blew up at step " << step << " (t = " << time_s << " s, dt = " << dt_s
      << " s): the largest velocity component is " << max_speed << " m/s";
  if (std::isfinite(max_speed)) out << ", above blowup_speed_m_per_s = " << limit;
  out << "; CFL number " << cfl
      << ". Reduce the time step (max_step_s, cfl_safety_factor) or the forcing, or refine the grid.";
  return out.str();
}

std::string cflMessage(long step, double time_s, double dt_s, double cfl, double bound) {
  std::ostringstream out;
  out << "fluid step " << step << " (t = " << time_s << " s, dt = " << dt_s << " s) has CFL number " << cfl
      << ", above the stability bound " << bound
      << " of the explicit advection scheme. Reduce the time step (max_step_s, fixed_step_s, "
         "cfl_safety_factor) or use a semi-Lagrangian scheme.";
  return out.str();
}

std::unique_ptr<DiffusionSolver2> makeDiffusionSolver(const FluidParams& params) {
  if (params.viscosity_solver == ViscositySolverType::fast_direct) {
    return std::make_unique<FastDiffusion2>(params.viscosity_tolerance);
  }
  return std::make_unique<ImplicitDiffusion2>(params.viscosity_tolerance, params.viscosity_max_iterations);
}

FluidParams checked(const FluidParams& params) {
  const std::string problems = params.validate();
  if (!problems.empty()) throw std::invalid_argument("invalid fluid parameters: " + problems);
  return params;
}

}  // namespace

FluidBlowUpError::FluidBlowUpError(long step, double time_s, double dt_s, double max_speed_m_per_s,
                                   double limit_m_per_s, double cfl_number)
    : std::runtime_error(blowUpMessage(step, time_s, dt_s, max_speed_m_per_s, limit_m_per_s, cfl_number)),
      step_(step),
      time_s_(time_s),
      cfl_number_(cfl_number) {}

FluidCflError::FluidCflError(long step, double time_s, double dt_s, double cfl_number, double bound)
    : FluidBlowUpError(cflMessage(step, time_s, dt_s, cfl_number, bound), step, time_s, cfl_number), bound_(bound) {}

FluidSolver2::FluidSolver2(const FluidParams& params)
    : params_(checked(params)),
      workers_(params_.threads > 1 ? std::make_unique<WorkerPool>(params_.threads) : nullptr),
      grid_(params_.cells_x, params_.cells_y, params_.cellSize_m()),
      force_density_(params_.cells_x, params_.cells_y),
      advection_(makeAdvectionSolver(params_.advection)),
      diffusion_(makeDiffusionSolver(params_)),
      pressure_(makePressureSolver(params_)) {
  advection_->setWorkers(workers_.get());
  diffusion_->setWorkers(workers_.get());
  pressure_->setWorkers(workers_.get());
  enforceWallNormalVelocity(grid_, walls());  // an inflow wall's faces carry its speed from the start
}

double FluidSolver2::nextTimeStep_s() const {
  return timeStepFor(maxVelocityComponent_m_per_s(grid_, workers_.get()));
}

double FluidSolver2::timeStepFor(double max_velocity_component_m_per_s) const {
  if (params_.time_step_policy == TimeStepPolicy::fixed) return params_.fixed_step_s;
  if (!(max_velocity_component_m_per_s > 0.0)) return params_.max_step_s;
  return std::min(params_.max_step_s, params_.cfl_safety_factor * grid_.dx_m / max_velocity_component_m_per_s);
}

FluidStepReport FluidSolver2::step() {
  const double speed = maxVelocityComponent_m_per_s(grid_, workers_.get());
  return runStep(timeStepFor(speed), speed);
}

FluidStepReport FluidSolver2::step(double dt_s) {
  return runStep(dt_s, maxVelocityComponent_m_per_s(grid_, workers_.get()));
}

FluidStepReport FluidSolver2::runStep(double dt_s, double start_speed_m_per_s) {
  if (!(std::isfinite(dt_s) && dt_s > 0.0)) {
    throw std::invalid_argument("fluid time step must be a positive number of seconds (got " + std::to_string(dt_s) +
                                ")");
  }
  const StepContext context{steps_done_, time_s_, dt_s};
  FluidStepReport report;
  report.dt_s = dt_s;
  report.cfl_number = start_speed_m_per_s * dt_s / grid_.dx_m;
  // An explicit scheme's bound, on the step's starting velocity (the CFL number reported). The
  // relative slack lets the adaptive step at cfl_safety_factor = bound through despite rounding.
  const double bound = advection_->maxStableCfl();
  if (stages_.advection && report.cfl_number > bound * (1.0 + 1e-12)) {
    throw FluidCflError(steps_done_, time_s_, dt_s, report.cfl_number, bound);
  }

  const bool force_first = params_.force_stage == ForceStage::before_advection;
  if (force_first && stages_.external_forces) applyExternalForces(context);
  if (stages_.advection) advectVelocity(context);
  if (!force_first && stages_.external_forces) applyExternalForces(context);
  if (stages_.viscosity) report.viscosity = applyViscosity(context);
  if (stages_.pressure) report.pressure = project(context);
  if (stages_.tracers) advectTracers(context);

  time_s_ += dt_s;
  ++steps_done_;
  report.steps_done = steps_done_;
  report.time_s = time_s_;
  const FlowSummary summary = summarizeFlow(grid_, params_.density_kg_per_m3, workers_.get(), row_energies_);
  report.max_velocity_component_m_per_s = summary.max_velocity_component_m_per_s;
  report.max_divergence_per_s = summary.max_divergence_per_s;
  report.kinetic_energy_joule_per_m = summary.kinetic_energy_joule_per_m;
  if (!(report.max_velocity_component_m_per_s <= params_.blowup_speed_m_per_s)) {
    throw FluidBlowUpError(steps_done_, time_s_, dt_s, report.max_velocity_component_m_per_s,
                           params_.blowup_speed_m_per_s, report.max_velocity_component_m_per_s * dt_s / grid_.dx_m);
  }
  return report;
}

void FluidSolver2::applyExternalForces(const StepContext& context) {
  const double dt = context.dt_s;
  const double inv_rho = 1.0 / params_.density_kg_per_m3;
  const double gx = params_.body_acceleration_x_m_per_s2;
  const double gy = params_.body_acceleration_y_m_per_s2;
  const FaceRange u_cols = unknownUColumns(grid_, walls());
  const FaceRange v_rows = unknownVRows(grid_, walls());
  // Rows of u and of v, cut among threads (each face independent).
  forPieces(workers_.get(), 0, grid_.ny + 1, [&](int j0, int j1, int) {
    for (int j = j0; j < std::min(j1, grid_.ny); ++j) {
      double* u = grid_.u_m_per_s.row(j);
      const double* f = force_density_.x.row(j);
      for (int i = u_cols.begin; i < u_cols.end; ++i) u[i] += dt * (gx + f[i] * inv_rho);
    }
    for (int j = std::max(j0, v_rows.begin); j < std::min(j1, v_rows.end); ++j) {
      double* v = grid_.v_m_per_s.row(j);
      const double* f = force_density_.y.row(j);
      for (int i = 0; i < grid_.nx; ++i) v[i] += dt * (gy + f[i] * inv_rho);
    }
  });
}

void FluidSolver2::advectVelocity(const StepContext& context) {
  advection_->advectVelocity(grid_, walls(), context.dt_s, u_scratch_, v_scratch_);
  std::swap(grid_.u_m_per_s, u_scratch_);
  std::swap(grid_.v_m_per_s, v_scratch_);
}

LinearSolveReport FluidSolver2::applyViscosity(const StepContext& context) {
  if (params_.kinematic_viscosity_m2_per_s == 0.0) return {};
  return diffusion_->diffuseVelocity(grid_, walls(), params_.kinematic_viscosity_m2_per_s, context.dt_s,
                                      params_.viscosity_scheme);
}

LinearSolveReport FluidSolver2::project(const StepContext& context) {
  return pressure_->project(grid_, walls(), params_.density_kg_per_m3, context.dt_s);
}

void FluidSolver2::advectTracers(const StepContext& context) {
  if (tracers_.empty()) return;
  sampler_.assign(grid_, walls());
  advectTracersRk2(tracers_, sampler_, context.dt_s, grid_.width_m(), grid_.height_m());
}

LinearSolveReport FluidSolver2::makeDivergenceFree() {
  enforceWallNormalVelocity(grid_, walls());
  grid_.pressure_pa.fill(0.0);
  // The projected velocity does not depend on dt or ρ; only the pressure does, and it is reset.
  const LinearSolveReport report = pressure_->project(grid_, walls(), 1.0, 1.0);
  grid_.pressure_pa.fill(0.0);
  return report;
}

double FluidSolver2::kineticEnergy_joule_per_m() const {
  return fluid::kineticEnergy_joule_per_m(grid_, params_.density_kg_per_m3);
}

double FluidSolver2::maxDivergence_per_s() const { return fluid::maxDivergence_per_s(grid_); }

double FluidSolver2::cflNumber(double dt_s) const { return fluid::cflNumber(grid_, dt_s); }

}  // namespace creaturelab::fluid
