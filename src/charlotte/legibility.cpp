#include "charlotte/legibility.hpp"

#include "charlotte/morphology.hpp"

namespace creaturelab::charlotte {

Legibility measureLegibility(const Inscription& ins, const CanvasMap& map, const Raster& target,
                             const springs::Network<3>& final_network, const std::vector<web::StrandType>& final_type,
                             const springs::Points<3>& final_x_m, int dilation_px) {
  const auto& x = ins.state.x_m;
  auto at = [&](int p) { return map.toPx(x.col(p).head<2>()); };
  std::vector<LinePx> before_lines, final_lines;
  for (const auto& s : ins.segments)
    if (s.origin == SegmentOrigin::spiral)
      for (int k : s.springs) before_lines.emplace_back(at(ins.network.spring_a[k]), at(ins.network.spring_b[k]));
  for (int k = 0; k < final_network.springCount(); ++k)
    if (final_type[k] == web::StrandType::spiral)
      final_lines.emplace_back(map.toPx(final_x_m.col(final_network.spring_a[k]).head<2>()),
                               map.toPx(final_x_m.col(final_network.spring_b[k]).head<2>()));
  const Raster before = captureLines(map.size_px, map.size_px, before_lines);
  const Raster final_silk = captureLines(map.size_px, map.size_px, final_lines);
  const Raster omega = dilate(before, dilation_px), kept = dilate(final_silk, dilation_px);

  double e = 0, t_in_omega = 0, both = 0, either = 0, in_n = 0, in_ink = 0, out_n = 0, out_ink = 0;
  for (std::size_t i = 0; i < omega.ink.size(); ++i) {
    const bool in_omega = omega.ink[i] >= 0.5f;
    const bool emptied = in_omega && kept.ink[i] < 0.5f;
    const bool t = ins.target_dilated.ink[i] >= 0.5f;
    e += emptied;
    t_in_omega += t && in_omega;
    both += emptied && t;
    either += emptied || (t && in_omega);
    if (!in_omega) continue;
    if (target.ink[i] >= 0.5f) ++in_n, in_ink += final_silk.ink[i];
    else if (!t) ++out_n, out_ink += final_silk.ink[i];
  }
  Legibility l;
  l.iou = either > 0 ? both / either : 0;
  l.precision = e > 0 ? both / e : 0;
  l.recall = t_in_omega > 0 ? both / t_in_omega : 0;
  l.density_inside = in_n > 0 ? in_ink / in_n : 0;
  l.density_outside = out_n > 0 ? out_ink / out_n : 0;
  const double sum = l.density_inside + l.density_outside;
  l.contrast = sum > 0 ? (l.density_outside - l.density_inside) / sum : 0;
  return l;
}

}  // namespace creaturelab::charlotte
