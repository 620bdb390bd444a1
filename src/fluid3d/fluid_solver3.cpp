#include "fluid3d/fluid_solver3.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fluid3d/pressure_operator3.hpp"

namespace creaturelab::fluid3d {
namespace solver3_detail {

FluidParams3 validated(const FluidParams3& params) {
  const std::string problems = params.validate();
  if (!problems.empty()) throw std::invalid_argument("fluid3d: " + problems);
  return params;
}

}  // namespace solver3_detail

FluidSolver3::FluidSolver3(const FluidParams3& params)
    : params_(solver3_detail::validated(params)),
      workers_(params.threads > 1 ? std::make_unique<WorkerPool>(params.threads) : nullptr),
      grid_({params.cells_x, params.cells_y, params.cells_z}, params.cellSize_m(), params.boundaries) {
  for (int a = 0; a < 3; ++a) {
    const std::array<int, 3> e = grid_.faceExtents(a);
    force_density_[a] = Array3(e[0], e[1], e[2]);
  }
  setAdvectionSolver(makeAdvectionSolver(params_.advection));
  setPressureSolver(makePressureSolver(params_));
  viscosity_ = std::make_unique<ViscositySolver3>(params_.viscosity_scheme, params_.viscosity_tolerance,
                                                  params_.viscosity_max_iterations);
  viscosity_->setWorkers(workers_.get());
}

FluidSolver3::~FluidSolver3() = default;

void FluidSolver3::setPressureSolver(std::unique_ptr<PressureSolver3> solver) {
  pressure_ = std::move(solver);
  pressure_->setWorkers(workers_.get());
}
void FluidSolver3::setAdvectionSolver(std::unique_ptr<AdvectionSolver3> solver) {
  advection_ = std::move(solver);
  advection_->setWorkers(workers_.get());
}

double FluidSolver3::nextTimeStep_s() const {
  if (params_.time_step_policy == TimeStepPolicy3::fixed) return params_.fixed_step_s;
  const double speed = maxVelocityComponent_m_per_s();
  if (speed <= 0.0) return params_.max_step_s;
  const double cfl = std::min(params_.cfl_safety_factor, advection_->maxStableCfl());
  return std::min(params_.max_step_s, cfl * grid_.dx_m / speed);
}

FluidStepReport3 FluidSolver3::step() { return step(nextTimeStep_s()); }

FluidStepReport3 FluidSolver3::step(double dt_s) {
  if (!(dt_s > 0.0 && std::isfinite(dt_s))) throw std::invalid_argument("fluid3d: the time step must be positive");
  FluidStepReport3 report;
  report.dt_s = dt_s;
  report.cfl_number = maxVelocityComponent_m_per_s() * dt_s / grid_.dx_m;
  if (stages_.advection && report.cfl_number > advection_->maxStableCfl()) {
    std::ostringstream message;
    message << "fluid3d refused step " << steps_done_ + 1 << " (t = " << time_s_ << " s): its CFL number "
            << report.cfl_number << " exceeds " << advection_->maxStableCfl() << ", the stability bound of "
            << toString(params_.advection) << " advection; take dt <= " << advection_->maxStableCfl() * grid_.dx_m /
                   maxVelocityComponent_m_per_s() << " s";
    throw FluidBlowUpError3(message.str());
  }
  if (stages_.external_forces) applyExternalForces(dt_s);
  if (stages_.advection) advectVelocity(dt_s);
  if (stages_.pressure && params_.projection == ProjectionScheme3::incremental) applyPressureGradient(dt_s);
  if (stages_.viscosity) report.viscosity = applyViscosity(dt_s);
  if (stages_.pressure) report.pressure = project(dt_s);
  time_s_ += dt_s;
  ++steps_done_;
  report.steps_done = steps_done_;
  report.time_s = time_s_;
  const double speed = maxVelocityComponent_m_per_s();
  if (!(speed <= params_.blowup_speed_m_per_s)) {
    std::ostringstream message;
    message << "fluid3d blew up at step " << steps_done_ << " (t = " << time_s_ << " s, dt = " << dt_s
            << " s): max velocity component " << speed << " m/s exceeds " << params_.blowup_speed_m_per_s
            << " m/s (CFL number " << report.cfl_number << ")";
    throw FluidBlowUpError3(message.str());
  }
  return report;
}

void FluidSolver3::applyExternalForces(double dt_s) {
  const double per_density = 1.0 / params_.density_kg_per_m3;
  for (int a = 0; a < 3; ++a) {
    Array3& u = grid_.velocity_m_per_s[a];
    const Array3& f = force_density_[a];
    const double g = params_.body_acceleration_m_per_s2[a];
    for (std::size_t t = 0; t < u.size(); ++t) u.data()[t] += dt_s * (g + f.data()[t] * per_density);
  }
  enforceSolidWalls(grid_);
}

void FluidSolver3::advectVelocity(double dt_s) {
  advection_->advect(grid_, dt_s, scratch_);
  for (int a = 0; a < 3; ++a) std::swap(grid_.velocity_m_per_s[a], scratch_[a]);
}

SolveReport3 FluidSolver3::applyViscosity(double dt_s) {
  return viscosity_->diffuse(grid_, params_.kinematic_viscosity_m2_per_s, dt_s);
}

SolveReport3 FluidSolver3::project(double dt_s) {
  return pressure_->project(grid_, params_.density_kg_per_m3, dt_s, params_.projection == ProjectionScheme3::incremental);
}

void FluidSolver3::applyPressureGradient(double dt_s) {
  subtractGradient(grid_, grid_.pressure_pa, dt_s / (params_.density_kg_per_m3 * grid_.dx_m), workers_.get());
}

SolveReport3 FluidSolver3::makeDivergenceFree() {
  enforceSolidWalls(grid_);
  grid_.pressure_pa.fill(0.0);
  const SolveReport3 report = pressure_->project(grid_, params_.density_kg_per_m3, 1.0);
  grid_.pressure_pa.fill(0.0);
  return report;
}

double FluidSolver3::kineticEnergy_joule() const {
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const Array3& u = grid_.velocity_m_per_s[a];
    const std::array<int, 3> e = grid_.faceExtents(a);
    for (int k = 0; k < e[2]; ++k)
      for (int j = 0; j < e[1]; ++j)
        for (int i = 0; i < e[0]; ++i) {
          const int m[3] = {i, j, k};
          const bool wall_face = !grid_.periodic(a) && (m[a] == 0 || m[a] == grid_.n[a]);
          const double v = u(i, j, k);
          sum += (wall_face ? 0.5 : 1.0) * v * v;
        }
  }
  return 0.5 * params_.density_kg_per_m3 * sum * grid_.cellVolume_m3();
}

double FluidSolver3::maxDivergence_per_s() const { return fluid3d::maxDivergence_per_s(grid_, workers_.get()); }

double FluidSolver3::maxVelocityComponent_m_per_s() const {
  std::vector<double> per_slab;
  double m = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double v = maxAbs3(grid_.velocity_m_per_s[a], workers_.get(), per_slab);
    if (!(v <= m)) m = v;
  }
  return m;
}

}  // namespace creaturelab::fluid3d
