#pragma once
// Parameters of the jellyfish's render model (Rudolf & Mould 2009,
// §3.4 "2D Rendering Model", §3.5 "3D Extrapolation", Fig. 12). SI units; where the paper gives no
// value the choice and its reason are beside the field. The `render` command's schema
// (kinds/jellyfish_render_params.cpp) documents each for `creaturelab list render`.
#include <cstdint>
#include <string>

namespace creaturelab::render {

enum class StructuralShape { sin, abs_sin };  // α sin(f σ) or α |sin(f σ)| (§3.5)

struct ThicknessProfile {
  // ϑ at the apex: Fig. 12 "Jellyfish Thickness (ϑ) 4mm". The variation scales of Fig. 12 are
  // multiples of this ϑ.
  double apex_m = 0.004;
  // Fig. 3 (and Fig. 2's cross-sections): the mesoglea is thickest at the apex and thins toward
  // the margin; the paper gives no numbers. ϑ(d) = ϑ_apex [r + (1 − r)(1 − d^p)], d the normalised
  // latitude (0 apex, 1 margin): a margin a quarter as thick as the apex, thinning faster toward it
  // (p = 2; zero slope at the apex, so the exumbrella stays smooth there).
  double margin_ratio = 0.25;
  double exponent = 2.0;

  double at(double d) const;
};

struct RenderParams {
  // --- resolution (§3.4: "an arbitrary resolution model for rendering")
  int rings = 64;      // latitudes per surface (sub- and exumbrella each), apex pole included
  int segments = 128;  // longitudes around every ring

  ThicknessProfile thickness;

  // --- tentacles (§3.2, §3.5: "the same disc extrapolation scheme ... along the 3D aperture")
  int tentacles = 16;              // placed evenly around the aperture; 0 = none. Not given.
  int tentacle_rings = 24;         // rings along each tentacle
  int tentacle_segments = 8;       // vertices around each tentacle ring
  // The 2-D model's tentacles are chains with 1/100 of the bell's section (Fig. 12), far too
  // thin to see; the render gives them their own thickness, tapering linearly to the tip.
  double tentacle_thickness_m = 0.8e-3;
  double tentacle_tip_ratio = 0.4;

  // --- variation (§3.5, Eq. 2, Fig. 12): each surface point moves along its normal by c_ij
  bool structural = true;
  StructuralShape structural_shape = StructuralShape::abs_sin;
  double structural_frequency = 8;    // f, "artistically chosen ... for the target species"
  double structural_scale = 0.375;    // α_str / ϑ (Fig. 12)
  // The pattern runs down the bell's meridians; at the apex every meridian meets, so its
  // amplitude rises from 0 at the apex to full at this latitude (smoothstep; not in the paper,
  // which shows no apex). 0 = no taper.
  double structural_apex_taper = 0.2;

  bool ridges = true;
  double ridge_frequency = 8;         // Fig. 3: "eight waves around its aperture"
  double ridge_scale = 1.51 - 1.36;   // (1.51 − 1.36) ϑ at full contraction (§3.5)

  bool noise = true;
  double noise_scale = 2.25;          // α_unstr / ϑ (Fig. 12)
  std::uint64_t noise_seed = 1;
  double noise_latitude_frequency = 2;    // Eq. 2's 2 d_i
  int noise_longitude_cells = 8;          // Eq. 2's 8 d_j; a power of two, so the noise closes around the bell
  double noise_time_frequency_hz = 0.01;  // Eq. 2's 0.01 t

  /// "" if usable, else one sentence per problem joined by "; ".
  std::string validate() const;
};

}  // namespace creaturelab::render
