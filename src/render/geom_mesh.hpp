#pragma once
// The surface of one of MuJoCo's primitive geoms as a closed triangle mesh in the geom's own frame
// (z up as in MuJoCo, metres), from its type and geom_size alone, so that a creature recorded as
// types, sizes and poses can be drawn without its model file: boxes as 12 triangles; spheres,
// ellipsoids, capsules and cylinders on a latitude-longitude grid of `slices` segments around z.
#include <array>

#include "render/triangle_mesh.hpp"

namespace creaturelab::render {

// MuJoCo's geom types (mjtGeom) that geomMesh draws.
enum class GeomShape : int { sphere = 2, capsule = 3, ellipsoid = 4, cylinder = 5, box = 6 };

// Whether `mujoco_type` is one of GeomShape (a mesh, plane or height field is not).
bool isPrimitiveGeom(int mujoco_type);

// The closed, outward-oriented surface with normals. size_m as MuJoCo's geom_size: a sphere's radius;
// a capsule's or cylinder's radius and half-length along z; an ellipsoid's radii; a box's half-sizes.
// Throws std::invalid_argument for a type that is not primitive or a size that is not positive.
TriangleMesh geomMesh(int mujoco_type, const std::array<double, 3>& size_m, int slices = 24);

}  // namespace creaturelab::render
