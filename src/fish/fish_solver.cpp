#include "fish/fish_solver.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace creaturelab::fish {

FishState restState(const FishModel& fish) {
  FishState s;
  s.x_m = fish.rest_positions_m;
  s.v_m_per_s.setZero();
  for (int e = 0; e < kUnits; ++e) s.rest_m[e] = fish.network.rest_length_m[e];
  return s;
}

std::string SolverParams::validate() const {
  const SolverParams& p = *this;
  if (!(p.dt_s > 0) || !std::isfinite(p.dt_s)) return "dt_s must be positive (got " + std::to_string(p.dt_s) + ")";
  if (!(p.water.mu >= 0) || !std::isfinite(p.water.mu)) return "water_mu must be >= 0 (got " + std::to_string(p.water.mu) + ")";
  if (!p.water.current_m_per_s.allFinite()) return "current_m_per_s must be finite";
  if (!(p.blowup_strain > 0)) return "blowup_strain must be positive";
  return "";
}

FishSolver::FishSolver(const FishModel& fish, SolverParams params) : fish_(fish), params_(std::move(params)) {
  if (auto problem = params_.validate(); !problem.empty()) throw std::invalid_argument(problem);
  for (int i = 0; i < kNodes; ++i) mass_kg_[i] = fish.network.mass_kg[i];
  for (int e = 0; e < kUnits; ++e) rest0_m_[e] = fish.network.rest_length_m[e];
}

// Stage 1 (spec §2, thesis ch. 4): r = x_j - x_i, e = |r| - l, e' = (v_j - v_i) . r / |r|,
// n_ij = (c e + gamma e') / |r|; the force on i is n_ij r, on j its opposite.
void FishSolver::unitForces(const FishState& s) {
  g_.setZero();
  const auto& net = fish_.network;
  for (int e = 0; e < kUnits; ++e) {
    const int i = net.spring_a[e], j = net.spring_b[e];
    const Eigen::RowVector3d r = s.x_m.row(j) - s.x_m.row(i);
    const double len = r.norm();
    const double rate = (s.v_m_per_s.row(j) - s.v_m_per_s.row(i)).dot(r) / len;
    const double n = (net.stiffness_n_per_m[e] * (len - s.rest_m[e]) + net.damping_ns_per_m[e] * rate) / len;
    n_[e] = n;
    g_.row(i) += n * r;
    g_.row(j) -= n * r;
  }
}

void FishSolver::waterForce(const FishState& s) {
  fw_.setZero();
  addWaterForce(fish_, params_.water, s.x_m, s.v_m_per_s, fw_);
}

// Stage 3: A = M/dt + dt K (thesis ch. 4: K(t) holds damping and stiffness through n_ij).
void FishSolver::assemble() {
  const double dt = params_.dt_s;
  a_.setZero();
  a_.diagonal() = mass_kg_ / dt;
  const auto& net = fish_.network;
  for (int e = 0; e < kUnits; ++e) {
    const int i = net.spring_a[e], j = net.spring_b[e];
    const double k = dt * n_[e];
    a_(i, i) += k;
    a_(j, j) += k;
    a_(i, j) -= k;
    a_(j, i) -= k;
  }
}

StepReport FishSolver::checkState(const NodeMatrix& x, const NodeMatrix& v) const {
  if (!x.allFinite() || !v.allFinite()) return {StepStatus::non_finite, "a node position or velocity is not finite"};
  const auto& net = fish_.network;
  const double hi = 1.0 + params_.blowup_strain, lo = 1.0 / hi;
  for (int e = 0; e < kUnits; ++e) {
    const double ratio = (x.row(net.spring_b[e]) - x.row(net.spring_a[e])).norm() / rest0_m_[e];
    if (!(ratio <= hi && ratio >= lo)) {
      std::ostringstream out;
      out << "unit " << e << " (nodes " << net.spring_a[e] << "-" << net.spring_b[e] << ") at " << ratio
          << " times its undeformed length, outside [" << lo << ", " << hi << "] (blowup_strain)";
      return {StepStatus::overstretched, out.str()};
    }
  }
  return {};
}

StepReport FishSolver::solveTangent(const FishState& s, const NodeMatrix& force) {
  const double dt = params_.dt_s;
  const auto& net = fish_.network;
  a3_.setZero();
  Eigen::Matrix<double, 3 * kNodes, 1> rhs, v;
  for (int i = 0; i < kNodes; ++i) {
    a3_.diagonal().segment<3>(3 * i).setConstant(mass_kg_[i] / dt);
    v.segment<3>(3 * i) = s.v_m_per_s.row(i).transpose();
    rhs.segment<3>(3 * i) = (force.row(i) + mass_kg_[i] / dt * s.v_m_per_s.row(i)).transpose();
  }
  for (int e = 0; e < kUnits; ++e) {
    const int i = net.spring_a[e], j = net.spring_b[e];
    const Eigen::Vector3d r = (s.x_m.row(j) - s.x_m.row(i)).transpose();
    const double len = r.norm(), c = net.stiffness_n_per_m[e], secant = c * (len - s.rest_m[e]) / len;
    const Eigen::Matrix3d rr = (r / len) * (r / len).transpose();
    const Eigen::Matrix3d damp = net.damping_ns_per_m[e] * rr;
    const Eigen::Matrix3d block = dt * (c * rr + secant * (Eigen::Matrix3d::Identity() - rr)) + damp;
    a3_.block<3, 3>(3 * i, 3 * i) += block;
    a3_.block<3, 3>(3 * j, 3 * j) += block;
    a3_.block<3, 3>(3 * i, 3 * j) -= block;
    a3_.block<3, 3>(3 * j, 3 * i) -= block;
    const Eigen::Vector3d dv = damp * (v.segment<3>(3 * i) - v.segment<3>(3 * j));  // + (D V)_i on the right
    rhs.segment<3>(3 * i) += dv;
    rhs.segment<3>(3 * j) -= dv;
  }
  ldlt3_.compute(a3_);
  if (ldlt3_.info() != Eigen::Success || !ldlt3_.isPositive() || !(ldlt3_.vectorD().minCoeff() > 0)) {
    std::ostringstream out;
    out << "the tangent matrix M/dt + dt K_t + D lost positive definiteness (smallest pivot " << ldlt3_.vectorD().minCoeff() << ")";
    return {StepStatus::not_positive_definite, out.str()};
  }
  const Eigen::Matrix<double, 3 * kNodes, 1> vn = ldlt3_.solve(rhs);
  for (int i = 0; i < kNodes; ++i) v_next_.row(i) = vn.segment<3>(3 * i).transpose();
  return {};
}

StepReport FishSolver::step(FishState& s) {
  const double dt = params_.dt_s;
  unitForces(s);
  waterForce(s);
  const NodeMatrix force = fw_ + g_;
  if (!force.allFinite() || !s.v_m_per_s.allFinite())
    return {StepStatus::non_finite, "a unit or water force (or a velocity) is not finite"};
  if (params_.scheme == Scheme::semi_implicit) {
    assemble();
    ldlt_.compute(a_);
    // LDL^T of a symmetric positive definite A has D > 0; a compressed unit (n_ij < 0) can make A
    // indefinite at a large step or amplitude (spec §2 hazards).
    if (ldlt_.info() != Eigen::Success || !ldlt_.isPositive() || !(ldlt_.vectorD().minCoeff() > 0)) {
      int worst = 0;
      for (int e = 1; e < kUnits; ++e)
        if (n_[e] < n_[worst]) worst = e;
      std::ostringstream out;
      out << "the effective-stiffness matrix M/dt + dt K lost positive definiteness (smallest pivot "
          << ldlt_.vectorD().minCoeff() << "; most compressed unit " << worst << ", n = " << n_[worst] << " N/m)";
      return {StepStatus::not_positive_definite, out.str()};
    }
    NodeMatrix rhs = force;
    rhs += (mass_kg_ / dt).asDiagonal() * s.v_m_per_s;
    v_next_ = ldlt_.solve(rhs);
    x_next_ = s.x_m + dt * v_next_;
  } else if (params_.scheme == Scheme::tangent_implicit) {
    if (StepReport r = solveTangent(s, force); r.status != StepStatus::ok) return r;
    x_next_ = s.x_m + dt * v_next_;
  } else {
    v_next_ = s.v_m_per_s + dt * (mass_kg_.cwiseInverse().asDiagonal() * force);
    x_next_ = s.x_m + dt * (params_.scheme == Scheme::explicit_euler ? s.v_m_per_s : v_next_);
  }
  if (StepReport r = checkState(x_next_, v_next_); r.status != StepStatus::ok) return r;
  s.x_m = x_next_;
  s.v_m_per_s = v_next_;
  ++s.step;
  s.time_s = double(s.step) * dt;  // not a running sum: no drift of the clock
  return {};
}

}  // namespace creaturelab::fish
