#pragma once
// Triangulated surfaces of a model's geoms, in each geom's own frame: the simple wind
// force of Lentine et al. 2010 §3.1 (Eq. 2) acts on
// "each triangle of the mesh". A box face is four triangles about its centre; spheres, capsules,
// ellipsoids and cylinders are tessellated on a latitude-longitude grid of their profile; mesh geoms
// use their own faces. Boxes and round geoms (slices a multiple of 4) are tessellated with the mirror
// symmetries of the solid, so a mirror-symmetric creature gets mirror-image markers and forces.
// Triangles are ordered counter-clockwise seen from outside: (b - a) x (c - a) is the outward normal
// times twice the area.
#include <vector>

#include "rigid/rigid_model.hpp"

namespace creaturelab::rigid {

struct Triangle {
  Vec3 a{}, b{}, c{};
};

struct GeomSurface {
  int geom = 0;
  int body = 0;
  std::vector<Triangle> triangles;  // geom frame, metres
};

// One surface per geom with a volume (planes and height fields are skipped), `slices` segments
// around each round geom (>= 3) and slices / 2 rings over each hemisphere.
std::vector<GeomSurface> geomSurfaces(const RigidModel& model, int slices);

}  // namespace creaturelab::rigid
