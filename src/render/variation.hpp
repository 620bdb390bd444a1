#pragma once
// Variation of the extrapolated surface (Rudolf & Mould 2009 §3.5, Eq. 2, Fig. 12): "we perturb
// each point z_ij on the surface by some scalar distance c_ij in the direction of its surface normal
// n_ij". Three kinds, each switchable (RenderParams):
//   structural   c = α_str sin(f σ_j)  or  α_str |sin(f σ_j)|,        α_str = 0.375 ϑ
//   ridges       c = (1 + sin(f σ_j)) / 2 · a_i (1.51 − 1.36) ϑ        exumbrella only; a_i in [0, 1]
//                the contraction of the muscle spring at latitude i (0 fully expanded, 1 fully contracted)
//   unstructured c = α_unstr d_i Q_P(2 d_i, 8 d_j, 0.01 t),            α_unstr = 2.25 ϑ
// with (d_i, d_j) the normalised latitude (0 apex, 1 margin) and longitude (σ_j / 2π), Q_P Perlin's
// improved noise (core/improved_noise.hpp; periodic over the 8 cells around the bell, so it closes
// at σ = 2π), ϑ the apex thickness. The factor d_i is the paper's attenuation toward the apex.
//
// Choices the paper leaves open, written down:
// - n_ij is the wall's outward normal, from the subumbrella toward the exumbrella (the mean of the
//   exumbrella's outward vertex normal at (i, j) and the opposite of the subumbrella's): structural
//   and unstructured variation move both surfaces of the bell wall by the same vector, keeping its
//   thickness; the ridges thicken the exumbrella only ("we do not modify the subumbrellar points").
// - The structural pattern is faded in from the apex over structural_apex_taper (smoothstep),
//   where every meridian meets; the ridges fade to the apex with the muscle state (slice_model2).
// - Tentacles (noise only, "so that the tentacles themselves exhibit some variation"): their
//   centreline moves along its meridian normal, with d = 1 + v (v from 0 at the root to 1 at the
//   tip, continuing the umbrella's d_i beyond the margin) and d_j = σ_k / 2π of the tentacle.
#include <vector>

#include "core/improved_noise.hpp"
#include "render/disc_extrapolation.hpp"

namespace creaturelab::render {

class Variation {
 public:
  Variation(const RenderParams& params, const MeshLayout& layout);

  bool umbrellaVaries() const { return structural_ || ridges_ || noise_; }
  bool tentaclesVary() const { return noise_; }

  /// Moves the umbrella's vertices along the wall normal (mesh.normals must be those of the
  /// unvaried surface) at time t.
  void umbrella(const Slice2& slice, double time_s, TriangleMesh& mesh);
  /// Moves tentacle k's centreline along its meridian normal.
  void tentacle(int k, double time_s, Centreline& line) const;

  /// The unstructured displacement c of Eq. 2 (m) at latitude d_i, longitude d_j and time t.
  double unstructured(double d_i, double d_j, double time_s) const;

 private:
  MeshLayout layout_;
  double longitude_cells_ = 8, latitude_frequency_ = 2, time_frequency_ = 0.01;
  bool structural_ = false, ridges_ = false, noise_ = false;
  double structural_m_ = 0, ridge_m_ = 0, noise_m_ = 0, taper_ = 0;
  std::vector<double> structural_pattern_, ridge_pattern_;  // per longitude j
  std::vector<double> tentacle_longitude_;                  // d_j of each tentacle
  core::ImprovedNoise noise_field_;
  std::vector<double> ring_noise_;  // scratch: c_unstr per (ring, longitude)
};

}  // namespace creaturelab::render
