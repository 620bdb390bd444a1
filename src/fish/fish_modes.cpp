#include "fish/fish_modes.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace creaturelab::fish {

RestModes restModes(const FishModel& fish) {
  constexpr int n = 3 * kNodes;
  using Matrix = Eigen::Matrix<double, n, n>;
  Matrix k = Matrix::Zero();
  const auto& net = fish.network;
  const NodeMatrix& x = fish.rest_positions_m;
  for (int e = 0; e < kUnits; ++e) {
    const int a = net.spring_a[e], b = net.spring_b[e];
    const Eigen::Vector3d u = (x.row(b) - x.row(a)).transpose().normalized();
    const Eigen::Matrix3d block = net.stiffness_n_per_m[e] * u * u.transpose();
    k.block<3, 3>(3 * a, 3 * a) += block;
    k.block<3, 3>(3 * b, 3 * b) += block;
    k.block<3, 3>(3 * a, 3 * b) -= block;
    k.block<3, 3>(3 * b, 3 * a) -= block;
  }
  // Symmetric form M^-1/2 K M^-1/2 (M diagonal).
  Eigen::Matrix<double, n, 1> inv_sqrt_m;
  for (int i = 0; i < kNodes; ++i) inv_sqrt_m.segment<3>(3 * i).setConstant(1.0 / std::sqrt(net.mass_kg[i]));
  const Matrix a = inv_sqrt_m.asDiagonal() * k * inv_sqrt_m.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Matrix> eig(a);
  RestModes out;
  const double top = eig.eigenvalues()(n - 1);
  out.highest_rad_per_s = std::sqrt(std::max(0.0, top));
  for (int m = 0; m < n; ++m) {
    const double w2 = eig.eigenvalues()(m);
    if (w2 <= 1e-9 * top) continue;  // the six rigid-body modes
    const Eigen::Matrix<double, n, 1> disp = inv_sqrt_m.asDiagonal() * eig.eigenvectors().col(m);
    double side = 0, all = disp.squaredNorm();
    for (int i = 0; i < kNodes; ++i) side += disp(3 * i + 1) * disp(3 * i + 1);
    if (side > 0.9 * all) {
      out.lowest_lateral_hz = std::sqrt(w2) / (2 * M_PI);
      break;
    }
  }
  return out;
}

}  // namespace creaturelab::fish
