#pragma once
// Boundary markers on the outlines of a planar MuJoCo creature (Lentine et al. 2010 §4.2): the
// fluid of the project is 2-D in the vertical x-z
// plane of the creature, so each geom is cut by that plane and its outline is sampled by markers
// no farther apart than `spacing_m`. The markers are fixed in their geom's frame and move with it.
// Outlines (geom frame, the cut y = 0): box the rectangle |x| <= sx, |z| <= sz; sphere a circle;
// ellipsoid the ellipse (sx, sz); cylinder the rectangle |x| <= r, |z| <= h; capsule the stadium
// of radius r around the segment |z| <= h. Geoms on the world body are static obstacles (body 0).
#include <string>
#include <vector>

#include "rigid/rigid_data.hpp"

namespace creaturelab::coupling {

using rigid::Vec3;

struct OutlineMarker {
  int geom = 0;
  int body = 0;
  Vec3 local_m{};         // in the geom's frame (y = 0)
  double length_m = 0.0;  // outline length the marker stands for (its share of the perimeter)
};

// Every geom with a volume, in geom order. Throws std::invalid_argument naming the geom when it is
// not planar (its y axis not along the world's y, so the x-z cut is not its outline) or of a type
// without an outline here (mesh, plane, height field).
std::vector<OutlineMarker> outlineMarkers(const rigid::RigidModel& model, const rigid::RigidData& data,
                                          double spacing_m);

// World position (m) of a marker at data's current kinematics.
Vec3 markerWorld(const rigid::RigidData& data, const OutlineMarker& m);

}  // namespace creaturelab::coupling
