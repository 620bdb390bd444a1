#include "springs/stability.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

#include "springs/bend.hpp"

namespace creaturelab::springs {

namespace {

template <int D> using Mat = Eigen::Matrix<double, D, D>;

// Spectral norm of a D x D block.
template <int D> double spectralNorm(const Mat<D>& b) {
  const Mat<D> btb = b.transpose() * b;
  Eigen::SelfAdjointEigenSolver<Mat<D>> eig(btb, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
}

// Spectral radius of a symmetric D x D block.
template <int D> double spectralRadius(const Mat<D>& b) {
  Eigen::SelfAdjointEigenSolver<Mat<D>> eig(0.5 * (b + b.transpose()), Eigen::EigenvaluesOnly);
  return eig.eigenvalues().cwiseAbs().maxCoeff();
}

// Accumulates the row data both Gershgorin forms need.
template <int D> struct Rows {
  std::vector<Mat<D>> diag;            // K_ii
  std::vector<double> offdiag_norm;    // sum_j ||K_ij||_2
  Eigen::Matrix<double, D, Eigen::Dynamic> offdiag_abs;  // per coordinate: sum over j != i of |K_ij(r, c)|
  const std::vector<uint8_t>& pinned;

  Rows(int n, const std::vector<uint8_t>& p)
      : diag(n, Mat<D>::Zero()), offdiag_norm(n, 0.0), offdiag_abs(Eigen::Matrix<double, D, Eigen::Dynamic>::Zero(D, n)),
        pinned(p) {}

  void addDiag(int i, const Mat<D>& b) {
    if (!pinned[i]) diag[i] += b;
  }
  // Off-diagonal block K_ij (row particle i, column particle j); pinned columns are eliminated.
  void addOffdiag(int i, int j, const Mat<D>& b, double norm) {
    if (pinned[i] || pinned[j]) return;
    offdiag_norm[i] += norm;
    offdiag_abs.col(i) += b.cwiseAbs().rowwise().sum();
  }
};

}  // namespace

template <int D> double estimateOmegaMaxRadPerS(const Network<D>& network, const State<D>& s) {
  const int n = network.particleCount();
  Rows<D> rows(n, network.pinned);
  for (int e = 0; e < network.springCount(); ++e) {
    const int a = network.spring_a[e], b = network.spring_b[e];
    const double k = network.stiffness_n_per_m[e];
    const Vec<D> l = s.x_m.col(a) - s.x_m.col(b);
    const double len = l.norm();
    // Stiffness block B = k u u^T + k tau (I - u u^T), tau = 1 - r/|l| (System::addStiffnessTriplets);
    // its eigenvalues are k (along the spring) and k tau (across), so ||B||_2 = k max(1, |tau|).
    Mat<D> block = k * Mat<D>::Identity();
    double norm = k;
    if (len > 0) {
      const Vec<D> u = l / len;
      const double tau = 1.0 - network.rest_length_m[e] / len;
      block = k * tau * Mat<D>::Identity() + k * (1.0 - tau) * u * u.transpose();
      norm = k * std::max(1.0, std::abs(tau));
    }
    rows.addDiag(a, block);
    rows.addDiag(b, block);
    rows.addOffdiag(a, b, block, norm);
    rows.addOffdiag(b, a, block, norm);
  }
  for (int e = 0; e < network.bendCount(); ++e) {
    const int idx[3] = {network.bend_i[e], network.bend_j[e], network.bend_k[e]};
    const Vec<D> a = s.x_m.col(idx[1]) - s.x_m.col(idx[0]);
    const Vec<D> b = s.x_m.col(idx[2]) - s.x_m.col(idx[1]);
    const Eigen::Matrix<double, 3 * D, 3 * D> h =
        bendEnergyHessian<D>(a, b, network.rest_angle_rad[e], network.bend_stiffness_nm_per_rad[e], false);
    for (int r = 0; r < 3; ++r) {
      rows.addDiag(idx[r], h.template block<D, D>(D * r, D * r));
      for (int c = 0; c < 3; ++c) {
        if (c == r) continue;
        const Mat<D> blk = h.template block<D, D>(D * r, D * c);
        rows.addOffdiag(idx[r], idx[c], blk, spectralNorm<D>(blk));
      }
    }
  }
  double block_bound = 0, scalar_bound = 0;
  for (int i = 0; i < n; ++i) {
    if (network.pinned[i]) continue;
    const double inv_m = 1.0 / network.mass_kg[i];
    block_bound = std::max(block_bound, (spectralRadius<D>(rows.diag[i]) + rows.offdiag_norm[i]) * inv_m);
    const Vec<D> row_abs = rows.diag[i].cwiseAbs().rowwise().sum() + rows.offdiag_abs.col(i);
    scalar_bound = std::max(scalar_bound, row_abs.maxCoeff() * inv_m);
  }
  return std::sqrt(std::min(block_bound, scalar_bound));
}

template <int D> DampingRatioBounds estimateDampingRatio(const Network<D>& network, double omega_max_rad_per_s) {
  if (!(omega_max_rad_per_s > 0)) return {0.0, 0.0};
  const int n = network.particleCount();
  std::vector<double> spring_damping(n, 0.0);
  for (int e = 0; e < network.springCount(); ++e) {
    spring_damping[network.spring_a[e]] += network.damping_ns_per_m[e];
    spring_damping[network.spring_b[e]] += network.damping_ns_per_m[e];
  }
  double low = std::numeric_limits<double>::infinity(), high = 0;
  for (int i = 0; i < n; ++i) {
    if (network.pinned[i]) continue;
    const double denom = 2.0 * network.mass_kg[i] * omega_max_rad_per_s;
    low = std::min(low, network.drag_ns_per_m / denom);
    // Gershgorin on M^-1 C: each spring's damping block k_d u u^T appears on the diagonal and once
    // off it, each of norm k_d.
    high = std::max(high, (network.drag_ns_per_m + 2.0 * spring_damping[i]) / denom);
  }
  if (high == 0 && low == std::numeric_limits<double>::infinity()) low = 0;
  return {low, high};
}

namespace {

// |R(z)| for RK4's stability polynomial R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24.
double rk4Amplification(std::complex<double> z) {
  return std::abs(1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0))));
}

// Largest a with |R(a * dir)| <= 1 for all of (0, a]: scan, then bisect the first crossing.
double rk4LimitAlongRay(std::complex<double> dir) {
  const double step = 1e-3;
  double stable = 0;
  for (double a = step; a < 10.0; a += step) {
    if (rk4Amplification(a * dir) > 1.0) {
      double lo = stable, hi = a;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (rk4Amplification(mid * dir) > 1.0 ? hi : lo) = mid;
      }
      return lo;
    }
    stable = a;
  }
  return stable;
}

}  // namespace

double stabilityLimitOmegaDt(IntegratorKind kind, double zeta) {
  zeta = std::max(0.0, zeta);
  switch (kind) {
    case IntegratorKind::ExplicitEuler:
      // Eigenvalues omega (-zeta +- i sqrt(1 - zeta^2)): |1 + h lambda|^2 <= 1 <=> omega h <= 2 zeta.
      // Overdamped: both real eigenvalues need h |lambda| <= 2.
      if (zeta <= 1) return 2.0 * zeta;
      return 2.0 / (zeta + std::sqrt(zeta * zeta - 1.0));
    case IntegratorKind::SymplecticEuler:
      // Step matrix on (x, v) with a = omega h: trace 2 - a^2 - 2 zeta a, det 1 - 2 zeta a.
      // Jury: |det| <= 1 and |trace| <= 1 + det  <=>  a^2 + 4 zeta a - 4 <= 0.
      return 2.0 / (zeta + std::sqrt(zeta * zeta + 1.0));
    case IntegratorKind::RK4:
      if (zeta < 1) return rk4LimitAlongRay({-zeta, std::sqrt(1.0 - zeta * zeta)});
      // Overdamped: the faster real eigenvalue omega (zeta + sqrt(zeta^2 - 1)) binds.
      return rk4LimitAlongRay({-1.0, 0.0}) / (zeta + std::sqrt(zeta * zeta - 1.0));
    case IntegratorKind::ImplicitEuler:
      return std::numeric_limits<double>::infinity();
  }
  return 0;
}

double autoStepS(IntegratorKind kind, double omega_max_rad_per_s, double damping_ratio, double safety) {
  const double limit = stabilityLimitOmegaDt(kind, damping_ratio);
  if (std::isinf(limit) || !(omega_max_rad_per_s > 0)) return std::numeric_limits<double>::infinity();
  return safety * limit / omega_max_rad_per_s;
}

template double estimateOmegaMaxRadPerS<2>(const Network<2>&, const State<2>&);
template double estimateOmegaMaxRadPerS<3>(const Network<3>&, const State<3>&);
template DampingRatioBounds estimateDampingRatio<2>(const Network<2>&, double);
template DampingRatioBounds estimateDampingRatio<3>(const Network<3>&, double);

}  // namespace creaturelab::springs
