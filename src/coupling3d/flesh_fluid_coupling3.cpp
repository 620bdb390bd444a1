#include "coupling3d/flesh_fluid_coupling3.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "coupling3d/forcing_cg3.hpp"
#include "coupling3d/mouth_markers3.hpp"
#include "flesh/binding.hpp"

namespace creaturelab::coupling3d {
// Named, not anonymous: the unity build joins this file with rigid_fluid_coupling3.cpp's.
namespace flesh_forcing {

const fluid3d::FluidParams3& checked(const RigidFluidParams3& p, const fluid3d::FluidParams3& f) {
  if (auto e = p.validate(f); !e.empty()) throw std::invalid_argument("coupling3d: " + e);
  if (p.viscosity_in_forcing)
    throw std::invalid_argument("coupling3d: viscosity_in_forcing is not available with flesh");
  return f;
}

// The flesh with its longest edge at most the markers' spacing (m): its vertices are the markers.
flesh::FleshParams fitted(flesh::FleshParams f, double spacing_m) {
  if (f.max_edge_m == 0 || f.max_edge_m > spacing_m) f.max_edge_m = spacing_m;
  return f;
}

const flesh::FleshParams& implicitFlesh(const RigidFluidParams3& p, const flesh::FleshParams& f) {
  if (p.forcing == Forcing3::coupled && !f.implicit_skeleton)
    throw std::invalid_argument("coupling3d: the coupled forcing with flesh needs the flesh's implicit_skeleton");
  return f;
}

// MuJoCo's qvel indices of the named joints.
std::vector<int> jointDofs(const rigid::RigidModel& model, const std::vector<std::string>& joints) {
  std::vector<int> dofs;
  for (const std::string& name : joints) {
    const int j = model.findJoint(name);
    if (j < 0) throw std::invalid_argument("coupling3d: held_joints: the model " + model.path() + " has no joint '" + name + "'");
    const rigid::JointInfo info = model.joint(j);
    const int n = info.type == rigid::JointType::free ? 6 : info.type == rigid::JointType::ball ? 3 : 1;
    for (int d = 0; d < n; ++d) dofs.push_back(info.dof + d);
  }
  return dofs;
}

}  // namespace flesh_forcing

FleshFluidCoupling3::FleshFluidCoupling3(const rigid::RigidData& data, const fluid3d::FluidParams3& f,
                                         const RigidFluidParams3& p, const flesh::FleshParams& fp)
    : p_(p),
      fluid_(flesh_forcing::checked(p, f)),
      flesh_(data.model(), flesh_forcing::fitted(flesh_forcing::implicitFlesh(p, fp), p.marker_spacing_cells * fluid_.grid().dx_m)),
      skeleton_(data.model()),
      held_dofs_(flesh_forcing::jointDofs(data.model(), p.held_joints)),
      mover_(data.model(), {}) {
  const fluid3d::MacGrid3& g = fluid_.grid();
  if (p_.interior_markers)
    interior_ = interiorMarkers(data.model(), g.dx_m, 0.5 * ib::kernelSupportCells(p_.kernel) * g.dx_m);
  mouth_of_.assign(interior_.size(), -1);
  for (std::size_t m = 0; m < p_.mouths.size(); ++m) {
    const std::vector<SurfaceMarker3> disc = mouthMarkers(data.model(), p_.mouths[m], p_.marker_spacing_cells * g.dx_m);
    interior_.insert(interior_.end(), disc.begin(), disc.end());
    mouth_of_.resize(interior_.size(), int(m));
  }
  mouth_flux_m_per_s_.assign(p_.mouths.size(), 0.0);
  sync(data);
  flesh_.placeOnSkeleton(skeleton_);
  const std::size_t n = std::size_t(flesh_.vertices()) + interior_.size();
  force_.assign(n, Vec3{});
  body_force_n_.assign(data.model().bodies(), Vec3{});
  bone_force_n_.assign(data.model().bodies(), Vec3{});
  reaction_.assign(data.model().dofs(), 0.0);
  if (p_.forcing == Forcing3::coupled) {
    std::vector<bool> fleshed(std::size_t(data.model().bodies()), false);
    for (int b : flesh_.mesh().body) fleshed[std::size_t(b)] = true;
    for (const SurfaceMarker3& m : interior_)
      if (m.body != 0 && !fleshed[std::size_t(m.body)])
        throw std::invalid_argument("coupling3d: body " + std::to_string(m.body) + " has interior markers but no flesh");
  }
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

// The interior (and mouth) markers after the nv vertices: positions in the fluid's frame and velocities, their
// bodies' at the point (plus a mouth's flux) as `bodies` has them.
void FleshFluidCoupling3::placeInterior(const rigid::RigidData& bodies, int nv, std::vector<Vec3>& now) {
  for (std::size_t k = 0; k < interior_.size(); ++k) {
    const Vec3 w = markerWorld(bodies, interior_[k]);
    Vec3 u = bodies.pointVelocity(interior_[k].body, w);
    if (mouth_of_[k] >= 0)
      addMouthFlux(bodies, p_.mouths[std::size_t(mouth_of_[k])], mouth_flux_m_per_s_[std::size_t(mouth_of_[k])], u);
    for (int a = 0; a < 3; ++a) {
      now[std::size_t(nv) + k][a] = w[a] - p_.origin_m[a];
      velocity_[std::size_t(nv) + k][a] = u[a];
    }
  }
}

// cells_per_step_: the farthest any marker moved from its last position to `now` in a coupled step of dt,
// in cells (0 before the first placement); CouplingError3 beyond max_marker_cells_per_step.
void FleshFluidCoupling3::checkMoved(const std::vector<Vec3>& now, double dt) {
  const double dx = fluid_.grid().dx_m;
  cells_per_step_ = 0.0;
  if (position_.size() == now.size())
    for (std::size_t k = 0; k < now.size(); ++k)
      cells_per_step_ = std::max(cells_per_step_, std::hypot(now[k][0] - position_[k][0], now[k][1] - position_[k][1],
                                                             now[k][2] - position_[k][2]) / dx);
  if (!(cells_per_step_ <= p_.max_marker_cells_per_step))
    throw CouplingError3("coupling3d: time step beyond the coupled stability limit: a flesh marker moved " +
                         std::to_string(cells_per_step_) + " cells in one step of " + std::to_string(dt) +
                         " s (limit max_marker_cells_per_step = " + std::to_string(p_.max_marker_cells_per_step) +
                         "); take a smaller step");
}

// Markers: the flesh's vertices, then the bones' interior markers, in the fluid's frame; with `step`,
// their velocities (the flesh's; the bodies' at the point) and the coupled stability limit.
void FleshFluidCoupling3::place(double dt, bool step) {
  const int nv = flesh_.vertices();
  const std::size_t n = std::size_t(nv) + interior_.size();
  const Eigen::Matrix3Xd& x = flesh_.positions_m();
  const Eigen::Matrix3Xd& v = flesh_.velocities_m_per_s();
  std::vector<Vec3> now(n);
  velocity_.resize(n);
  for (int i = 0; i < nv; ++i)
    for (int a = 0; a < 3; ++a) {
      now[i][a] = x(a, i) - p_.origin_m[a];
      velocity_[i][a] = v(a, i);
    }
  placeInterior(skeleton_, nv, now);
  cells_per_step_ = 0.0;
  if (step) checkMoved(now, dt);
  transfer_.locate(fluid_.grid(), p_.kernel, now);
  position_ = std::move(now);
  // Direct-forcing masses: ρ dA dx at a vertex (its share of the deformed surface), ρ dV inside.
  flesh_.vertexAreas(area_m2_);
  const double rho = fluid_.params().density_kg_per_m3;
  const double dx = fluid_.grid().dx_m;
  mass_.resize(n);
  for (int i = 0; i < nv; ++i) mass_[i] = rho * area_m2_[i] * dx;
  for (std::size_t k = 0; k < interior_.size(); ++k)
    mass_[nv + k] = rho * (interior_[k].area_m2 * dx + interior_[k].volume_m3);  // a mouth's: ρ dA dx
}

void FleshFluidCoupling3::advanceFluid(double dt) {
  if (!(dt > 0 && std::isfinite(dt))) throw std::invalid_argument("coupling3d: the time step must be positive");
  const fluid3d::FluidStages3& stages = fluid_.stages();
  if (stages.external_forces) fluid_.applyExternalForces(dt);
  if (stages.advection) fluid_.advectVelocity(dt);
  if (stages.viscosity) fluid_.applyViscosity(dt);
  if (p_.forcing == Forcing3::coupled) return;  // the flesh steps in forceFluid, with the forces
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
  boneForces();
}

void FleshFluidCoupling3::applyReaction(rigid::RigidData& data) const {
  if (p_.forcing != Forcing3::coupled) applyFluidForce(data);
}

void FleshFluidCoupling3::applyFluidForce(rigid::RigidData& data) const {
  double* f = data.appliedForces();
  for (std::size_t d = 0; d < reaction_.size(); ++d) f[d] += reaction_[d];
}

void FleshFluidCoupling3::forceFluid(const rigid::RigidData& data, double dt) {
  if (p_.forcing == Forcing3::coupled)
    throw std::logic_error("coupling3d: the coupled forcing changes the bodies' velocities: pass them as non-const");
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

void FleshFluidCoupling3::forceFluid(rigid::RigidData& data, double dt) {
  if (p_.forcing != Forcing3::coupled) {
    forceFluid(static_cast<const rigid::RigidData&>(data), dt);
    return;
  }
  if (!(dt > 0 && std::isfinite(dt))) throw std::invalid_argument("coupling3d: the time step must be positive");
  coupledStep(data, dt);
  const double speed = fluid_.maxVelocityComponent_m_per_s();
  if (!(speed <= fluid_.params().blowup_speed_m_per_s))
    throw fluid3d::FluidBlowUpError3("coupling3d: the fluid blew up in the forcing stage at t = " +
                                     std::to_string(fluid_.time_s()) + " s: max velocity component " +
                                     std::to_string(speed) + " m/s");
}

void FleshFluidCoupling3::setMouthFlux(std::size_t mouth, double flux_m_per_s) {
  if (mouth >= mouth_flux_m_per_s_.size())
    throw std::invalid_argument("coupling3d: mouth " + std::to_string(mouth) + " of " +
                                std::to_string(mouth_flux_m_per_s_.size()));
  if (!std::isfinite(flux_m_per_s)) throw std::invalid_argument("coupling3d: a mouth's flux must be finite");
  mouth_flux_m_per_s_[mouth] = flux_m_per_s;
}

void FleshFluidCoupling3::setHeldDofs(const std::vector<int>& dofs) {
  for (int d : dofs)
    if (d < 0 || d >= skeleton_.model().dofs())
      throw std::invalid_argument("coupling3d: held DOF " + std::to_string(d) + " is not in the model " +
                                  skeleton_.model().path());
  held_dofs_ = dofs;
}

// The coupled step (header): the flesh's backward Euler system K y = b0 against the skeleton at the step's
// start (skeleton_), the markers where the step without the fluid's force takes them, the forces solved with
// the flesh's and bones' answer h G K⁻¹ Gᵀ, then the flesh's step and the bones' velocity change with them.
void FleshFluidCoupling3::coupledStep(rigid::RigidData& data, double dt) {
  flesh_.externalForces_n().setZero();
  flesh_.beginStep(skeleton_, dt, held_dofs_);
  try {
    placeCoupled(data, dt);
  } catch (const std::invalid_argument& e) {
    throw CouplingError3(std::string("coupling3d: the flesh left the fluid box (or came within the kernel's reach of "
                                     "a wall): ") + e.what());
  }
  projectedForcing(dt);
  // y = K⁻¹ (b0 − h Gᵀ F): the flesh and the bones take exactly −dt Σ F (momentum to K's round-off).
  toSystem(force_, system_b_);
  system_b_ = flesh_.stepRightHandSide() - dt * system_b_;
  flesh_.solveStep(system_b_, system_y_);
  const int dofs = skeleton_.model().dofs();
  std::fill(skeleton_.appliedForces(), skeleton_.appliedForces() + dofs, 0.0);
  flesh_.endStep(skeleton_, dt, system_y_);
  if (!flesh_.lastStep().cg_converged) throw CouplingError3("coupling3d: the flesh's step gave a non-finite state");
  // The generalised forces on the bones (binding at the step's end, interior markers' −F), for applyFluidForce.
  const int nv = flesh_.vertices();
  for (std::size_t k = 0; k < interior_.size(); ++k) {
    if (interior_[k].body == 0) continue;
    const Vec3& F = force_[nv + k];
    const Vec3 x = markerWorld(skeleton_, interior_[k]);
    skeleton_.applyForceAt(interior_[k].body, {-F[0], -F[1], -F[2]}, x);
  }
  reaction_.assign(skeleton_.appliedForces(), skeleton_.appliedForces() + dofs);
  boneForces();
  const std::vector<double> du(system_y_.data() + 3 * nv, system_y_.data() + 3 * nv + dofs);
  mover_.apply(data, du, dt);
  reaction();
  const double cells = cells_per_step_;
  sync(data);
  place(dt, false);
  cells_per_step_ = cells;
}

// Markers and their velocities for the coupled solve: vertex i at x_i + h (v_i + dv0_i) moving at v_i + dv0_i
// (the flesh's step without the fluid's force, y0 = K⁻¹ b0), the interior markers at data's pose moving with
// data's velocity plus the bones' du0; their arms from their bodies' centres of mass at the step's start.
void FleshFluidCoupling3::placeCoupled(const rigid::RigidData& data, double dt) {
  flesh_.solveStep(flesh_.stepRightHandSide(), system_y_);
  const int nv = flesh_.vertices();
  const std::size_t n = std::size_t(nv) + interior_.size();
  const Eigen::Matrix3Xd& x = flesh_.positions_m();
  const Eigen::Matrix3Xd& v = flesh_.velocities_m_per_s();
  arm_.resize(n);
  for (std::size_t k = 0; k < interior_.size(); ++k) {
    const int b = interior_[k].body;
    const Vec3 w = markerWorld(skeleton_, interior_[k]);
    const double* c = skeleton_.bodyComPosition(b);
    arm_[nv + k] = {w[0] - c[0], w[1] - c[1], w[2] - c[2]};
  }
  std::vector<Vec3> base;
  fromSystem(system_y_, base);  // dv0 at the vertices, the bones' du0 at the interior markers
  std::vector<Vec3> now(n);
  velocity_.resize(n);
  for (int i = 0; i < nv; ++i)
    for (int a = 0; a < 3; ++a) {
      velocity_[i][a] = v(a, i) + base[i][a];
      now[i][a] = x(a, i) + dt * velocity_[i][a] - p_.origin_m[a];
    }
  placeInterior(data, nv, now);
  for (std::size_t k = std::size_t(nv); k < n; ++k)
    for (int a = 0; a < 3; ++a) velocity_[k][a] += base[k][a];
  checkMoved(now, dt);
  transfer_.locate(fluid_.grid(), p_.kernel, now);
  position_ = std::move(now);
  // The preconditioner's weights: 1 / (dt/(ρ dV) + h / K_ii), K_ii the vertex's diagonal in the flesh's system
  // (the bones, much heavier than a marker's fluid, add nothing).
  const Eigen::VectorXd& diag = flesh_.stepDiagonal();
  weight_.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    for (int a = 0; a < 3; ++a)
      weight_[k][a] = 1.0 / (dt / mass_[k] + (int(k) < nv ? dt / diag[3 * int(k) + a] : 0.0));
}

// b = Gᵀ f: the vertices' forces on their rows, the interior markers' as generalised forces J_bᵀ (f, r × f).
void FleshFluidCoupling3::toSystem(const std::vector<Vec3>& f, Eigen::VectorXd& b) const {
  const int nv = flesh_.vertices();
  const int dofs = skeleton_.model().dofs();
  b.setZero(3 * nv + dofs);
  for (int i = 0; i < nv; ++i)
    for (int a = 0; a < 3; ++a) b[3 * i + a] = f[std::size_t(i)][a];
  std::vector<Eigen::Matrix<double, 6, 1>> wrench(std::size_t(skeleton_.model().bodies()), Eigen::Matrix<double, 6, 1>::Zero());
  for (std::size_t k = 0; k < interior_.size(); ++k) {
    const int body = interior_[k].body;
    if (body == 0) continue;
    const Vec3& F = f[nv + k];
    const Vec3& r = arm_[nv + k];
    Eigen::Matrix<double, 6, 1>& w = wrench[std::size_t(body)];
    for (int a = 0; a < 3; ++a) w[a] += F[a];
    w[3] += r[1] * F[2] - r[2] * F[1];
    w[4] += r[2] * F[0] - r[0] * F[2];
    w[5] += r[0] * F[1] - r[1] * F[0];
  }
  for (std::size_t body = 1; body < wrench.size(); ++body) {
    const Eigen::MatrixXd& J = flesh_.bodyJacobian(int(body));
    if (J.size() == 0) continue;
    b.tail(dofs).noalias() += J.transpose() * wrench[body];
  }
}

// v = G y: the vertices' rows; at an interior marker its body's velocity J_b du at the marker's arm.
void FleshFluidCoupling3::fromSystem(const Eigen::VectorXd& y, std::vector<Vec3>& v) const {
  const int nv = flesh_.vertices();
  const int dofs = skeleton_.model().dofs();
  v.resize(std::size_t(nv) + interior_.size());
  for (int i = 0; i < nv; ++i)
    for (int a = 0; a < 3; ++a) v[std::size_t(i)][a] = y[3 * i + a];
  std::vector<Eigen::Matrix<double, 6, 1>> twist(std::size_t(skeleton_.model().bodies()), Eigen::Matrix<double, 6, 1>::Zero());
  for (std::size_t body = 1; body < twist.size(); ++body) {
    const Eigen::MatrixXd& J = flesh_.bodyJacobian(int(body));
    if (J.size() > 0) twist[body].noalias() = J * y.tail(dofs);
  }
  for (std::size_t k = 0; k < interior_.size(); ++k) {
    const int body = interior_[k].body;
    const Eigen::Matrix<double, 6, 1>& t = twist[std::size_t(body)];
    const Vec3& r = arm_[nv + k];
    v[nv + k] = {t[0] + t[4] * r[2] - t[5] * r[1], t[1] + t[5] * r[0] - t[3] * r[2], t[2] + t[3] * r[1] - t[4] * r[0]};
  }
}

// out = h G K⁻¹ Gᵀ f: the markers' velocity change, through the flesh's step and the bones, that the forces
// −f on them cause within the step (the sign taken by the caller). Symmetric positive semi-definite.
void FleshFluidCoupling3::solidResponse(const std::vector<Vec3>& f, std::vector<Vec3>& out, double dt) {
  toSystem(f, system_b_);
  flesh_.solveStep(system_b_, system_y_);
  system_y_ *= dt;
  fromSystem(system_y_, out);
}

// RigidFluidCoupling3::projectedForcing's solve (its comment derives it) on the flesh's markers:
// A F = I P S F dt/ρ + ε D F = V − I P u~ by preconditioned CG, warm-started from the last forces; with
// Forcing3::coupled A adds the flesh's and bones' answer h G K⁻¹ Gᵀ (solidResponse) and the preconditioner
// the flesh's diagonal.
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
  const bool coupled = p_.forcing == Forcing3::coupled;
  if (coupled) {
    solidResponse(force_, solid_, dt);
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) residual_[k][a] -= solid_[k][a];
  }
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
    if (coupled) {
      solidResponse(d, solid_, dt);
      for (std::size_t k = 0; k < n; ++k)
        for (int a = 0; a < 3; ++a) out[k][a] += solid_[k][a];
    }
  };
  auto advance = [&](double alpha) { forcing::addScaled(g.velocity_m_per_s, alpha, spread_); };
  auto precondition = [&](const std::vector<Vec3>& r, std::vector<Vec3>& z) {
    if (coupled) {
      for (std::size_t k = 0; k < n; ++k)
        for (int a = 0; a < 3; ++a) z[k][a] = weight_[k][a] * r[k][a];
      return;
    }
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

// The force on each bone: −f_i(t + h) of its vertices' binding springs, −F of its interior and mouth markers.
void FleshFluidCoupling3::boneForces() {
  std::fill(bone_force_n_.begin(), bone_force_n_.end(), Vec3{});
  const int nv = flesh_.vertices();
  const Eigen::Matrix3Xd& binding = flesh_.bindingForces_n();
  if (binding.cols() == nv)
    for (int i = 0; i < nv; ++i)
      for (int a = 0; a < 3; ++a) bone_force_n_[flesh_.mesh().body[i]][a] -= binding(a, i);
  for (std::size_t k = 0; k < interior_.size(); ++k)
    for (int a = 0; a < 3; ++a) bone_force_n_[interior_[k].body][a] -= force_[nv + k][a];
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
  s.bone_force_n = bone_force_n_;
  s.reaction = reaction_;
  s.mouth_flux_m_per_s = mouth_flux_m_per_s_;
}

void FleshFluidCoupling3::restore(const FleshFluidState3& s, const rigid::RigidData& data) {
  fluid_.grid() = s.grid;
  flesh_.setState(s.flesh_x_m, s.flesh_v_m_per_s);
  force_ = s.force_n;
  body_force_n_ = s.body_force_n;
  bone_force_n_ = s.bone_force_n;
  reaction_ = s.reaction;
  if (s.mouth_flux_m_per_s.size() == mouth_flux_m_per_s_.size()) mouth_flux_m_per_s_ = s.mouth_flux_m_per_s;
  sync(data);
  place(0.0, false);
}

}  // namespace creaturelab::coupling3d
