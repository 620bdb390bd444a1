#include "ib/coupling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

namespace creaturelab::ib {

std::string_view to_string(ImplicitMobility mobility) {
  return mobility == ImplicitMobility::stencil ? "stencil" : "local_mass";
}

std::optional<ImplicitMobility> parse_implicit_mobility(std::string_view name) {
  if (name == "stencil") return ImplicitMobility::stencil;
  if (name == "local_mass") return ImplicitMobility::local_mass;
  return std::nullopt;
}

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
  const double rho = fluid_.params().density_kg_per_m3;
  transfer_.interpolate(fluid_.grid(), velocity_);

  triplets_.clear();
  body_.stiffness(t1_s, markers_, 1.0, triplets_);
  Eigen::SparseMatrix<double> stiffness(n, n);
  stiffness.setFromTriplets(triplets_.begin(), triplets_.end());
  Eigen::VectorXd free(n), force(n);
  for (int i = 0; i < n / 2; ++i) {
    free[2 * i] = velocity_[i].x;
    free[2 * i + 1] = velocity_[i].y;
    force[2 * i] = force_[i].x;
    force[2 * i + 1] = force_[i].y;
  }

  Eigen::VectorXd predicted;
  if (params_.mobility == ImplicitMobility::stencil) {
    // (I − dt M K) U* = U_free + M F with M = dt/(ρ dx²) G, sparse: markers couple only through
    // shared faces. Not symmetric.
    gram_triplets_.clear();
    transfer_.gramTriplets(dt_s / (rho * dx * dx), gram_triplets_);
    Eigen::SparseMatrix<double> mobility(n, n);
    mobility.setFromTriplets(gram_triplets_.begin(), gram_triplets_.end());
    Eigen::SparseMatrix<double> identity(n, n);
    identity.setIdentity();
    const Eigen::SparseMatrix<double> system = identity - dt_s * (mobility * stiffness);
    // Sparse LU. Its symbolic analysis (the costly part for the bell) is redone only when the
    // pattern changes, i.e. when a marker's stencil moves to other faces.
    Eigen::SparseMatrix<double> compressed = system;
    compressed.makeCompressed();
    const bool same_pattern =
        lu_ready_ && compressed.rows() == pattern_outer_.size() - 1 &&
        std::equal(pattern_outer_.begin(), pattern_outer_.end(), compressed.outerIndexPtr()) &&
        static_cast<long>(pattern_inner_.size()) == compressed.nonZeros() &&
        std::equal(pattern_inner_.begin(), pattern_inner_.end(), compressed.innerIndexPtr());
    if (!same_pattern) {
      lu_.analyzePattern(compressed);
      pattern_outer_.assign(compressed.outerIndexPtr(), compressed.outerIndexPtr() + compressed.outerSize() + 1);
      pattern_inner_.assign(compressed.innerIndexPtr(), compressed.innerIndexPtr() + compressed.nonZeros());
      lu_ready_ = true;
    }
    lu_.factorize(compressed);
    if (lu_.info() != Eigen::Success)
      throw std::runtime_error("immersed boundary: the semi-implicit force system is singular");
    predicted = lu_.solve(free + mobility * force);
  } else {
    // (m I − dt² K) U* = m U_free + dt F: the same with M = dt / m.
    const double mass = params_.implicit_mass_factor * rho * dx * dx;
    Eigen::SparseMatrix<double> system = -(dt_s * dt_s) * stiffness;
    Eigen::SparseMatrix<double> mass_matrix(n, n);
    mass_matrix.setIdentity();
    system += mass * mass_matrix;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("immersed boundary: the semi-implicit force system is not positive definite");
    predicted = solver.solve(mass * free + dt_s * force);
  }
  if (!predicted.allFinite())
    throw std::runtime_error("immersed boundary: the semi-implicit force is not finite at t = " + std::to_string(t1_s) + " s");
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
