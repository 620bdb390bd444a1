// Dense decompositions the tests use to check solvers against, compiled once in one translation unit
// (tests/support/dense_linalg.cpp): each of Eigen's decompositions costs seconds of compile time in
// every test program that instantiates it, in both build trees.
#pragma once

#include <Eigen/Core>

namespace creaturelab::test {

// The eigenvalues of the symmetric matrix a, ascending (Eigen's SelfAdjointEigenSolver).
Eigen::VectorXd symmetricEigenvalues(const Eigen::MatrixXd& a);

// The eigenvalues lambda of a x = lambda b x, a symmetric and b symmetric positive definite,
// ascending (Eigen's GeneralizedSelfAdjointEigenSolver).
Eigen::VectorXd generalizedSymmetricEigenvalues(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

// x with a x = b, by LU with partial pivoting (a invertible).
Eigen::VectorXd luSolve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

// x with a x = b, by the robust Cholesky LDLT (a symmetric, positive or negative semi-definite).
Eigen::VectorXd ldltSolve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

}  // namespace creaturelab::test
