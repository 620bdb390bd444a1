#include "web/wind_gen.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "web/measure.hpp"

namespace creaturelab::web {

void WindGen::next() {
  if (degree % 50 == 0) random = -3.0 + 6.0 * core::uniform01(seed, core::purposeId("web.wind"), std::uint64_t(degree / 50));
  const double s = std::sin(double(degree) * M_PI / 180.0);
  x = random * wind_n * s;
  y = random * wind_n * s;
  z = -wind_n * s;
  ++degree;
}

WebWind::WebWind(const WebModel& model, const springs::State<3>& start, WindGen gen)
    : gen_(gen),
      weight_(Eigen::VectorXd::Ones(start.x_m.cols())),
      force_n_(springs::Points<3>::Zero(3, start.x_m.cols())) {
  double radius = 0;
  for (int a : model.attachment_particles)
    radius = std::max(radius, (model.state.x_m.col(a) - hubPositionM(model, model.state)).norm());
  const Eigen::Vector3d hub = hubPositionM(model, start);
  for (int i = 0; i < start.x_m.cols(); ++i) weight_[i] = std::exp((start.x_m.col(i) - hub).norm() / (radius * 50));
}

void WebWind::next() {
  gen_.next();
  for (int i = 0; i < force_n_.cols(); ++i) force_n_.col(i) = weight_[i] * Eigen::Vector3d(gen_.x, gen_.y, gen_.z);
}

}  // namespace creaturelab::web
