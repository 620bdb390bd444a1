#pragma once
// Angular (bending) spring kernel: the turning angle theta between segments a = x_j - x_i and
// b = x_k - x_j, its gradient and the Hessian of E = 0.5 kb (theta - theta0)^2.
// Not in the thesis (its strands have no bending stiffness); needed for the jellyfish bell, whose
// curved rest shape must be kept, hence the signed angle in 2D.
//
// Both dimensions use theta = atan2(s, c) with c = a . b and s the "sine part":
//   2D  s = a_x b_y - a_y b_x (signed),   3D  s = |a x b| (unsigned).
// Then  d theta = (c ds - s dc) / r2,  r2 = s^2 + c^2 = |a|^2 |b|^2,  which stays accurate at
// every angle (acos(c / |a||b|) loses all digits near 0 and pi — the rejected alternative).
// 3D straight-chain guard: |a x b| is not differentiable at a x b = 0, so there the gradient of s
// is taken as 0 (theta's gradient then vanishes: zero force, a cone tip of E when theta0 != 0) and
// the Hessian uses the smooth small-angle limit of 0.5 kb theta^2 (exact when theta0 = 0) or only
// its Gauss-Newton part otherwise.
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "springs/network.hpp"

namespace creaturelab::springs {

template <int D> struct AngleGradient {
  double theta;  // radians
  Vec<D> d_da;   // d theta / d a
  Vec<D> d_db;   // d theta / d b
};

namespace bend_detail {
// Below this |a x b| / (|a||b|) the 3D angle is treated as straight (or folded back).
inline constexpr double kStraightSine = 1e-7;

inline Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}
}  // namespace bend_detail

template <int D> inline double bendAngle(const Vec<D>& a, const Vec<D>& b) {
  static_assert(D == 2 || D == 3);
  if constexpr (D == 2) {
    return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  } else {
    return std::atan2(a.cross(b).norm(), a.dot(b));
  }
}

// theta - theta0 as used in E = 0.5 kb (theta - theta0)^2. In 2D it is wrapped into [-pi, pi], so
// the energy is continuous where the signed angle jumps from pi to -pi (a joint folding back);
// it is discontinuous only at the opposite of the rest angle. In 3D both lie in [0, pi].
template <int D> inline double bendDeviation(double theta, double theta0) {
  if constexpr (D == 2) {
    return std::remainder(theta - theta0, 2 * M_PI);
  } else {
    return theta - theta0;
  }
}

template <int D> inline AngleGradient<D> angleGradient(const Vec<D>& a, const Vec<D>& b) {
  static_assert(D == 2 || D == 3);
  const double c = a.dot(b);
  AngleGradient<D> g;
  double s;
  Vec<D> ds_da, ds_db;
  if constexpr (D == 2) {
    s = a.x() * b.y() - a.y() * b.x();
    ds_da = Vec<D>(b.y(), -b.x());
    ds_db = Vec<D>(-a.y(), a.x());
  } else {
    const Eigen::Vector3d n = a.cross(b);
    s = n.norm();
    if (s > 0) {
      const Eigen::Vector3d nh = n / s;
      ds_da = b.cross(nh);
      ds_db = nh.cross(a);
    } else {
      ds_da.setZero();
      ds_db.setZero();
    }
  }
  const double r2 = s * s + c * c;
  g.theta = std::atan2(s, c);
  if (r2 > 0) {
    g.d_da = (c * ds_da - s * b) / r2;
    g.d_db = (c * ds_db - s * a) / r2;
  } else {
    g.d_da.setZero();
    g.d_db.setZero();
  }
  return g;
}

// Hessian of E = 0.5 kb (theta - theta0)^2 with respect to (x_i, x_j, x_k), stacked in that order.
// gauss_newton_only keeps kb grad(theta) grad(theta)^T (positive semi-definite).
template <int D>
Eigen::Matrix<double, 3 * D, 3 * D> bendEnergyHessian(const Vec<D>& a, const Vec<D>& b, double theta0, double kb,
                                                      bool gauss_newton_only) {
  static_assert(D == 2 || D == 3);
  using MatQ = Eigen::Matrix<double, 2 * D, 2 * D>;
  using VecQ = Eigen::Matrix<double, 2 * D, 1>;
  const AngleGradient<D> ag = angleGradient<D>(a, b);
  VecQ g;
  g << ag.d_da, ag.d_db;
  MatQ hq = kb * g * g.transpose();

  const double c = a.dot(b);
  const double r2 = a.squaredNorm() * b.squaredNorm();
  if (!gauss_newton_only && r2 > 0) {
    VecQ grad_c;
    grad_c << b, a;
    MatQ h_c = MatQ::Zero();
    h_c.template block<D, D>(0, D).setIdentity();
    h_c.template block<D, D>(D, 0).setIdentity();
    double s;
    VecQ grad_s;
    MatQ h_s = MatQ::Zero();
    bool straight = false;
    Eigen::Matrix<double, 3, 2 * D> n_jac;  // 3D only: d(a x b)/d(a, b)
    if constexpr (D == 2) {
      s = a.x() * b.y() - a.y() * b.x();
      grad_s << b.y(), -b.x(), -a.y(), a.x();
      h_s(0, 3) = 1;   // d2 s / da_x db_y
      h_s(1, 2) = -1;  // d2 s / da_y db_x
      h_s(3, 0) = 1;
      h_s(2, 1) = -1;
    } else {
      const Eigen::Vector3d n = a.cross(b);
      s = n.norm();
      n_jac << -bend_detail::skew(b), bend_detail::skew(a);
      if (s > bend_detail::kStraightSine * std::sqrt(r2)) {
        const Eigen::Vector3d nh = n / s;
        grad_s = n_jac.transpose() * nh;
        h_s = n_jac.transpose() * (Eigen::Matrix3d::Identity() - nh * nh.transpose()) * n_jac / s;
        h_s.template block<3, 3>(0, 3) -= bend_detail::skew(nh);
        h_s.template block<3, 3>(3, 0) += bend_detail::skew(nh);
      } else {
        straight = true;
      }
    }
    if (!straight) {
      const MatQ h_theta = (grad_s * grad_c.transpose() - grad_c * grad_s.transpose() + c * h_s - s * h_c) / r2 -
                           g * (2 * s * grad_s + 2 * c * grad_c).transpose() / r2;
      hq += kb * bendDeviation<D>(ag.theta, theta0) * 0.5 * (h_theta + h_theta.transpose());
    } else if constexpr (D == 3) {
      // Smooth limit: near theta = 0, theta^2 = |a x b|^2 / r2 + O(theta^4), whose Hessian at
      // a x b = 0 is 2 N^T N / r2 (N = d(a x b)/d(a,b)); same at theta = pi with (pi - theta)^2.
      const bool rest_matches = (c > 0 && theta0 == 0) || (c < 0 && theta0 == M_PI);
      if (rest_matches) hq = kb * n_jac.transpose() * n_jac / r2;
    }
  }
  // x-space: a = x_j - x_i, b = x_k - x_j  ->  q = T x.
  Eigen::Matrix<double, 2 * D, 3 * D> t = Eigen::Matrix<double, 2 * D, 3 * D>::Zero();
  t.template block<D, D>(0, 0) = -Eigen::Matrix<double, D, D>::Identity();
  t.template block<D, D>(0, D) = Eigen::Matrix<double, D, D>::Identity();
  t.template block<D, D>(D, D) = -Eigen::Matrix<double, D, D>::Identity();
  t.template block<D, D>(D, 2 * D) = Eigen::Matrix<double, D, D>::Identity();
  return t.transpose() * hq * t;
}

}  // namespace creaturelab::springs
