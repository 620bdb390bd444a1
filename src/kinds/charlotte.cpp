#include "kinds/charlotte.hpp"

#include <cmath>

#include "charlotte/canvas.hpp"
#include "charlotte/inscribe.hpp"
#include "charlotte/inscription_measures.hpp"
#include "charlotte/inscription_renders.hpp"
#include "charlotte/legibility.hpp"
#include "charlotte/morphology.hpp"
#include "charlotte/netpbm.hpp"
#include "charlotte/resettle.hpp"
#include "charlotte/text_target.hpp"
#include "springs/equilibrium.hpp"
#include "springs/provot.hpp"
#include "springs/simulate.hpp"
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
  w.air_drag_ns_per_m = r.real("drag_ns_per_m");
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

// The static equilibrium, which a long RK4 run reaches (the web kind checks its hub sag to 1%), with the
// inner frame's constant inward force (Fig. 5.8) as part of the potential; its iterations.
int settleWeb(const web::WebModel& model, springs::State<3>& state) {
  springs::System<3> system(model.network);
  system.setConstantForce(model.external_force_n);
  const auto eq = springs::solveStaticEquilibrium(system, state);
  if (!eq.converged) throw RunFailure("the web's static equilibrium did not converge");
  return eq.iterations;
}

ch::ResettleParams resettleParams(const ParamReader& r) {
  return {r.text("resettle") == "dynamic", r.real("resettle_time_s"), r.real("settling_fraction")};
}

// The resettled web's series: the hub's shift per frame, the frames' times and (dynamic) kinetic
// energy; a run that failed has the shift so far only.
Result resettleSeries(const ch::Resettled& after) {
  Result result;
  result.timeseries["hub_shift_m"] = {after.hub_shift_m, "m"};
  if (!after.time_s.empty()) result.timeseries["time_s"] = {after.time_s, "s"};
  if (!after.kinetic_energy_j.empty()) result.timeseries["kinetic_energy_j"] = {after.kinetic_energy_j, "J"};
  return result;
}

void addInscriptionMetrics(Result& result, const web::WebModel& model, int settle_iterations, const ch::Inscription& ins,
                           const ch::Pruned& pruned, const ch::InscriptionMeasures& im, const ch::Resettled& after) {
  const double nan = std::nan("");
  const int removed = im.segments_removed, inside = im.removed_inside_target;
  auto& m = result.metrics;
  m["particles"] = {double(model.counts.particles), ""};
  m["spiral_segments"] = {double(ins.spiral_segments), ""};
  m["settle_iterations"] = {double(settle_iterations), ""};
  m["segments_removed"] = {double(removed), ""};
  m["removed_inside_target"] = {double(inside), ""};
  m["removed_outside_target"] = {double(removed - inside), ""};
  m["removed_inside_fraction"] = {removed > 0 ? double(inside) / removed : nan, ""};
  m["springs_removed"] = {double(ins.removed_springs.size()), ""};
  m["particles_removed"] = {double(pruned.dropped_particles), ""};
  m["crosshatch_candidates"] = {double(ins.crosshatch_candidates), ""};
  m["crosshatch_kept"] = {double(ins.crosshatch_kept), ""};
  m["attachments"] = {double(ins.attachments), ""};
  m["outline_segments"] = {double(im.outline_segments), ""};
  m["target_area_fraction"] = {im.target_area_fraction, ""};
  m["emptied_iou"] = {im.settled.iou, ""};
  m["emptied_precision"] = {im.settled.precision, ""};
  m["emptied_recall"] = {im.settled.recall, ""};
  m["letter_contrast"] = {im.settled.contrast, ""};
  m["cut_emptied_iou"] = {im.cut.iou, ""};
  m["cut_letter_contrast"] = {im.cut.contrast, ""};
  m["settling_time_s"] = {after.settling_time_s, "s"};
  m["resettle_iterations"] = {after.iterations, ""};
  m["hub_shift_m"] = {after.hub_shift_m.back(), "m"};
  m["max_strain"] = {springs::maxStrain(pruned.network, after.state), ""};
}

// Topology: the web with every strand the emphasis laid, before removal; which segment each spring
// belongs to; the segments' ends, scores and fates; the removed springs. Positions of every particle
// of that web: settled before removal (frame 0) and at the end (frame 1; a dropped mass stays where
// it was).
void addInscriptionTables(Result& result, const web::WebModel& model, const ch::Inscription& ins,
                          const ch::Pruned& pruned, const springs::State<3>& state,
                          const std::vector<std::int64_t>& spring_segment) {
  auto& topo = result.topology;
  for (std::size_t i = 0; i < ins.segments.size(); ++i) {
    const auto& s = ins.segments[i];
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

  Tracks& tracks = result.lagrangian["positions_m"];
  tracks.points = ins.network.particleCount();
  tracks.dim = 3;
  const double t_end = result.timeseries["time_s"].values.back();
  tracks.time_s = {0.0, t_end};
  springs::Points<3> end = ins.state.x_m;
  for (int i = 0; i < int(pruned.particle_of.size()); ++i) end.col(pruned.particle_of[i]) = state.x_m.col(i);
  tracks.data.assign(ins.state.x_m.data(), ins.state.x_m.data() + ins.state.x_m.size());
  tracks.data.insert(tracks.data.end(), end.data(), end.data() + end.size());
}

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
      real("drag_ns_per_m", w.air_drag_ns_per_m, "N*s/m", 0, 1,
           "air friction (§5.2.1: 1e-8 N s/m); it sets the resettle's 5-10 s, exp(-t / 2 s) for 10 ug masses"),
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

  // 1. Settle (§6: "create an orb web ... and then to allow the web simulation to settle down").
  springs::State<3> settled = model.state;
  const int settle_iterations = settleWeb(model, settled);

  // 2. Target on the canvas mapped onto the settled web.
  const ch::CanvasMap map = ch::canvasOver(settled.x_m, int(r.integer("canvas_px")));
  const ch::Raster target = targetOnCanvas(r, map, web::hubPositionM(model, settled).head<2>());

  // 3. Inscribe: capture, dilate, score, select, emphasise (charlotte/inscribe.hpp).
  const ch::InscribeParams ip = inscribeParams(r);
  const ch::Inscription ins = ch::inscribe(model, settled, map, target, web::strandSpec(wp, StrandType::spiral),
                                           wp.particle_mass_kg, ip);

  // 4. Remove the selected segments and settle again (charlotte/resettle.hpp).
  const ch::Pruned pruned = ch::removeSprings(ins.network, ins.state, ins.type, ins.removed_springs);
  ch::Resettled after;
  try {
    ch::resettle(model, pruned, resettleParams(r), after);
  } catch (const springs::DivergenceError& e) {
    throw RunFailure(e.what(), resettleSeries(after));
  }
  if (!after.converged) throw RunFailure("the static equilibrium after removal did not converge", resettleSeries(after));

  // 5. Measures, tables and (7) renders, written by the runner beside the point file.
  Result result = resettleSeries(after);
  const auto measures = ch::measureInscription(ins, map, target, pruned, after.state.x_m, ip.dilation_px);
  addInscriptionMetrics(result, model, settle_iterations, ins, pruned, measures, after);
  const std::vector<std::int64_t> spring_segment = ch::springSegments(ins);
  addInscriptionTables(result, model, ins, pruned, after.state, spring_segment);
  if (r.boolean("renders"))
    result.artifacts = ch::renderInscription(model, settled.x_m, ins, target, map, pruned, after.state.x_m, spring_segment);
  return result;
}

}  // namespace creaturelab::kinds
