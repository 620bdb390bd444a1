#include "flesh/binding.hpp"

#include <vector>

#include <Eigen/Geometry>

namespace creaturelab::flesh {

void anchorStates(const FleshMesh& mesh, const rigid::RigidData& skeleton, Eigen::Matrix3Xd& anchor_m,
                  Eigen::Matrix3Xd& anchor_v_m_per_s) {
  const int n = mesh.vertices();
  anchor_m.resize(3, n);
  anchor_v_m_per_s.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const int b = mesh.body[i];
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> rot(skeleton.bodyRotation(b));
    const Eigen::Vector3d p = Eigen::Map<const Eigen::Vector3d>(skeleton.bodyPosition(b)) + rot * mesh.anchor_in_body_m.col(i);
    anchor_m.col(i) = p;
    const rigid::Vec3 v = skeleton.pointVelocity(b, {p[0], p[1], p[2]});
    anchor_v_m_per_s.col(i) = Eigen::Vector3d(v[0], v[1], v[2]);
  }
}

void applyReactions(const FleshMesh& mesh, const Eigen::Matrix3Xd& force_on_flesh_n, const Eigen::Matrix3Xd& anchor_m,
                    rigid::RigidData& skeleton) {
  const int bodies = skeleton.model().bodies();
  std::vector<Eigen::Vector3d> force(bodies, Eigen::Vector3d::Zero()), torque(bodies, Eigen::Vector3d::Zero());
  std::vector<char> touched(bodies, 0);
  for (int i = 0; i < mesh.vertices(); ++i) {
    const int b = mesh.body[i];
    const Eigen::Vector3d f = -force_on_flesh_n.col(i);
    const Eigen::Vector3d r = anchor_m.col(i) - Eigen::Map<const Eigen::Vector3d>(skeleton.bodyComPosition(b));
    force[b] += f;
    torque[b] += r.cross(f);
    touched[b] = 1;
  }
  for (int b = 0; b < bodies; ++b) {
    if (!touched[b]) continue;
    const double* c = skeleton.bodyComPosition(b);
    skeleton.applyWrenchAt(b, {force[b][0], force[b][1], force[b][2]}, {torque[b][0], torque[b][1], torque[b][2]},
                           {c[0], c[1], c[2]});
  }
}

}  // namespace creaturelab::flesh
