#include "kinds/charlotte.hpp"

#include <cmath>
#include <optional>

#include "charlotte/canvas.hpp"
#include "charlotte/inscribe.hpp"
#include "charlotte/legibility.hpp"
#include "charlotte/morphology.hpp"
#include "charlotte/netpbm.hpp"
#include "charlotte/render.hpp"
#include "charlotte/text_target.hpp"
#include "kinds/spring_run.hpp"
#include "springs/equilibrium.hpp"
#include "springs/provot.hpp"
#include "web/build.hpp"
#include "web/measure.hpp"
#include "web/web_builder.hpp"

namespace creaturelab::kinds {
namespace {

namespace ch = charlotte;
using web::StrandType;

web::WebParams webParams(const ParamReader& r) {
  web::WebParams w;
  for (auto& p : w.attachment_points_m) p *= r.real("frame_scale");
  w.secondary_spoke_stride = int(r.integer("secondary_spoke_stride"));
  w.spiral_density = int(r.integer("spiral_density"));
  w.spiral_jitter = r.real("spiral_jitter");
  w.spiral_k_n_per_m = r.real("spiral_k_n_per_m");
  w.spoke_k_n_per_m = r.real("spoke_k_n_per_m");
  w.seed = std::uint64_t(r.integer("seed"));
  return w;
}

ch::InscribeParams inscribeParams(const ParamReader& r) {
  ch::InscribeParams p;
  p.dilation_px = int(r.integer("dilation_px"));
  p.band_px = int(r.integer("band_px"));
  p.threshold = int(r.integer("threshold"));
  const std::string& e = r.text("emphasis");
  p.emphasis = e == "cross_hatch"          ? ch::Emphasis::cross_hatch
               : e == "random_attachments" ? ch::Emphasis::random_attachments
               : e == "strong_outline"     ? ch::Emphasis::strong_outline
                                           : ch::Emphasis::none;
  p.crosshatch_reach = int(r.integer("crosshatch_reach"));
  p.attachment_probability = r.real("attachment_probability");
  p.attachment_max_length_m = r.real("attachment_max_length_m");
  p.seed = std::uint64_t(r.integer("seed"));
  return p;
}

// The target on the canvas (thesis §6, Figs. 6.1, 6.6, 6.18), centred on the hub plus the offset.
ch::Raster targetOnCanvas(const ParamReader& r, const ch::CanvasMap& map, const Eigen::Vector2d& hub_m) {
  const Eigen::Vector2d centre = hub_m + Eigen::Vector2d(r.real("target_offset_x_m"), r.real("target_offset_y_m"));
  const std::string& kind = r.text("target");
  if (kind == "random_gaps")
    return ch::randomGapsTarget(map, centre, r.real("gaps_region_radius_m"), int(r.integer("gap_count")),
                                r.real("gap_radius_m"), std::uint64_t(r.integer("seed")));
  if (kind == "image")
    return ch::placePicture(ch::readNetpbmFile(r.text("image_file")), map, centre, r.real("target_width_m"),
                            r.real("target_max_height_m"));
  return ch::textTarget(r.text("text"), r.text("font"), map, centre, r.real("target_width_m"),
                        r.real("target_max_height_m"));
}

// Shades on a light page (the book's Fig. 6.5 look): frames darkest, spiral lightest; the emphasis
// strands black and wider (Fig. 6.13: "shaded darker than the rest"; Fig. 6.14: outlines stronger).
struct Style {
  float grey, width_px, alpha;
};
Style styleOf(StrandType t) {
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
constexpr Style kEmphasis{0.0f, 1.6f, 1.0f};
// Cross-hatch strands (Fig. 6.12) a shade darker than the spiral: the hatch is meant to stand out by
// its density and direction, which a 600-pixel render of a 1 m web can barely resolve otherwise.
constexpr Style kHatch{0.05f, 1.0f, 0.9f};
constexpr ch::Rgb kPage{0.97f, 0.96f, 0.93f};

ch::Rgb grey(float g) { return {g, g, g}; }

}  // namespace

CharlotteKind::CharlotteKind() {
  const web::WebParams w;
  const ch::InscribeParams d;
  params_ = {
      // the web (src/web, thesis §5.2); the other construction values are the web kind's defaults
      real("frame_scale", 1.0, "", 0.05, 20, "scales the default 7-point frame (1.07 m across)"),
      integer("secondary_spoke_stride", 2, 1, 1000,
              "a secondary spoke from every n-th inner-frame mass (2: ~80 radii, segments short enough for letters)"),
      integer("spiral_density", w.spiral_density, 1, 1000, "SPIRAL_DENSITY of the processed spiral (Fig. 5.16: 5)"),
      real("spiral_jitter", w.spiral_jitter, "", 0, 1, "randomness of the spiral (§5.2)"),
      real("spiral_k_n_per_m", w.spiral_k_n_per_m, "N/m", 1e-9, 1e3, "spiral k (the web kind's default; thesis gives none of its own)"),
      real("spoke_k_n_per_m", w.spoke_k_n_per_m, "N/m", 1e-9, 1e3, "radial spoke k (§5.2.1: 0.01 N/m)"),
      integer("seed", std::int64_t(w.seed), 0, std::int64_t(1) << 62,
              "seed of every random choice (web, random attachments, random gaps)"),
      // the target (§6, Figs. 6.1, 6.6, 6.16, 6.18)
      choice("target", "text", {"text", "image", "random_gaps"},
             "inscribe text (set in `font`), a PBM/PGM image, or random gaps (Fig. 6.18)"),
      text("text", "PIG", "", "the text, UTF-8; \\n breaks a line (Fig. 6.11: P, I, G)"),
      text("font", std::string(ch::kDefaultFont), "",
           "pango font description of the text, installed (fc-list); heavy capitals as in Fig. 6.10 (thesis names none)"),
      text("image_file", "", "", "PBM/PGM target image (P1/P2/P4/P5; dark = target), path from the working folder"),
      real("target_width_m", 0.85, "m", 1e-3, 100,
           "width of the target on the web, the height following its aspect (the default inner frame is ~0.85 m wide)"),
      real("target_max_height_m", 0.5, "m", 1e-3, 100, "largest height of the target on the web"),
      real("target_offset_x_m", 0.0, "m", -100, 100, "target centre right of the hub"),
      real("target_offset_y_m", 0.0, "m", -100, 100, "target centre above the hub"),
      integer("gap_count", 12, 1, 10000, "random gaps: how many discs (Fig. 6.18; thesis gives none)"),
      real("gap_radius_m", 0.035, "m", 1e-4, 10, "random gaps: disc radius"),
      real("gaps_region_radius_m", 0.33, "m", 0, 100, "random gaps: centres within this distance of the target centre"),
      // the procedure (§6, Fig. 6.9)
      integer("canvas_px", 600, 64, 4096, "canvas side, pixels (§5.3.1: 600 x 600)"),
      integer("dilation_px", d.dilation_px, 1, 99, "structuring element side, odd (§6: 7x7)"),
      integer("band_px", d.band_px, 1, 99, "neighbourhood width of a segment, odd (§6: five pixels)"),
      integer("threshold", d.threshold, 0, 10, "remove segments scoring above this (§6: 8)"),
      choice("emphasis", "none", {"none", "cross_hatch", "random_attachments", "strong_outline"},
             "emphasis of the letters (Figs. 6.11, 6.12, 6.13, 6.14)"),
      integer("crosshatch_reach", d.crosshatch_reach, 1, 100,
              "cross-hatch: strands to the masses this many places in and out along the partner's spoke (Fig. 6.12)"),
      real("attachment_probability", d.attachment_probability, "", 0, 1,
           "random attachments: chance a mass inside the letters starts one (Fig. 6.13; thesis gives none)"),
      real("attachment_max_length_m", d.attachment_max_length_m, "m", 1e-4, 10, "random attachments: longest strand"),
      // settling (§6: "allow the web simulation to settle down"; after removal, so it stays physical)
      choice("resettle", "dynamic", {"dynamic", "static"},
             "after removal: RK4 run from the old rest state (gives the settling time), or the static equilibrium"),
      real("resettle_time_s", 12.0, "s", 0.02, 1e4, "dynamic resettle: simulated time (the web settles in 5-10 s, §5.1)"),
      real("settling_fraction", 1e-4, "", 1e-12, 1, "settled when kinetic energy stays below this fraction of its peak"),
      boolean("renders", true, "return PNG renders (web, overlay, cut, result) for the run folder"),
  };
  metrics_ = {
      {"particles", "", "particles of the web as built"},
      {"spiral_segments", "", "spiral segments of the web (mass on a spoke to mass on the next, Fig. 6.2)"},
      {"settle_iterations", "", "Newton iterations of the first settle (static equilibrium)"},
      {"segments_removed", "", "spiral segments removed (score above the threshold)"},
      {"removed_inside_target", "", "removed segments whose middle lies on the (undilated) target"},
      {"removed_outside_target", "", "removed segments whose middle lies off the target (dilation spill)"},
      {"removed_inside_fraction", "", "removed_inside_target / segments_removed (NaN if none removed)"},
      {"springs_removed", "", "springs of the removed segments"},
      {"particles_removed", "", "masses dropped with their segments"},
      {"crosshatch_candidates", "", "cross-hatch strands proposed and scored (Fig. 6.12)"},
      {"crosshatch_kept", "", "cross-hatch strands that matched and were laid"},
      {"attachments", "", "random attachments laid inside the letters (Fig. 6.13)"},
      {"outline_segments", "", "kept segments drawn stronger around the letters (Fig. 6.14)"},
      {"target_area_fraction", "", "share of the canvas the dilated target covers"},
      {"emptied_iou", "", "overlap (intersection over union) of the region the final web lost and the dilated target"},
      {"emptied_precision", "", "share of the region the final web lost on the dilated target"},
      {"emptied_recall", "", "share of the dilated target (where there was spiral) the final web lost"},
      {"letter_contrast", "", "(d_out - d_in)/(d_out + d_in) of final spiral density; +1 empty letters, <0 denser"},
      {"cut_emptied_iou", "", "emptied_iou of the web just after removal, before it settles again"},
      {"cut_letter_contrast", "", "letter_contrast of the web just after removal, before it settles again"},
      {"settling_time_s", "s", "after removal: kinetic energy stays below settling_fraction of its peak (dynamic)"},
      {"resettle_iterations", "", "Newton iterations of the static resettle (static only)"},
      {"hub_shift_m", "m", "how far the hub moved from the first rest state to the end"},
      {"max_strain", "", "largest (length - rest) / rest at the end"},
  };
}

std::string CharlotteKind::doc() const {
  return "text or an image inscribed into a settled orb web (A. Mehla, Modeling and Animation of Orb Webs, MSc "
         "thesis 2005, ch. 6)";
}

std::string CharlotteKind::validate(const Params& params) const {
  ParamReader r(params);
  if (std::string e = webParams(r).validate(); !e.empty()) return e;
  if (std::string e = inscribeParams(r).validate(); !e.empty()) return e;
  if (r.text("target") == "text") return ch::checkText(r.text("text"), r.text("font"));
  if (r.text("target") == "image") {
    try {
      (void)ch::readNetpbmFile(r.text("image_file"));
    } catch (const std::invalid_argument& e) {
      return std::string("image_file: ") + e.what();
    }
  }
  return "";
}

Result CharlotteKind::run(const Params& params) const {
  ParamReader r(params);
  const web::WebParams wp = webParams(r);
  const web::WebModel model = web::build(wp);
  const double nan = std::nan("");
  Result result;

  // 1. Settle (§6: "create an orb web ... and then to allow the web simulation to settle down"): the
  // static equilibrium, which a long RK4 run reaches (the web kind checks its hub sag to 1%), with the
  // inner frame's constant inward force (Fig. 5.8) as part of the potential.
  springs::System<3> system(model.network);
  system.setConstantForce(model.external_force_n);
  springs::State<3> settled = model.state;
  const auto eq = springs::solveStaticEquilibrium(system, settled);
  if (!eq.converged) throw RunFailure("the web's static equilibrium did not converge", result);

  // 2. Target on the canvas mapped onto the settled web.
  const Eigen::Vector2d hub = web::hubPositionM(model, settled).head<2>();
  const ch::CanvasMap map = ch::canvasOver(settled.x_m, int(r.integer("canvas_px")));
  const ch::Raster target = targetOnCanvas(r, map, hub);

  // 3. Inscribe: capture, dilate, score, select, emphasise (charlotte/inscribe.hpp).
  const ch::InscribeParams ip = inscribeParams(r);
  const ch::Inscription ins = ch::inscribe(model, settled, map, target, web::strandSpec(wp, StrandType::spiral),
                                           wp.particle_mass_kg, ip);

  // 4. Remove the selected segments and settle again.
  const ch::Pruned pruned = ch::removeSprings(ins.network, ins.state, ins.type, ins.removed_springs);
  springs::System<3> after(pruned.network);
  springs::Points<3> frame_force = springs::Points<3>::Zero(3, pruned.network.particleCount());
  for (int i = 0; i < pruned.network.particleCount(); ++i)  // the web's own masses keep their force; new ones have none
    if (pruned.particle_of[i] < model.network.particleCount())
      frame_force.col(i) = model.external_force_n.col(pruned.particle_of[i]);
  after.setConstantForce(frame_force);
  springs::State<3> state = pruned.state;
  std::vector<int> hub_after;
  for (int h : model.hub_particles) hub_after.push_back(pruned.new_particle[h]);
  auto hubOf = [&](const springs::State<3>& s) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int h : hub_after) sum += s.x_m.col(h);
    return Eigen::Vector3d(sum / double(hub_after.size()));
  };
  const Eigen::Vector3d hub0 = hubOf(state);
  std::optional<double> settling;
  double resettle_iterations = nan;
  auto& hub_shift = result.timeseries["hub_shift_m"] = {{}, "m"};
  if (r.text("resettle") == "dynamic") {
    springs::SimulationOptions opt;
    opt.integrator = springs::IntegratorKind::RK4;  // the thesis's integrator (§4.2, Eq. 4.16-4.19)
    opt.frame_interval_s = 0.02;                    // §5.2.1 'time step'
    opt.end_time_s = r.real("resettle_time_s");
    opt.settling_fraction = r.real("settling_fraction");
    const auto summary = runOrFail(
        after, state, opt, [&](int, double, const springs::State<3>& s) { hub_shift.values.push_back((hubOf(s) - hub0).norm()); },
        result);
    settling = summary.settling_time_s;
    result.timeseries["time_s"] = {summary.time_s, "s"};
    result.timeseries["kinetic_energy_j"] = {summary.kinetic_energy_j, "J"};
  } else {
    const auto eq2 = springs::solveStaticEquilibrium(after, state);
    if (!eq2.converged) throw RunFailure("the static equilibrium after removal did not converge", result);
    resettle_iterations = eq2.iterations;
    result.timeseries["time_s"] = {{0.0}, "s"};
    hub_shift.values.push_back((hubOf(state) - hub0).norm());
  }

  // 5. Metrics.
  const ch::Legibility leg =
      ch::measureLegibility(ins, map, target, pruned.network, pruned.type, state.x_m, ip.dilation_px);
  const ch::Legibility cut =
      ch::measureLegibility(ins, map, target, pruned.network, pruned.type, pruned.state.x_m, ip.dilation_px);
  int removed = 0, inside = 0, outline = 0;
  for (std::size_t i = 0; i < ins.segments.size(); ++i) {
    removed += ins.removed[i];
    inside += ins.removed[i] && ins.inside[i];
    outline += ins.outline[i];
  }
  double target_px = 0;
  for (float v : ins.target_dilated.ink) target_px += v >= 0.5f;
  auto& m = result.metrics;
  m["particles"] = {double(model.counts.particles), ""};
  m["spiral_segments"] = {double(ins.spiral_segments), ""};
  m["settle_iterations"] = {double(eq.iterations), ""};
  m["segments_removed"] = {double(removed), ""};
  m["removed_inside_target"] = {double(inside), ""};
  m["removed_outside_target"] = {double(removed - inside), ""};
  m["removed_inside_fraction"] = {removed > 0 ? double(inside) / removed : nan, ""};
  m["springs_removed"] = {double(ins.removed_springs.size()), ""};
  m["particles_removed"] = {double(pruned.dropped_particles), ""};
  m["crosshatch_candidates"] = {double(ins.crosshatch_candidates), ""};
  m["crosshatch_kept"] = {double(ins.crosshatch_kept), ""};
  m["attachments"] = {double(ins.attachments), ""};
  m["outline_segments"] = {double(outline), ""};
  m["target_area_fraction"] = {target_px / double(map.size_px) / double(map.size_px), ""};
  m["emptied_iou"] = {leg.iou, ""};
  m["emptied_precision"] = {leg.precision, ""};
  m["emptied_recall"] = {leg.recall, ""};
  m["letter_contrast"] = {leg.contrast, ""};
  m["cut_emptied_iou"] = {cut.iou, ""};
  m["cut_letter_contrast"] = {cut.contrast, ""};
  m["settling_time_s"] = {settling.value_or(nan), "s"};
  m["resettle_iterations"] = {resettle_iterations, ""};
  m["hub_shift_m"] = {hub_shift.values.back(), "m"};
  m["max_strain"] = {springs::maxStrain(pruned.network, state), ""};

  // 6. Topology: the web with every strand the emphasis laid, before removal; which segment each
  // spring belongs to; the segments' ends, scores and fates; the removed springs.
  auto& topo = result.topology;
  std::vector<std::int64_t> spring_segment(ins.network.springCount(), -1);
  for (std::size_t i = 0; i < ins.segments.size(); ++i) {
    const auto& s = ins.segments[i];
    for (int k : s.springs) spring_segment[k] = std::int64_t(i);
    topo["segment_a"].push_back(s.a);
    topo["segment_b"].push_back(s.b);
    topo["segment_origin"].push_back(std::int64_t(s.origin));  // 0 spiral, 1 cross-hatch, 2 random attachment
    topo["segment_score"].push_back(ins.score[i]);             // -1: not scored (random attachment)
    topo["segment_outline"].push_back(ins.outline[i]);
    topo["segment_inside_target"].push_back(ins.inside[i]);
    if (ins.removed[i]) topo["removed_segments"].push_back(std::int64_t(i));
  }
  for (int k = 0; k < ins.network.springCount(); ++k) {
    topo["spring_a"].push_back(ins.network.spring_a[k]);
    topo["spring_b"].push_back(ins.network.spring_b[k]);
    topo["spring_type"].push_back(static_cast<int>(ins.type[k]));
  }
  topo["spring_segment"] = spring_segment;
  topo["removed_springs"].assign(ins.removed_springs.begin(), ins.removed_springs.end());
  topo["removed_segments"];  // present even when empty
  for (int a : model.attachment_particles) topo["attachment_particles"].push_back(a);
  for (int h : model.hub_particles) topo["hub_particles"].push_back(h);

  // Positions of every particle of that web: settled before removal (frame 0) and at the end (frame
  // 1; a dropped mass stays where it was).
  Tracks& tracks = result.lagrangian["positions_m"];
  tracks.points = ins.network.particleCount();
  tracks.dim = 3;
  const double t_end = result.timeseries["time_s"].values.back();
  tracks.time_s = {0.0, t_end};
  springs::Points<3> end = ins.state.x_m;
  for (int i = 0; i < int(pruned.particle_of.size()); ++i) end.col(pruned.particle_of[i]) = state.x_m.col(i);
  tracks.data.assign(ins.state.x_m.data(), ins.state.x_m.data() + ins.state.x_m.size());
  tracks.data.insert(tracks.data.end(), end.data(), end.data() + end.size());

  // 7. Renders, written by the runner beside the point file: the settled web (Fig. 6.7), the target
  // over it with the segments to remove in red (Figs. 6.3, 6.10), the web just after the cut, and the
  // result after it settled again (Figs. 6.4, 6.11-6.18).
  if (r.boolean("renders")) {
    const int n = map.size_px;
    auto strand = [&](ch::Painter& p, const springs::Network<3>& net, const springs::Points<3>& x, int k,
                      const Style& st) {
      p.line(map.toPx(x.col(net.spring_a[k]).head<2>()), map.toPx(x.col(net.spring_b[k]).head<2>()), st.width_px,
             grey(st.grey), st.alpha);
    };
    ch::Painter before(n, n, kPage);
    for (int k = 0; k < model.network.springCount(); ++k) strand(before, model.network, settled.x_m, k, styleOf(model.spring_type[k]));
    result.artifacts["web.png"] = before.png();

    ch::Painter overlay(n, n, kPage);
    overlay.wash(ins.target_dilated, {0.95f, 0.55f, 0.45f}, 0.5f);  // the dilated target ...
    overlay.wash(target, {0.8f, 0.2f, 0.15f}, 0.5f);                 // ... and the target itself
    for (int k = 0; k < ins.network.springCount(); ++k) {
      const bool gone = spring_segment[k] >= 0 && ins.removed[std::size_t(spring_segment[k])];
      const Style st = styleOf(ins.type[k]);
      if (!gone) strand(overlay, ins.network, ins.state.x_m, k, st);
      else
        overlay.line(map.toPx(ins.state.x_m.col(ins.network.spring_a[k]).head<2>()),
                     map.toPx(ins.state.x_m.col(ins.network.spring_b[k]).head<2>()), 1.2f, {0.75f, 0.05f, 0.05f}, 1.0f);
    }
    result.artifacts["overlay.png"] = overlay.png();

    // The web after removal at the positions x: emphasis strands drawn last, so they lie on top.
    auto pruned_web = [&](const springs::Points<3>& x) {
      ch::Painter p(n, n, kPage);
      for (int pass = 0; pass < 2; ++pass)
        for (int k = 0; k < pruned.network.springCount(); ++k) {
          const std::int64_t seg = spring_segment[std::size_t(pruned.spring_of[k])];
          const auto origin = seg >= 0 ? ins.segments[std::size_t(seg)].origin : ch::SegmentOrigin::spiral;
          const bool strong = seg >= 0 && (ins.outline[std::size_t(seg)] || origin == ch::SegmentOrigin::attachment);
          const bool hatch = origin == ch::SegmentOrigin::cross_hatch;
          if ((strong || hatch) != (pass == 1)) continue;
          strand(p, pruned.network, x, k, strong ? kEmphasis : hatch ? kHatch : styleOf(pruned.type[k]));
        }
      return p.png();
    };
    result.artifacts["cut.png"] = pruned_web(pruned.state.x_m);
    result.artifacts["result.png"] = pruned_web(state.x_m);
  }
  return result;
}

}  // namespace creaturelab::kinds
