#include "coupling/rigid_fluid_coupling.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/SparseCholesky>

#include "fluid/boundary2.hpp"

namespace creaturelab::coupling {

std::string RigidFluidParams::validate(const fluid::FluidParams& fluid) const {
  const RigidFluidParams& p = *this;
  if (auto e = fluid.validate(); !e.empty()) return e;
  if (!(p.marker_spacing_cells > 0 && p.marker_spacing_cells <= 1.0))
    return "marker_spacing_cells must be in (0, 1]: markers coarser than one cell leave gaps the kernel does not "
           "close and the fluid leaks through the body (got " + std::to_string(p.marker_spacing_cells) + ")";
  if (p.forcing_iterations < 1 || p.forcing_iterations > 100) return "forcing_iterations must be 1..100";
  if (p.projection_rounds < 1 || p.projection_rounds > 20) return "projection_rounds must be 1..20";
  if (!(p.forcing_regularisation >= 0 && p.forcing_regularisation < 1)) return "forcing_regularisation must be in [0, 1)";
  if (!(p.depth_m > 0)) return "depth_m must be positive";
  if (!(p.max_marker_cells_per_step > 0 && p.max_marker_cells_per_step <= 2))
    return "max_marker_cells_per_step must be in (0, 2]";
  if (auto e = p.mouth.validate(); !e.empty()) return e;
  return p.inflow.validate(fluid);
}

namespace {
void scaleBy(fluid::Array2& a, double s) {
  double* p = a.data();
  for (std::size_t k = 0; k < a.size(); ++k) p[k] *= s;
}
void addScaled(fluid::Array2& a, double s, const fluid::Array2& b) {
  double* p = a.data();
  const double* q = b.data();
  for (std::size_t k = 0; k < a.size(); ++k) p[k] += s * q[k];
}
const fluid::FluidParams& checked(const RigidFluidParams& p, const fluid::FluidParams& f) {
  if (auto e = p.validate(f); !e.empty()) throw std::invalid_argument(e);
  return f;
}
}  // namespace

RigidFluidCoupling::RigidFluidCoupling(const rigid::RigidData& data, const fluid::FluidParams& f,
                                       const RigidFluidParams& p)
    : p_(p), fluid_(checked(p, f)) {
  const double dx = fluid_.grid().dx_m;
  markers_ = outlineMarkers(data.model(), data, p_.marker_spacing_cells * dx);
  mouth_begin_ = markers_.size();
  const auto mouth = mouthMarkers(data.model(), p_.mouth, p_.marker_spacing_cells * dx);
  markers_.insert(markers_.end(), mouth.begin(), mouth.end());
  placeMarkers(data);
  if (p_.inflow.stream_m_per_s != 0) fillStream(fluid_.grid(), p_.inflow.stream_m_per_s);
  const int nb = data.model().bodies();
  body_force_n_.assign(nb, Vec3{});
  body_torque_n_m_.assign(nb, Vec3{});
  body_point_m_.assign(nb, Vec3{});
  force_.assign(markers_.size(), {});
  spread_ = fluid::FaceVectorField2(fluid_.grid().nx, fluid_.grid().ny);
}

void RigidFluidCoupling::placeMarkers(const rigid::RigidData& data) {
  place(data, previous_);
  try {
    transfer_.locate(fluid_.grid(), p_.kernel, previous_);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("a body is outside the fluid box or within the kernel's reach of a wall "
                                            "(world x = fluid x + ") + std::to_string(p_.origin_x_m) +
                                " m, z = fluid y + " + std::to_string(p_.origin_z_m) + " m): " + e.what());
  }
}

void RigidFluidCoupling::place(const rigid::RigidData& data, std::vector<fluid::Vec2>& out) const {
  out.resize(markers_.size());
  for (std::size_t k = 0; k < markers_.size(); ++k) {
    const Vec3 w = markerWorld(data, markers_[k]);
    out[k] = {w[0] - p_.origin_x_m, w[2] - p_.origin_z_m};
  }
}

void RigidFluidCoupling::locate(const std::vector<fluid::Vec2>& x) {
  try {
    transfer_.locate(fluid_.grid(), p_.kernel, x);
  } catch (const std::invalid_argument& e) {
    throw CouplingError(std::string("a body left the fluid box (or came within the kernel's reach of a wall): ") +
                        e.what());
  }
}

void RigidFluidCoupling::advanceFluid(double dt) {
  const fluid::StepContext c{fluid_.stepsDone(), time_s_, dt};
  fluid_.forceDensity_n_per_m3().fill(0.0);  // the bodies force by velocity, in forceFluid
  fluid_.applyExternalForces(c);
  applyInflow(fluid_.grid(), p_.inflow);
  fluid_.advectVelocity(c);
  fluid_.applyViscosity(c);
  applyInflow(fluid_.grid(), p_.inflow);
}

void RigidFluidCoupling::forceFluid(const rigid::RigidData& data, double dt) {
  fluid::MacGrid2& g = fluid_.grid();
  const double dx = g.dx_m;
  const std::size_t n = markers_.size();
  place(data, current_);
  velocity_.resize(n);
  cells_per_step_ = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double ddx = current_[k].x - previous_[k].x, ddy = current_[k].y - previous_[k].y;
    cells_per_step_ = std::max(cells_per_step_, std::hypot(ddx, ddy) / dx);
    velocity_[k] = {ddx / dt, ddy / dt};
  }
  if (!(cells_per_step_ <= p_.max_marker_cells_per_step))
    throw CouplingError("time step beyond the coupled stability limit: a marker moved " +
                        std::to_string(cells_per_step_) + " cells in one step of " + std::to_string(dt) +
                        " s (limit max_marker_cells_per_step = " + std::to_string(p_.max_marker_cells_per_step) +
                        "); take a smaller step");
  addMouthFlux(data);
  locate(current_);
  std::swap(previous_, current_);
  if (p_.forcing == Forcing::projected) {
    projectedForcing(dt);
  } else {
    force_.assign(n, {});
    sweeps(dt);
  }
  reaction(data);
}

// The mouth's markers move with their body plus the phase's flux along the mouth's normal, turned
// with the geom (mouth.hpp; §7.2). The flux of the step is the one at its start.
void RigidFluidCoupling::addMouthFlux(const rigid::RigidData& data) {
  const double flux = mouthFlux_m_per_s(p_.mouth, time_s_);
  if (flux == 0.0) return;
  const double norm = std::hypot(p_.mouth.normal_x, p_.mouth.normal_z);
  const double nx = p_.mouth.normal_x / norm, nz = p_.mouth.normal_z / norm;
  for (std::size_t k = mouth_begin_; k < markers_.size(); ++k) {
    const double* R = data.geomRotation(markers_[k].geom);  // row-major
    velocity_[k].x += flux * (R[0] * nx + R[2] * nz);
    velocity_[k].y += flux * (R[6] * nx + R[8] * nz);
  }
}

// The marker forces f for which the projected velocity meets the markers' velocity,
//   I P (u~ + dt/rho S f) = V,
// by conjugate gradients on A f = I P S f dt/rho (symmetric positive semi-definite: S = I^T / dx^2
// and P is an orthogonal projection), preconditioned by the direct-forcing mass rho dA_k / dt or by
// the factored forcing without the projection (RigidFluidParams::forcing_preconditioner).
// This is the immersed-boundary projection of Taira & Colonius 2007 (J. Comput. Phys. 225) with
// our rigid markers: one fluid projection per iteration.
void RigidFluidCoupling::projectedForcing(double dt) {
  fluid::MacGrid2& g = fluid_.grid();
  const double dx = g.dx_m, rho = fluid_.params().density_kg_per_m3;
  const std::size_t n = markers_.size();
  const fluid::StepContext c{fluid_.stepsDone(), time_s_, dt};
  // Warm start: the last step's forces (a steady flow needs the same ones again), spread before
  // the first projection, which therefore costs nothing extra.
  force_.resize(n);
  spread_.fill(0.0);
  transfer_.spread(force_, spread_);
  addScaled(g.u_m_per_s, dt / rho, spread_.x);
  addScaled(g.v_m_per_s, dt / rho, spread_.y);
  fluid_.project(c);
  applyInflow(g, p_.inflow);
  const fluid::Array2 pressure = g.pressure_pa;
  // Residual r = V - I u (m/s), search direction p (N/m), A p (m/s).
  std::vector<fluid::Vec2>& r = sampled_;
  r.resize(n);
  transfer_.interpolate(g, r);
  double scale = 0;
  // Regularised by eps D f (D = dt / (rho dA_k), the preconditioner's inverse, velocity per force):
  // forces the fluid cannot feel (markers of two bodies on the same faces pushing against each
  // other, e.g. a block's end at the square it is hinged to) are damped to zero instead of growing
  // step after step through the warm start. The equation is for the total f, so the warm start's
  // share of such forces is removed too.
  const double eps = p_.forcing_regularisation;
  auto mobility = [&](std::size_t k) { return dt / (rho * markers_[k].length_m * dx); };
  for (std::size_t k = 0; k < n; ++k) {
    const double d = eps * mobility(k);
    r[k] = {velocity_[k].x - r[k].x - d * force_[k].x, velocity_[k].y - r[k].y - d * force_[k].y};
    scale = std::max({scale, std::abs(velocity_[k].x), std::abs(velocity_[k].y)});
  }
  for (double u : {fluid::maxAbs(g.u_m_per_s), fluid::maxAbs(g.v_m_per_s)}) scale = std::max(scale, u);
  z_.resize(n);
  direction_.resize(n);
  applied_.resize(n);
  // gram: A0 = dt/(rho dx^2) G + eps D, A without the projection (I S = G / dx^2), exactly
  // symmetric and positive definite for eps > 0; factored by sparse LDL^T (fill-reducing ordering,
  // one thread: the same factors bit for bit). Falls back to the mass for a step whose A0 does not
  // factor (eps = 0 with two markers on the same spot).
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> gram_factor;
  bool use_gram = false;
  if (p_.forcing_preconditioner == ForcingPreconditioner::gram && n > 0) {
    transfer_.gram(dt / (rho * dx * dx), gram_);
    for (std::size_t k = 0; k < n; ++k) {
      const int i = static_cast<int>(2 * k);
      gram_.coeffRef(i, i) += eps * mobility(k);
      gram_.coeffRef(i + 1, i + 1) += eps * mobility(k);
    }
    gram_factor.compute(gram_);
    use_gram = gram_factor.info() == Eigen::Success && gram_factor.vectorD().minCoeff() > 0;
    packed_.resize(static_cast<Eigen::Index>(2 * n));
  }
  auto precondition = [&](double& rz) {
    rz = 0;
    if (use_gram) {
      for (std::size_t k = 0; k < n; ++k) packed_[2 * k] = r[k].x, packed_[2 * k + 1] = r[k].y;
      packed_ = gram_factor.solve(packed_);
      for (std::size_t k = 0; k < n; ++k) z_[k] = {packed_[2 * k], packed_[2 * k + 1]};
    } else {
      for (std::size_t k = 0; k < n; ++k) {
        const double m = rho * markers_[k].length_m * dx / dt;
        z_[k] = {m * r[k].x, m * r[k].y};
      }
    }
    for (std::size_t k = 0; k < n; ++k) rz += z_[k].x * r[k].x + z_[k].y * r[k].y;
  };
  auto residual = [&]() {
    double e = 0;
    for (const auto& x : r) e = std::max({e, std::abs(x.x), std::abs(x.y)});
    return e;
  };
  double rz = 0;
  precondition(rz);
  direction_ = z_;
  work_.nx = g.nx;
  work_.ny = g.ny;
  work_.dx_m = g.dx_m;
  iterations_ = 0;
  const double tol = p_.forcing_tolerance * (scale > 0 ? scale : 1.0);
  while (residual() > tol && iterations_ < p_.max_forcing_iterations && rz > 0) {
    ++iterations_;
    // q = P S p dt / rho, in work_.
    spread_.fill(0.0);
    transfer_.spread(direction_, spread_);
    // The spread field becomes work_'s velocity by a swap, not a copy; spread_ takes work_'s old
    // arrays (the right shape after the first iteration) and is zeroed again before its next use.
    std::swap(work_.u_m_per_s, spread_.x);
    std::swap(work_.v_m_per_s, spread_.y);
    if (spread_.x.nx() != work_.u_m_per_s.nx() || spread_.x.ny() != work_.u_m_per_s.ny() ||
        spread_.y.nx() != work_.v_m_per_s.nx() || spread_.y.ny() != work_.v_m_per_s.ny())
      spread_ = fluid::FaceVectorField2(g.nx, g.ny);
    const double to_velocity = dt / rho;
    scaleBy(work_.u_m_per_s, to_velocity);
    scaleBy(work_.v_m_per_s, to_velocity);
    std::swap(work_.u_m_per_s, g.u_m_per_s);
    std::swap(work_.v_m_per_s, g.v_m_per_s);
    fluid_.project(c);
    std::swap(work_.u_m_per_s, g.u_m_per_s);
    std::swap(work_.v_m_per_s, g.v_m_per_s);
    transfer_.interpolate(work_, applied_);
    for (std::size_t k = 0; k < n; ++k) {
      const double d = eps * mobility(k);
      applied_[k].x += d * direction_[k].x;
      applied_[k].y += d * direction_[k].y;
    }
    double pap = 0;
    for (std::size_t k = 0; k < n; ++k) pap += direction_[k].x * applied_[k].x + direction_[k].y * applied_[k].y;
    if (!(pap > 0)) break;
    const double alpha = rz / pap;
    for (std::size_t k = 0; k < n; ++k) {
      force_[k].x += alpha * direction_[k].x;
      force_[k].y += alpha * direction_[k].y;
      r[k].x -= alpha * applied_[k].x;
      r[k].y -= alpha * applied_[k].y;
    }
    addScaled(g.u_m_per_s, alpha, work_.u_m_per_s);
    addScaled(g.v_m_per_s, alpha, work_.v_m_per_s);
    const double rz_old = rz;
    precondition(rz);
    const double beta = rz / rz_old;
    for (std::size_t k = 0; k < n; ++k)
      direction_[k] = {z_[k].x + beta * direction_[k].x, z_[k].y + beta * direction_[k].y};
  }
  forcing_residual_m_per_s_ = residual();
  g.pressure_pa = pressure;
  applyInflow(g, p_.inflow);
}

// Multi-direct forcing: each sweep corrects the velocity the previous sweeps left at the markers.
void RigidFluidCoupling::sweeps(double dt) {
  fluid::MacGrid2& g = fluid_.grid();
  const double dx = g.dx_m, rho = fluid_.params().density_kg_per_m3;
  const std::size_t n = markers_.size();
  sampled_.resize(n);
  sweep_.resize(n);
  const fluid::Walls& walls = fluid_.walls();
  const fluid::FaceRange u_cols = fluid::unknownUColumns(g, walls);
  const fluid::FaceRange v_rows = fluid::unknownVRows(g, walls);
  for (int it = 0; it < p_.forcing_iterations; ++it) {
    transfer_.interpolate(g, sampled_);
    for (std::size_t k = 0; k < n; ++k) {
      const double mass_per_dt = p_.forcing_relaxation * rho * markers_[k].length_m * dx / dt;  // kg/(m s) per metre of depth
      sweep_[k] = {mass_per_dt * (velocity_[k].x - sampled_[k].x), mass_per_dt * (velocity_[k].y - sampled_[k].y)};
      force_[k].x += sweep_[k].x;
      force_[k].y += sweep_[k].y;
    }
    spread_.fill(0.0);
    transfer_.spread(sweep_, spread_);
    const double scale = dt / rho;
    for (int j = 0; j < g.ny; ++j)
      for (int i = u_cols.begin; i < u_cols.end; ++i) g.u_m_per_s(i, j) += scale * spread_.x(i, j);
    for (int j = v_rows.begin; j < v_rows.end; ++j)
      for (int i = 0; i < g.nx; ++i) g.v_m_per_s(i, j) += scale * spread_.y(i, j);
  }
}

// The reaction: -G depth on each marker's body, as one wrench about the body's centre of mass.
void RigidFluidCoupling::reaction(const rigid::RigidData& data) {
  for (std::size_t b = 1; b < body_point_m_.size(); ++b) {
    const double* c = data.bodyComPosition(int(b));
    body_point_m_[b] = {c[0], c[1], c[2]};
  }
  sumReaction();
}

void RigidFluidCoupling::sumReaction() {
  const std::size_t n = markers_.size();
  std::fill(body_force_n_.begin(), body_force_n_.end(), Vec3{});
  std::fill(body_torque_n_m_.begin(), body_torque_n_m_.end(), Vec3{});
  for (std::size_t k = 0; k < n; ++k) {
    const int b = markers_[k].body;
    const double fx = -p_.depth_m * force_[k].x, fz = -p_.depth_m * force_[k].y;
    const double rx = previous_[k].x + p_.origin_x_m - body_point_m_[b][0];
    const double rz = previous_[k].y + p_.origin_z_m - body_point_m_[b][2];
    body_force_n_[b][0] += fx;
    body_force_n_[b][2] += fz;
    body_torque_n_m_[b][1] += rz * fx - rx * fz;  // (r x F)_y
  }
}

fluid::LinearSolveReport RigidFluidCoupling::project(double dt) {
  const fluid::StepContext c{fluid_.stepsDone(), time_s_, dt};
  fluid::LinearSolveReport r{};
  if (p_.forcing == Forcing::sweeps) {
    r = fluid_.project(c);
    applyInflow(fluid_.grid(), p_.inflow);
  }
  // The projection moves the velocity at the markers again; further rounds of forcing and
  // projection take that leak back out (each round's forces add to the exchange).
  for (int round = 1; p_.forcing == Forcing::sweeps && round < p_.projection_rounds; ++round) {
    sweeps(dt);
    r = fluid_.project(c);
    applyInflow(fluid_.grid(), p_.inflow);
  }
  if (p_.forcing == Forcing::sweeps && p_.projection_rounds > 1) sumReaction();
  time_s_ += dt;
  const double speed = std::max(fluid::maxAbs(fluid_.grid().u_m_per_s), fluid::maxAbs(fluid_.grid().v_m_per_s));
  if (!(speed <= fluid_.params().blowup_speed_m_per_s))
    throw fluid::FluidBlowUpError(fluid_.stepsDone(), time_s_, dt, speed, fluid_.params().blowup_speed_m_per_s,
                                  speed * dt / fluid_.grid().dx_m);
  return r;
}

void RigidFluidCoupling::applyReaction(rigid::RigidData& data) const {
  for (std::size_t b = 1; b < body_force_n_.size(); ++b)
    data.applyWrenchAt(int(b), body_force_n_[b], body_torque_n_m_[b], body_point_m_[b]);
}

void RigidFluidCoupling::save(CouplingState& s) const {
  s.grid = fluid_.grid();
  s.previous_m = previous_;
  s.marker_force_n_per_m = force_;
  s.body_force_n = body_force_n_;
  s.body_torque_n_m = body_torque_n_m_;
  s.body_point_m = body_point_m_;
  s.time_s = time_s_;
}

void RigidFluidCoupling::restore(const CouplingState& s) {
  fluid_.grid() = s.grid;
  previous_ = s.previous_m;
  force_ = s.marker_force_n_per_m;
  body_force_n_ = s.body_force_n;
  body_torque_n_m_ = s.body_torque_n_m;
  body_point_m_ = s.body_point_m;
  time_s_ = s.time_s;
}

}  // namespace creaturelab::coupling
