#include "web/measure.hpp"

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

}  // namespace creaturelab::web
