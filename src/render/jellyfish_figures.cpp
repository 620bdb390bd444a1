#include "render/jellyfish_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/jellyfish_renderer.hpp"
#include "render/pov_scene.hpp"

namespace creaturelab::render {
namespace {

double apertureWidth(const SliceRecording& swim, int k) {
  const SliceFrame f = swim.frame(k);
  const int right = 2 * (swim.topology.bell_markers - 1);
  return std::hypot(f.markers_xy[right] - f.markers_xy[0], f.markers_xy[right + 1] - f.markers_xy[1]);
}

int mostContractedFrame(const SliceRecording& swim) {
  int best = 0;
  for (int k = 1; k < swim.frames(); ++k)
    if (apertureWidth(swim, k) < apertureWidth(swim, best)) best = k;
  return best;
}

// The frames of the last whole contraction-expansion cycle in the run (from a phase-0 start; a
// cycle counts as whole when the frames reach within one frame of its end), `count` of them evenly
// spaced; the recorded frames nearest those times.
std::vector<int> cycleFrames(const SliceRecording& swim, int count) {
  const double t0 = swim.time_s.front(), t1 = swim.time_s.back();
  const double frame_s = swim.frames() > 1 ? swim.time_s[1] - t0 : 0.0;
  const double period = swim.contraction_hz > 0 ? 1.0 / swim.contraction_hz : t1 - t0 + frame_s;
  double start = std::floor((t1 - t0 + frame_s) / period + 1e-9) * period + t0 - period;
  if (start < t0) start = t0;
  std::vector<int> out;
  for (int m = 0; m < count; ++m) {
    const double t = start + period * m / count;
    int best = 0;
    for (int k = 1; k < swim.frames(); ++k)
      if (std::abs(swim.time_s[k] - t) < std::abs(swim.time_s[best] - t)) best = k;
    if (out.empty() || out.back() != best) out.push_back(best);
  }
  return out;
}

std::string timeCaption(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "t = %.2f s", t);
  return buf;
}

class FigureMaker {
 public:
  FigureMaker(const SliceRecording& swim, const RenderParams& params) : swim_(swim), params_(params) {}

  // Fig. 7: the contracted frame's slice with example pairs and their discs.
  PovFigure fig07() const {
    JellyfishRenderer renderer(params_, swim_.topology, swim_.markers);
    renderer.render(swim_.frame(mostContractedFrame(swim_)));
    std::vector<int> rings;
    for (double f : {0.0, 0.2, 0.4, 0.6, 0.8}) rings.push_back(int(std::lround(f * (params_.rings - 2))));
    const PovView view{1200, 900, 20, 28, 0.06};
    PovFigure figure{"fig07_disc_extrapolation", view.width_px, view.height_px, {}, {}};
    figure.scene = povSliceDiscsScene(
        renderer.slice(), rings, view, "Rudolf & Mould 2009 Fig. 7: point pairs of the 2-D slice extrapolated to 3-D discs");
    return figure;
  }

  // Fig. 9: naive extrapolation expanded and contracted, each variation alone, all combined.
  PovFigure fig09() const {
    RenderParams plain = params_;
    plain.tentacles = 0;  // the figure is about the umbrella
    plain.structural = plain.ridges = plain.noise = false;
    const auto only = [&](bool structural, bool ridges, bool noise) {
      RenderParams p = plain;
      p.structural = structural;
      p.ridges = ridges;
      p.noise = noise;
      return p;
    };
    const int expanded = 0, closed = mostContractedFrame(swim_);
    const PovView view{1500, 1000, 20, 0, 0.05};
    PovFigure figure{"fig09_variation", view.width_px, view.height_px, {}, {}};
    std::vector<PovPlacement> items = {
        place(plain, expanded, "fig09_naive_expanded", "naive, expanded", figure),
        place(plain, closed, "fig09_naive_contracted", "naive, contracted", figure),
        place(only(true, false, false), expanded, "fig09_structural", "structural", figure),
        place(only(false, true, false), closed, "fig09_ridges", "compression ridges", figure),
        place(only(false, false, true), expanded, "fig09_noise", "noise (Eq. 2)", figure),
        place(only(true, true, true), closed, "fig09_combined", "combined", figure),
    };
    double w = 0, h = 0;
    for (const auto& it : items) {
      w = std::max(w, it.bounds.hi.x - it.bounds.lo.x);
      h = std::max(h, it.bounds.hi.y - it.bounds.lo.y);
    }
    for (std::size_t k = 0; k < items.size(); ++k)
      items[k].offset = items[k].offset + Vec3{1.25 * w * double(k % 3), -1.6 * h * double(k / 3), 0};
    figure.scene = povGalleryScene(items, view, "Rudolf & Mould 2009 Fig. 9: naive extrapolation and variation");
    return figure;
  }

  // Fig. 10: one contraction-expansion cycle, Lambertian shading; each frame at its height
  // relative to the first (the bell swims up).
  PovFigure fig10() const {
    const PovView view{2000, 650, 12, 0, 0.04};
    PovFigure figure{"fig10_contraction_cycle", view.width_px, view.height_px, {}, {}};
    const std::vector<int> cycle = cycleFrames(swim_, 8);
    std::vector<PovPlacement> items;
    for (std::size_t m = 0; m < cycle.size(); ++m)
      items.push_back(place(params_, cycle[m], "fig10_frame" + std::to_string(m), timeCaption(swim_.time_s[cycle[m]]),
                            figure));
    double w = 0;
    for (const auto& it : items) w = std::max(w, it.bounds.hi.x - it.bounds.lo.x);
    const double y0 = items.front().bounds.centre().y;
    for (std::size_t m = 0; m < items.size(); ++m)
      items[m].offset = items[m].offset + Vec3{1.15 * w * double(m), items[m].bounds.centre().y - y0, 0};
    figure.scene = povGalleryScene(items, view, "Rudolf & Mould 2009 Fig. 10: a contraction-expansion cycle");
    return figure;
  }

 private:
  // Renders frame k with `params`, adds its mesh include NAME.inc to the figure, returns the placement.
  PovPlacement place(const RenderParams& params, int k, const std::string& name, const std::string& caption,
                     PovFigure& figure) const {
    JellyfishRenderer renderer(params, swim_.topology, swim_.markers);
    const TriangleMesh& mesh = renderer.render(swim_.frame(k));
    figure.includes.emplace_back(name + ".inc", povMeshInclude(mesh, name));
    PovPlacement p{name + ".inc", name, caption, boundsOf(mesh), {}};
    p.offset = -1.0 * Vec3{p.bounds.centre().x, p.bounds.centre().y, p.bounds.centre().z};
    return p;
  }

  const SliceRecording& swim_;
  RenderParams params_;
};

}  // namespace

std::vector<int> jellyfishFigureFrames(const SliceRecording& swim) {
  std::vector<int> out = cycleFrames(swim, 8);
  out.push_back(0);
  out.push_back(mostContractedFrame(swim));
  return out;
}

std::vector<PovFigure> jellyfishFigures(const SliceRecording& swim, const RenderParams& params) {
  const FigureMaker maker(swim, params);
  return {maker.fig07(), maker.fig09(), maker.fig10()};
}

}  // namespace creaturelab::render
