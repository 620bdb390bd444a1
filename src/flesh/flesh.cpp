#include "flesh/flesh.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

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

}  // namespace

Flesh::Flesh(const rigid::RigidModel& model, const FleshParams& params)
    : params_(params),
      mesh_(buildFleshMesh(model, params)),  // validates the parameters first
      edges_(edgeNetwork(mesh_, params, model.gravity_m_per_s2())),
      model_bodies_(model.bodies()) {
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

void Flesh::startStep(rigid::RigidData& skeleton, double h_s, bool solved_with_impulses) {
  if (!(h_s > 0) || !std::isfinite(h_s)) throw std::invalid_argument("flesh: step needs a positive time step (s)");
  if (solved_with_impulses && !params_.implicit_skeleton)
    throw std::invalid_argument("flesh: a step solved with outside impulses needs implicit_skeleton");
  if (skeleton.model().bodies() != model_bodies_)
    throw std::invalid_argument("flesh: stepped against a skeleton of " + std::to_string(skeleton.model().bodies()) +
                                " bodies, built on one of " + std::to_string(model_bodies_));
  if (external_n_.cols() != vertices())
    throw std::invalid_argument("flesh: externalForces_n() must keep its 3 x " + std::to_string(vertices()) + " shape");
  skeleton.kinematics();
  anchorStates(mesh_, skeleton, anchor_m_, anchor_v_);
  anchorJacobians(skeleton);
}

void Flesh::step(rigid::RigidData& skeleton, double h_s) {
  startStep(skeleton, h_s, false);
  forcesAtStart();
  rightHandSide(h_s);
  assembleMatrix(h_s);
  solveVelocityChange();
  integrate(h_s);
  bindingReactions(h_s, skeleton);
  external_n_.setZero();
}

void Flesh::anchorJacobians(rigid::RigidData& skeleton) {
  dofs_ = params_.implicit_skeleton ? skeleton.model().dofs() : 0;
  if (dofs_ == 0) return;
  // RigidData offers no Jacobian, but a wrench applied at a point is J^T times it: a unit force at a
  // body's centre of mass c gives a row of its linear Jacobian there, a unit couple a row of its
  // angular one. The applied forces are restored afterwards.
  double* applied = skeleton.appliedForces();
  const std::vector<double> keep(applied, applied + dofs_);
  const int bodies = skeleton.model().bodies();
  body_jacobian_.assign(bodies, Eigen::MatrixXd());
  std::vector<Eigen::MatrixXd>& body_jacobian = body_jacobian_;  // 6 x dofs: linear at c, then angular
  for (int b : mesh_.body) {
    if (body_jacobian[b].size() > 0) continue;
    body_jacobian[b].setZero(6, dofs_);
    const double* c = skeleton.bodyComPosition(b);
    for (int row = 0; row < 6; ++row) {
      rigid::Vec3 unit{0, 0, 0}, zero{0, 0, 0};
      unit[row % 3] = 1;
      std::fill(applied, applied + dofs_, 0.0);
      skeleton.applyWrenchAt(b, row < 3 ? unit : zero, row < 3 ? zero : unit, {c[0], c[1], c[2]});
      for (int j = 0; j < dofs_; ++j) body_jacobian[b](row, j) = applied[j];
    }
  }
  std::copy(keep.begin(), keep.end(), applied);
  // J_i = J_v(c) - [r_i]x J_w, r_i = p_i - c: the anchor's velocity v(c) + w x r_i.
  anchor_jacobian_.resize(3 * vertices(), dofs_);
  for (int i = 0; i < vertices(); ++i) {
    const int b = mesh_.body[i];
    const Eigen::Vector3d r = anchor_m_.col(i) - Eigen::Map<const Eigen::Vector3d>(skeleton.bodyComPosition(b));
    Eigen::Matrix3d cross_r;
    cross_r << 0, -r[2], r[1], r[2], 0, -r[0], -r[1], r[0], 0;
    anchor_jacobian_.middleRows<3>(3 * i) = body_jacobian[b].topRows<3>() - cross_r * body_jacobian[b].bottomRows<3>();
  }
  std::vector<double> b_matrix;
  skeleton.eulerMatrix(b_matrix);
  euler_matrix_ = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      b_matrix.data(), dofs_, dofs_);
}

void Flesh::forcesAtStart() {
  edges_.forces(state_, 0.0, force_n_);  // edge springs with their damping, and weight
  force_n_ += external_n_;
  binding_force_n_.resize(3, vertices());
  for (int i = 0; i < vertices(); ++i)
    binding_force_n_.col(i) = -binding_k_[i] * (state_.x_m.col(i) - anchor_m_.col(i)) -
                              binding_c_[i] * (state_.v_m_per_s.col(i) - anchor_v_.col(i));
  force_n_ += binding_force_n_;
  stiffness_.clear();
  damping_.clear();
  edges_.addStiffnessTriplets(state_, 1.0, stiffness_, /*clamp_compression=*/true);
  edges_.addDampingTriplets(state_, 1.0, damping_);
}

void Flesh::rightHandSide(double h) {
  // Flesh rows: h (f0 + h K_edges v0 - h k_i (v0 - w_i)), the binding's df/dx = -k_i I acting on the
  // velocity relative to the anchor. Skeleton rows: -h sum_i J_i^T (f_i - h k_i (v_i - w_i)).
  const int n3 = 3 * vertices();
  rhs_.resize(n3 + dofs_);
  const double* v0 = state_.v_m_per_s.data();
  const double* w0 = anchor_v_.data();
  for (int r = 0; r < n3; ++r) rhs_[r] = force_n_.data()[r] - h * binding_k_[r / 3] * (v0[r] - w0[r]);
  for (const auto& t : stiffness_) rhs_[t.row()] += h * t.value() * v0[t.col()];
  rhs_.head(n3) *= h;
  if (dofs_ == 0) return;
  Eigen::VectorXd binding(n3);
  for (int r = 0; r < n3; ++r) binding[r] = binding_force_n_.data()[r] - h * binding_k_[r / 3] * (v0[r] - w0[r]);
  rhs_.tail(dofs_) = -h * (anchor_jacobian_.transpose() * binding);
}

void Flesh::assembleMatrix(double h) {
  const int n3 = 3 * vertices();
  entries_.clear();
  entries_.reserve(n3 + damping_.size() + stiffness_.size());
  for (int r = 0; r < n3; ++r) {
    const int i = r / 3;
    entries_.emplace_back(r, r, mesh_.mass_kg[i] + h * binding_c_[i] + h * h * binding_k_[i]);
  }
  for (const auto& t : damping_) entries_.emplace_back(t.row(), t.col(), -h * t.value());
  for (const auto& t : stiffness_) entries_.emplace_back(t.row(), t.col(), -h * h * t.value());
  if (dofs_ > 0) {
    // -h G J and its transpose; B + h J^T G J.
    Eigen::MatrixXd body_block = euler_matrix_;
    for (int r = 0; r < n3; ++r) {
      const double hg = h * (binding_c_[r / 3] + h * binding_k_[r / 3]);
      for (int j = 0; j < dofs_; ++j) {
        const double jr = anchor_jacobian_(r, j);
        if (jr == 0) continue;
        entries_.emplace_back(r, n3 + j, -hg * jr);
        entries_.emplace_back(n3 + j, r, -hg * jr);
      }
      body_block.noalias() += hg * anchor_jacobian_.row(r).transpose() * anchor_jacobian_.row(r);
    }
    for (int a = 0; a < dofs_; ++a)
      for (int b = 0; b < dofs_; ++b)
        if (body_block(a, b) != 0) entries_.emplace_back(n3 + a, n3 + b, body_block(a, b));
  }
  a_.resize(n3 + dofs_, n3 + dofs_);
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
  state_.v_m_per_s.reshaped() += dv_.head(3 * vertices());
  state_.x_m += h * state_.v_m_per_s;
}

void Flesh::bindingReactions(double h, rigid::RigidData& skeleton) {
  // f_i(t + h) with the anchor's velocity at the step's end, w_i + J_i du (du = 0 when explicit), and
  // its position p_i + h (w_i + J_i du); its reaction acts at the anchor's present point.
  Eigen::Matrix3Xd anchor_v1 = anchor_v_;
  if (dofs_ > 0) anchor_v1.reshaped() += anchor_jacobian_ * dv_.tail(dofs_);
  for (int i = 0; i < vertices(); ++i)
    binding_force_n_.col(i) = -binding_k_[i] * (state_.x_m.col(i) - anchor_m_.col(i) - h * anchor_v1.col(i)) -
                              binding_c_[i] * (state_.v_m_per_s.col(i) - anchor_v1.col(i));
  summary_.binding_impulse_on_flesh_ns = h * binding_force_n_.rowwise().sum();
  applyReactions(mesh_, binding_force_n_, anchor_m_, skeleton);
}

void Flesh::beginStep(rigid::RigidData& skeleton, double h_s, const std::vector<int>& held_dofs) {
  startStep(skeleton, h_s, true);
  for (int d : held_dofs) {
    if (d < 0 || d >= dofs_) throw std::invalid_argument("flesh: held DOF " + std::to_string(d) + " is not the skeleton's");
    anchor_jacobian_.col(d).setZero();
    for (Eigen::MatrixXd& j : body_jacobian_)
      if (j.size() > 0) j.col(d).setZero();
    euler_matrix_.row(d).setZero();
    euler_matrix_.col(d).setZero();
    euler_matrix_(d, d) = 1.0;
  }
  forcesAtStart();
  rightHandSide(h_s);
  assembleMatrix(h_s);
  diagonal_ = a_.diagonal();
  ldlt_.compute(a_);
  if (ldlt_.info() != Eigen::Success) throw std::invalid_argument("flesh: the step's matrix could not be factorised");
}

void Flesh::solveStep(const Eigen::VectorXd& b, Eigen::VectorXd& y) const {
  if (b.size() != a_.rows()) throw std::invalid_argument("flesh: solveStep with a right-hand side of the wrong size");
  y = ldlt_.solve(b);
}

void Flesh::endStep(rigid::RigidData& skeleton, double h_s, const Eigen::VectorXd& y) {
  if (y.size() != a_.rows()) throw std::invalid_argument("flesh: endStep with a solution of the wrong size");
  dv_ = y;
  summary_.cg_iterations = 0;
  summary_.cg_relative_residual = 0;
  summary_.cg_converged = y.allFinite();
  integrate(h_s);
  bindingReactions(h_s, skeleton);
  external_n_.setZero();
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
