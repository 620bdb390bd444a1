#pragma once
// 3-D extrapolation of the 2-D render model by discs (Rudolf & Mould 2009 §3.5, Fig. 7): "for each
// pair of points x_i and x_j opposite to each other on the umbrella ... we define an axis of rotation
// for each pair, which goes orthogonally through the centre of the line segment between the two
// points"; the slice need not be symmetric, so each pair has its own axis. Revolving the pair gives
// a ring of points,
//     z_ij = c_i + cos σ_j h_i + sin σ_j |h_i| ẑ,   c_i = (x_i + x_j) / 2,  h_i = (x_j − x_i) / 2,
// σ_j = 2π j / segments the longitude (σ = 0 at the right-hand point x_j, ẑ out of the slice). The
// rings are stitched into one closed surface: the exumbrella from its apex down to the margin,
// across the margin, the subumbrella up to its apex; each apex is a single vertex (a pole). The
// tentacles use the same discs: the k-th tentacle's centreline is the point at its longitude σ_k
// on the disc of each pair of opposite tentacle points, and its tube is a ring of discs around that
// centreline. Each piece is a closed genus-0 surface, oriented outward. Pure geometry: no I/O.
#include <vector>

#include "render/render_params.hpp"
#include "render/slice_model2.hpp"
#include "render/triangle_mesh.hpp"

namespace creaturelab::render {

/// Where each ring's vertices are in the mesh (fixed by the parameters).
struct MeshLayout {
  int rings = 0, segments = 0;  // per umbrella surface; ring i = 0 is the margin, rings − 1 the apex pole
  int tentacles = 0, tentacle_rings = 0, tentacle_segments = 0;

  int exumbrellaPole() const { return 0; }
  int exumbrellaRing(int i) const { return 1 + (rings - 2 - i) * segments; }  // i in 0 .. rings − 2
  int subumbrellaRing(int i) const { return 1 + (rings - 1 + i) * segments; }
  int subumbrellaPole() const { return 1 + 2 * (rings - 1) * segments; }
  int umbrellaVertices() const { return 2 + 2 * (rings - 1) * segments; }
  int tentacleVertices() const { return 2 + tentacle_rings * tentacle_segments; }
  int tentacleRoot(int k) const { return umbrellaVertices() + k * tentacleVertices(); }
  int tentacleRing(int k, int l) const { return tentacleRoot(k) + 1 + l * tentacle_segments; }
  int tentacleTip(int k) const { return tentacleRoot(k) + tentacleVertices() - 1; }
  int vertices() const { return umbrellaVertices() + tentacles * tentacleVertices(); }
  int triangles() const { return 4 * segments * (rings - 1) + tentacles * 2 * tentacle_segments * tentacle_rings; }
};

/// A tentacle's centreline in 3-D: points root → tip with the unit normal in its meridian plane
/// (the 2-D slice's normal of the tentacle, carried to its longitude).
struct Centreline {
  std::vector<Vec3> points, normals;
};

class DiscExtrapolation {
 public:
  /// `tentacles`: whether the slice has tentacles (params.tentacles of them are placed).
  DiscExtrapolation(const RenderParams& params, bool tentacles);

  const MeshLayout& layout() const { return layout_; }
  /// Sizes `mesh` and writes its triangles and parts (the same for every frame).
  void initialise(TriangleMesh& mesh) const;
  /// The umbrella's vertices from the slice's ring pairs.
  void umbrella(const Slice2& slice, TriangleMesh& mesh) const;
  /// Tentacle k's centreline from the slice's tentacle pairs.
  void centreline(const Slice2& slice, int k, Centreline& out) const;
  /// Tentacle k's tube around `line`, its radius tapering from the root to the tip.
  void tube(const Centreline& line, int k, TriangleMesh& mesh) const;

  double longitude(int j) const { return 2.0 * M_PI * j / layout_.segments; }                 // σ_j
  double tentacleLongitude(int k) const { return 2.0 * M_PI * (k + 0.5) / layout_.tentacles; }  // σ_k

 private:
  MeshLayout layout_;
  std::vector<double> cos_, sin_;            // of σ_j
  std::vector<double> tube_cos_, tube_sin_;  // around a tentacle
  std::vector<double> tube_radius_m_;        // per tentacle ring
};

/// The point at longitude (cos σ, sin σ) on the disc of the pair (left, right).
inline Vec3 discPoint(const Eigen::Vector2d& left, const Eigen::Vector2d& right, double cos_sigma, double sin_sigma) {
  const double cx = 0.5 * (left.x() + right.x()), cy = 0.5 * (left.y() + right.y());
  const double hx = 0.5 * (right.x() - left.x()), hy = 0.5 * (right.y() - left.y());
  return {cx + cos_sigma * hx, cy + cos_sigma * hy, sin_sigma * std::sqrt(hx * hx + hy * hy)};
}

}  // namespace creaturelab::render
