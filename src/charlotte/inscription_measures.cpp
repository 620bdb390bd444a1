#include "charlotte/inscription_measures.hpp"

namespace creaturelab::charlotte {

InscriptionMeasures measureInscription(const Inscription& ins, const CanvasMap& map, const Raster& target,
                                       const Pruned& pruned, const springs::Points<3>& final_x_m, int dilation_px) {
  InscriptionMeasures m;
  m.settled = measureLegibility(ins, map, target, pruned.network, pruned.type, final_x_m, dilation_px);
  m.cut = measureLegibility(ins, map, target, pruned.network, pruned.type, pruned.state.x_m, dilation_px);
  for (std::size_t i = 0; i < ins.segments.size(); ++i) {
    m.segments_removed += ins.removed[i];
    m.removed_inside_target += ins.removed[i] && ins.inside[i];
    m.outline_segments += ins.outline[i];
  }
  double target_px = 0;
  for (float v : ins.target_dilated.ink) target_px += v >= 0.5f;
  m.target_area_fraction = target_px / double(map.size_px) / double(map.size_px);
  return m;
}

std::vector<std::int64_t> springSegments(const Inscription& ins) {
  std::vector<std::int64_t> spring_segment(ins.network.springCount(), -1);
  for (std::size_t i = 0; i < ins.segments.size(); ++i)
    for (int k : ins.segments[i].springs) spring_segment[k] = std::int64_t(i);
  return spring_segment;
}

}  // namespace creaturelab::charlotte
