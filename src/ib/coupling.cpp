#include "ib/coupling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <Eigen/LU>

namespace creaturelab::ib {

std::string_view to_string(ImplicitMobility mobility) {
  return mobility == ImplicitMobility::stencil ? "stencil" : "local_mass";
}

std::optional<ImplicitMobility> parseImplicitMobility(std::string_view name) {
  if (name == "stencil") return ImplicitMobility::stencil;
  if (name == "local_mass") return ImplicitMobility::local_mass;
  return std::nullopt;
}

std::string CouplingParams::validate() const {
  std::string out;
  auto problem = [&](const std::string& text) { out += (out.empty() ? "" : "; ") + text; };
  if (!(implicit_mass_factor > 0)) problem("implicit_mass_factor must be > 0");
  if (!(implicit_theta >= 0.5 && implicit_theta <= 1.0)) problem("implicit_theta must lie in [0.5, 1]");
  if (!(factor_reuse.tolerance >= 0) || factor_reuse.max_sweeps < 1)
    problem("factor reuse needs a tolerance >= 0 and at least one sweep");
  return out;
}

ImmersedBoundary2::ImmersedBoundary2(fluid::FluidSolver2& fluid, const ElasticBody& body,
                                     std::vector<fluid::Vec2> markers_m, CouplingParams params)
    : fluid_(fluid), body_(body), markers_(std::move(markers_m)), params_(params), banded_solver_(params.factor_reuse) {
  if (static_cast<int>(markers_.size()) != body_.markerCount())
    throw std::invalid_argument("immersed boundary: " + std::to_string(markers_.size()) + " markers for a body of " +
                                std::to_string(body_.markerCount()));
  if (const std::string err = params_.validate(); !err.empty())
    throw std::invalid_argument("immersed boundary: " + err);
  if (!params_.marker_kernel_scales.empty() && params_.marker_kernel_scales.size() != markers_.size())
    throw std::invalid_argument("immersed boundary: " + std::to_string(params_.marker_kernel_scales.size()) +
                                " marker kernel stretches for " + std::to_string(markers_.size()) + " markers");
  force_.resize(markers_.size());
  velocity_.resize(markers_.size());
  if (params_.banded_solve && static_cast<int>(markers_.size()) >= kBandedFromMarkers) order_ = body_.solveOrder();
  if (!order_.empty()) {
    slot_.assign(markers_.size(), -1);
    for (std::size_t k = 0; k < order_.size(); ++k) {
      const int m = order_[k];
      if (order_.size() != markers_.size() || m < 0 || m >= static_cast<int>(markers_.size()) || slot_[m] >= 0)
        throw std::invalid_argument("immersed boundary: the body's solve order is not a permutation of its markers");
      slot_[m] = static_cast<int>(k);
    }
  }
}

namespace {

// Unknown 2 k + axis → its place in the banded solve, 2 slot[k] + axis.
int bandedIndex(const std::vector<int>& slot, int unknown) { return 2 * slot[unknown / 2] + unknown % 2; }

// The largest |row − column| among the nonzeros of `a`, in the banded solve's numbering.
int bandwidth(const Eigen::SparseMatrix<double>& a, const std::vector<int>& slot) {
  int width = 0;
  for (int j = 0; j < a.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator k(a, j); k; ++k)
      width = std::max(width, std::abs(bandedIndex(slot, static_cast<int>(k.row())) - bandedIndex(slot, j)));
  return width;
}

}  // namespace

// entry(i, j) −= dt (M K)(i, j) over the nonzeros of the product, in one fixed order whatever the
// storage (dense or banded), so that both solves see the same sums.
template <class Entry>
void ImmersedBoundary2::subtractDtMk(const Eigen::SparseMatrix<double>& stiffness, double dt_s, Entry entry) const {
  for (int j = 0; j < stiffness.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator k(stiffness, j); k; ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator i(mobility_, k.row()); i; ++i)
        entry(static_cast<int>(i.row()), j) -= dt_s * i.value() * k.value();
}

// subtract_dt_mk into the band: the same products subtracted in the same order, with each row's
// banded index looked up once per entry of M (mobility_rows_) rather than once per product, and
// the column's storage found once per column of K (the lookups were most of this stage's time), and
// θ dt M(i, k) formed once per entry of M (mobility_dt_), as the product's left-to-right order forms it.
// Each column's reach, the diagonal and the rows of M's columns met, goes to the band (set_reach).
void ImmersedBoundary2::subtractDtMkBanded(const Eigen::SparseMatrix<double>& stiffness) {
  const int* m_outer = mobility_.outerIndexPtr();
  const double* m_dt = mobility_dt_.data();
  const int* m_row = mobility_rows_.data();
  reach_first_.resize(static_cast<std::size_t>(stiffness.outerSize()));
  reach_last_.resize(static_cast<std::size_t>(stiffness.outerSize()));
  for (int j = 0; j < stiffness.outerSize(); ++j) {
    const int jb = bandedIndex(slot_, j);
    double* column = banded_.column(jb);
    int first = jb, last = jb;
    for (Eigen::SparseMatrix<double>::InnerIterator k(stiffness, j); k; ++k) {
      const double kv = k.value();
      for (int p = m_outer[k.row()]; p < m_outer[k.row() + 1]; ++p) column[m_row[p]] -= m_dt[p] * kv;
      first = std::min(first, mobility_first_[k.row()]);
      last = std::max(last, mobility_last_[k.row()]);
    }
    reach_first_[jb] = first;
    reach_last_[jb] = last;
  }
  banded_.setReach(reach_first_, reach_last_);
}

// mobility_rows_ and mobility_dt_, and per column of M the least and greatest of its banded rows
// (mobility_first_, _last_). Returns M's bandwidth in the banded numbering (as bandwidth() does).
int ImmersedBoundary2::indexMobilityRows(double theta_dt_s) {
  const int* m_outer = mobility_.outerIndexPtr();
  const int* m_inner = mobility_.innerIndexPtr();
  const double* m_value = mobility_.valuePtr();
  mobility_rows_.resize(static_cast<std::size_t>(mobility_.nonZeros()));
  mobility_dt_.resize(static_cast<std::size_t>(mobility_.nonZeros()));
  mobility_first_.assign(static_cast<std::size_t>(mobility_.outerSize()), std::numeric_limits<int>::max());
  mobility_last_.assign(static_cast<std::size_t>(mobility_.outerSize()), std::numeric_limits<int>::min());
  for (int k = 0; k < mobility_.outerSize(); ++k)
    for (int p = m_outer[k]; p < m_outer[k + 1]; ++p) {
      const int row = bandedIndex(slot_, m_inner[p]);
      mobility_rows_[static_cast<std::size_t>(p)] = row;
      mobility_dt_[static_cast<std::size_t>(p)] = theta_dt_s * m_value[p];
      mobility_first_[k] = std::min(mobility_first_[k], row);
      mobility_last_[k] = std::max(mobility_last_[k], row);
    }
  int width = 0;
  for (int k = 0; k < mobility_.outerSize(); ++k)
    if (m_outer[k] < m_outer[k + 1]) {
      const int column = bandedIndex(slot_, k);
      width = std::max({width, column - mobility_first_[k], mobility_last_[k] - column});
    }
  return width;
}

namespace {
std::runtime_error singularSystem(double t_s) {
  return std::runtime_error("immersed boundary: the semi-implicit force system is singular at t = " +
                            std::to_string(t_s) + " s");
}
}  // namespace

// I − θ dt M K into the band (theta_dt_s = θ dt), M = mobility_ (gram() fills it in order, so
// makeCompressed() is a no-op; the loops read its arrays). Entry (i, j) of M K joins i to j
// through some k with M(i, k) and K(k, j) nonzero, so the system's band is at most the sum of
// the two bands.
void ImmersedBoundary2::assembleBanded(const Eigen::SparseMatrix<double>& stiffness, double theta_dt_s) {
  const int n = static_cast<int>(stiffness.rows());
  mobility_.makeCompressed();
  const int width = indexMobilityRows(theta_dt_s) + bandwidth(stiffness, slot_);
  banded_.reset(n, width, width);
  for (int i = 0; i < n; ++i) banded_.at(i, i) = 1.0;
  subtractDtMkBanded(stiffness);
}

// G v through the stencils (Transfer::apply_gram), G not formed, into natural_y_ (numbering 2 marker + axis).
const std::vector<double>& ImmersedBoundary2::applyGram(const Eigen::VectorXd& v) {
  natural_x_.assign(v.data(), v.data() + v.size());
  natural_y_.resize(natural_x_.size());
  transfer_.applyGram(natural_x_, natural_y_, gram_patch_);
  return natural_y_;
}

// The banded system on an earlier step's factors (ReusedBandedSolve) with M applied, not formed:
// the right-hand side U_free + M F and each refinement sweep's product need only M's product, so
// G and I − θ dt M K are formed only on the steps that factor anew (rare on the 1 mm jellyfish).
// The answer is the same system's to the refinement's tolerance; only the rounding of M's products
// differs from the formed matrix's.
Eigen::VectorXd ImmersedBoundary2::solveWithoutAssembly(const Eigen::SparseMatrix<double>& stiffness,
                                                        const Eigen::VectorXd& free, const Eigen::VectorXd& force,
                                                        double scale, double t1_s, double theta_dt_s) {
  const int n = static_cast<int>(free.size());
  const double theta_dt_scale = theta_dt_s * scale;
  const std::vector<double>& g_force = applyGram(force);
  banded_rhs_.resize(n);
  Eigen::VectorXd porous_force = Eigen::VectorXd::Zero(n);
  addPorous(force, porous_force, 1.0);  // P F
  for (int i = 0; i < n; ++i) banded_rhs_[bandedIndex(slot_, i)] = free[i] + scale * g_force[i] + porous_force[i];
  const double dt_s = theta_dt_s / params_.implicit_theta;
  Eigen::VectorXd xn(n), predicted(n), kx(n), porous_kx(n);
  const auto apply = [&](const std::vector<double>& x, std::vector<double>& ax) {  // (I − dt (θ M + P) K) x
    for (int i = 0; i < n; ++i) xn[i] = x[bandedIndex(slot_, i)];
    kx = stiffness * xn;
    const std::vector<double>& g_kx = applyGram(kx);
    porous_kx.setZero();
    addPorous(kx, porous_kx, dt_s);
    ax.resize(n);
    for (int i = 0; i < n; ++i) ax[bandedIndex(slot_, i)] = xn[i] - theta_dt_scale * g_kx[i] - porous_kx[i];
  };
  const auto assemble = [&]() -> const BandedLU& {
    transfer_.gram(scale, mobility_);
    if (!porous_.empty()) mobility_ += porousMatrix(n, 1.0 / params_.implicit_theta);
    assembleBanded(stiffness, theta_dt_s);
    return banded_;
  };
  if (!banded_solver_.solve(n, apply, assemble, banded_rhs_)) throw singularSystem(t1_s);
  for (int i = 0; i < n; ++i) predicted[i] = banded_rhs_[bandedIndex(slot_, i)];
  return predicted;
}

namespace {
SlipBlock slipBlock(const PorousSlip& p) {
  return {p.mobility * p.nx * p.nx + p.axial_mobility * p.ny * p.ny,
          (p.mobility - p.axial_mobility) * p.nx * p.ny,
          p.mobility * p.ny * p.ny + p.axial_mobility * p.nx * p.nx};
}
}  // namespace

// out += factor P x (numbering 2 marker + axis).
void ImmersedBoundary2::addPorous(const Eigen::VectorXd& x, Eigen::VectorXd& out, double factor) const {
  for (const PorousSlip& p : porous_) {
    const long i = 2L * p.marker;
    const SlipBlock b = slipBlock(p);
    out[i] += factor * (b.xx * x[i] + b.xy * x[i + 1]);
    out[i + 1] += factor * (b.xy * x[i] + b.yy * x[i + 1]);
  }
}

void ImmersedBoundary2::semiImplicitForce(double t1_s, double dt_s) {
  const int n = 2 * static_cast<int>(markers_.size());
  const double dx = fluid_.grid().dx_m;
  const double rho = fluid_.params().density_kg_per_m3;
  transfer_.interpolate(fluid_.grid(), velocity_);

  triplets_.clear();
  body_.stiffness(t1_s, markers_, 1.0, triplets_);
  stiffness_.resize(n, n);
  stiffness_.setFromTriplets(triplets_.begin(), triplets_.end());
  const Eigen::SparseMatrix<double>& stiffness = stiffness_;
  Eigen::VectorXd free(n), force(n);
  for (int i = 0; i < n / 2; ++i) {
    free[2 * i] = velocity_[i].x;
    free[2 * i + 1] = velocity_[i].y;
    force[2 * i] = force_[i].x;
    force[2 * i + 1] = force_[i].y;
  }

  Eigen::VectorXd predicted;
  const double theta_dt_s = params_.implicit_theta * dt_s;  // exactly dt_s at θ = 1
  if (params_.mobility == ImplicitMobility::stencil) {
    // (I − θ dt M K) U* = U_free + M F with M = dt/(ρ dx²) G. Not symmetric, and in effect dense:
    // for the bell on 100² about half the entries of I − θ dt M K are nonzero, since every marker
    // reaches its neighbours within the kernel's 4 cells along the chain and the muscles join
    // opposite sides, so a dense LU (86 µs for 106 unknowns) beats sparse LU with its symbolic
    // analysis (Eigen's SparseLU took about twice as long, Transfer's stencils changing every step).
    const double scale = dt_s / (rho * dx * dx);
    if (!order_.empty() && params_.factor_reuse.tolerance > 0) {
      predicted = solveWithoutAssembly(stiffness, free, force, scale, t1_s, theta_dt_s);
    } else {
      transfer_.gram(scale, mobility_);
      Eigen::VectorXd rhs = free + mobility_ * force;
      if (!porous_.empty()) {  // (M + P) F on the right; θ M + P = θ (M + P / θ) in the system
        addPorous(force, rhs, 1.0);
        mobility_ += porousMatrix(n, 1.0 / params_.implicit_theta);
      }
      if (!order_.empty()) {
        assembleBanded(stiffness, theta_dt_s);
        banded_rhs_.resize(n);
        for (int i = 0; i < n; ++i) banded_rhs_[bandedIndex(slot_, i)] = rhs[i];
        if (!banded_solver_.solve(banded_, banded_rhs_)) throw singularSystem(t1_s);
        predicted.resize(n);
        for (int i = 0; i < n; ++i) predicted[i] = banded_rhs_[bandedIndex(slot_, i)];
      } else {
        system_.setIdentity(n, n);
        subtractDtMk(stiffness, theta_dt_s, [&](int i, int j) -> double& { return system_(i, j); });
        lu_.compute(system_);
        predicted = lu_.solve(rhs);
      }
    }
  } else {
    // (m I − θ dt² K) U* = m U_free + dt F: the same with M = dt / m.
    const double mass = params_.implicit_mass_factor * rho * dx * dx;
    Eigen::SparseMatrix<double> system = -(theta_dt_s * dt_s) * stiffness;
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
  const Eigen::VectorXd correction = theta_dt_s * (stiffness * predicted);
  for (int i = 0; i < n / 2; ++i) {
    force_[i].x += correction[2 * i];
    force_[i].y += correction[2 * i + 1];
  }
}

// The Darcy slip s of the porous markers, added to their fluid velocity v = I u^{n+1} (coupling.hpp).
// Semi-implicit with the stencil mobility: backward Euler at the markers' end-of-step positions,
// s = P F(X^n + dt (v + s)) linearised, i.e. (I − dt P K) s = P (F + dt K v) on the porous markers
// (s is zero elsewhere); otherwise explicit, s = P F.
void ImmersedBoundary2::addPorousSlip(double dt_s) {
  const int count = static_cast<int>(porous_.size());
  std::vector<SlipBlock> blocks(porous_.size());
  for (int q = 0; q < count; ++q) blocks[q] = slipBlock(porous_[q]);
  Eigen::VectorXd slip(2 * count);  // P F, then P (F + dt K v)
  for (int q = 0; q < count; ++q) {
    const SlipBlock& b = blocks[q];
    const fluid::Vec2 f = slip_force_[porous_[q].marker];
    slip[2 * q] = b.xx * f.x + b.xy * f.y;
    slip[2 * q + 1] = b.xy * f.x + b.yy * f.y;
  }
  if (params_.semi_implicit && params_.mobility == ImplicitMobility::stencil) {
    Eigen::VectorXd v(2 * markers_.size());
    for (std::size_t i = 0; i < markers_.size(); ++i) v[2 * i] = velocity_[i].x, v[2 * i + 1] = velocity_[i].y;
    const Eigen::VectorXd kv = stiffness_ * v;
    for (int q = 0; q < count; ++q) {
      const SlipBlock& b = blocks[q];
      const long i = 2L * porous_[q].marker;
      slip[2 * q] += dt_s * (b.xx * kv[i] + b.xy * kv[i + 1]);
      slip[2 * q + 1] += dt_s * (b.xy * kv[i] + b.yy * kv[i + 1]);
    }
    slip_solver_.compute(porousSlipSystem(blocks, dt_s));
    if (slip_solver_.info() != Eigen::Success)
      throw std::runtime_error("immersed boundary: the porous slip system is singular at t = " +
                               std::to_string(fluid_.time_s()) + " s");
    slip = slip_solver_.solve(slip).eval();
  }
  for (int q = 0; q < count; ++q) {
    velocity_[porous_[q].marker].x += slip[2 * q];
    velocity_[porous_[q].marker].y += slip[2 * q + 1];
  }
}

// I − dt P K restricted to the porous markers (numbering 2 · porous index + axis); `blocks` are P's.
Eigen::SparseMatrix<double> ImmersedBoundary2::porousSlipSystem(const std::vector<SlipBlock>& blocks, double dt_s) const {
  const int count = static_cast<int>(porous_.size());
  std::vector<int> slot(markers_.size(), -1);  // marker -> its index among the porous ones
  for (int q = 0; q < count; ++q) slot[porous_[q].marker] = q;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < 2 * count; ++i) entries.emplace_back(i, i, 1.0);
  for (int j = 0; j < stiffness_.outerSize(); ++j) {
    const int qc = slot[j / 2];
    if (qc < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator k(stiffness_, j); k; ++k) {
      const int qr = slot[k.row() / 2];
      if (qr < 0) continue;
      const SlipBlock& b = blocks[qr];  // column k.row() % 2 of P's block, times − dt K
      const double scale = -dt_s * k.value();
      entries.emplace_back(2 * qr, 2 * qc + j % 2, scale * (k.row() % 2 == 0 ? b.xx : b.xy));
      entries.emplace_back(2 * qr + 1, 2 * qc + j % 2, scale * (k.row() % 2 == 0 ? b.xy : b.yy));
    }
  }
  Eigen::SparseMatrix<double> system(2 * count, 2 * count);
  system.setFromTriplets(entries.begin(), entries.end());
  return system;
}

Eigen::SparseMatrix<double> ImmersedBoundary2::porousMatrix(int n, double factor) const {
  std::vector<Eigen::Triplet<double>> entries;
  for (const PorousSlip& p : porous_) {
    const int i = 2 * p.marker;
    const SlipBlock b = slipBlock(p);
    entries.emplace_back(i, i, factor * b.xx);
    entries.emplace_back(i, i + 1, factor * b.xy);
    entries.emplace_back(i + 1, i, factor * b.xy);
    entries.emplace_back(i + 1, i + 1, factor * b.yy);
  }
  Eigen::SparseMatrix<double> out(n, n);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

CouplingStepReport ImmersedBoundary2::step(double dt_s) {
  const double t1_s = fluid_.time_s() + dt_s;
  transfer_.locate(fluid_.grid(), params_.kernel, markers_, params_.kernel_scale, params_.marker_kernel_scales);
  body_.forces(t1_s, markers_, force_);
  body_.porousSlips(markers_, porous_);
  for (const PorousSlip& p : porous_) {
    if (p.marker < 0 || p.marker >= static_cast<int>(markers_.size()) || !(p.mobility >= 0) || !(p.axial_mobility >= 0))
      throw std::invalid_argument("immersed boundary: a porous slip names marker " + std::to_string(p.marker) +
                                  " of " + std::to_string(markers_.size()) + " or has a negative mobility");
  }
  slip_force_.assign(markers_.size(), {});
  for (const PorousSlip& p : porous_) slip_force_[p.marker] = force_[p.marker];  // F(X^n), before the correction
  if (params_.semi_implicit) semiImplicitForce(t1_s, dt_s);

  auto& density = fluid_.forceDensity_n_per_m3();
  density.fill(0.0);
  transfer_.spread(force_, density);

  CouplingStepReport report;
  report.fluid = fluid_.step(dt_s);

  transfer_.interpolate(fluid_.grid(), velocity_);
  if (!porous_.empty()) addPorousSlip(dt_s);
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
