#include "web/measure.hpp"

#include <algorithm>
#include <cmath>

namespace creaturelab::web {

Eigen::Vector3d hubPositionM(const WebModel& model, const springs::State<3>& s) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int p : model.hub_particles) sum += s.x_m.col(p);
  return model.hub_particles.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(model.hub_particles.size()));
}

double hubSagM(const WebModel& model, const springs::State<3>& s) {
  return hubPositionM(model, model.state).y() - hubPositionM(model, s).y();
}

double meanStrain(const WebModel& model, const springs::State<3>& s, StrandType type) {
  const auto& net = model.network;
  double sum = 0;
  int count = 0;
  for (int i = 0; i < net.springCount(); ++i) {
    if (model.spring_type[i] != type) continue;
    const double len = (s.x_m.col(net.spring_a[i]) - s.x_m.col(net.spring_b[i])).norm();
    sum += (len - net.rest_length_m[i]) / net.rest_length_m[i];
    ++count;
  }
  return count ? sum / count : 0.0;
}

double meanElongation(const WebModel& m, const springs::State<3>& s, std::initializer_list<StrandType> types) {
  double sum = 0;
  int n = 0;
  for (StrandType t : types) {
    int count = 0;
    for (StrandType u : m.spring_type) count += (u == t);
    sum += meanStrain(m, s, t) * count;
    n += count;
  }
  return n ? sum / n : std::nan("");
}

double spiralCoverage(const WebModel& m) {
  const Eigen::Vector2d hub(m.hub_centre_m.x(), m.hub_centre_m.y());
  auto radius = [&](int i) { return (m.state.x_m.col(i).head<2>() - hub).norm(); };
  double r_min = HUGE_VAL, r_max = 0, frame = 0;
  for (int s = 0; s < m.network.springCount(); ++s) {
    if (m.spring_type[s] != StrandType::spiral) continue;
    for (int i : {m.network.spring_a[s], m.network.spring_b[s]}) {
      r_min = std::min(r_min, radius(i));
      r_max = std::max(r_max, radius(i));
    }
  }
  for (int i : m.inner_frame_particles) frame += radius(i) / double(m.inner_frame_particles.size());
  return r_max > 0 ? (r_max * r_max - r_min * r_min) / (frame * frame) : 0.0;
}

}  // namespace creaturelab::web
