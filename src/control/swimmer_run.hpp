#pragma once
// What the aqueous swimmer's run measures and how its phases steer the controller (M. Lentine et al.,
// "Creature Control in a Fluid Environment", 2010 §7.2, Fig. 7): per frame the tracked body's centre
// of mass height, the phase and the mouth's flux; at the end the rise per cycle. No I/O: the kind
// copies the series and values into its Result.
#include <string>
#include <vector>

#include "control/fluid_controller.hpp"
#include "control/run_measures.hpp"
#include "coupling/mouth.hpp"

namespace creaturelab::control {

// Per phase of the mouth's schedule, the senses and strength (rad/s) of the controlled joints;
// an empty list keeps the controller's own.
struct SwimmerPhases {
  coupling::PhaseSchedule schedule;
  std::vector<std::vector<Sense>> senses;
  std::vector<double> strengths_rad_per_s;

  // Before a frame: the senses and strength of the phase the controller's time is in.
  void apply(FluidController& controller) const;
};

// Creature mass over the mass of the fluid its outlines displace (rho x area x depth): the
// staggered coupling's added-mass stability depends on it (rigid_fluid_coupling.hpp).
double densityRatio(const rigid::RigidModel& model, const coupling::RigidFluidCoupling& c, double rho_kg_per_m3);

// What a coupled blow-up likely means, for the failure message (exit 3).
std::string stabilityHint(double density_ratio);

struct RiseSettings {
  int body = -1;  // body whose subtree's centre of mass is tracked; < 0: none
  coupling::MouthParams mouth;
  int frames_per_cycle = 1;
  int cycles = 1;  // rise per cycle: mean over the last this many cycles
};

// Records the tracked body's centre of mass height (m), the phase and the mouth flux (m/s) per frame
// and measures the rise per cycle.
class RiseRecorder {
 public:
  explicit RiseRecorder(RiseSettings s);
  bool active() const { return s_.body >= 0; }
  void start(const rigid::RigidData& data);  // the height the rise counts from
  void record(const rigid::RigidData& data);
  const SeriesSet& series() const { return series_; }
  // creature_density_ratio always; rise_per_cycle_m and rise_total_m when a body is tracked.
  std::vector<NamedValue> measure(double density_ratio) const;

 private:
  RiseSettings s_;
  SeriesSet series_;
  std::vector<double> *z_ = nullptr, *phase_ = nullptr, *flux_ = nullptr;
  double z0_ = 0;
};

}  // namespace creaturelab::control
