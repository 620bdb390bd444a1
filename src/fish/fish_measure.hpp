#pragma once
// What the experiments measure on a recorded run (fish_run.hpp): swimming speed and lateral drift,
// the heading change and radius of a turn, the travel of the centre of mass.
#include <cmath>
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
  // After the warm-up (a window of one swim period, given): the direction of travel over the first
  // window after warmup_s against that over the last window of the run (signed, left > 0), and the
  // sideways displacement from warmup_s to the end, perpendicular to that first direction, over the
  // distance. The start from rest leaves the fish a heading of its own (the left side starts the
  // wave); these measure whether it then swims straight.
  double settled_heading_change_deg = std::nan("");
  double settled_lateral_drift_fraction = std::nan("");
};

struct TurnMeasures {
  bool found = false;          // the schedule has a left or right item
  double heading_change_deg = 0;  // over that item, signed (left > 0)
  double path_m = 0;              // centre-of-mass path length over it
  double radius_m = 0;            // path / |heading change in radians|
};

// A manoeuvre from a swimming start (how Tu's fish turn): the direction of travel of the centre of
// mass, averaged over one window (a swim period) just before the first item that is not swim
// (left, right or glide) and over the window just after it: the turn the item made.
// A glide item in its place is the control: the heading the swim alone would have changed.
struct TravelTurn {
  bool found = false;               // a non-swim item with a full window before it and after it
  double heading_change_deg = 0;    // signed angle from the first travel direction to the last (left > 0)
  double path_m = 0;                // centre-of-mass path length over the item
  double radius_m = 0;              // path / |heading change in radians|
};

SwimMeasures measureSwim(const FishRecord& rec, double body_length_m, double warmup_s, double window_s = 0);
TurnMeasures measureTurn(const FishRecord& rec, const std::vector<ScheduleItem>& schedule);
TravelTurn measureTravelTurn(const FishRecord& rec, const std::vector<ScheduleItem>& schedule, double window_s);

}  // namespace creaturelab::fish
