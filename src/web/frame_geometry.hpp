#pragma once
// The frame's plane geometry before any mass is laid (Mehla 2005 §5.2,
// Fig. 5.5 steps 1-5): the centre and the inner-frame corners, and the checks that the attachment
// points make a usable frame.
#include <string>
#include <vector>

#include "web/geometry2.hpp"

namespace creaturelab::web {

struct WebParams;

// Fig. 5.5 steps 2-4: the middle of the points' bounding box, ((xmin + xmax)/2, (ymin + ymax)/2).
Point2 frameCentre(const std::vector<Point2>& attachment_points_m);

// Fig. 5.5 step 5: each point moved toward the centre by move_outer_m (MOVE_OUTER).
std::vector<Point2> innerFramePoints(const std::vector<Point2>& attachment_points_m, const Point2& centre_m,
                                     double move_outer_m);

// The shape checks of WebParams::validate(): duplicates (closer than 1 mm), three consecutive points
// collinear (turning angle below 1e-3 rad), a self-intersecting frame, a centre outside the frame,
// MOVE_OUTER too large or folding the inner frame, inner-frame sides too short for a middle mass, hub or free zone reaching the
// inner frame. "" when the frame is usable.
std::string validateFrameGeometry(const WebParams& p);

}  // namespace creaturelab::web
