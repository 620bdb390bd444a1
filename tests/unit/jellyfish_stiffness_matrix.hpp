#pragma once
// Test support shared by the jellyfish body tests: the body's stiffness as a dense matrix.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "jellyfish/jellyfish_body.hpp"

namespace creaturelab::jellyfish::testing {

/// Dense dF/dX from the body's triplets (numbering 2 * marker + axis).
inline Eigen::MatrixXd stiffnessMatrix(const JellyfishBody& body, double t_s, const std::vector<fluid::Vec2>& x_m) {
  std::vector<Eigen::Triplet<double>> triplets;
  body.stiffness(t_s, x_m, 1.0, triplets);
  const int n = 2 * static_cast<int>(x_m.size());
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(triplets.begin(), triplets.end());
  return Eigen::MatrixXd(k);
}

}  // namespace creaturelab::jellyfish::testing
