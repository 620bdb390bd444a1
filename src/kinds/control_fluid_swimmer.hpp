#pragma once
// The swimmer's part of the control_fluid kind (Lentine et al. 2010 §7.2, Fig. 7,
// "Creature Control in a Fluid Environment"; issue 16): the mouth and its phases (coupling/mouth.hpp),
// the controlled joints' sense per phase, and the rise of the creature per cycle.
#include <string>
#include <vector>

#include "control/controller_params.hpp"
#include "coupling/rigid_fluid_coupling.hpp"
#include "kinds/kind.hpp"

namespace creaturelab::kinds {

// Parameters and metrics appended to control_fluid's.
std::vector<ParamSpec> swimmerParams();
std::vector<MetricSpec> swimmerMetrics();

// The mouth and its phase schedule; throws std::invalid_argument naming the key.
coupling::MouthParams mouthParams(const ParamReader& r);

// Per phase, the sense of every controlled joint (phase_senses; empty: the fixed senses).
std::vector<std::vector<control::Sense>> phaseSenses(const ParamReader& r, int joints);

// Per phase, the strength (rad/s) of every controlled joint (phase_strength_rad_per_s; empty: fixed).
std::vector<double> phaseStrengths(const ParamReader& r);

// "" when the swimmer's parameters fit the rest, else what is wrong.
std::string validateSwimmer(const ParamReader& r, const rigid::RigidModel& model);

// Creature mass over the mass of the fluid its outlines displace (rho x area x depth): the
// staggered coupling's added-mass stability depends on it (rigid_fluid_coupling.hpp).
double densityRatio(const rigid::RigidModel& model, const coupling::RigidFluidCoupling& c, double rho_kg_per_m3);

// What a coupled blow-up likely means, for the failure message (exit 3).
std::string stabilityHint(double density_ratio);

// Records the tracked body's centre of mass height, the phase and the mouth flux per frame and
// measures the rise per cycle.
class RiseRecorder {
 public:
  RiseRecorder(const ParamReader& r, const rigid::RigidModel& model, Result& result);
  bool active() const { return body_ >= 0; }
  void start(const rigid::RigidData& data);  // the height the rise counts from
  void record(const rigid::RigidData& data);
  void measure(Result& result, double density_ratio) const;

 private:
  int body_ = -1;
  coupling::MouthParams mouth_;
  int frames_per_cycle_ = 1, cycles_ = 1;
  Series *z_ = nullptr, *phase_ = nullptr, *flux_ = nullptr;
  double z0_ = 0;
};

}  // namespace creaturelab::kinds
