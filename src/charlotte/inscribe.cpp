#include "charlotte/inscribe.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>

#include "charlotte/morphology.hpp"
#include "charlotte/score.hpp"
#include "core/rng.hpp"
#include "io/cairo_image.hpp"

namespace creaturelab::charlotte {
namespace {

constexpr auto kAttachmentPurpose = core::purposeId("charlotte.attachments");
constexpr auto kGapsPurpose = core::purposeId("charlotte.random_gaps");

std::pair<int, int> unordered(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

Eigen::Vector2d px(const CanvasMap& map, const springs::Points<3>& x_m, int p) {
  return map.toPx(x_m.col(p).head<2>());
}

// Spoke (radius) of each particle and its place along it (0 at the frame end), -1 if on none.
struct RadiusIndex {
  std::vector<int> radius, place;
  RadiusIndex(const std::vector<std::vector<int>>& radii, int particles) : radius(particles, -1), place(particles, -1) {
    for (int r = 0; r < int(radii.size()); ++r)
      for (int k = 0; k < int(radii[r].size()); ++k) {
        const int p = radii[r][k];
        if (p < particles && radius[p] < 0) radius[p] = r, place[p] = k;
      }
  }
};

int maxParticle(const std::vector<Segment>& segs) {
  int m = -1;
  for (const auto& s : segs) m = std::max({m, s.a, s.b});
  return m;
}

}  // namespace

std::string InscribeParams::validate() const {
  if (dilation_px < 1 || dilation_px % 2 == 0 || dilation_px > 99)
    return "dilation_px is " + std::to_string(dilation_px) + "; the structuring element must be odd, 1 to 99 (thesis: 7)";
  if (band_px < 1 || band_px % 2 == 0 || band_px > 99)
    return "band_px is " + std::to_string(band_px) + "; the neighbourhood must be an odd width, 1 to 99 (thesis: 5)";
  if (threshold < 0 || threshold > 10)
    return "threshold is " + std::to_string(threshold) + "; scores run 0 to 10 (thesis: 8)";
  if (crosshatch_reach < 1) return "crosshatch_reach must be at least 1";
  if (!(attachment_probability >= 0 && attachment_probability <= 1))
    return "attachment_probability must lie in [0, 1]";
  if (!(attachment_max_length_m > 0)) return "attachment_max_length_m must be positive";
  return "";
}

Raster captureSource(const springs::Network<3>& net, const springs::Points<3>& x_m, const CanvasMap& map,
                     const std::vector<std::pair<int, int>>& extra_lines) {
  std::vector<LinePx> lines;
  lines.reserve(std::size_t(net.springCount()) + extra_lines.size());
  for (int s = 0; s < net.springCount(); ++s) lines.emplace_back(px(map, x_m, net.spring_a[s]), px(map, x_m, net.spring_b[s]));
  for (const auto& [a, b] : extra_lines) lines.emplace_back(px(map, x_m, a), px(map, x_m, b));
  return captureLines(map.size_px, map.size_px, lines);
}

std::vector<std::pair<int, int>> crossHatchPairs(const std::vector<std::vector<int>>& radii,
                                                 const std::vector<Segment>& spiral, int reach) {
  const RadiusIndex where(radii, maxParticle(spiral) + 1);
  // The spiral masses of each spoke, in order along it.
  std::map<int, std::vector<int>> on_radius;
  std::set<std::pair<int, int>> joined;
  for (const auto& s : spiral) {
    joined.insert(unordered(s.a, s.b));
    for (int p : {s.a, s.b})
      if (where.radius[p] >= 0) on_radius[where.radius[p]].push_back(p);
  }
  for (auto& [r, list] : on_radius) {
    std::sort(list.begin(), list.end(), [&](int p, int q) { return where.place[p] < where.place[q]; });
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  std::vector<std::pair<int, int>> out;
  for (const auto& s : spiral) {
    if (where.radius[s.b] < 0 || where.radius[s.a] == where.radius[s.b]) continue;
    const auto& list = on_radius[where.radius[s.b]];
    const auto k = std::find(list.begin(), list.end(), s.b) - list.begin();
    for (auto j : {k - reach, k + reach}) {
      if (j < 0 || j >= long(list.size()) || list[j] == s.a) continue;
      if (joined.insert(unordered(s.a, list[j])).second) out.emplace_back(s.a, list[j]);
    }
  }
  return out;
}

std::vector<std::pair<int, int>> randomAttachmentPairs(const std::vector<std::vector<int>>& radii,
                                                       const std::vector<Segment>& spiral,
                                                       const springs::Points<3>& x_m, const CanvasMap& map,
                                                       const Raster& target, const InscribeParams& p) {
  const RadiusIndex where(radii, maxParticle(spiral) + 1);
  auto inkAt = [&](const Eigen::Vector2d& q_px) {
    const int x = int(std::floor(q_px.x())), y = int(std::floor(q_px.y()));
    return target.contains(x, y) ? target.at(x, y) : 0.0f;
  };
  std::set<int> inside_set;
  std::set<std::pair<int, int>> joined;
  for (const auto& s : spiral) {
    joined.insert(unordered(s.a, s.b));
    for (int m : {s.a, s.b})
      if (inkAt(px(map, x_m, m)) >= 0.5f) inside_set.insert(m);
  }
  const std::vector<int> inside(inside_set.begin(), inside_set.end());  // ascending
  std::vector<std::pair<int, int>> out;
  for (int a : inside) {
    if (core::uniform01(p.seed, kAttachmentPurpose, 2 * std::uint64_t(a)) >= p.attachment_probability) continue;
    std::vector<int> partners;
    for (int b : inside) {
      if (b == a || where.radius[b] == where.radius[a]) continue;
      const Eigen::Vector3d d = x_m.col(b) - x_m.col(a);
      if (d.norm() > p.attachment_max_length_m || joined.count(unordered(a, b))) continue;
      if (inkAt(px(map, x_m, a) + 0.5 * (px(map, x_m, b) - px(map, x_m, a))) < 0.5f) continue;
      partners.push_back(b);
    }
    if (partners.empty()) continue;
    const double u = core::uniform01(p.seed, kAttachmentPurpose, 2 * std::uint64_t(a) + 1);
    const int b = partners[std::min(partners.size() - 1, std::size_t(u * double(partners.size())))];
    joined.insert(unordered(a, b));
    out.emplace_back(a, b);
  }
  return out;
}

Raster randomGapsTarget(const CanvasMap& map, const Eigen::Vector2d& centre_m, double region_radius_m, int count,
                        double radius_m, std::uint64_t seed) {
  io::CairoImage img(map.size_px, map.size_px, io::PixelFormat::grey8);
  cairo_t* cr = img.cr();
  cairo_set_source_rgba(cr, 0, 0, 0, 1);
  for (int g = 0; g < count; ++g) {
    // Uniform over the disc: radius R sqrt(u), angle 2 pi v.
    const double rr = region_radius_m * std::sqrt(core::uniform01(seed, kGapsPurpose, 2 * std::uint64_t(g)));
    const double th = 2 * std::numbers::pi * core::uniform01(seed, kGapsPurpose, 2 * std::uint64_t(g) + 1);
    const Eigen::Vector2d c_px = map.toPx(centre_m + rr * Eigen::Vector2d(std::cos(th), std::sin(th)));
    cairo_new_sub_path(cr);
    cairo_arc(cr, c_px.x(), c_px.y(), radius_m * map.px_per_m, 0, 2 * std::numbers::pi);
  }
  cairo_fill(cr);  // one path, non-zero winding: overlapping discs unite
  Raster r(map.size_px, map.size_px);
  r.ink = img.coverage();
  return r;
}

Inscription inscribe(const web::WebModel& model, const springs::State<3>& settled, const CanvasMap& map,
                     const Raster& target, const web::StrandSpec& spiral, double mass_kg, const InscribeParams& p) {
  if (std::string err = p.validate(); !err.empty()) throw std::invalid_argument(err);
  if (target.width != map.size_px || target.height != map.size_px)
    throw std::invalid_argument("inscribe: the target raster is not the canvas's size");
  Inscription ins;
  ins.network = model.network;
  ins.state = settled;
  ins.type = model.spring_type;

  // 1. segments (Fig. 6.2)
  ins.segments = spiralSegments(ins.network, ins.type);
  ins.spiral_segments = int(ins.segments.size());
  // 2. candidates (Fig. 6.12)
  std::vector<std::pair<int, int>> hatch;
  if (p.emphasis == Emphasis::cross_hatch) hatch = crossHatchPairs(model.spokes, ins.segments, p.crosshatch_reach);
  ins.crosshatch_candidates = int(hatch.size());
  // 3. capture: "capture the current orb web image from the screen to obtain the source image" (§6)
  ins.source = captureSource(ins.network, ins.state.x_m, map, hatch);
  // 4. dilate (Figs. 6.7-6.8)
  ins.source_dilated = dilate(ins.source, p.dilation_px);
  ins.target_dilated = dilate(target, p.dilation_px);
  // 5. score (Fig. 6.9) and 6. select: "segments with a score above a certain threshold score ... are removed"
  auto scoreOf = [&](int a, int b) {
    return scoreSegment(ins.source_dilated, ins.target_dilated, px(map, ins.state.x_m, a), px(map, ins.state.x_m, b),
                        p.band_px)
        .score;
  };
  for (const auto& s : ins.segments) {
    const int sc = scoreOf(s.a, s.b);
    ins.score.push_back(sc);
    ins.removed.push_back(sc > p.threshold);
  }
  // Cross-hatch: "in the region where there is an intensity match, these additional strand segments
  // are not removed from the final model" (Fig. 6.12): laid where they score above the threshold.
  for (const auto& [a, b] : hatch) {
    const int sc = scoreOf(a, b);
    if (sc <= p.threshold) continue;
    ins.segments.push_back(layStrand(ins.network, ins.state, ins.type, a, b, spiral, web::StrandType::spiral, mass_kg,
                                     SegmentOrigin::cross_hatch));
    ins.score.push_back(sc);
    ins.removed.push_back(0);
    ++ins.crosshatch_kept;
  }
  // 7. emphasis. Outline (Fig. 6.14: "increasing the intensity of the strands surrounding the
  // letters"): the spiral segments kept whose neighbourhood the dilated target still reaches.
  ins.outline.assign(ins.segments.size(), 0);
  if (p.emphasis == Emphasis::strong_outline)
    for (int i = 0; i < ins.spiral_segments; ++i) ins.outline[i] = !ins.removed[i] && ins.score[i] >= 1;
  if (p.emphasis == Emphasis::random_attachments) {
    const std::vector<Segment> web_spiral(ins.segments.begin(), ins.segments.begin() + ins.spiral_segments);
    for (const auto& [a, b] : randomAttachmentPairs(model.spokes, web_spiral, ins.state.x_m, map, target, p)) {
      ins.segments.push_back(layStrand(ins.network, ins.state, ins.type, a, b, spiral, web::StrandType::spiral, mass_kg,
                                       SegmentOrigin::attachment));
      ins.score.push_back(-1);
      ins.removed.push_back(0);
      ++ins.attachments;
    }
  }
  ins.outline.resize(ins.segments.size(), 0);  // attachments are not outline
  for (const auto& s : ins.segments) {
    const Eigen::Vector2d mid = 0.5 * (px(map, ins.state.x_m, s.a) + px(map, ins.state.x_m, s.b));
    const int x = int(std::floor(mid.x())), y = int(std::floor(mid.y()));
    ins.inside.push_back(target.contains(x, y) && target.at(x, y) >= 0.5f);
  }
  for (std::size_t i = 0; i < ins.segments.size(); ++i)
    if (ins.removed[i]) ins.removed_springs.insert(ins.removed_springs.end(), ins.segments[i].springs.begin(),
                                                   ins.segments[i].springs.end());
  std::sort(ins.removed_springs.begin(), ins.removed_springs.end());
  return ins;
}

}  // namespace creaturelab::charlotte
