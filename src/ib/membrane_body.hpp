#pragma once
// A closed elastic membrane: the classic test of the immersed boundary method (Peskin 2002, Acta
// Numerica 11, the jellyfish paper's ref. [19]; an ellipse relaxing to a circle as in Tu & Peskin
// 1992, SIAM J. Sci. Stat. Comput. 13). It tests the coupling of coupling.hpp (Rudolf & Mould 2009 §3.2).
// N markers start on an ellipse and are joined in a ring by Hookean springs of ZERO rest length:
//
//   E = ½ k Σ_k |X_{k+1} − X_k|²,      F_k = −∂E/∂X_k = k (X_{k+1} − 2 X_k + X_{k−1}),
//
// the discrete form of Peskin's elastic fibre force F = ∂/∂s (T τ) (Peskin 2002) with a tension
// T = k |∂X/∂s| that grows with stretching and never vanishes: the tension of segment k is
// k |X_{k+1} − X_k|, N/m per metre of depth. k is N/m per metre of depth
// (N/m², a force per metre of depth per metre of stretch), indices are taken modulo N.
//
// Why zero rest length (and not springs of a small rest length, springs::System):
//  - The force is linear in X, so ∂F/∂X is a constant (k times the ring's graph Laplacian, ⊗ I₂)
//    and exactly negative semi-definite. The semi-implicit coupling (coupling.hpp) then solves the
//    true backward-Euler system, with nothing clamped: the test measures the coupling, not a
//    linearisation of the body.
//  - With a rest length r > 0, segments shorter than r push, and a ring of pushing springs can
//    buckle; with r = 0 every segment pulls, always.
//  - The membrane is always under tension: its elastic energy is least for the shortest perimeter,
//    so it relaxes to the circle of the same area (the fluid is incompressible), which it then
//    holds by a pressure jump Δp = T / R across it (Laplace's law). The only way the enclosed area
//    can change is fluid leaking through the membrane: numerical (the interpolated velocity is not
//    exactly divergence free; Peskin & Printz 1993, J. Comput. Phys. 105), driven by Δp. That leak is what the test
//    measures. (springs::Network also refuses rest lengths ≤ 0.)
// The energy is minimised at fixed area by a regular N-gon: markers end equally spaced.
#include <span>
#include <string>
#include <vector>

#include "ib/coupling.hpp"

namespace creaturelab::ib {

/// The ellipse the membrane starts on and its spring constant. Plain struct; validate() says
/// what is wrong.
struct MembraneParams {
  double centre_x_m = 0.5;
  double centre_y_m = 0.5;
  double semi_axis_x_m = 0.25;   ///< along x
  double semi_axis_y_m = 0.15;   ///< along y
  int markers = 256;             ///< N ≥ 3, equally spaced in arc length on the ellipse
  /// k per metre of depth (N/m²), > 0; about the jellyfish bell mesoglea's E t / L.
  double stiffness_n_per_m = 2000.0;

  /// semi_axis_x_m, semi_axis_y_m, markers, stiffness_n_per_m for the membrane kind
  /// (kinds/describe.hpp); the centre is the kind's box's.
  template <class V>
  void describe(V& v) {
    v.real("semi_axis_x_m", semi_axis_x_m, "m", 1e-6, 100, "initial ellipse's semi-axis along x (centred in the box)");
    v.real("semi_axis_y_m", semi_axis_y_m, "m", 1e-6, 100, "initial ellipse's semi-axis along y");
    v.integer("markers", markers, 3, 100000,
              "markers, equally spaced on the ellipse; keep them < dx/2 apart (gaps of 1-2 cells leak)");
    v.real("stiffness_n_per_m", stiffness_n_per_m, "N/m^2", 1e-12, 1e12,
           "zero-rest-length spring constant, N/m per metre of depth; tension = k x segment length");
  }

  /// "" when usable; otherwise one sentence per problem, joined by "; ".
  std::string validate() const;
};

/// N points equally spaced in arc length on the ellipse, counter-clockwise, the first at
/// (centre_x + semi_axis_x, centre_y). Arc length by the composite midpoint rule on 64 N
/// sub-intervals of the angle, inverted linearly: the arcs between neighbours are equal to a
/// relative 1e-4 (measured 1e-6 to 7e-5 for N = 3..256 and aspect ratios up to 10; exact for a
/// circle). Throws std::invalid_argument with validate()'s message.
std::vector<fluid::Vec2> ellipseMarkers(const MembraneParams& params);

/// The ring of zero-rest-length springs above, as the immersed boundary sees it.
class MembraneBody : public ElasticBody {
 public:
  /// Throws std::invalid_argument if markers < 3 or the stiffness is not a positive number.
  MembraneBody(int markers, double stiffness_n_per_m);

  int markerCount() const override { return markers_; }
  /// F_k = k (X_{k+1} − 2 X_k + X_{k−1}); time-independent.
  void forces(double t_s, std::span<const fluid::Vec2> x_m, std::span<fluid::Vec2> force_n_per_m) const override;
  /// scale · ∂F/∂X = scale · k (ring Laplacian) ⊗ I₂, whatever x_m is (nothing to clamp).
  void stiffness(double t_s, std::span<const fluid::Vec2> x_m, double scale,
                 std::vector<Eigen::Triplet<double>>& out) const override;

  /// ½ k Σ |X_{k+1} − X_k|², J per metre of depth.
  double elasticEnergy(std::span<const fluid::Vec2> x_m) const;
  /// Mean segment tension k |X_{k+1} − X_k|, N/m (per metre of depth).
  double meanTension(std::span<const fluid::Vec2> x_m) const;
  double stiffness_n_per_m() const { return k_; }

 private:
  int markers_;
  double k_;
};

/// Shape measures of a closed polygon (the markers in order, not repeated at the end).
struct PolygonShape {
  double area_m2 = 0;      ///< signed shoelace area, > 0 counter-clockwise
  fluid::Vec2 centroid_m;  ///< centroid of the enclosed area
  double perimeter_m = 0;
  /// sqrt(λ_max / λ_min) of the area's second-moment tensor about the centroid: a / b for an
  /// ellipse of semi-axes a ≥ b (its second moments are π a³ b / 4 and π a b³ / 4), 1 for a
  /// regular polygon, whatever its orientation. NaN for a degenerate polygon.
  double aspect_ratio = 0;
};
PolygonShape polygonShape(std::span<const fluid::Vec2> x_m);

}  // namespace creaturelab::ib
