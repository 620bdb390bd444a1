#pragma once
// The settings of the jellyfish's render hook (kinds/jellyfish_render.cpp; render/render_params.hpp),
// declared once (kinds/describe.hpp): name, unit, default, range and doc of every render.* setting, so
// that `creaturelab render` checks a `key=value` as the runner checks an experiment's [params]
// (kinds/params.hpp), and `creaturelab list render` documents them. The defaults are RenderParams'.
#include <cstdint>
#include <string>
#include <vector>

#include "kinds/describe.hpp"
#include "render/render_params.hpp"

namespace creaturelab::kinds {

struct JellyfishRenderSettings {
  render::RenderParams render;
  RealOrAuto thickness_m;  // auto: the recorded bell's thickness (render.thickness.apex_m)

  template <class V>
  void describe(V& v) {
    render::RenderParams& d = render;
    // --- resolution (§3.4)
    v.integer("rings", d.rings, 3, 4096, "latitudes per surface (sub- and exumbrella each), apex pole included");
    v.integer("segments", d.segments, 3, 8192, "longitudes around every ring (§3.5's σ_j)");
    // --- thickness (§3.4, Figs. 3, 12)
    v.realOrAuto("thickness_m", thickness_m, "m", 1e-6, 1,
                 "umbrella thickness ϑ at the apex (Fig. 12: 4 mm); auto = the run's bell_thickness_m. The "
                 "variation scales are multiples of it");
    v.real("margin_thickness_ratio", d.thickness.margin_ratio, "", 1e-3, 1,
           "thickness at the margin / at the apex (Fig. 3: thinning toward the margin; not given)");
    v.real("thickness_exponent", d.thickness.exponent, "", 0.1, 10, "ϑ(d) = ϑ_apex [r + (1 - r)(1 - d^p)], d = 0 apex .. 1 margin");
    // --- tentacles (§3.5)
    v.integer("tentacles", d.tentacles, 0, 1024, "tentacles around the aperture (0 = none; not given)");
    v.integer("tentacle_rings", d.tentacle_rings, 2, 4096, "rings along each tentacle");
    v.integer("tentacle_segments", d.tentacle_segments, 3, 1024, "vertices around each tentacle ring");
    v.real("tentacle_thickness_m", d.tentacle_thickness_m, "m", 1e-6, 1,
           "tentacle diameter at the root (the slice's 1/100 section is too thin to see; not given)");
    v.real("tentacle_tip_ratio", d.tentacle_tip_ratio, "", 1e-3, 1, "tip diameter / root diameter");
    // --- variation (§3.5, Eq. 2, Fig. 12)
    v.boolean("structural", d.structural, "structural variation α_str sin(f σ) or α_str |sin(f σ)|");
    v.choice("structural_shape", d.structural_shape,
             {{"sin", render::StructuralShape::sin}, {"abs_sin", render::StructuralShape::abs_sin}},
             "sin(f σ) or |sin(f σ)| (§3.5)");
    v.real("structural_frequency", d.structural_frequency, "", 0, 1000, "f of the structural pattern (per species)");
    v.real("structural_scale", d.structural_scale, "", -100, 100, "α_str / ϑ (Fig. 12: 0.375)");
    v.real("structural_apex_taper", d.structural_apex_taper, "", 0, 1,
           "the structural pattern fades in from the apex over this latitude (0 = no taper; not in the paper)");
    v.boolean("ridges", d.ridges, "compression ridges on the exumbrella, following the recorded muscle state");
    v.real("ridge_frequency", d.ridge_frequency, "", 0, 1000, "ridges around the bell (Fig. 3: eight)");
    v.real("ridge_scale", d.ridge_scale, "", -100, 100, "ridge height / ϑ at full contraction ((1.51 - 1.36), §3.5)");
    v.boolean("noise", d.noise, "unstructured variation: Perlin noise, Eq. 2");
    v.real("noise_scale", d.noise_scale, "", -100, 100, "α_unstr / ϑ (Fig. 12: 2.25)");
    v.integer("noise_seed", d.noise_seed, 0, std::int64_t(1) << 62,
              "seed of the noise's permutation (the same seed gives bitwise the same meshes)");
    v.real("noise_latitude_frequency", d.noise_latitude_frequency, "", 0, 256, "Eq. 2's 2 in Q_P(2 d_i, ., .)");
    v.integer("noise_longitude_cells", d.noise_longitude_cells, 1, 256,
              "Eq. 2's 8 in Q_P(., 8 d_j, .): a power of two, so the noise closes around the bell");
    v.real("noise_time_frequency_hz", d.noise_time_frequency_hz, "Hz", 0, 1e3, "Eq. 2's 0.01 in Q_P(., ., 0.01 t)");
  }
};

const std::vector<ParamSpec>& renderParamSpecs();

/// RenderParams from a resolved set (every spec present); `run_thickness_m` is the recorded bell's
/// thickness, used when thickness_m = "auto".
render::RenderParams renderParams(const Params& params, double run_thickness_m);

}  // namespace creaturelab::kinds
