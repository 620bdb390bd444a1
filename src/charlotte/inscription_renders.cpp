#include "charlotte/inscription_renders.hpp"

#include "charlotte/render.hpp"

namespace creaturelab::charlotte {
namespace {

using web::StrandType;

// Shades on a light page (the book's Fig. 6.5 look): frames darkest, spiral lightest; the emphasis
// strands black and wider (Fig. 6.13: "shaded darker than the rest"; Fig. 6.14: outlines stronger).
struct StrandStyle {
  float grey, width_px, alpha;
};
StrandStyle strandStyleOf(StrandType t) {
  switch (t) {
    case StrandType::outer_frame:
    case StrandType::inner_frame: return {0.15f, 1.3f, 1.0f};
    case StrandType::primary_spoke:
    case StrandType::hub:
    case StrandType::secondary_spoke: return {0.45f, 0.8f, 0.8f};
    case StrandType::spiral: break;
  }
  return {0.2f, 0.9f, 0.85f};
}
constexpr StrandStyle kEmphasisStyle{0.0f, 1.6f, 1.0f};
// Cross-hatch strands (Fig. 6.12) a shade darker than the spiral: the hatch is meant to stand out by
// its density and direction, which a 600-pixel render of a 1 m web can barely resolve otherwise.
constexpr StrandStyle kHatchStyle{0.05f, 1.0f, 0.9f};
constexpr Rgb kPageColour{0.97f, 0.96f, 0.93f};

Rgb greyRgb(float g) { return {g, g, g}; }

}  // namespace

std::map<std::string, std::vector<std::uint8_t>> renderInscription(
    const web::WebModel& model, const springs::Points<3>& settled_x_m, const Inscription& ins, const Raster& target,
    const CanvasMap& map, const Pruned& pruned, const springs::Points<3>& final_x_m,
    const std::vector<std::int64_t>& spring_segment) {
  std::map<std::string, std::vector<std::uint8_t>> out;
  const int n = map.size_px;
  auto strand = [&](Painter& p, const springs::Network<3>& net, const springs::Points<3>& x, int k,
                    const StrandStyle& st) {
    p.line(map.toPx(x.col(net.spring_a[k]).head<2>()), map.toPx(x.col(net.spring_b[k]).head<2>()), st.width_px,
           greyRgb(st.grey), st.alpha);
  };
  Painter before(n, n, kPageColour);
  for (int k = 0; k < model.network.springCount(); ++k)
    strand(before, model.network, settled_x_m, k, strandStyleOf(model.spring_type[k]));
  out["web.png"] = before.png();

  Painter overlay(n, n, kPageColour);
  overlay.wash(ins.target_dilated, {0.95f, 0.55f, 0.45f}, 0.5f);  // the dilated target ...
  overlay.wash(target, {0.8f, 0.2f, 0.15f}, 0.5f);                 // ... and the target itself
  for (int k = 0; k < ins.network.springCount(); ++k) {
    const bool gone = spring_segment[k] >= 0 && ins.removed[std::size_t(spring_segment[k])];
    const StrandStyle st = strandStyleOf(ins.type[k]);
    if (!gone) strand(overlay, ins.network, ins.state.x_m, k, st);
    else
      overlay.line(map.toPx(ins.state.x_m.col(ins.network.spring_a[k]).head<2>()),
                   map.toPx(ins.state.x_m.col(ins.network.spring_b[k]).head<2>()), 1.2f, {0.75f, 0.05f, 0.05f}, 1.0f);
  }
  out["overlay.png"] = overlay.png();

  // The web after removal at the positions x: emphasis strands drawn last, so they lie on top.
  auto pruned_web = [&](const springs::Points<3>& x) {
    Painter p(n, n, kPageColour);
    for (int pass = 0; pass < 2; ++pass)
      for (int k = 0; k < pruned.network.springCount(); ++k) {
        const std::int64_t seg = spring_segment[std::size_t(pruned.spring_of[k])];
        const auto origin = seg >= 0 ? ins.segments[std::size_t(seg)].origin : SegmentOrigin::spiral;
        const bool strong = seg >= 0 && (ins.outline[std::size_t(seg)] || origin == SegmentOrigin::attachment);
        const bool hatch = origin == SegmentOrigin::cross_hatch;
        if ((strong || hatch) != (pass == 1)) continue;
        strand(p, pruned.network, x, k, strong ? kEmphasisStyle : hatch ? kHatchStyle : strandStyleOf(pruned.type[k]));
      }
    return p.png();
  };
  out["cut.png"] = pruned_web(pruned.state.x_m);
  out["result.png"] = pruned_web(final_x_m);
  return out;
}

}  // namespace creaturelab::charlotte
