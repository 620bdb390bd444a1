#include "web/frame_stage.hpp"

#include "web/frame_geometry.hpp"

namespace creaturelab::web {

FrameLayout layFrame(WebBuilder& web) {
  const auto& pts = web.params().attachment_points_m;
  const int n = static_cast<int>(pts.size());
  FrameLayout f;
  f.centre_m = frameCentre(pts);
  const auto inner = innerFramePoints(pts, f.centre_m, web.params().move_outer_m);
  for (int i = 0; i < n; ++i) f.attachment.push_back(web.addParticle(pts[i], /*pinned=*/true));
  for (int i = 0; i < n; ++i) f.corners.push_back(web.addParticle(inner[i], false));
  for (int i = 0; i < n; ++i) web.layStrand(f.attachment[i], f.corners[i], StrandType::outer_frame);
  for (int i = 0; i < n; ++i) {
    f.segments.push_back(web.layStrand(f.corners[i], f.corners[(i + 1) % n], StrandType::inner_frame));
    const auto& seg = f.segments.back();
    f.chain.insert(f.chain.end(), seg.begin(), seg.end() - 1);  // the next segment starts at its last mass
  }
  return f;
}

}  // namespace creaturelab::web
