#pragma once
// Immersed-boundary coupling of an elastic body and the 2-D fluid (Peskin 2002, Acta Numerica 11,
// §4 and §6; Rudolf & Mould 2009, seeds/jellyfish-rudolf-mould-2009.txt §3.2): the body's markers
// are massless and move with the fluid velocity interpolated at them; their elastic forces are
// spread onto the grid as the force term F of Eq. 1.
//
// One step of size dt, from (u^n, X^n):
//   1. locate    stencils of X^n (Transfer::locate)
//   2. forces    F = F(X^n, t^{n+1})                                   (the body's elastic forces)
//   3. implicit  optional, see below: F ← F + dt K U*
//   4. spread    f = S F                                              (Peskin 2002 Eq. 6.4)
//   5. fluid     u^{n+1} = fluid step with the force density f        (Eq. 1)
//   6. move      X^{n+1} = X^n + dt I u^{n+1}                          (Peskin 2002 Eq. 6.5)
//
// Stability. Explicit forces make the coupled step stiff (Stockie & Wetton 1999, the paper's ref.
// [28]): a marker spring of stiffness k pushes about ρ dx² of fluid per metre of depth, so steps
// beyond about 2 sqrt(ρ dx² / k) blow up; the bell's angular springs (1.186 N·m/rad on 2 mm
// segments, an effective k ≈ 3e5 N/m) would need dt ≈ 5e-4 s. The paper met the same limit
// (§3.2, §4: "time-steps of the order of 0.01 s begin to hit the stability limits") and used
// CFL with a safety factor of 0.001. Here step 3 makes the elastic force semi-implicit instead:
// the force is evaluated at the predicted positions X^n + dt U*, linearised (K = ∂F/∂X, with
// compressed springs' transverse terms clamped so −K is positive semi-definite), where U* solves
//   (m I − dt² K) U* = m I u^n + dt F
// — backward Euler of the markers with the fluid's response replaced by a local added mass
// m = implicit_mass_factor · ρ dx² per marker. Only the force is changed; the markers still move
// with the fluid, so the coupling stays consistent whatever m is. For stiff modes the force
// tends to −m U/dt, which the fluid (mobility ≤ 1 / (ρ dx²) per marker for both kernels) absorbs
// when implicit_mass_factor ≤ 1; above about 4 the step blows up again.
// What it buys, measured on a closed membrane at dt = 0.01 s on 50² (tests/physics/
// ib_membrane_test.cpp, experiments/jellyfish/membrane.toml): stability always, accuracy only up
// to about twice the explicit limit. With bilinear weights a membrane of k = 1e5 N/m² stays
// within 0.16 cells of a small-step run; at 2e5 it crumples (1.4% area loss), at 5e5 it loses
// 21% in 2 s; Peskin's kernel holds to 2e5 and crumples at 5e5. The jellyfish's chain springs are
// soft (E t / L ≈ 2 N/m); its angular springs are stiff but act on bending only, and its bell
// stays smooth at 0.01 s (analysis/plot_jellyfish.py film strips; its converged quantities are
// listed in the issue-5 note).
#include <span>
#include <vector>

#include <Eigen/SparseCore>

#include "fluid/fluid_solver2.hpp"
#include "ib/kernel.hpp"
#include "ib/transfer.hpp"

namespace creaturelab::ib {

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
};

struct CouplingParams {
  Kernel kernel = Kernel::bilinear;  // the paper's choice (§3.2)
  bool semi_implicit = true;
  double implicit_mass_factor = 1.0;  // m = factor · ρ dx², see above
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
  const std::vector<fluid::Vec2>& applied_force_n_per_m() const { return force_; }
  const CouplingParams& params() const { return params_; }

 private:
  void semiImplicitForce(double t1_s, double dt_s);

  fluid::FluidSolver2& fluid_;
  const ElasticBody& body_;
  std::vector<fluid::Vec2> markers_;
  CouplingParams params_;
  Transfer transfer_;
  std::vector<fluid::Vec2> force_, velocity_;
  std::vector<Eigen::Triplet<double>> triplets_;
};

}  // namespace creaturelab::ib
