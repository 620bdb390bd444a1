#pragma once
// What the experiments measure on a recorded run (fish_run.hpp): swimming speed and lateral drift,
// the heading change and radius of a turn, the travel of the centre of mass.
#include <vector>

#include "fish/fish_run.hpp"
#include "fish/motor.hpp"

namespace creaturelab::fish {

struct SwimMeasures {
  // From warmup_s to the end (the gait has settled): centre-of-mass displacement in the horizontal plane.
  double speed_body_lengths_per_s = 0;
  double speed_m_per_s = 0;
  // Over the whole run: the sideways displacement of the centre of mass, perpendicular to the heading
  // the fish had at rest (+x), and that over the forward displacement.
  double lateral_drift_m = 0;
  double forward_distance_m = 0;
  double lateral_drift_fraction = 0;
  double com_travel_m = 0;         // |com(end) - com(0)|, all three axes
  double vertical_drift_m = 0;     // |z_com(end) - z_com(0)|: the body is mirror-symmetric top to bottom
};

struct TurnMeasures {
  bool found = false;          // the schedule has a left or right item
  double heading_change_deg = 0;  // over that item, signed (left > 0)
  double path_m = 0;              // centre-of-mass path length over it
  double radius_m = 0;            // path / |heading change in radians|
};

SwimMeasures measureSwim(const FishRecord& rec, double body_length_m, double warmup_s);
TurnMeasures measureTurn(const FishRecord& rec, const std::vector<ScheduleItem>& schedule);

}  // namespace creaturelab::fish
