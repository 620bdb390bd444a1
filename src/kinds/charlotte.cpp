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

// The target on the canvas (thesis §6, Figs. 6.1, 6.6, 6.18), centred on the hub plus the offset.
ch::Raster targetOnCanvas(const CharlotteParams& q, const ch::CanvasMap& map, const Eigen::Vector2d& hub_m) {
  const Eigen::Vector2d centre = hub_m + Eigen::Vector2d(q.target_offset_x_m, q.target_offset_y_m);
  if (q.target == "random_gaps")
    return ch::randomGapsTarget(map, centre, q.gaps_region_radius_m, int(q.gap_count), q.gap_radius_m, q.web.seed);
  if (q.target == "image")
    return ch::placePicture(ch::readNetpbmFile(q.image_file), map, centre, q.target_width_m, q.target_max_height_m);
  return ch::textTarget(q.text, q.font, map, centre, q.target_width_m, q.target_max_height_m);
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

web::WebParams CharlotteParams::webParams() const {
  web::WebParams w = web;
  for (auto& p : w.attachment_points_m) p *= frame_scale;
  return w;
}

ch::InscribeParams CharlotteParams::inscribeParams() const {
  ch::InscribeParams p = inscribe;
  p.seed = web.seed;
  return p;
}

std::string CharlotteParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  if (std::string e = webParams().validate(); !e.empty()) return e;
  if (std::string e = inscribeParams().validate(); !e.empty()) return e;
  if (target == "text") return ch::checkText(text, font);
  if (target == "image") {
    try {
      (void)ch::readNetpbmFile(image_file);
    } catch (const std::invalid_argument& e) {
      return std::string("image_file: ") + e.what();
    }
  }
  return "";
}

Result CharlotteKind::run(const Params& params) const {
  const CharlotteParams q = readParams<CharlotteParams>(params);
  const web::WebParams wp = q.webParams();
  const web::WebModel model = web::build(wp);

  // 1. Settle (§6: "create an orb web ... and then to allow the web simulation to settle down").
  springs::State<3> settled = model.state;
  const int settle_iterations = settleWeb(model, settled);

  // 2. Target on the canvas mapped onto the settled web.
  const ch::CanvasMap map = ch::canvasOver(settled.x_m, int(q.canvas_px));
  const ch::Raster target = targetOnCanvas(q, map, web::hubPositionM(model, settled).head<2>());

  // 3. Inscribe: capture, dilate, score, select, emphasise (charlotte/inscribe.hpp).
  const ch::InscribeParams ip = q.inscribeParams();
  const ch::Inscription ins = ch::inscribe(model, settled, map, target, web::strandSpec(wp, StrandType::spiral),
                                           wp.particle_mass_kg, ip);

  // 4. Remove the selected segments and settle again (charlotte/resettle.hpp).
  const ch::Pruned pruned = ch::removeSprings(ins.network, ins.state, ins.type, ins.removed_springs);
  ch::Resettled after;
  try {
    ch::resettle(model, pruned, q.resettleParams(), after);
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
  if (q.renders)
    result.artifacts = ch::renderInscription(model, settled.x_m, ins, target, map, pruned, after.state.x_m, spring_segment);
  return result;
}

}  // namespace creaturelab::kinds
