#include "coupling3d/rigid_fluid_coupling3.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "coupling3d/forcing_cg3.hpp"
#include "coupling3d/mouth_markers3.hpp"

namespace creaturelab::coupling3d {

using forcing::addScaled;
using forcing::maxAbs;
using forcing::zero;

std::string RigidFluidParams3::validate(const fluid3d::FluidParams3& fluid) const {
  if (auto e = fluid.validate(); !e.empty()) return e;
  if (!(marker_spacing_cells > 0 && marker_spacing_cells <= 1.0))
    return "marker_spacing_cells must be in (0, 1]: markers farther apart than a cell leave gaps the kernel does "
           "not close and the fluid leaks through the body (got " + std::to_string(marker_spacing_cells) + ")";
  if (!(marker_retraction_cells >= 0 && marker_retraction_cells < 2.0))
    return "marker_retraction_cells must be in [0, 2): 2 cells inside, the kernel no longer reaches the surface (got " +
           std::to_string(marker_retraction_cells) + ")";
  if (!(forcing_tolerance > 0 && forcing_tolerance < 1)) return "forcing_tolerance must be in (0, 1)";
  if (max_forcing_iterations < 1 || max_forcing_iterations > 10000) return "max_forcing_iterations must be 1..10000";
  if (!(forcing_regularisation >= 0 && forcing_regularisation < 1)) return "forcing_regularisation must be in [0, 1)";
  for (double x : origin_m)
    if (!std::isfinite(x)) return "origin_m must be a finite point";
  if (!(max_marker_cells_per_step > 0 && max_marker_cells_per_step <= 2))
    return "max_marker_cells_per_step must be in (0, 2]";
  for (const Mouth3& m : mouths) {
    if (m.geom < 0) return "a mouth needs the geom that carries it";
    if (!(m.radius_m > 0 && std::isfinite(m.radius_m))) return "a mouth's radius_m must be positive";
    const double n = std::hypot(m.normal_geom[0], m.normal_geom[1], m.normal_geom[2]);
    if (!(n > 0 && std::isfinite(n))) return "a mouth's normal_geom must be a nonzero direction";
  }
  return "";
}

namespace {

const fluid3d::FluidParams3& checked(const RigidFluidParams3& p, const fluid3d::FluidParams3& f) {
  if (auto e = p.validate(f); !e.empty()) throw std::invalid_argument("coupling3d: " + e);
  return f;
}

}  // namespace

RigidFluidCoupling3::RigidFluidCoupling3(const rigid::RigidData& data, const fluid3d::FluidParams3& f,
                                         const RigidFluidParams3& p)
    : p_(p), fluid_(checked(p, f)), mobility_(data.model(), p.held_joints) {
  const fluid3d::MacGrid3& g = fluid_.grid();
  markers_ = modelSurfaceMarkers(data.model(), p_.marker_spacing_cells * g.dx_m, p_.marker_retraction_cells * g.dx_m);
  if (p_.interior_markers) {
    // At least the kernel's half-width inside, so that no interior marker's stencil reaches past the surface.
    const double margin = 0.5 * ib::kernelSupportCells(p_.kernel) * g.dx_m;
    const std::vector<SurfaceMarker3> inside = interiorMarkers(data.model(), g.dx_m, margin);
    markers_.insert(markers_.end(), inside.begin(), inside.end());
  }
  mouth_of_.assign(markers_.size(), -1);
  for (std::size_t m = 0; m < p_.mouths.size(); ++m) {
    const std::vector<SurfaceMarker3> disc = mouthMarkers(data.model(), p_.mouths[m], p_.marker_spacing_cells * g.dx_m);
    markers_.insert(markers_.end(), disc.begin(), disc.end());
    mouth_of_.resize(markers_.size(), static_cast<int>(m));
  }
  mouth_flux_m_per_s_.assign(p_.mouths.size(), 0.0);
  mass_.resize(markers_.size());
  for (std::size_t k = 0; k < markers_.size(); ++k)
    mass_[k] = f.density_kg_per_m3 * (markers_[k].area_m2 * g.dx_m + markers_[k].volume_m3);
  placeMarkers(data);
  const int nb = data.model().bodies();
  body_force_n_.assign(nb, Vec3{});
  body_torque_n_m_.assign(nb, Vec3{});
  body_point_m_.assign(nb, Vec3{});
  force_.assign(markers_.size(), Vec3{});
  for (int a = 0; a < 3; ++a) {
    const std::array<int, 3> e = g.faceExtents(a);
    spread_[a] = fluid3d::Array3(e[0], e[1], e[2]);
  }
}

void RigidFluidCoupling3::place(const rigid::RigidData& data, std::vector<Vec3>& out) const {
  out.resize(markers_.size());
  for (std::size_t k = 0; k < markers_.size(); ++k) {
    const Vec3 w = markerWorld(data, markers_[k]);
    out[k] = {w[0] - p_.origin_m[0], w[1] - p_.origin_m[1], w[2] - p_.origin_m[2]};
  }
}

void RigidFluidCoupling3::placeMarkers(const rigid::RigidData& data) {
  place(data, previous_);
  try {
    transfer_.locate(fluid_.grid(), p_.kernel, previous_);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("coupling3d: a body is outside the fluid box or within the kernel's "
                                            "reach of a wall (fluid = world − origin_m): ") + e.what());
  }
}

void RigidFluidCoupling3::advanceFluid(double dt) {
  const fluid3d::FluidStages3& stages = fluid_.stages();
  if (stages.external_forces) fluid_.applyExternalForces(dt);
  if (stages.advection) fluid_.advectVelocity(dt);
  if (stages.viscosity && !p_.viscosity_in_forcing) fluid_.applyViscosity(dt);
}

void RigidFluidCoupling3::respond(fluid3d::FaceField3& velocity, double dt) {
  fluid3d::MacGrid3& g = fluid_.grid();
  const fluid3d::FluidStages3& stages = fluid_.stages();
  std::swap(velocity, g.velocity_m_per_s);
  const bool viscous = p_.viscosity_in_forcing && stages.viscosity;
  if (stages.pressure && viscous) fluid_.project(dt);
  if (viscous) fluid_.applyViscosity(dt);
  if (stages.pressure) fluid_.project(dt);
  std::swap(velocity, g.velocity_m_per_s);
}

void RigidFluidCoupling3::forceFluid(const rigid::RigidData& data, double dt) {
  if (p_.forcing == Forcing3::coupled)
    throw std::logic_error("coupling3d: the coupled forcing changes the bodies' velocities: pass them as non-const");
  force(data, dt);
}

void RigidFluidCoupling3::forceFluid(rigid::RigidData& data, double dt) {
  if (p_.forcing != Forcing3::coupled) {
    force(data, dt);
    return;
  }
  mobility_.update(data);
  force(data, dt);
  // The impulse −dt J_bᵀ F the solve gave each body, on its velocities and (as MuJoCo's Euler step would
  // have with it) its positions; the markers' next displacement starts from there.
  mobility_.velocityChange(body_force_n_, body_torque_n_m_, dt, dv_);
  mobility_.apply(data, dv_, dt);
  place(data, previous_);
}

void RigidFluidCoupling3::setMouthFlux(std::size_t mouth, double flux_m_per_s) {
  if (mouth >= mouth_flux_m_per_s_.size())
    throw std::invalid_argument("coupling3d: mouth " + std::to_string(mouth) + " of " +
                                std::to_string(mouth_flux_m_per_s_.size()));
  if (!std::isfinite(flux_m_per_s)) throw std::invalid_argument("coupling3d: a mouth's flux must be finite");
  mouth_flux_m_per_s_[mouth] = flux_m_per_s;
}

// The markers' velocity V (m/s): their displacement over the step, or with the coupled forcing the
// bodies' velocity at data's state (the solid's v* before the fluid's impulse); a mouth's adds its flux.
void RigidFluidCoupling3::markerVelocities(const rigid::RigidData& data, double dt) {
  const std::size_t n = markers_.size();
  velocity_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const int b = markers_[k].body;
    if (p_.forcing == Forcing3::coupled) {
      velocity_[k] = b == 0 ? Vec3{} : data.pointVelocity(b, {current_[k][0] + p_.origin_m[0], current_[k][1] + p_.origin_m[1],
                                                             current_[k][2] + p_.origin_m[2]});
    } else {
      for (int a = 0; a < 3; ++a) velocity_[k][a] = (current_[k][a] - previous_[k][a]) / dt;
    }
    const int m = mouth_of_[k];
    if (m < 0) continue;
    addMouthFlux(data, p_.mouths[static_cast<std::size_t>(m)], mouth_flux_m_per_s_[static_cast<std::size_t>(m)], velocity_[k]);
  }
}

void RigidFluidCoupling3::force(const rigid::RigidData& data, double dt) {
  if (!(dt > 0 && std::isfinite(dt))) throw std::invalid_argument("coupling3d: the time step must be positive");
  const double dx = fluid_.grid().dx_m;
  const std::size_t n = markers_.size();
  place(data, current_);
  cells_per_step_ = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double d = current_[k][a] - previous_[k][a];
      d2 += d * d;
    }
    cells_per_step_ = std::max(cells_per_step_, std::sqrt(d2) / dx);
  }
  if (!(cells_per_step_ <= p_.max_marker_cells_per_step))
    throw CouplingError3("coupling3d: time step beyond the coupled stability limit: a marker moved " +
                         std::to_string(cells_per_step_) + " cells in one step of " + std::to_string(dt) +
                         " s (limit max_marker_cells_per_step = " + std::to_string(p_.max_marker_cells_per_step) +
                         "); take a smaller step");
  try {
    transfer_.locate(fluid_.grid(), p_.kernel, current_);
  } catch (const std::invalid_argument& e) {
    throw CouplingError3(std::string("coupling3d: a body left the fluid box (or came within the kernel's reach of a "
                                     "wall): ") + e.what());
  }
  markerVelocities(data, dt);
  std::swap(previous_, current_);
  if (p_.forcing != Forcing3::off) {
    projectedForcing(dt);
  } else {
    std::fill(force_.begin(), force_.end(), Vec3{});
    iterations_ = 0;
    residual_m_per_s_ = 0.0;
    fluid3d::FaceField3& u = fluid_.grid().velocity_m_per_s;
    std::swap(u, spread_);
    respond(spread_, dt);
    std::swap(u, spread_);
  }
  reaction(data);
  const double speed = fluid_.maxVelocityComponent_m_per_s();
  if (!(speed <= fluid_.params().blowup_speed_m_per_s))
    throw fluid3d::FluidBlowUpError3("coupling3d: the fluid blew up in the forcing stage at t = " +
                                     std::to_string(fluid_.time_s()) + " s: max velocity component " +
                                     std::to_string(speed) + " m/s");
}

// With the coupled forcing, the velocity change of the markers that forces f (N) on them cause through
// the bodies within the step: out_k = J_k dt A⁻¹ Σ_b J_bᵀ (Σ f, Σ r × f) (solid_mobility3.hpp), r from the
// body's centre of mass to the marker; zero on the world body's and the held bodies' markers.
void RigidFluidCoupling3::solidResponse(const std::vector<Vec3>& f, std::vector<Vec3>& out, double dt) {
  const std::size_t nb = body_force_n_.size();
  wrench_force_.assign(nb, Vec3{});
  wrench_torque_.assign(nb, Vec3{});
  for (std::size_t k = 0; k < markers_.size(); ++k) {
    const int b = markers_[k].body;
    if (b == 0) continue;
    const Vec3 r = markerArm(k);
    Vec3& F = wrench_force_[static_cast<std::size_t>(b)];
    Vec3& T = wrench_torque_[static_cast<std::size_t>(b)];
    for (int a = 0; a < 3; ++a) F[a] += f[k][a];
    T[0] += r[1] * f[k][2] - r[2] * f[k][1];
    T[1] += r[2] * f[k][0] - r[0] * f[k][2];
    T[2] += r[0] * f[k][1] - r[1] * f[k][0];
  }
  mobility_.velocityChange(wrench_force_, wrench_torque_, dt, dv_);
  body_linear_.assign(nb, Vec3{});
  body_angular_.assign(nb, Vec3{});
  for (std::size_t b = 1; b < nb; ++b) mobility_.bodyVelocity(static_cast<int>(b), dv_, body_linear_[b], body_angular_[b]);
  out.resize(markers_.size());
  for (std::size_t k = 0; k < markers_.size(); ++k) {
    const int b = markers_[k].body;
    if (b == 0) {
      out[k] = Vec3{};
      continue;
    }
    const Vec3 r = markerArm(k);
    const Vec3& v = body_linear_[static_cast<std::size_t>(b)];
    const Vec3& w = body_angular_[static_cast<std::size_t>(b)];
    out[k] = {v[0] + w[1] * r[2] - w[2] * r[1], v[1] + w[2] * r[0] - w[0] * r[2], v[2] + w[0] * r[1] - w[1] * r[0]};
  }
}

Vec3 RigidFluidCoupling3::markerArm(std::size_t k) const {
  const Vec3& c = mobility_.bodyPoint_m(markers_[k].body);
  return {previous_[k][0] + p_.origin_m[0] - c[0], previous_[k][1] + p_.origin_m[1] - c[1],
          previous_[k][2] + p_.origin_m[2] - c[2]};
}

// The marker forces F (N) for which the projected velocity meets the markers' velocity V,
//   I P (u~ + dt/ρ S F) = V,
// by conjugate gradients on A F = I P S F dt/ρ + ε D F = V − I P u~ (A symmetric positive
// definite for ε > 0: S = Iᵀ/dx³ and P an orthogonal projection), with D = dt/(ρ dV) per marker
// (the direct-forcing mobility, dV = dA dx on the surface) and the preconditioner D⁻¹. The regularisation ε D F damps forces
// the fluid cannot feel; the equation holds for the total F, so the warm start's share is damped too.
// Warm start: the last step's forces (a steady flow needs the same ones again), spread before the
// first projection, which therefore costs nothing extra.
// Forcing3::coupled adds the bodies' answer within the step, dt J A⁻¹ Jᵀ F (solidResponse), to A: the
// markers' velocity is then the bodies' v* less what the forces take from them (Eq. 9, header).
void RigidFluidCoupling3::projectedForcing(double dt) {
  fluid3d::MacGrid3& g = fluid_.grid();
  const double rho = fluid_.params().density_kg_per_m3;
  const double to_velocity = dt / rho;
  const double eps = p_.forcing_regularisation;
  // The direct-forcing mobility dt/(ρ dV) of a marker, times 1/(1 + 6 ν dt/dx²) when the forcing acts
  // through the viscous step: the diagonal of (I − ν dt ∇²)⁻¹'s inverse on the 7-point stencil, so that
  // the preconditioner and the regularisation keep their scale relative to A whatever ν dt/dx².
  const double nu_number = fluid_.params().kinematic_viscosity_m2_per_s * dt / (g.dx_m * g.dx_m);
  const double mobility = p_.viscosity_in_forcing && fluid_.stages().viscosity ? 1.0 / (1.0 + 6.0 * nu_number) : 1.0;
  const std::size_t n = markers_.size();
  force_.resize(n, Vec3{});
  zero(spread_);
  transfer_.spread(force_, spread_);
  addScaled(g.velocity_m_per_s, to_velocity, spread_);
  std::swap(g.velocity_m_per_s, spread_);
  respond(spread_, dt);
  std::swap(g.velocity_m_per_s, spread_);
  const fluid3d::Array3 pressure_pa = g.pressure_pa;
  residual_.resize(n);
  transfer_.interpolate(g.velocity_m_per_s, residual_);
  double scale = std::max(maxAbs(velocity_), fluid_.maxVelocityComponent_m_per_s());
  for (std::size_t k = 0; k < n; ++k)
    for (int a = 0; a < 3; ++a)
      residual_[k][a] = velocity_[k][a] - residual_[k][a] - eps * mobility * dt / mass_[k] * force_[k][a];
  const bool coupled = p_.forcing == Forcing3::coupled;
  if (coupled) {
    solidResponse(force_, solid_, dt);
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) residual_[k][a] -= solid_[k][a];
  }
  const double tol = p_.forcing_tolerance * (scale > 0 ? scale : 1.0);
  auto apply = [&](const std::vector<Vec3>& d, std::vector<Vec3>& out) {
    // q = P S d dt/ρ (P H P S d dt/ρ with viscosity_in_forcing), in spread_.
    zero(spread_);
    transfer_.spread(d, spread_);
    for (int a = 0; a < 3; ++a) {
      double* p = spread_[a].data();
      for (std::size_t t = 0; t < spread_[a].size(); ++t) p[t] *= to_velocity;
    }
    g.pressure_pa.fill(0.0);  // the projection's warm start: the increment's pressure is not the flow's
    respond(spread_, dt);
    transfer_.interpolate(spread_, out);
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) out[k][a] += eps * mobility * dt / mass_[k] * d[k][a];
    if (coupled) {
      solidResponse(d, solid_, dt);
      for (std::size_t k = 0; k < n; ++k)
        for (int a = 0; a < 3; ++a) out[k][a] += solid_[k][a];
    }
  };
  auto advance = [&](double alpha) { addScaled(g.velocity_m_per_s, alpha, spread_); };
  auto precondition = [&](const std::vector<Vec3>& r, std::vector<Vec3>& z) {
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) z[k][a] = mass_[k] / (mobility * dt) * r[k][a];
  };
  iterations_ = forcing::conjugateGradients(force_, residual_, work_, tol, p_.max_forcing_iterations, apply, advance,
                                            precondition);
  residual_m_per_s_ = maxAbs(residual_);
  g.pressure_pa = pressure_pa;
}

// The reaction: −F on each marker's body, as one force and torque about the body's centre of mass.
void RigidFluidCoupling3::reaction(const rigid::RigidData& data) {
  for (std::size_t b = 1; b < body_point_m_.size(); ++b) {
    const double* c = data.bodyComPosition(static_cast<int>(b));
    body_point_m_[b] = {c[0], c[1], c[2]};
  }
  std::fill(body_force_n_.begin(), body_force_n_.end(), Vec3{});
  std::fill(body_torque_n_m_.begin(), body_torque_n_m_.end(), Vec3{});
  for (std::size_t k = 0; k < markers_.size(); ++k) {
    const int b = markers_[k].body;
    const Vec3 f{-force_[k][0], -force_[k][1], -force_[k][2]};
    Vec3 r;
    for (int a = 0; a < 3; ++a) r[a] = previous_[k][a] + p_.origin_m[a] - body_point_m_[b][a];
    Vec3& F = body_force_n_[b];
    Vec3& T = body_torque_n_m_[b];
    for (int a = 0; a < 3; ++a) F[a] += f[a];
    T[0] += r[1] * f[2] - r[2] * f[1];
    T[1] += r[2] * f[0] - r[0] * f[2];
    T[2] += r[0] * f[1] - r[1] * f[0];
  }
}

void RigidFluidCoupling3::applyReaction(rigid::RigidData& data) const {
  if (p_.forcing != Forcing3::coupled) applyFluidForce(data);
}

void RigidFluidCoupling3::applyFluidForce(rigid::RigidData& data) const {
  for (std::size_t b = 1; b < body_force_n_.size(); ++b)
    data.applyWrenchAt(static_cast<int>(b), body_force_n_[b], body_torque_n_m_[b], body_point_m_[b]);
}

void RigidFluidCoupling3::save(CouplingState3& s) const {
  s.grid = fluid_.grid();
  s.positions_m = previous_;
  s.forces_n = force_;
  s.body_force_n = body_force_n_;
  s.body_torque_n_m = body_torque_n_m_;
  s.body_point_m = body_point_m_;
  s.mouth_flux_m_per_s = mouth_flux_m_per_s_;
}

void RigidFluidCoupling3::restore(const CouplingState3& s) {
  const fluid3d::MacGrid3& g = fluid_.grid();
  if (s.grid.n != g.n || s.positions_m.size() != markers_.size() || s.forces_n.size() != markers_.size() ||
      s.body_force_n.size() != body_force_n_.size() || s.mouth_flux_m_per_s.size() != mouth_flux_m_per_s_.size())
    throw std::invalid_argument("coupling3d: restore: the state is of another coupling (grid or markers differ)");
  transfer_.locate(g, p_.kernel, s.positions_m);
  fluid_.grid() = s.grid;
  previous_ = s.positions_m;
  force_ = s.forces_n;
  body_force_n_ = s.body_force_n;
  body_torque_n_m_ = s.body_torque_n_m;
  body_point_m_ = s.body_point_m;
  mouth_flux_m_per_s_ = s.mouth_flux_m_per_s;
}

}  // namespace creaturelab::coupling3d
