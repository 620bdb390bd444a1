#include "coupling3d/flesh_fluid_coupling3.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "coupling3d/forcing_cg3.hpp"
#include "flesh/binding.hpp"

namespace creaturelab::coupling3d {
// Named, not anonymous: the unity build joins this file with rigid_fluid_coupling3.cpp's.
namespace flesh_forcing {

const fluid3d::FluidParams3& checked(const RigidFluidParams3& p, const fluid3d::FluidParams3& f) {
  if (auto e = p.validate(f); !e.empty()) throw std::invalid_argument("coupling3d: " + e);
  if (p.forcing != Forcing3::projected && p.forcing != Forcing3::off)
    throw std::invalid_argument("coupling3d: the flesh couples to the fluid by projected forcing (or off) only");
  if (p.viscosity_in_forcing)
    throw std::invalid_argument("coupling3d: viscosity_in_forcing is not available with flesh");
  return f;
}

// The flesh with its longest edge at most the markers' spacing (m): its vertices are the markers.
flesh::FleshParams fitted(flesh::FleshParams f, double spacing_m) {
  if (f.max_edge_m == 0 || f.max_edge_m > spacing_m) f.max_edge_m = spacing_m;
  return f;
}

}  // namespace flesh_forcing

FleshFluidCoupling3::FleshFluidCoupling3(const rigid::RigidData& data, const fluid3d::FluidParams3& f,
                                         const RigidFluidParams3& p, const flesh::FleshParams& fp)
    : p_(p),
      fluid_(flesh_forcing::checked(p, f)),
      flesh_(data.model(), flesh_forcing::fitted(fp, p.marker_spacing_cells * fluid_.grid().dx_m)),
      skeleton_(data.model()) {
  const fluid3d::MacGrid3& g = fluid_.grid();
  if (p_.interior_markers)
    interior_ = interiorMarkers(data.model(), g.dx_m, 0.5 * ib::kernelSupportCells(p_.kernel) * g.dx_m);
  sync(data);
  flesh_.placeOnSkeleton(skeleton_);
  const std::size_t n = std::size_t(flesh_.vertices()) + interior_.size();
  force_.assign(n, Vec3{});
  body_force_n_.assign(data.model().bodies(), Vec3{});
  reaction_.assign(data.model().dofs(), 0.0);
  for (int a = 0; a < 3; ++a) {
    const std::array<int, 3> e = g.faceExtents(a);
    spread_[a] = fluid3d::Array3(e[0], e[1], e[2]);
  }
  try {
    place(0.0, false);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("coupling3d: the flesh is outside the fluid box or within the kernel's "
                                            "reach of a wall (fluid = world − origin_m): ") + e.what());
  }
}

void FleshFluidCoupling3::sync(const rigid::RigidData& data) {
  skeleton_.restore(data.save());
  skeleton_.kinematics();
}

// Markers: the flesh's vertices, then the bones' interior markers, in the fluid's frame; with `step`,
// their velocities (the flesh's; the bodies' at the point) and the coupled stability limit.
void FleshFluidCoupling3::place(double dt, bool step) {
  const int nv = flesh_.vertices();
  const std::size_t n = std::size_t(nv) + interior_.size();
  const Eigen::Matrix3Xd& x = flesh_.positions_m();
  const Eigen::Matrix3Xd& v = flesh_.velocities_m_per_s();
  const double dx = fluid_.grid().dx_m;
  std::vector<Vec3> now(n);
  velocity_.resize(n);
  for (int i = 0; i < nv; ++i)
    for (int a = 0; a < 3; ++a) {
      now[i][a] = x(a, i) - p_.origin_m[a];
      velocity_[i][a] = v(a, i);
    }
  for (std::size_t k = 0; k < interior_.size(); ++k) {
    const Vec3 w = markerWorld(skeleton_, interior_[k]);
    const Vec3 u = skeleton_.pointVelocity(interior_[k].body, w);
    for (int a = 0; a < 3; ++a) {
      now[nv + k][a] = w[a] - p_.origin_m[a];
      velocity_[nv + k][a] = u[a];
    }
  }
  cells_per_step_ = 0.0;
  if (step && position_.size() == n)
    for (std::size_t k = 0; k < n; ++k)
      cells_per_step_ = std::max(cells_per_step_, std::hypot(now[k][0] - position_[k][0], now[k][1] - position_[k][1],
                                                             now[k][2] - position_[k][2]) / dx);
  if (step && !(cells_per_step_ <= p_.max_marker_cells_per_step))
    throw CouplingError3("coupling3d: time step beyond the coupled stability limit: a flesh marker moved " +
                         std::to_string(cells_per_step_) + " cells in one step of " + std::to_string(dt) +
                         " s (limit max_marker_cells_per_step = " + std::to_string(p_.max_marker_cells_per_step) +
                         "); take a smaller step");
  transfer_.locate(fluid_.grid(), p_.kernel, now);
  position_ = std::move(now);
  // Direct-forcing masses: ρ dA dx at a vertex (its share of the deformed surface), ρ dV inside.
  flesh_.vertexAreas(area_m2_);
  const double rho = fluid_.params().density_kg_per_m3;
  mass_.resize(n);
  for (int i = 0; i < nv; ++i) mass_[i] = rho * area_m2_[i] * dx;
  for (std::size_t k = 0; k < interior_.size(); ++k) mass_[nv + k] = rho * interior_[k].volume_m3;
}

void FleshFluidCoupling3::advanceFluid(double dt) {
  if (!(dt > 0 && std::isfinite(dt))) throw std::invalid_argument("coupling3d: the time step must be positive");
  const fluid3d::FluidStages3& stages = fluid_.stages();
  if (stages.external_forces) fluid_.applyExternalForces(dt);
  if (stages.advection) fluid_.advectVelocity(dt);
  if (stages.viscosity) fluid_.applyViscosity(dt);
  // The flesh's step with the fluid's last reaction, against the skeleton as forceFluid left it; the
  // binding's reactions on the bones are what the scratch skeleton's applied forces collect.
  Eigen::Matrix3Xd& load = flesh_.externalForces_n();
  for (int i = 0; i < flesh_.vertices(); ++i)
    for (int a = 0; a < 3; ++a) load(a, i) = -force_[i][a];
  const int dofs = skeleton_.model().dofs();
  std::fill(skeleton_.appliedForces(), skeleton_.appliedForces() + dofs, 0.0);
  flesh_.step(skeleton_, dt);
  if (!flesh_.lastStep().cg_converged)
    throw CouplingError3("coupling3d: the flesh's linear solve did not converge (relative residual " +
                         std::to_string(flesh_.lastStep().cg_relative_residual) + ")");
  reaction_.assign(skeleton_.appliedForces(), skeleton_.appliedForces() + dofs);
  // The interior markers' reaction, on their bodies at their points of the last forcing.
  const int nv = flesh_.vertices();
  std::fill(skeleton_.appliedForces(), skeleton_.appliedForces() + dofs, 0.0);
  for (std::size_t k = 0; k < interior_.size(); ++k) {
    const Vec3& F = force_[nv + k];
    const Vec3& x = position_[nv + k];
    skeleton_.applyForceAt(interior_[k].body, {-F[0], -F[1], -F[2]},
                           {x[0] + p_.origin_m[0], x[1] + p_.origin_m[1], x[2] + p_.origin_m[2]});
  }
  for (int d = 0; d < dofs; ++d) reaction_[d] += skeleton_.appliedForces()[d];
}

void FleshFluidCoupling3::applyReaction(rigid::RigidData& data) const {
  double* f = data.appliedForces();
  for (std::size_t d = 0; d < reaction_.size(); ++d) f[d] += reaction_[d];
}

void FleshFluidCoupling3::forceFluid(const rigid::RigidData& data, double dt) {
  if (!(dt > 0 && std::isfinite(dt))) throw std::invalid_argument("coupling3d: the time step must be positive");
  sync(data);
  try {
    place(dt, true);
  } catch (const std::invalid_argument& e) {
    throw CouplingError3(std::string("coupling3d: the flesh left the fluid box (or came within the kernel's reach of "
                                     "a wall): ") + e.what());
  }
  if (p_.forcing == Forcing3::projected) {
    projectedForcing(dt);
  } else {
    std::fill(force_.begin(), force_.end(), Vec3{});
    iterations_ = 0;
    residual_m_per_s_ = 0.0;
    if (fluid_.stages().pressure) fluid_.project(dt);
  }
  reaction();
  const double speed = fluid_.maxVelocityComponent_m_per_s();
  if (!(speed <= fluid_.params().blowup_speed_m_per_s))
    throw fluid3d::FluidBlowUpError3("coupling3d: the fluid blew up in the forcing stage at t = " +
                                     std::to_string(fluid_.time_s()) + " s: max velocity component " +
                                     std::to_string(speed) + " m/s");
}

// RigidFluidCoupling3::projectedForcing's solve (its comment derives it) on the flesh's markers:
// A F = I P S F dt/ρ + ε D F = V − I P u~ by preconditioned CG, warm-started from the last forces.
void FleshFluidCoupling3::projectedForcing(double dt) {
  fluid3d::MacGrid3& g = fluid_.grid();
  const double to_velocity = dt / fluid_.params().density_kg_per_m3;
  const double eps = p_.forcing_regularisation;
  const std::size_t n = position_.size();
  const bool pressure = fluid_.stages().pressure;
  forcing::zero(spread_);
  transfer_.spread(force_, spread_);
  forcing::addScaled(g.velocity_m_per_s, to_velocity, spread_);
  if (pressure) fluid_.project(dt);
  const fluid3d::Array3 pressure_pa = g.pressure_pa;
  residual_.resize(n);
  transfer_.interpolate(g.velocity_m_per_s, residual_);
  const double scale = std::max(forcing::maxAbs(velocity_), fluid_.maxVelocityComponent_m_per_s());
  for (std::size_t k = 0; k < n; ++k)
    for (int a = 0; a < 3; ++a)
      residual_[k][a] = velocity_[k][a] - residual_[k][a] - eps * dt / mass_[k] * force_[k][a];
  const double tol = p_.forcing_tolerance * (scale > 0 ? scale : 1.0);
  auto apply = [&](const std::vector<Vec3>& d, std::vector<Vec3>& out) {
    forcing::zero(spread_);
    transfer_.spread(d, spread_);
    for (int a = 0; a < 3; ++a) {
      double* q = spread_[a].data();
      for (std::size_t t = 0; t < spread_[a].size(); ++t) q[t] *= to_velocity;
    }
    if (pressure) {
      std::swap(g.velocity_m_per_s, spread_);
      g.pressure_pa.fill(0.0);
      fluid_.project(dt);
      std::swap(g.velocity_m_per_s, spread_);
    }
    transfer_.interpolate(spread_, out);
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) out[k][a] += eps * dt / mass_[k] * d[k][a];
  };
  auto advance = [&](double alpha) { forcing::addScaled(g.velocity_m_per_s, alpha, spread_); };
  auto precondition = [&](const std::vector<Vec3>& r, std::vector<Vec3>& z) {
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) z[k][a] = mass_[k] / dt * r[k][a];
  };
  iterations_ = forcing::conjugateGradients(force_, residual_, work_, tol, p_.max_forcing_iterations, apply, advance,
                                            precondition);
  residual_m_per_s_ = forcing::maxAbs(residual_);
  g.pressure_pa = pressure_pa;
}

// The fluid's force on each body: −F of its vertices' and its interior markers'.
void FleshFluidCoupling3::reaction() {
  std::fill(body_force_n_.begin(), body_force_n_.end(), Vec3{});
  const int nv = flesh_.vertices();
  for (std::size_t k = 0; k < force_.size(); ++k) {
    const int b = int(k) < nv ? flesh_.mesh().body[k] : interior_[k - nv].body;
    for (int a = 0; a < 3; ++a) body_force_n_[b][a] -= force_[k][a];
  }
}

void FleshFluidCoupling3::placeMarkers(const rigid::RigidData& data) {
  // Each vertex turned and moved with its body from the last pose (skeleton_) to data's.
  Eigen::Matrix3Xd anchor0, anchor_v0, anchor1, anchor_v1;
  flesh::anchorStates(flesh_.mesh(), skeleton_, anchor0, anchor_v0);
  std::vector<Eigen::Matrix3d> turn(data.model().bodies());
  for (int b = 0; b < data.model().bodies(); ++b) {
    using RowMajor3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
    turn[b] = Eigen::Map<const RowMajor3>(data.bodyRotation(b)) * Eigen::Map<const RowMajor3>(skeleton_.bodyRotation(b)).transpose();
  }
  sync(data);
  flesh::anchorStates(flesh_.mesh(), skeleton_, anchor1, anchor_v1);
  Eigen::Matrix3Xd x = flesh_.positions_m(), v = flesh_.velocities_m_per_s();
  for (int i = 0; i < flesh_.vertices(); ++i) {
    const Eigen::Matrix3d& r = turn[flesh_.mesh().body[i]];
    x.col(i) = anchor1.col(i) + r * (x.col(i) - anchor0.col(i));
    v.col(i) = anchor_v1.col(i) + r * (v.col(i) - anchor_v0.col(i));
  }
  flesh_.setState(x, v);
  try {
    place(0.0, false);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("coupling3d: the flesh is outside the fluid box or within the kernel's "
                                            "reach of a wall: ") + e.what());
  }
}

void FleshFluidCoupling3::save(FleshFluidState3& s) const {
  s.grid = fluid_.grid();
  s.flesh_x_m = flesh_.positions_m();
  s.flesh_v_m_per_s = flesh_.velocities_m_per_s();
  s.force_n = force_;
  s.body_force_n = body_force_n_;
  s.reaction = reaction_;
}

void FleshFluidCoupling3::restore(const FleshFluidState3& s, const rigid::RigidData& data) {
  fluid_.grid() = s.grid;
  flesh_.setState(s.flesh_x_m, s.flesh_v_m_per_s);
  force_ = s.force_n;
  body_force_n_ = s.body_force_n;
  reaction_ = s.reaction;
  sync(data);
  place(0.0, false);
}

}  // namespace creaturelab::coupling3d
