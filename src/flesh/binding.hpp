#pragma once
// The flesh's binding to the skeleton (Lentine et al. 2010 §7.1: the mesh "bound to the rigid body
// skeleton"): where each vertex's anchor is and how fast it moves, and the binding springs' reactions
// handed to the bodies (equal and opposite, at the anchors), so that flesh and skeleton together
// conserve momentum.
#include <Eigen/Core>

#include "flesh/flesh_mesh.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::flesh {

// World position (m) and velocity (m/s) of every vertex's anchor, at the skeleton's pose and velocity
// as its kinematics last computed them (RigidData::kinematics).
void anchorStates(const FleshMesh& mesh, const rigid::RigidData& skeleton, Eigen::Matrix3Xd& anchor_m,
                  Eigen::Matrix3Xd& anchor_v_m_per_s);

// Adds minus force_on_flesh_n[i] (N) at anchor_m[i] to vertex i's body, summed per body into one force
// at the body's centre of mass and one couple (RigidData::applyWrenchAt), the same generalised force
// as one force per anchor at a body's cost instead of a vertex's.
void applyReactions(const FleshMesh& mesh, const Eigen::Matrix3Xd& force_on_flesh_n, const Eigen::Matrix3Xd& anchor_m,
                    rigid::RigidData& skeleton);

}  // namespace creaturelab::flesh
