#include "ib/coupling.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCholesky>

namespace creaturelab::ib {

ImmersedBoundary2::ImmersedBoundary2(fluid::FluidSolver2& fluid, const ElasticBody& body,
                                     std::vector<fluid::Vec2> markers_m, CouplingParams params)
    : fluid_(fluid), body_(body), markers_(std::move(markers_m)), params_(params) {
  if (static_cast<int>(markers_.size()) != body_.markerCount())
    throw std::invalid_argument("immersed boundary: " + std::to_string(markers_.size()) + " markers for a body of " +
                                std::to_string(body_.markerCount()));
  if (!(params_.implicit_mass_factor > 0))
    throw std::invalid_argument("immersed boundary: implicit_mass_factor must be > 0");
  force_.resize(markers_.size());
  velocity_.resize(markers_.size());
}

void ImmersedBoundary2::semiImplicitForce(double t1_s, double dt_s) {
  const int n = 2 * static_cast<int>(markers_.size());
  const double dx = fluid_.grid().dx_m;
  const double mass = params_.implicit_mass_factor * fluid_.params().density_kg_per_m3 * dx * dx;
  transfer_.interpolate(fluid_.grid(), velocity_);

  triplets_.clear();
  body_.stiffness(t1_s, markers_, 1.0, triplets_);
  Eigen::SparseMatrix<double> stiffness(n, n);
  stiffness.setFromTriplets(triplets_.begin(), triplets_.end());
  Eigen::SparseMatrix<double> system = -(dt_s * dt_s) * stiffness;
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n / 2; ++i) {
    rhs[2 * i] = mass * velocity_[i].x + dt_s * force_[i].x;
    rhs[2 * i + 1] = mass * velocity_[i].y + dt_s * force_[i].y;
  }
  std::vector<Eigen::Triplet<double>> diagonal;
  diagonal.reserve(n);
  for (int i = 0; i < n; ++i) diagonal.emplace_back(i, i, mass);
  Eigen::SparseMatrix<double> mass_matrix(n, n);
  mass_matrix.setFromTriplets(diagonal.begin(), diagonal.end());
  system += mass_matrix;

  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("immersed boundary: the semi-implicit force system is not positive definite");
  const Eigen::VectorXd predicted = solver.solve(rhs);
  const Eigen::VectorXd correction = dt_s * (stiffness * predicted);
  for (int i = 0; i < n / 2; ++i) {
    force_[i].x += correction[2 * i];
    force_[i].y += correction[2 * i + 1];
  }
}

CouplingStepReport ImmersedBoundary2::step(double dt_s) {
  const double t1_s = fluid_.time_s() + dt_s;
  transfer_.locate(fluid_.grid(), params_.kernel, markers_);
  body_.forces(t1_s, markers_, force_);
  if (params_.semi_implicit) semiImplicitForce(t1_s, dt_s);

  auto& density = fluid_.force_density_n_per_m3();
  density.fill(0.0);
  transfer_.spread(force_, density);

  CouplingStepReport report;
  report.fluid = fluid_.step(dt_s);

  transfer_.interpolate(fluid_.grid(), velocity_);
  for (std::size_t k = 0; k < markers_.size(); ++k) {
    const fluid::Vec2 u = velocity_[k];
    markers_[k].x += dt_s * u.x;
    markers_[k].y += dt_s * u.y;
    if (!std::isfinite(markers_[k].x) || !std::isfinite(markers_[k].y))
      throw std::runtime_error("immersed boundary: marker " + std::to_string(k) + " is no longer finite at t = " +
                               std::to_string(fluid_.time_s()) + " s");
    report.max_marker_speed_m_per_s = std::max(report.max_marker_speed_m_per_s, std::hypot(u.x, u.y));
  }
  return report;
}

}  // namespace creaturelab::ib
