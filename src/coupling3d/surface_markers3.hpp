#pragma once
// Immersed-boundary markers on the surfaces of a MuJoCo model's geoms (Lentine et al. 2010 §4.2,
// the bodies' surfaces as triangle meshes, from rigid/geom_surface.hpp). Each triangle is cut into
// m² similar triangles, m = ceil(longest edge / spacing), and each piece gives one marker at its
// centroid, standing for its area; so no two neighbouring markers are farther apart than the
// spacing and the areas sum to the surface's. The markers are fixed in their geom's frame and move
// with it. Geoms on the world body (body 0) are static obstacles.

#include <vector>

#include "coupling3d/transfer3.hpp"
#include "rigid/geom_surface.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::coupling3d {

struct SurfaceMarker3 {
  int geom = 0;
  int body = 0;
  Vec3 local_m{};          ///< position in the geom's frame
  double area_m2 = 0.0;    ///< surface area the marker stands for (0 for an interior marker)
  double volume_m3 = 0.0;  ///< volume an interior marker stands for (0 on the surface)
};

/// Markers of the given surfaces, in surface and triangle order, each moved `retraction_m` inward along
/// its triangle's normal (0: on the surface; see RigidFluidParams3::marker_retraction_cells); the areas
/// stay the surface's. Throws std::invalid_argument for a spacing that is not a positive length or a
/// negative retraction.
std::vector<SurfaceMarker3> surfaceMarkers(const std::vector<rigid::GeomSurface>& surfaces, double spacing_m,
                                           double retraction_m = 0.0);

/// Markers of every geom with a volume of the model (rigid::geomSurfaces), its round geoms
/// tessellated finely enough that a facet's chord is at most the spacing (and at least 16 slices).
std::vector<SurfaceMarker3> modelSurfaceMarkers(const rigid::RigidModel& model, double spacing_m,
                                                double retraction_m = 0.0);

/// Interior markers of the model's primitive geoms (sphere, capsule, ellipsoid, cylinder, box; not
/// meshes): the points of a cubic lattice of side `spacing_m` centred on the geom that lie at least
/// `margin_m` inside its surface, each standing for spacing³. They make the fluid inside a body move
/// with it: surface markers alone constrain only the kernel-averaged velocity on the surface, and the
/// fluid a few cells inside is left to the projection and viscosity.
std::vector<SurfaceMarker3> interiorMarkers(const rigid::RigidModel& model, double spacing_m, double margin_m);

/// World position (m) of a marker at data's current kinematics.
Vec3 markerWorld(const rigid::RigidData& data, const SurfaceMarker3& m);

}  // namespace creaturelab::coupling3d
