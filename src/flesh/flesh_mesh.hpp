#pragma once
// The flesh's mesh (Lentine et al. 2010 §7.1: "a deformable mesh that is bound to the rigid body
// skeleton"): a closed triangle surface per geom of the skeleton, the geom's own surface
// (rigid::geomSurfaces) pushed outward along its vertex normals by the flesh's thickness.
//
// Why a surface and not tetrahedra: the fluid sees only the skin (its markers are the vertices),
// and the skeleton inside is rigid, so the flesh is a shell whose shape is held by its binding to the
// bones; a volume mesh would add interior vertices that nothing outside can see. Why one shell per
// geom and not one surface wrapping the whole skeleton: every vertex then belongs to exactly one body
// and no vertex needs to be blended across a joint; where two geoms' shells overlap (a leg's root in
// the body) they interpenetrate, which the fluid's markers do not mind.
//
// Each vertex is bound to its geom's body at the point where it sits at the model's reference
// configuration (qpos0), fixed in the body's frame. Its mass is the flesh's density times its share
// of the shell's volume: every triangle's prism between the geom's surface (inner) and the flesh's
// (outer), by Simpson's rule in the offset, V = t (A_in + 4 A_mid + A_out) / 6 (exact when the area
// grows quadratically with the offset, as it does along vertex normals), shared equally by its three
// vertices.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "flesh/flesh_params.hpp"
#include "rigid/rigid_model.hpp"

namespace creaturelab::flesh {

struct FleshMesh {
  Eigen::Matrix3Xd rest_m;                      // vertex positions at the reference configuration, world frame
  std::vector<std::array<int, 3>> triangles;    // counter-clockwise seen from outside
  std::vector<int> body;                        // per vertex: the MuJoCo body it is bound to
  std::vector<int> geom;                        // per vertex: the geom whose surface it offsets
  Eigen::Matrix3Xd anchor_in_body_m;            // per vertex: its anchor in its body's frame
  Eigen::VectorXd mass_kg;                      // per vertex
  std::vector<std::array<int, 2>> edges;        // each edge once, a < b
  std::vector<double> edge_adjacent_area_m2;    // per edge: the rest areas of its (two) triangles, summed

  int vertices() const { return int(mass_kg.size()); }
};

// The flesh of every geom with a volume on a body other than the world (planes, height fields and
// the world's own geoms are the ground, not the creature). Throws std::invalid_argument when the
// parameters are invalid or the model has nothing to wrap.
FleshMesh buildFleshMesh(const rigid::RigidModel& model, const FleshParams& params);

// Area of each vertex's share of the surface at positions x (one third of each adjacent triangle), m^2.
void vertexAreas(const FleshMesh& mesh, const Eigen::Matrix3Xd& x_m, Eigen::VectorXd& area_m2);

}  // namespace creaturelab::flesh
