#pragma once
// What the aqueous swimmer's run in the 3-D fluid measures (M. Lentine et al., "Creature Control in a
// Fluid Environment", 2010 §7.2, Fig. 7): per frame the tracked body's subtree centre of mass (x, y, z)
// and the phase; at the end the rise per cycle over whole cycles with its standard error, the drift,
// and the creature's density against the water its geoms displace. No I/O: the kind copies the series
// and values into its Result.
#include <string>
#include <vector>

#include "control/run_measures.hpp"
#include "coupling/mouth.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::control {

// Volume (m^3) of a MuJoCo primitive geom from its type and size (sphere, capsule, ellipsoid,
// cylinder, box); 0 for any other type (meshes, planes).
double geomVolume_m3(int type, const Vec3& size);

// Creature mass (every body but the world) over the mass of the fluid its geoms displace
// (rho x their volumes): the staggered coupling's added-mass stability depends on it.
double densityRatio3(const rigid::RigidModel& model, double rho_kg_per_m3);

// What a coupled blow-up likely means, for the failure message (exit 3).
std::string stabilityHint3(double density_ratio);

struct RiseSettings3 {
  int body = 0;                        // body whose subtree's centre of mass is tracked (> 0)
  coupling::PhaseSchedule schedule;    // the phases recorded per frame
  int frames_per_cycle = 1;
  int cycles = 1;                      // rise per cycle: over the last this many whole cycles
};

// Rise per cycle over the last `cycles` whole cycles of heights z (z[0] the start, one value per frame
// after it): the mean of the cycles' rises, and its standard error sqrt(sum (r_k - mean)^2 / (cycles - 1))
// / sqrt(cycles) with the cycles taken as independent samples (NaN with one cycle). Both NaN when z
// does not cover the cycles.
struct CycleRise {
  double mean_m = 0, stderr_m = 0;
};
CycleRise cycleRise(const std::vector<double>& z, int frames_per_cycle, int cycles);

class RiseRecorder3 {
 public:
  explicit RiseRecorder3(RiseSettings3 s);
  void start(const rigid::RigidData& data);  // the position the rise counts from
  void record(const rigid::RigidData& data);
  const SeriesSet& series() const { return series_; }
  // rise_per_cycle_m (+ _stderr), rise_total_m, drift_m (horizontal, over the run), creature_density_ratio.
  std::vector<NamedValue> measure(double density_ratio) const;

 private:
  RiseSettings3 s_;
  SeriesSet series_;
  std::vector<double> *x_, *y_, *z_, *phase_;
  Vec3 start_{};
};

}  // namespace creaturelab::control
