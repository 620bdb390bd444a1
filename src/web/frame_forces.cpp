#include "web/frame_forces.hpp"

namespace creaturelab::web {

springs::Points<3> inwardFrameForces(const std::vector<int>& chain, const springs::Points<3>& x_m,
                                     const Point2& centre_m, double q_n_per_m, int particle_count) {
  springs::Points<3> f = springs::Points<3>::Zero(3, particle_count);
  const int n = static_cast<int>(chain.size());
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d x = x_m.col(chain[i]);
    const Eigen::Vector3d prev = x_m.col(chain[(i + n - 1) % n]), next = x_m.col(chain[(i + 1) % n]);
    const double share_m = 0.5 * ((x - prev).norm() + (next - x).norm());
    const Eigen::Vector3d inward = (Eigen::Vector3d(centre_m.x(), centre_m.y(), 0) - x).normalized();
    f.col(chain[i]) = q_n_per_m * share_m * inward;
  }
  return f;
}

}  // namespace creaturelab::web
