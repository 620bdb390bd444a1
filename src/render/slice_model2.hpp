#pragma once
// The 2-D render model of the jellyfish slice (Rudolf & Mould 2009
// §3.4): the simulation's point masses are the subumbrellar surface; "we can generate the exumbrellar
// side by computing surface normals at each point-mass, and then projecting backward through the
// thickness of the umbrella", then "generate an arbitrary resolution model for rendering by
// interpolating a cubic spline through the original point-masses and then the newly generated
// exumbrellar points". Tentacles: the same, with their own thickness. Pure geometry: no I/O.
//
// Splines: Eigen's unsupported Splines module (B-spline interpolation of Piegl & Tiller, The NURBS
// Book §9.2.1, with knots by averaging). Eigen's SplineFitting::Interpolate builds and factors the
// collocation matrix on every call; here the parameters are the markers' material coordinates
// u_k = k / N, the same for every frame, so the matrix is factored once and each frame costs one
// solve (the same spline, a tenth of the time for a 65-marker bell).
#include <Eigen/Core>
#include <Eigen/LU>
#include <cstdint>
#include <span>
#include <string>
#include <unsupported/Eigen/Splines>
#include <vector>

#include "render/render_params.hpp"

namespace creaturelab::render {

using Spline2 = Eigen::Spline<double, 2>;

/// Interpolating cubic B-spline through points at fixed parameters u_k = k / (n − 1) (degree
/// n − 1 below four points).
class SplineInterpolator {
 public:
  explicit SplineInterpolator(int points);
  int points() const { return int(parameters_.size()); }
  /// The spline through `pts` (2 × points): S(u_k) = pts.col(k).
  Spline2 fit(const Eigen::Matrix2Xd& pts) const;

 private:
  Eigen::RowVectorXd parameters_;
  Spline2::KnotVectorType knots_;
  Eigen::PartialPivLU<Eigen::MatrixXd> collocation_;
};

/// Which markers of the simulation are what (the jellyfish kind's /topology).
struct SliceTopology {
  int bell_markers = 0;             // markers 0 .. bell_markers − 1: left aperture → apex → right aperture
  std::vector<int> left_tentacle;   // marker indices from the root (marker 0) to the tip; empty = none
  std::vector<int> right_tentacle;  // from the root (marker bell_markers − 1) to the tip
  std::vector<int> muscle_markers;  // each muscle element's left marker (0 = aperture), ascending
  /// "" if usable with `markers` markers per frame, else why not.
  std::string validate(int markers) const;
};

/// The topology from the tables a jellyfish run records (/topology): bell_markers, springs as
/// (a, b) pairs (each tentacle is the chain of springs beyond the bell from an aperture marker)
/// and muscles as (left, right) pairs.
SliceTopology sliceTopology(int bell_markers, std::span<const std::int64_t> springs,
                            std::span<const std::int64_t> muscles, int markers);

/// One recorded frame.
struct SliceFrame {
  double time_s = 0;
  std::span<const double> markers_xy;         // (markers, 2) row-major, metres
  std::span<const double> muscle_activation;  // one per muscle element in [0, 1], or empty (no ridges)
};

/// The resampled 2-D model of one frame. Rings run from the margin (i = 0) to the apex
/// (i = rings − 1), where the left and right points coincide; each ring is a pair of opposite
/// points (x_i, x_j of §3.5) on the subumbrella and one on the exumbrella.
struct Slice2 {
  std::vector<Eigen::Vector2d> sub_left, sub_right, exum_left, exum_right;  // per ring
  std::vector<double> latitude;   // d_i per ring: 0 at the apex, 1 at the margin
  std::vector<double> thickness_m;  // ϑ(d_i)
  std::vector<double> contraction;  // per ring in [0, 1]: the muscle state the ridges follow
  // The markers and the generated exumbrellar points (Fig. 7), left aperture → apex → right.
  std::vector<Eigen::Vector2d> sub_markers, exum_markers;
  // Tentacles: left and right centrelines, sampled root → tip (empty without tentacles).
  std::vector<Eigen::Vector2d> tentacle_left, tentacle_right;
};

/// The 2-D render model (§3.4): fits the splines of a frame and resamples them.
class SliceModel2 {
 public:
  /// Throws std::invalid_argument for unusable parameters or topology.
  SliceModel2(const RenderParams& params, SliceTopology topology, int markers);

  /// "" when the frame's outline can be rendered, else why not: the wrong number of markers,
  /// coordinates not finite, two neighbouring markers at one place, the closed outline
  /// (subumbrella, margin, exumbrella) crossing itself.
  std::string check(const SliceFrame& frame) const;

  /// Fills `out` from `frame` (which check() accepted).
  void build(const SliceFrame& frame, Slice2& out) const;

  const SliceTopology& topology() const { return topology_; }
  int rings() const { return params_.rings; }

 private:
  // The subumbrella's spline and the exumbrellar points projected from it.
  void projectExumbrella(const SliceFrame& frame, Eigen::Matrix2Xd& sub, Eigen::Matrix2Xd& exum, Spline2* spline) const;
  double ringContraction(double marker_position, std::span<const double> activation) const;

  RenderParams params_;
  SliceTopology topology_;
  int markers_ = 0;
  SplineInterpolator bell_;
  SplineInterpolator tentacle_left_, tentacle_right_;
};

}  // namespace creaturelab::render
