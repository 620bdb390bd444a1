#include "web/web_run.hpp"

#include <cmath>

#include "springs/provot.hpp"
#include "web/measure.hpp"

namespace creaturelab::web {

WebRunRecorder::WebRunRecorder(const WebModel& model, const Eigen::Vector3d& hub_start_m, int frames_per_track)
    : model_(model), hub_start_m_(hub_start_m), frames_per_track_(frames_per_track) {
  positions_.points = int(model.state.x_m.cols());
}

void WebRunRecorder::record(int frame, double t_s, const springs::State<3>& s) {
  hub_sag_m_.push_back(hubSagM(model_, s));
  const double d = (hubPositionM(model_, s) - hub_start_m_).norm();
  sum_d2_ += d * d;
  ++frames_;
  if (frame % frames_per_track_ == 0) {
    positions_.time_s.push_back(t_s);
    positions_.data.insert(positions_.data.end(), s.x_m.data(), s.x_m.data() + s.x_m.size());
  }
}

double WebRunRecorder::hubRmsDisplacement_m() const { return frames_ ? std::sqrt(sum_d2_ / frames_) : std::nan(""); }

std::vector<core::NamedValue> webMeasures(const WebModel& model, const springs::Network<3>& net, const WebRunEnd& end) {
  const double nan = std::nan("");
  const auto& c = model.counts;
  const double sag = hubSagM(model, end.state);
  const double static_sag = end.eq.converged ? hubSagM(model, end.statics) : nan;
  return {
      {"particles", "", double(c.particles)},
      {"springs", "", double(c.springs)},
      {"spokes", "", double(c.spokes)},
      {"spiral_segments", "", double(c.spiral_segments)},
      {"spiral_coverage", "", spiralCoverage(model)},
      {"silk_length_m", "m", c.silk_length_m},
      {"web_mass_kg", "kg", c.web_mass_kg},
      {"hub_sag_m", "m", sag},
      {"static_hub_sag_m", "m", static_sag},
      {"static_sag_rel_diff", "", std::fabs(sag - static_sag) / static_sag},
      {"static_iterations", "", end.eq.converged ? double(end.eq.iterations) : nan},
      {"max_strain", "", springs::maxStrain(net, end.state)},
      {"settling_time_s", "s", end.settling_time_s.value_or(nan)},
      {"elongation_outer_frame", "", meanElongation(model, end.state, {StrandType::outer_frame})},
      {"elongation_inner_frame", "", meanElongation(model, end.state, {StrandType::inner_frame})},
      {"elongation_radial", "", meanElongation(model, end.state, {StrandType::primary_spoke, StrandType::secondary_spoke})},
      {"elongation_spiral", "", meanElongation(model, end.state, {StrandType::spiral})},
      {"hub_rms_displacement_m", "m", end.hub_rms_displacement_m},
      {"dt_used_s", "s", end.dt_used_s},
  };
}

std::map<std::string, std::vector<std::int64_t>> webTopology(const WebModel& model) {
  std::map<std::string, std::vector<std::int64_t>> topo;
  for (int s = 0; s < model.network.springCount(); ++s) {
    topo["spring_a"].push_back(model.network.spring_a[s]);
    topo["spring_b"].push_back(model.network.spring_b[s]);
    topo["spring_type"].push_back(static_cast<int>(model.spring_type[s]));
  }
  for (int a : model.attachment_particles) topo["attachment_particles"].push_back(a);
  for (int h : model.hub_particles) topo["hub_particles"].push_back(h);
  return topo;
}

}  // namespace creaturelab::web
