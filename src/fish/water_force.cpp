#include "fish/water_force.hpp"

#include <algorithm>

namespace creaturelab::fish {

void addWaterForce(const FishModel& fish, const WaterParams& water, const NodeMatrix& x, const NodeMatrix& v,
                   NodeMatrix& force_n) {
  if (water.mu == 0) return;  // fish in air: exactly no force (not a product with zero)
  for (const Face& face : fish.faces) {
    const FaceFrame frame = faceNormal(x, face);
    Eigen::Vector3d vel = Eigen::Vector3d::Zero();
    for (int c : face.node) vel += v.row(c).transpose();
    vel = vel / 4.0 - water.current_m_per_s;
    const double push = frame.normal.dot(vel);  // > 0: the face moves into the water
    double magnitude = -water.mu * frame.area_m2 * push;
    if (water.law == WaterLaw::quadratic) magnitude *= vel.norm();
    const double along_normal = std::min(0.0, magnitude);
    if (along_normal == 0) continue;
    const Eigen::RowVector3d per_corner = (0.25 * along_normal) * frame.normal.transpose();
    for (int c : face.node) force_n.row(c) += per_corner;
  }
}

}  // namespace creaturelab::fish
