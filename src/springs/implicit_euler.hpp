#pragma once
// Linearised backward Euler after Baraff & Witkin, "Large steps in cloth simulation", SIGGRAPH
// 1998, Eq. 15-16: one Newton step of v1 = v0 + h M^-1 f(x0 + h v1, v1) per time step,
//   (M - h df/dv - h^2 df/dx) dv = h (f0 + h df/dx v0),   v1 = v0 + dv,   x1 = x0 + h v1.
// The thesis (Mehla 2005 §4.2, §5.1) calls implicit integration "non-trivial
// and not recommended"; it is here because it is the way to the taut strands the thesis could
// not reach with explicit steps.
// The matrix is assembled sparse over the free coordinates only (pinned rows and columns
// eliminated: their dv is 0) and solved by Eigen's ConjugateGradient with a Jacobi
// preconditioner. CG needs a symmetric positive definite matrix, so df/dx is taken with
// clamp_compression (System::addStiffnessTriplets): compressed springs lose their negative
// transverse stiffness, bends keep only their Gauss-Newton part. That changes only the
// linearisation, not the forces, so the step stays first-order accurate.
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "springs/integrator.hpp"

namespace creaturelab::springs {

template <int D> class ImplicitEuler final : public Integrator<D> {
 public:
  // Relative residual |A dv - rhs| / |rhs| at which CG stops.
  explicit ImplicitEuler(double cg_tolerance = 1e-12) : cg_tolerance_(cg_tolerance) {}
  void step(const System<D>& system, State<D>& s, const StepContext& ctx) override;
  int lastCgIterations() const { return last_cg_iterations_; }
  double lastCgRelativeResidual() const { return last_cg_error_; }

 private:
  void assemble(double h, int free_dofs);

  double cg_tolerance_;
  int last_cg_iterations_ = 0;
  double last_cg_error_ = 0;
  Points<D> f0_;
  std::vector<Eigen::Triplet<double>> stiffness_, damping_;
  std::vector<int> reduced_;      // full coordinate -> free coordinate, -1 when pinned
  Eigen::VectorXd mass_of_free_;  // kg, per free coordinate
  // A's sparsity pattern is the same every step for a given system: it is built once and later
  // steps only refill the values through slot_ (index of each triplet's entry in A's values).
  std::vector<int> pattern_rows_, pattern_cols_, slot_;
  Eigen::SparseMatrix<double> a_;
  Eigen::VectorXd rhs_, dv_;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg_;
};

extern template class ImplicitEuler<2>;
extern template class ImplicitEuler<3>;

}  // namespace creaturelab::springs
