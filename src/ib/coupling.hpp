#pragma once
// Immersed-boundary coupling of an elastic body and the 2-D fluid (Peskin 2002, Acta Numerica 11,
// §4 and §6; Rudolf & Mould 2009 §3.2): the body's markers
// are massless and move with the fluid velocity interpolated at them; their elastic forces are
// spread onto the grid as the force term F of Eq. 1.
//
// One step of size dt, from (u^n, X^n):
//   1. locate    stencils of X^n (Transfer::locate)
//   2. forces    F = F(X^n, t^{n+1})                                   (the body's elastic forces)
//   3. implicit  optional, see below: F ← F + θ dt K U*
//   4. spread    f = S F                                              (Peskin 2002 Eq. 6.4)
//   5. fluid     u^{n+1} = fluid step with the force density f        (Eq. 1)
//   6. move      X^{n+1} = X^n + dt I u^{n+1}                          (Peskin 2002 Eq. 6.5)
//                plus, for porous markers (PorousSlip), dt s, their Darcy slip (below; P = Σ (α n nᵀ + α_t t tᵀ)/ds)
//
// Porous slip. P is a mobility like M, so the semi-implicit step takes it into the prediction:
//   (I − dt (θ M + P) K) U* = I u^n + (M + P) F,   F_impl = F + θ dt K U*,
// F_impl spread. The porous markers then move by v + s with v = I u^{n+1} and the slip taken by
// backward Euler at their actual end positions (a filament's slip relaxes its stiff bending modes at
// rates far beyond 1/dt, which the trapezoidal θ = ½ would leave ringing):
//   (I − dt P K) s = P (F + dt K v)   on the porous markers.
// Taking s from the fluid's actual v, not from U*, keeps the step stable where M over-predicts the
// fluid's response (the projection lowers it): a slip from the predicted end force overshoots by the
// difference, which θ = ½ does not damp. P ⪰ 0, K ⪯ 0, so both systems' eigenvalues stay ≥ 1. Without
// the semi-implicit step, and with local_mass, the slip is explicit, s = P F.
//
// Stability. Explicit forces make the coupled step stiff (Stockie & Wetton 1999, the paper's ref.
// [28]): a marker spring of stiffness k pushes about ρ dx² of fluid per metre of depth, so steps
// beyond about 2 sqrt(ρ dx² / k) blow up; the bell's angular springs (1.186 N·m/rad on 2 mm
// segments, an effective k ≈ 3e5 N/m) would need dt ≈ 5e-4 s. The paper met the same limit
// (§3.2, §4: "time-steps of the order of 0.01 s begin to hit the stability limits") and used
// CFL with a safety factor of 0.001. Here step 3 makes the elastic force semi-implicit instead:
// the force is evaluated at the predicted positions X^n + dt U*, linearised (K = ∂F/∂X, with
// compressed springs' transverse terms clamped so −K is positive semi-definite), where U* is the
// markers' velocity after the step as predicted by a mobility M (velocity per force) of the
// fluid:  U* = U_free + M F_impl,  F_impl = F + dt K U*,  i.e.
//   (I − dt M K) U* = I u^n + M F,        F_impl = F + dt K U*.
// Only the force is changed; the markers still move with the fluid, so the coupling stays
// consistent whatever M is.
// Where in the step the force is evaluated (implicit_theta = θ): at X^n + θ dt U*, i.e.
//   (I − θ dt M K) U* = I u^n + M F,      F_impl = F + θ dt K U*.
// θ = 1 (CouplingParams' default; the jellyfish kind's is ½) is the backward-Euler
// end of the step above: first order, and it damps the bell's elastic recoil by O(dt). θ = ½ takes
// the force at the middle of the markers' motion (the trapezoidal rule of the linearised force),
// which does not damp. For a linear body with the true fluid response the θ-method is
// unconditionally stable for θ ≥ ½ and only conditionally below (cf.
// Newren, Fogelson, Guy & Kirby 2007, J. Comput. Phys. 222, on backward-Euler and Crank–Nicolson
// immersed-boundary steps); M here only approximates that response, so this is a guide, not a
// proof: the membrane test runs θ = ½ at 0.01 s, and tests/physics/jellyfish_swim_test.cpp runs the
// bell at θ = ½ on the paper's 100² grid at 0.01 s. θ < ½ is not offered. Any θ ≥ 0 keeps
// I − θ dt M K's eigenvalues ≥ 1 (below). On the jellyfish the backward-Euler force is the leading
// step error, which θ = ½ reduces (studies/jellyfish/convergence.toml).
//
// Two mobilities (ImplicitMobility):
//  - stencil (default): M = dt/ρ · I S, the force spread and read back through the markers' own
//    stencils, without the projection (Transfer::gram). Markers that share grid faces share
//    their response, so a zigzag between neighbours two to a cell, which the grid cannot move,
//    keeps its full restoring force. The projection only lowers the true mobility, so M errs
//    toward more implicit damping. I − dt M K has eigenvalues ≥ 1 (M ⪰ 0, K ⪯ 0): always solvable.
//  - local_mass: every marker alone, M = dt / (implicit_mass_factor ρ dx²). Cheaper, but it
//    over-predicts the mobility of sub-cell modes and so cancels their restoring force; the
//    chain then zigzags at the grid scale (below).
//
// Measured (tests/physics/ib_membrane_test.cpp, experiments/jellyfish/membrane.toml, and the
// jellyfish's chain): local_mass at 0.01 s on 50² keeps a membrane of k = 1e5 N/m² within 0.16
// cells of a small-step run and crumples it above. For the bell at 0.7 Hz on 100², the largest
// |second difference| of the turning angle along the chain (explicit steps of 2e-4 s: 0.09 rad):
// local_mass, bilinear, 0.01 s: 0.96; stencil, bilinear, 0.01 s: 0.77, at 0.0025 s: 0.18;
// stencil, peskin4, 0.01 s: 0.06. At 0.02 s bilinear crumples the bell; the swimmer stops such a
// run with an error.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <Eigen/Dense>

#include "fluid/fluid_solver2.hpp"
#include "ib/banded_lu.hpp"
#include "ib/reused_banded_solve.hpp"
#include "ib/kernel.hpp"
#include "ib/transfer.hpp"

namespace creaturelab::ib {

/// A porous marker's Darcy slip (Kim & Peskin 2006, "Penalty immersed boundary method for an elastic
/// boundary with mass" / "2-D parachute simulation by the immersed boundary method"; IB2d's porous
/// points as Miles & Battista 2019, Fluids 4:169, use them for tentacles): the marker moves through the
/// fluid along its unit normal n at U_p = α (F · n) / ds, with F the force it spreads (N/m), ds its share
/// of the chain's arc (m) and α the Darcy coefficient (m/(Pa s), slip velocity per pressure jump), so
/// the fluid passes through the chain at α times the normal load per length; mobility = α / ds. A chain
/// that stands for sparse filaments also lets the fluid by along itself: U_t = α_t (F · t) / ds along the
/// unit tangent t = (n_y, −n_x), axial_mobility = α_t / ds (0: a sheet, no slip along it).
struct PorousSlip {
  int marker = 0;
  double nx = 0, ny = 0;      // unit normal
  double mobility = 0;        // α / ds, (m/s) per (N/m)
  double axial_mobility = 0;  // α_t / ds, (m/s) per (N/m)
};

/// A porous marker's 2 × 2 block of P, α n nᵀ + α_t t tᵀ over ds ((m/s) per (N/m)), symmetric.
struct SlipBlock {
  double xx = 0, xy = 0, yy = 0;
};

/// The elastic structure, seen by the coupling: forces and stiffness at given marker positions.
class ElasticBody {
 public:
  virtual ~ElasticBody() = default;
  virtual int markerCount() const = 0;
  /// Elastic force on each marker, N per metre of depth (overwrites `force`).
  virtual void forces(double t_s, std::span<const fluid::Vec2> x_m, std::span<fluid::Vec2> force_n_per_m) const = 0;
  /// Appends scale · ∂F/∂X as triplets, numbering 2 · marker + axis, with compressed springs'
  /// transverse terms clamped (so that −∂F/∂X is positive semi-definite).
  virtual void stiffness(double t_s, std::span<const fluid::Vec2> x_m, double scale,
                         std::vector<Eigen::Triplet<double>>& out) const = 0;
  /// A permutation of the markers (order[k] = the marker solved k-th) in which markers near each
  /// other in space, or joined by a spring, are near each other, so that the semi-implicit system
  /// is banded. Empty (the default): the body has no such order and the system is solved dense.
  virtual std::vector<int> solveOrder() const { return {}; }
  /// The porous markers' slips at positions x (overwrites `out`); none by default (impermeable).
  virtual void porousSlips(std::span<const fluid::Vec2> x_m, std::vector<PorousSlip>& out) const {
    (void)x_m;
    out.clear();
  }
};

enum class ImplicitMobility { stencil, local_mass };
std::string_view to_string(ImplicitMobility mobility);
std::optional<ImplicitMobility> parseImplicitMobility(std::string_view name);

struct CouplingParams {
  // Not the paper's bilinear (§3.2; selectable): with the semi-implicit step at the 0.01 s the
  // speed goal needs, only Peskin's kernel keeps the bell as smooth as small explicit steps do
  // ("Measured" above); the kernels experiment compares the two.
  Kernel kernel = Kernel::peskin4;
  // The kernel stretched to kernel_scale cells per kernel unit (Transfer::locate): 1 is Peskin's
  // grid-scaled delta; a fixed physical width (scale ∝ 1/dx) makes a grid study refine one body.
  int kernel_scale = 1;
  // Each marker's own stretch (Transfer::locate), e.g. filaments narrower than the body they hang
  // from; empty: kernel_scale for every marker.
  std::vector<int> marker_kernel_scales{};
  bool semi_implicit = true;
  ImplicitMobility mobility = ImplicitMobility::stencil;
  double implicit_mass_factor = 1.0;  // local_mass only: m = factor · ρ dx², see above
  // The linearised force taken at X^n + θ dt U*, θ in [½, 1] (above): 1 as before, ½ without
  // the backward-Euler damping.
  double implicit_theta = 1.0;
  // stencil only: solve banded when the body gives a solveOrder() and has kBandedFromMarkers
  // markers or more (the same system; false keeps the dense LU, for comparison).
  bool banded_solve = true;
  // banded only: refine on an earlier step's factors, factoring anew when that stops converging
  // (ib/reused_banded_solve.hpp), with M applied rather than formed (Transfer::apply_gram); tolerance
  // 0 factors the formed system every step (the plain banded LU, bit for bit). Not the dense solve:
  // on the paper's 100² grid at 0.01 s the system changes so much per step that the refinement
  // nearly always fails (tried, slower).
  FactorReuse factor_reuse{};

  /// kernel, semi_implicit, implicit_mobility, implicit_mass_factor, implicit_theta and
  /// implicit_reuse_tolerance for the immersed-boundary kinds (kinds/describe.hpp: name, unit, range,
  /// one-line doc); the kernel's stretch and the per-marker ones are the kind's to derive.
  template <class V>
  void describe(V& v) {
    v.choice("kernel", kernel, {Kernel::bilinear, Kernel::peskin4},
             "spreading/interpolation: the jellyfish paper's bilinear hat (Rudolf & Mould §3.2) or Peskin's 4-point "
             "function (Peskin 2002 §6)");
    v.boolean("semi_implicit", semi_implicit, "linearised implicit elastic forces (ib/coupling.hpp); false = explicit Peskin");
    v.choice("implicit_mobility", mobility, {ImplicitMobility::stencil, ImplicitMobility::local_mass},
             "fluid response assumed by the semi-implicit force: through the markers' stencils, or each marker alone "
             "(ib/coupling.hpp)");
    v.real("implicit_mass_factor", implicit_mass_factor, "", 1e-6, 100, "local_mass only: added mass per marker in rho dx^2");
    v.real("implicit_theta", implicit_theta, "", 0.5, 1.0,
           "semi-implicit only: elastic force at X^n + theta dt U* (ib/coupling.hpp); 1 = backward Euler, which damps "
           "the recoil; 0.5 = the step's middle");
    v.real("implicit_reuse_tolerance", factor_reuse.tolerance, "", 0, 1e-4,
           "banded solve (>= 300 markers): relative residual accepted when refining on earlier LU factors, else "
           "refactored (ib/reused_banded_solve.hpp); 0 = every step");
  }

  /// "" when usable; otherwise one sentence per problem, joined by "; ".
  std::string validate() const;
};

struct CouplingStepReport {
  fluid::FluidStepReport fluid;
  double max_marker_speed_m_per_s = 0;
};

class ImmersedBoundary2 {
 public:
  /// The fluid and body must outlive this object. Markers start at `markers_m`.
  ImmersedBoundary2(fluid::FluidSolver2& fluid, const ElasticBody& body, std::vector<fluid::Vec2> markers_m,
                    CouplingParams params);

  /// One coupled step of dt_s. Throws std::invalid_argument (a marker too close to a wall, via
  /// Transfer) or fluid::FluidBlowUpError; throws std::runtime_error when a marker stops being finite.
  CouplingStepReport step(double dt_s);

  const std::vector<fluid::Vec2>& markers_m() const { return markers_; }
  /// The force spread in the last step (after the semi-implicit correction), N/m.
  const std::vector<fluid::Vec2>& appliedForce_n_per_m() const { return force_; }
  const CouplingParams& params() const { return params_; }
  /// The banded solve's counts so far: systems solved, factorisations, refinement sweeps.
  const ReusedBandedSolve& bandedSolver() const { return banded_solver_; }

 private:
  void semiImplicitForce(double t1_s, double dt_s);
  void assembleBanded(const Eigen::SparseMatrix<double>& stiffness, double theta_dt_s);
  const std::vector<double>& applyGram(const Eigen::VectorXd& v);
  Eigen::VectorXd solveWithoutAssembly(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& free,
                                       const Eigen::VectorXd& force, double scale, double t1_s, double theta_dt_s);

  fluid::FluidSolver2& fluid_;
  const ElasticBody& body_;
  std::vector<fluid::Vec2> markers_;
  CouplingParams params_;
  Transfer transfer_;
  std::vector<fluid::Vec2> force_, velocity_;
  std::vector<fluid::Vec2> slip_force_;  // the porous markers' F(X^n), N/m
  std::vector<PorousSlip> porous_;
  Eigen::SparseMatrix<double> stiffness_;  // K = ∂F/∂X at X^n (semi-implicit steps)
  Eigen::SparseLU<Eigen::SparseMatrix<double>> slip_solver_;
  void addPorousSlip(double dt_s);
  Eigen::SparseMatrix<double> porousSlipSystem(const std::vector<SlipBlock>& blocks, double dt_s) const;
  void addPorous(const Eigen::VectorXd& x, Eigen::VectorXd& out, double factor) const;
  Eigen::SparseMatrix<double> porousMatrix(int n, double factor) const;  // factor P, 2n × 2n numbering
  std::vector<Eigen::Triplet<double>> triplets_;
  // The stencil mobility's M, the system I − θ dt M K and its LU (kept to reuse their storage).
  Eigen::SparseMatrix<double> mobility_;
  template <class Entry>
  void subtractDtMk(const Eigen::SparseMatrix<double>& stiffness, double dt_s, Entry entry) const;
  void subtractDtMkBanded(const Eigen::SparseMatrix<double>& stiffness);
  int indexMobilityRows(double theta_dt_s);
  Eigen::MatrixXd system_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  // The banded solve (bodies with a solveOrder() of at least kBandedFromMarkers markers): the
  // unknown 2 k + axis of marker order_[k]; slot_[marker] = k.
  std::vector<int> order_, slot_;
  std::vector<int> mobility_rows_;  // the banded index of the row of each stored entry of mobility_
  std::vector<double> mobility_dt_;  // θ dt times each stored entry of mobility_
  std::vector<int> mobility_first_, mobility_last_;  // per column of mobility_, its least and greatest banded row
  std::vector<int> reach_first_, reach_last_;        // per column of the band, the rows assembled (set_reach)
  BandedLU banded_;
  ReusedBandedSolve banded_solver_;
  std::vector<double> banded_rhs_;
  std::vector<double> natural_x_, natural_y_, gram_patch_;  // applyGram's scratch
};

/// Bodies with a solveOrder() and at least this many markers solve the semi-implicit system banded;
/// smaller ones keep the dense LU, so that the grid-following bells up to 128 segments (under 300
/// markers with their tentacles) and their baselines stay bit for bit what they were. At 256
/// segments (419 markers) the banded solve is much faster (tests/bench/bench_jellyfish.cpp,
/// BM_SimulatedSecondPeskin256).
inline constexpr int kBandedFromMarkers = 300;

}  // namespace creaturelab::ib
