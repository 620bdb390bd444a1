#include "render/render_params.hpp"

#include <cmath>
#include <vector>

namespace creaturelab::render {

double ThicknessProfile::at(double d) const {
  return apex_m * (margin_ratio + (1.0 - margin_ratio) * (1.0 - std::pow(d, exponent)));
}

std::string RenderParams::validate() const {
  std::vector<std::string> problems;
  const auto need = [&](bool ok, const std::string& what) {
    if (!ok) problems.push_back(what);
  };
  need(rings >= 3 && rings <= 4096, "rings must be in 3..4096");
  need(segments >= 3 && segments <= 8192, "segments must be in 3..8192");
  need(std::isfinite(thickness.apex_m) && thickness.apex_m > 0, "the apex thickness must be positive");
  need(thickness.margin_ratio > 0 && thickness.margin_ratio <= 1, "the margin thickness ratio must be in (0, 1]");
  need(thickness.exponent > 0 && std::isfinite(thickness.exponent), "the thickness exponent must be positive");
  need(tentacles >= 0 && tentacles <= 1024, "tentacles must be in 0..1024");
  need(tentacle_rings >= 2 && tentacle_rings <= 4096, "tentacle_rings must be in 2..4096");
  need(tentacle_segments >= 3 && tentacle_segments <= 1024, "tentacle_segments must be in 3..1024");
  need(tentacle_thickness_m > 0 && std::isfinite(tentacle_thickness_m), "the tentacle thickness must be positive");
  need(tentacle_tip_ratio > 0 && tentacle_tip_ratio <= 1, "the tentacle tip ratio must be in (0, 1]");
  need(std::isfinite(structural_frequency) && std::isfinite(structural_scale), "structural values must be finite");
  need(structural_apex_taper >= 0 && structural_apex_taper <= 1, "structural_apex_taper must be in [0, 1]");
  need(std::isfinite(ridge_frequency) && std::isfinite(ridge_scale), "ridge values must be finite");
  need(std::isfinite(noise_scale) && std::isfinite(noise_latitude_frequency) && std::isfinite(noise_time_frequency_hz),
       "noise values must be finite");
  const int cells = noise_longitude_cells;
  need(cells >= 1 && cells <= 256 && (cells & (cells - 1)) == 0,
       "noise_longitude_cells must be a power of two up to 256 (so the noise closes around the bell)");
  std::string out;
  for (const auto& p : problems) out += (out.empty() ? "" : "; ") + p;
  return out;
}

}  // namespace creaturelab::render
