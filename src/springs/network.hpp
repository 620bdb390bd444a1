#pragma once
// Particles and springs stored as arrays (struct of arrays), the model of thesis ch. 4
// (Mehla 2005 §4.2, Figs. 4.5-4.6): one entry per particle or spring, so the
// force loop of System is a tight pass over contiguous arrays instead of chasing pointers.
// Positions and velocities are not stored here: they live in State, which integrators own.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace creaturelab::springs {

template <int D> using Vec = Eigen::Matrix<double, D, 1>;
// One column per particle: the D coordinates of a particle are contiguous in memory.
template <int D> using Points = Eigen::Matrix<double, D, Eigen::Dynamic>;

template <int D> struct State {
  Points<D> x_m;        // positions, metres
  Points<D> v_m_per_s;  // velocities, metres per second
};

// A state with `particle_count` particles, all at the origin and at rest.
template <int D> State<D> zeroState(int particle_count);

template <int D> struct Network {
  // Per particle.
  Eigen::VectorXd mass_kg;     // kilograms, > 0 for every particle
  std::vector<uint8_t> pinned; // 1 = fixed: receives no force (moves only with a velocity set by hand)

  // Damped Hookean springs, thesis Eq. 4.14-4.15:
  //   f_a = -[k_s (|l| - r) + k_d (l' . l)/|l|] l/|l|,  f_b = -f_a,  l = x_a - x_b.
  std::vector<int> spring_a, spring_b;
  std::vector<double> rest_length_m;       // r, metres, > 0
  std::vector<double> stiffness_n_per_m;   // k_s, newtons per metre, > 0
  std::vector<double> damping_ns_per_m;    // k_d, newton seconds per metre, >= 0

  // Angular (bending) springs at joint j between segments (i,j) and (j,k):
  //   E = 0.5 kb (theta - theta0)^2.
  // theta is the turning angle between a = x_j - x_i and b = x_k - x_j (0 for a straight chain).
  // 2D: signed, atan2(a x b, a . b) in (-pi, pi], so a curved rest shape (jellyfish bell) keeps
  //     its handedness; theta - theta0 is wrapped into [-pi, pi] (bend.hpp).
  // 3D: unsigned, atan2(|a x b|, a . b) in [0, pi]; see bend.hpp for the straight-chain guard.
  std::vector<int> bend_i, bend_j, bend_k;
  std::vector<double> rest_angle_rad;            // theta0, radians
  std::vector<double> bend_stiffness_nm_per_rad; // kb, newton metres per radian (energy per rad^2), >= 0

  Vec<D> gravity_m_per_s2 = Vec<D>::Zero();  // Eq. 4.6: f = m g, metres per second squared
  double drag_ns_per_m = 0;                  // Eq. 4.7: f = -k_d v, same coefficient for every particle

  // Appends one particle and returns its index.
  int addParticle(double mass_kg, bool pinned);
  // Appends one spring between particles a and b and returns its index.
  int addSpring(int a, int b, double rest_m, double k_n_per_m, double damping_ns_per_m = 0);
  // Appends one angular spring at joint j of segments (i,j), (j,k) and returns its index.
  int addBend(int i, int j, int k, double rest_angle_rad, double kb);

  int particleCount() const { return static_cast<int>(mass_kg.size()); }
  int springCount() const { return static_cast<int>(spring_a.size()); }
  int bendCount() const { return static_cast<int>(bend_i.size()); }

  // "" when the network can be simulated; otherwise a sentence naming the first problem found
  // (array lengths, bad particle index, non-positive mass / rest length / stiffness, ...).
  std::string validate() const;
};

// Turning angle at joint j, as defined above (signed in 2D, unsigned in 3D). Use it to take a
// bend's rest angle from a drawn shape: addBend(i, j, k, turningAngleRad<D>(xi, xj, xk), kb).
template <int D> double turningAngleRad(const Vec<D>& xi, const Vec<D>& xj, const Vec<D>& xk);

extern template struct Network<2>;
extern template struct Network<3>;

}  // namespace creaturelab::springs
