#include "springs/network.hpp"

#include <cmath>
#include <sstream>

#include "springs/bend.hpp"

namespace creaturelab::springs {

template <int D> State<D> zeroState(int particle_count) {
  State<D> s;
  s.x_m = Points<D>::Zero(D, particle_count);
  s.v_m_per_s = Points<D>::Zero(D, particle_count);
  return s;
}

template <int D> int Network<D>::addParticle(double mass, bool is_pinned) {
  const Eigen::Index n = mass_kg.size();
  mass_kg.conservativeResize(n + 1);
  mass_kg[n] = mass;
  pinned.push_back(is_pinned ? 1 : 0);
  return static_cast<int>(n);
}

template <int D> int Network<D>::addSpring(int a, int b, double rest_m, double k_n_per_m, double damping) {
  spring_a.push_back(a);
  spring_b.push_back(b);
  rest_length_m.push_back(rest_m);
  stiffness_n_per_m.push_back(k_n_per_m);
  damping_ns_per_m.push_back(damping);
  return static_cast<int>(spring_a.size()) - 1;
}

template <int D> int Network<D>::addBend(int i, int j, int k, double rest_angle, double kb) {
  bend_i.push_back(i);
  bend_j.push_back(j);
  bend_k.push_back(k);
  rest_angle_rad.push_back(rest_angle);
  bend_stiffness_nm_per_rad.push_back(kb);
  return static_cast<int>(bend_i.size()) - 1;
}


template <int D> std::string Network<D>::validate() const {
  std::ostringstream msg;
  const int n = particleCount();
  if (pinned.size() != static_cast<size_t>(n)) {
    msg << "pinned has " << pinned.size() << " entries but there are " << n << " particles";
    return msg.str();
  }
  for (int p = 0; p < n; ++p) {
    if (!(mass_kg[p] > 0) || !std::isfinite(mass_kg[p])) {
      msg << "particle " << p << " has mass " << mass_kg[p] << " kg; masses must be positive and finite";
      return msg.str();
    }
  }
  const size_t ns = spring_a.size();
  if (spring_b.size() != ns || rest_length_m.size() != ns || stiffness_n_per_m.size() != ns ||
      damping_ns_per_m.size() != ns) {
    msg << "spring arrays differ in length (spring_a " << ns << ", spring_b " << spring_b.size()
        << ", rest_length_m " << rest_length_m.size() << ", stiffness_n_per_m " << stiffness_n_per_m.size()
        << ", damping_ns_per_m " << damping_ns_per_m.size() << ")";
    return msg.str();
  }
  for (size_t s = 0; s < ns; ++s) {
    const int a = spring_a[s], b = spring_b[s];
    if (a < 0 || a >= n || b < 0 || b >= n) {
      msg << "spring " << s << " joins particles " << a << " and " << b << ", but particles are numbered 0 to "
          << n - 1;
      return msg.str();
    }
    if (a == b) {
      msg << "spring " << s << " joins particle " << a << " to itself";
      return msg.str();
    }
    if (!(rest_length_m[s] > 0) || !std::isfinite(rest_length_m[s])) {
      msg << "spring " << s << " has rest length " << rest_length_m[s] << " m; rest lengths must be positive";
      return msg.str();
    }
    if (!(stiffness_n_per_m[s] > 0) || !std::isfinite(stiffness_n_per_m[s])) {
      msg << "spring " << s << " has stiffness " << stiffness_n_per_m[s] << " N/m; stiffness must be positive";
      return msg.str();
    }
    if (!(damping_ns_per_m[s] >= 0) || !std::isfinite(damping_ns_per_m[s])) {
      msg << "spring " << s << " has damping " << damping_ns_per_m[s] << " N s/m; damping must be zero or positive";
      return msg.str();
    }
  }
  const size_t nb = bend_i.size();
  if (bend_j.size() != nb || bend_k.size() != nb || rest_angle_rad.size() != nb ||
      bend_stiffness_nm_per_rad.size() != nb) {
    msg << "bend arrays differ in length (bend_i " << nb << ", bend_j " << bend_j.size() << ", bend_k "
        << bend_k.size() << ", rest_angle_rad " << rest_angle_rad.size() << ", bend_stiffness_nm_per_rad "
        << bend_stiffness_nm_per_rad.size() << ")";
    return msg.str();
  }
  for (size_t b = 0; b < nb; ++b) {
    const int i = bend_i[b], j = bend_j[b], k = bend_k[b];
    if (i < 0 || i >= n || j < 0 || j >= n || k < 0 || k >= n) {
      msg << "bend " << b << " uses particles " << i << ", " << j << ", " << k
          << ", but particles are numbered 0 to " << n - 1;
      return msg.str();
    }
    if (i == j || j == k || i == k) {
      msg << "bend " << b << " needs three different particles, got " << i << ", " << j << ", " << k;
      return msg.str();
    }
    if (!(bend_stiffness_nm_per_rad[b] >= 0) || !std::isfinite(bend_stiffness_nm_per_rad[b])) {
      msg << "bend " << b << " has stiffness " << bend_stiffness_nm_per_rad[b]
          << " N m/rad; bend stiffness must be zero or positive";
      return msg.str();
    }
    const double lo = D == 2 ? -M_PI : 0.0;
    if (!(rest_angle_rad[b] >= lo && rest_angle_rad[b] <= M_PI)) {
      msg << "bend " << b << " has rest angle " << rest_angle_rad[b] << " rad; in " << D
          << "D it must lie in [" << (D == 2 ? "-pi" : "0") << ", pi]";
      return msg.str();
    }
  }
  if (!gravity_m_per_s2.allFinite()) return "gravity_m_per_s2 is not finite";
  if (!(drag_ns_per_m >= 0) || !std::isfinite(drag_ns_per_m)) {
    msg << "drag_ns_per_m is " << drag_ns_per_m << " N s/m; drag must be zero or positive";
    return msg.str();
  }
  return "";
}

template <int D> double turningAngleRad(const Vec<D>& xi, const Vec<D>& xj, const Vec<D>& xk) {
  return bendAngle<D>(xj - xi, xk - xj);
}

template struct Network<2>;
template struct Network<3>;
template State<2> zeroState<2>(int);
template State<3> zeroState<3>(int);
template double turningAngleRad<2>(const Vec<2>&, const Vec<2>&, const Vec<2>&);
template double turningAngleRad<3>(const Vec<3>&, const Vec<3>&, const Vec<3>&);

}  // namespace creaturelab::springs
