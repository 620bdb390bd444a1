#include "kinds/jellyfish_render_params.hpp"

namespace creaturelab::kinds {

const std::vector<ParamSpec>& renderParamSpecs() {
  static const std::vector<ParamSpec> specs = [] {
    const render::RenderParams d;
    return std::vector<ParamSpec>{
        // --- resolution (§3.4)
        integer("rings", d.rings, 3, 4096, "latitudes per surface (sub- and exumbrella each), apex pole included"),
        integer("segments", d.segments, 3, 8192, "longitudes around every ring (§3.5's σ_j)"),
        // --- thickness (§3.4, Figs. 3, 12)
        realOrAuto("thickness_m", "m", 1e-6, 1,
                   "umbrella thickness ϑ at the apex (Fig. 12: 4 mm); auto = the run's bell_thickness_m. The "
                   "variation scales are multiples of it"),
        real("margin_thickness_ratio", d.thickness.margin_ratio, "", 1e-3, 1,
             "thickness at the margin / at the apex (Fig. 3: thinning toward the margin; not given)"),
        real("thickness_exponent", d.thickness.exponent, "", 0.1, 10,
             "ϑ(d) = ϑ_apex [r + (1 - r)(1 - d^p)], d = 0 apex .. 1 margin"),
        // --- tentacles (§3.5)
        integer("tentacles", d.tentacles, 0, 1024, "tentacles around the aperture (0 = none; not given)"),
        integer("tentacle_rings", d.tentacle_rings, 2, 4096, "rings along each tentacle"),
        integer("tentacle_segments", d.tentacle_segments, 3, 1024, "vertices around each tentacle ring"),
        real("tentacle_thickness_m", d.tentacle_thickness_m, "m", 1e-6, 1,
             "tentacle diameter at the root (the slice's 1/100 section is too thin to see; not given)"),
        real("tentacle_tip_ratio", d.tentacle_tip_ratio, "", 1e-3, 1, "tip diameter / root diameter"),
        // --- variation (§3.5, Eq. 2, Fig. 12)
        boolean("structural", d.structural, "structural variation α_str sin(f σ) or α_str |sin(f σ)|"),
        choice("structural_shape", "abs_sin", {"sin", "abs_sin"}, "sin(f σ) or |sin(f σ)| (§3.5)"),
        real("structural_frequency", d.structural_frequency, "", 0, 1000, "f of the structural pattern (per species)"),
        real("structural_scale", d.structural_scale, "", -100, 100, "α_str / ϑ (Fig. 12: 0.375)"),
        real("structural_apex_taper", d.structural_apex_taper, "", 0, 1,
             "the structural pattern fades in from the apex over this latitude (0 = no taper; not in the paper)"),
        boolean("ridges", d.ridges, "compression ridges on the exumbrella, following the recorded muscle state"),
        real("ridge_frequency", d.ridge_frequency, "", 0, 1000, "ridges around the bell (Fig. 3: eight)"),
        real("ridge_scale", d.ridge_scale, "", -100, 100, "ridge height / ϑ at full contraction ((1.51 - 1.36), §3.5)"),
        boolean("noise", d.noise, "unstructured variation: Perlin noise, Eq. 2"),
        real("noise_scale", d.noise_scale, "", -100, 100, "α_unstr / ϑ (Fig. 12: 2.25)"),
        integer("noise_seed", std::int64_t(d.noise_seed), 0, std::int64_t(1) << 62,
                "seed of the noise's permutation (the same seed gives bitwise the same meshes)"),
        real("noise_latitude_frequency", d.noise_latitude_frequency, "", 0, 256, "Eq. 2's 2 in Q_P(2 d_i, ., .)"),
        integer("noise_longitude_cells", d.noise_longitude_cells, 1, 256,
                "Eq. 2's 8 in Q_P(., 8 d_j, .): a power of two, so the noise closes around the bell"),
        real("noise_time_frequency_hz", d.noise_time_frequency_hz, "Hz", 0, 1e3, "Eq. 2's 0.01 in Q_P(., ., 0.01 t)"),
    };
  }();
  return specs;
}

render::RenderParams renderParams(const Params& params, double run_thickness_m) {
  const ParamReader r(params);
  render::RenderParams p;
  p.rings = int(r.integer("rings"));
  p.segments = int(r.integer("segments"));
  p.thickness.apex_m = r.isAuto("thickness_m") ? run_thickness_m : r.real("thickness_m");
  p.thickness.margin_ratio = r.real("margin_thickness_ratio");
  p.thickness.exponent = r.real("thickness_exponent");
  p.tentacles = int(r.integer("tentacles"));
  p.tentacle_rings = int(r.integer("tentacle_rings"));
  p.tentacle_segments = int(r.integer("tentacle_segments"));
  p.tentacle_thickness_m = r.real("tentacle_thickness_m");
  p.tentacle_tip_ratio = r.real("tentacle_tip_ratio");
  p.structural = r.boolean("structural");
  p.structural_shape = r.text("structural_shape") == "sin" ? render::StructuralShape::sin : render::StructuralShape::abs_sin;
  p.structural_frequency = r.real("structural_frequency");
  p.structural_scale = r.real("structural_scale");
  p.structural_apex_taper = r.real("structural_apex_taper");
  p.ridges = r.boolean("ridges");
  p.ridge_frequency = r.real("ridge_frequency");
  p.ridge_scale = r.real("ridge_scale");
  p.noise = r.boolean("noise");
  p.noise_scale = r.real("noise_scale");
  p.noise_seed = std::uint64_t(r.integer("noise_seed"));
  p.noise_latitude_frequency = r.real("noise_latitude_frequency");
  p.noise_longitude_cells = int(r.integer("noise_longitude_cells"));
  p.noise_time_frequency_hz = r.real("noise_time_frequency_hz");
  return p;
}

}  // namespace creaturelab::kinds
