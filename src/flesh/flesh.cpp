#include "flesh/flesh.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "flesh/binding.hpp"

namespace creaturelab::flesh {
namespace {

// The edge springs (flesh_params.hpp: Van Gelder's stiffness, damping as a ratio of the critical) and
// the flesh's weight under the model's gravity, as a spring network.
springs::Network<3> edgeNetwork(const FleshMesh& mesh, const FleshParams& p, const rigid::Vec3& gravity) {
  springs::Network<3> net;
  for (int i = 0; i < mesh.vertices(); ++i) net.addParticle(mesh.mass_kg[i], false);
  for (size_t e = 0; e < mesh.edges.size(); ++e) {
    const int a = mesh.edges[e][0], b = mesh.edges[e][1];
    const double rest = (mesh.rest_m.col(a) - mesh.rest_m.col(b)).norm();
    const double k = p.youngs_modulus_pa * p.thickness_m * mesh.edge_adjacent_area_m2[e] / (rest * rest);
    const double reduced_mass = mesh.mass_kg[a] * mesh.mass_kg[b] / (mesh.mass_kg[a] + mesh.mass_kg[b]);
    net.addSpring(a, b, rest, k, 2 * p.stretch_damping_ratio * std::sqrt(k * reduced_mass));
  }
  net.gravity_m_per_s2 = springs::Vec<3>(gravity[0], gravity[1], gravity[2]);
  return net;
}

FleshMesh validatedMesh(const rigid::RigidModel& model, const FleshParams& params) {
  return buildFleshMesh(model, params);  // validates params first
}

}  // namespace

Flesh::Flesh(const rigid::RigidModel& model, const FleshParams& params)
    : params_(params),
      mesh_(validatedMesh(model, params)),
      edges_(edgeNetwork(mesh_, params, model.gravity_m_per_s2())) {
  const int n = mesh_.vertices();
  state_.x_m = mesh_.rest_m;
  state_.v_m_per_s.setZero(3, n);
  external_n_.setZero(3, n);
  const double omega = 2 * std::numbers::pi * params_.binding_hz;
  binding_k_ = mesh_.mass_kg * (omega * omega);
  binding_c_ = mesh_.mass_kg * (2 * params_.binding_damping_ratio * omega);
}

void Flesh::vertexAreas(Eigen::VectorXd& area_m2) const { flesh::vertexAreas(mesh_, state_.x_m, area_m2); }

void Flesh::setState(const Eigen::Matrix3Xd& x_m, const Eigen::Matrix3Xd& v_m_per_s) {
  if (x_m.cols() != vertices() || v_m_per_s.cols() != vertices())
    throw std::invalid_argument("flesh: setState needs " + std::to_string(vertices()) + " positions and velocities");
  if (!x_m.allFinite() || !v_m_per_s.allFinite())
    throw std::invalid_argument("flesh: setState with a non-finite position or velocity");
  state_.x_m = x_m;
  state_.v_m_per_s = v_m_per_s;
}

void Flesh::placeOnSkeleton(rigid::RigidData& skeleton) {
  skeleton.kinematics();
  anchorStates(mesh_, skeleton, state_.x_m, state_.v_m_per_s);
}

void Flesh::step(rigid::RigidData& skeleton, double h_s) {
  if (!(h_s > 0) || !std::isfinite(h_s)) throw std::invalid_argument("flesh: step needs a positive time step (s)");
  skeleton.kinematics();
  anchorStates(mesh_, skeleton, anchor_m_, anchor_v_);
  forcesAtStart();
  rightHandSide(h_s);
  assembleMatrix(h_s);
  solveVelocityChange();
  integrate(h_s);
  bindingReactions(h_s, skeleton);
  external_n_.setZero();
}

void Flesh::forcesAtStart() {
  edges_.forces(state_, 0.0, force_n_);  // edge springs with their damping, and weight
  force_n_ += external_n_;
  for (int i = 0; i < vertices(); ++i)
    force_n_.col(i) -= binding_k_[i] * (state_.x_m.col(i) - anchor_m_.col(i)) +
                       binding_c_[i] * (state_.v_m_per_s.col(i) - anchor_v_.col(i));
  stiffness_.clear();
  damping_.clear();
  edges_.addStiffnessTriplets(state_, 1.0, stiffness_, /*clamp_compression=*/true);
  edges_.addDampingTriplets(state_, 1.0, damping_);
}

void Flesh::rightHandSide(double h) {
  // b = h (f0 + h K_edges v0 - h k_i (v0 - w_i)): the binding's df/dx = -k_i I acts on the velocity
  // relative to the anchor, the anchor moving on with w_i.
  const int dofs = 3 * vertices();
  rhs_.resize(dofs);
  const double* v0 = state_.v_m_per_s.data();
  for (int r = 0; r < dofs; ++r) rhs_[r] = force_n_.data()[r] - h * binding_k_[r / 3] * (v0[r] - anchor_v_.data()[r]);
  for (const auto& t : stiffness_) rhs_[t.row()] += h * t.value() * v0[t.col()];
  rhs_ *= h;
}

void Flesh::assembleMatrix(double h) {
  const int dofs = 3 * vertices();
  entries_.clear();
  entries_.reserve(dofs + damping_.size() + stiffness_.size());
  for (int r = 0; r < dofs; ++r) {
    const int i = r / 3;
    entries_.emplace_back(r, r, mesh_.mass_kg[i] + h * binding_c_[i] + h * h * binding_k_[i]);
  }
  for (const auto& t : damping_) entries_.emplace_back(t.row(), t.col(), -h * t.value());
  for (const auto& t : stiffness_) entries_.emplace_back(t.row(), t.col(), -h * h * t.value());
  a_.resize(dofs, dofs);
  a_.setFromTriplets(entries_.begin(), entries_.end());
}

void Flesh::solveVelocityChange() {
  cg_.setTolerance(params_.cg_tolerance);
  cg_.setMaxIterations(params_.cg_max_iterations);
  cg_.compute(a_);
  dv_.setZero(rhs_.size());
  dv_ = cg_.solveWithGuess(rhs_, dv_);
  summary_.cg_iterations = int(cg_.iterations());
  summary_.cg_relative_residual = cg_.error();
  summary_.cg_converged = cg_.info() == Eigen::Success;
}

void Flesh::integrate(double h) {
  state_.v_m_per_s.reshaped() += dv_;
  state_.x_m += h * state_.v_m_per_s;
}

void Flesh::bindingReactions(double h, rigid::RigidData& skeleton) {
  // f_i(x1, v1) with the anchor at p_i + h w_i; its reaction acts at the anchor's present point.
  binding_force_n_.resize(3, vertices());
  for (int i = 0; i < vertices(); ++i)
    binding_force_n_.col(i) = -binding_k_[i] * (state_.x_m.col(i) - anchor_m_.col(i) - h * anchor_v_.col(i)) -
                              binding_c_[i] * (state_.v_m_per_s.col(i) - anchor_v_.col(i));
  summary_.binding_impulse_on_flesh_ns = h * binding_force_n_.rowwise().sum();
  applyReactions(mesh_, binding_force_n_, anchor_m_, skeleton);
}

double Flesh::kineticEnergy_j() const { return edges_.kineticEnergy(state_); }

double Flesh::stretchEnergy_j() const { return edges_.elasticEnergy(state_); }

double Flesh::bindingEnergy_j(const rigid::RigidData& skeleton) const {
  Eigen::Matrix3Xd anchor, anchor_v;
  anchorStates(mesh_, skeleton, anchor, anchor_v);
  double e = 0;
  for (int i = 0; i < vertices(); ++i) e += 0.5 * binding_k_[i] * (state_.x_m.col(i) - anchor.col(i)).squaredNorm();
  return e;
}

Eigen::Vector3d Flesh::linearMomentum_kg_m_per_s() const {
  return state_.v_m_per_s * mesh_.mass_kg;
}

}  // namespace creaturelab::flesh
