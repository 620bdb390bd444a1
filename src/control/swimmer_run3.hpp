#pragma once
// The aqueous swimmer's run in the 3-D fluid (M. Lentine et al., "Creature Control in a Fluid
// Environment", 2010 §7.2, Fig. 7): its coupled fluid, whose mouth's flux follows the phases, and what
// it measures: per frame the tracked body's subtree centre of mass (x, y, z) and the phase; at the end
// the rise per cycle over whole cycles with its standard error, the drift, and the creature's density
// against the water its geoms displace. No I/O: the kind copies the series and values into its Result.
#include <string>
#include <vector>

#include "control/coupled_fluid.hpp"
#include "control/run_measures.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"
#include "coupling/mouth.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::control {

// The 3-D coupled fluid (as coupled_fluid3.hpp's CoupledFluid3, exact snapshot) whose mouths
// (RigidFluidParams3::mouths) take, at each coupled step, the flux of the phase the step's middle is in:
// flux_m_per_s[phase] (m/s, + expels). The flux is a function of the bodies' time alone, so a derivative
// evaluation restored from the main copy sees the same flux as the frame it perturbs.
class SwimmerFluid3 final : public CoupledFluid {
 public:
  SwimmerFluid3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p,
                coupling::PhaseSchedule schedule, std::vector<double> flux_m_per_s);
  void advanceFluid(double dt_s) override { c_.advanceFluid(dt_s); }
  // Projected or off forcing (the coupled solve changes data: forceAndCorrect); both set the mouths' flux first.
  void forceAndProject(const rigid::RigidData& data, double dt_s) override;
  bool coupledSolve() const override { return c_.params().forcing == coupling3d::Forcing3::coupled; }
  void forceAndCorrect(rigid::RigidData& data, double dt_s, const std::vector<int>& held_dofs) override;
  void applyReaction(rigid::RigidData& data) const override { c_.applyReaction(data); }
  void applyFluidForce(rigid::RigidData& data) const override { c_.applyFluidForce(data); }
  const std::vector<Vec3>& bodyForce_n() const override { return c_.bodyForce_n(); }
  int forcingIterations() const override { return c_.forcingIterations(); }
  void placeMarkers(const rigid::RigidData& data) override { c_.placeMarkers(data); }
  void save(std::unique_ptr<FluidSnapshot>& s) const override;
  void restore(const FluidSnapshot& s, const rigid::RigidData& data) override;
  bool exactSnapshot() const override { return true; }
  const coupling3d::RigidFluidCoupling3& coupling() const { return c_; }
  // The mouths' flux (m/s) at time t_s; 0 without phases.
  double flux_m_per_s(double t_s) const;

 private:
  void setFlux(double time_s, double dt_s);  // the mouths' flux of the step ending at time_s
  coupling3d::RigidFluidCoupling3 c_;
  coupling::PhaseSchedule schedule_;
  std::vector<double> flux_m_per_s_;
};

// Makes SwimmerFluid3s; a single-threaded one's fluid takes one thread.
CoupledFluidFactory swimmerFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p,
                                 const coupling::PhaseSchedule& schedule, const std::vector<double>& flux_m_per_s);

// Volume (m^3) of a MuJoCo primitive geom from its type and size (sphere, capsule, ellipsoid,
// cylinder, box); 0 for any other type (meshes, planes).
double geomVolume_m3(int type, const Vec3& size);

// Creature mass (every body but the world) over the mass of the fluid its geoms displace
// (rho x their volumes): the staggered coupling's added-mass stability depends on it.
double densityRatio3(const rigid::RigidModel& model, double rho_kg_per_m3);

// What a coupled blow-up likely means, for the failure message (exit 3): the density ratio, and with the
// staggered (projected) forcing its added-mass limit and the remedies.
std::string stabilityHint3(double density_ratio, bool staggered);

struct RiseSettings3 {
  int body = 0;                        // body whose subtree's centre of mass is tracked (> 0)
  coupling::PhaseSchedule schedule;    // the phases recorded per frame
  std::vector<double> flux_m_per_s;    // the mouth's flux per phase, recorded per frame; empty: none
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
  std::vector<double> *x_, *y_, *z_, *phase_, *flux_;
  Vec3 start_{};
};

}  // namespace creaturelab::control
