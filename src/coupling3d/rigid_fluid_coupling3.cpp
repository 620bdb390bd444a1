#include "coupling3d/rigid_fluid_coupling3.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace creaturelab::coupling3d {

std::string RigidFluidParams3::validate(const fluid3d::FluidParams3& fluid) const {
  if (auto e = fluid.validate(); !e.empty()) return e;
  if (!(marker_spacing_cells > 0 && marker_spacing_cells <= 1.0))
    return "marker_spacing_cells must be in (0, 1]: markers farther apart than a cell leave gaps the kernel does "
           "not close and the fluid leaks through the body (got " + std::to_string(marker_spacing_cells) + ")";
  if (!(forcing_tolerance > 0 && forcing_tolerance < 1)) return "forcing_tolerance must be in (0, 1)";
  if (max_forcing_iterations < 1 || max_forcing_iterations > 10000) return "max_forcing_iterations must be 1..10000";
  if (!(forcing_regularisation >= 0 && forcing_regularisation < 1)) return "forcing_regularisation must be in [0, 1)";
  for (double x : origin_m)
    if (!std::isfinite(x)) return "origin_m must be a finite point";
  if (!(max_marker_cells_per_step > 0 && max_marker_cells_per_step <= 2))
    return "max_marker_cells_per_step must be in (0, 2]";
  return "";
}

namespace {

const fluid3d::FluidParams3& checked(const RigidFluidParams3& p, const fluid3d::FluidParams3& f) {
  if (auto e = p.validate(f); !e.empty()) throw std::invalid_argument("coupling3d: " + e);
  return f;
}

void zero(fluid3d::FaceField3& field) {
  for (fluid3d::Array3& a : field) a.fill(0.0);
}

// a += s b, component by component.
void addScaled(fluid3d::FaceField3& a, double s, const fluid3d::FaceField3& b) {
  for (int c = 0; c < 3; ++c) {
    double* p = a[c].data();
    const double* q = b[c].data();
    for (std::size_t t = 0; t < a[c].size(); ++t) p[t] += s * q[t];
  }
}

double dot(const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  double s = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) s += x[k][0] * y[k][0] + x[k][1] * y[k][1] + x[k][2] * y[k][2];
  return s;
}

double maxAbs(const std::vector<Vec3>& x) {
  double m = 0.0;
  for (const Vec3& v : x) m = std::max({m, std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  return m;
}

}  // namespace

RigidFluidCoupling3::RigidFluidCoupling3(const rigid::RigidData& data, const fluid3d::FluidParams3& f,
                                         const RigidFluidParams3& p)
    : p_(p), fluid_(checked(p, f)) {
  const fluid3d::MacGrid3& g = fluid_.grid();
  markers_ = modelSurfaceMarkers(data.model(), p_.marker_spacing_cells * g.dx_m);
  if (p_.interior_markers) {
    // At least the kernel's half-width inside, so that no interior marker's stencil reaches past the surface.
    const double margin = 0.5 * ib::kernelSupportCells(p_.kernel) * g.dx_m;
    const std::vector<SurfaceMarker3> inside = interiorMarkers(data.model(), g.dx_m, margin);
    markers_.insert(markers_.end(), inside.begin(), inside.end());
  }
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
  if (!(dt > 0 && std::isfinite(dt))) throw std::invalid_argument("coupling3d: the time step must be positive");
  const double dx = fluid_.grid().dx_m;
  const std::size_t n = markers_.size();
  place(data, current_);
  velocity_.resize(n);
  cells_per_step_ = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double d = current_[k][a] - previous_[k][a];
      velocity_[k][a] = d / dt;
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
  std::swap(previous_, current_);
  if (p_.forcing == Forcing3::projected) {
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

// The marker forces F (N) for which the projected velocity meets the markers' velocity V,
//   I P (u~ + dt/ρ S F) = V,
// by conjugate gradients on A F = I P S F dt/ρ + ε D F = V − I P u~ (A symmetric positive
// definite for ε > 0: S = Iᵀ/dx³ and P an orthogonal projection), with D = dt/(ρ dV) per marker
// (the direct-forcing mobility, dV = dA dx on the surface) and the preconditioner D⁻¹. The regularisation ε D F damps forces
// the fluid cannot feel; the equation holds for the total F, so the warm start's share is damped too.
// Warm start: the last step's forces (a steady flow needs the same ones again), spread before the
// first projection, which therefore costs nothing extra.
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
  z_.resize(n);
  direction_.resize(n);
  applied_.resize(n);
  auto precondition = [&]() {
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) z_[k][a] = mass_[k] / (mobility * dt) * residual_[k][a];
    return dot(z_, residual_);
  };
  double rz = precondition();
  direction_ = z_;
  iterations_ = 0;
  const double tol = p_.forcing_tolerance * (scale > 0 ? scale : 1.0);
  while (maxAbs(residual_) > tol && iterations_ < p_.max_forcing_iterations && rz > 0) {
    ++iterations_;
    // q = P S p dt/ρ (P H P S p dt/ρ with viscosity_in_forcing), in spread_.
    zero(spread_);
    transfer_.spread(direction_, spread_);
    for (int a = 0; a < 3; ++a) {
      double* p = spread_[a].data();
      for (std::size_t t = 0; t < spread_[a].size(); ++t) p[t] *= to_velocity;
    }
    g.pressure_pa.fill(0.0);  // the projection's warm start: the increment's pressure is not the flow's
    respond(spread_, dt);
    transfer_.interpolate(spread_, applied_);
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) applied_[k][a] += eps * mobility * dt / mass_[k] * direction_[k][a];
    const double pap = dot(direction_, applied_);
    if (!(pap > 0)) break;
    const double alpha = rz / pap;
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) {
        force_[k][a] += alpha * direction_[k][a];
        residual_[k][a] -= alpha * applied_[k][a];
      }
    addScaled(g.velocity_m_per_s, alpha, spread_);
    const double rz_old = rz;
    rz = precondition();
    const double beta = rz / rz_old;
    for (std::size_t k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a) direction_[k][a] = z_[k][a] + beta * direction_[k][a];
  }
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
  for (std::size_t b = 1; b < body_force_n_.size(); ++b)
    data.applyWrenchAt(static_cast<int>(b), body_force_n_[b], body_torque_n_m_[b], body_point_m_[b]);
}

}  // namespace creaturelab::coupling3d
