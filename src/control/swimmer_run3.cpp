#include "control/swimmer_run3.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace creaturelab::control {

namespace {
struct SwimmerSnapshot3 final : FluidSnapshot {
  coupling3d::CouplingState3 state;
};
}  // namespace

SwimmerFluid3::SwimmerFluid3(const rigid::RigidData& data, const fluid3d::FluidParams3& fluid,
                             const coupling3d::RigidFluidParams3& p, coupling::PhaseSchedule schedule,
                             std::vector<double> flux_m_per_s)
    : c_(data, fluid, p), schedule_(std::move(schedule)), flux_m_per_s_(std::move(flux_m_per_s)) {}

double SwimmerFluid3::flux_m_per_s(double t_s) const {
  return flux_m_per_s_.empty() ? 0.0 : flux_m_per_s_[coupling::phaseAt(schedule_, t_s)];
}

void SwimmerFluid3::setFlux(double time_s, double dt_s) {
  // The bodies' time is the step's end: the flux of the step's middle.
  const double flux = flux_m_per_s(time_s - 0.5 * dt_s);
  for (std::size_t m = 0; m < c_.params().mouths.size(); ++m) c_.setMouthFlux(m, flux);
}

void SwimmerFluid3::forceAndProject(const rigid::RigidData& data, double dt_s) {
  setFlux(data.time_s(), dt_s);
  c_.forceFluid(data, dt_s);
}

void SwimmerFluid3::forceAndCorrect(rigid::RigidData& data, double dt_s, const std::vector<int>& held_dofs) {
  setFlux(data.time_s(), dt_s);
  c_.setHeldDofs(held_dofs);
  c_.forceFluid(data, dt_s);
}

void SwimmerFluid3::save(std::unique_ptr<FluidSnapshot>& s) const {
  if (!dynamic_cast<SwimmerSnapshot3*>(s.get())) s = std::make_unique<SwimmerSnapshot3>();
  c_.save(static_cast<SwimmerSnapshot3&>(*s).state);
}

void SwimmerFluid3::restore(const FluidSnapshot& s, const rigid::RigidData&) {
  c_.restore(dynamic_cast<const SwimmerSnapshot3&>(s).state);
}

CoupledFluidFactory swimmerFluid(const fluid3d::FluidParams3& fluid, const coupling3d::RigidFluidParams3& p,
                                 const coupling::PhaseSchedule& schedule, const std::vector<double>& flux_m_per_s) {
  return [=](const rigid::RigidData& data, bool single_threaded) -> std::unique_ptr<CoupledFluid> {
    fluid3d::FluidParams3 f = fluid;
    if (single_threaded) f.threads = 1;
    return std::make_unique<SwimmerFluid3>(data, f, p, schedule, flux_m_per_s);
  };
}

double geomVolume_m3(int type, const Vec3& s) {
  constexpr double pi = std::numbers::pi;
  switch (type) {
    case 2: return 4.0 / 3.0 * pi * s[0] * s[0] * s[0];                                // sphere: radius
    case 3: return pi * s[0] * s[0] * (2.0 * s[1]) + 4.0 / 3.0 * pi * s[0] * s[0] * s[0];  // capsule: radius, half-length
    case 4: return 4.0 / 3.0 * pi * s[0] * s[1] * s[2];                                // ellipsoid: semi-axes
    case 5: return pi * s[0] * s[0] * (2.0 * s[1]);                                    // cylinder: radius, half-length
    case 6: return 8.0 * s[0] * s[1] * s[2];                                           // box: half-sizes
    default: return 0.0;
  }
}

double densityRatio3(const rigid::RigidModel& model, double rho) {
  double volume = 0, mass = 0;
  for (int g = 0; g < model.geoms(); ++g)
    if (model.geomBody(g) > 0) volume += geomVolume_m3(model.geomType(g), model.geomSize(g));
  for (int b = 1; b < model.bodies(); ++b) mass += model.bodyMass_kg(b);
  return volume > 0 ? mass / (rho * volume) : 0.0;
}

std::string stabilityHint3(double ratio, bool staggered) {
  const std::string head = " [creature mass / displaced fluid mass = " + std::to_string(ratio);
  if (!staggered) return head + "]";
  return head +
         "; free bodies coupled explicitly (the staggered step) are unstable when too light for the fluid they "
         "move (added mass): use forcing = coupled (Eq. 9), or with projected forcing give the root's DOFs more "
         "armature with armature_added_mass, make the creature denser or hold its root]";
}

CycleRise cycleRise(const std::vector<double>& z, int per_cycle, int cycles) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const long n = long(z.size()) - 1;  // frames recorded after the start
  if (per_cycle < 1 || cycles < 1 || n < long(per_cycle) * cycles) return {nan, nan};
  std::vector<double> r(cycles);
  double mean = 0;
  for (int k = 0; k < cycles; ++k) {
    const long end = n - long(cycles - 1 - k) * per_cycle;
    r[k] = z[end] - z[end - per_cycle];
    mean += r[k] / cycles;
  }
  if (cycles < 2) return {mean, nan};
  double ss = 0;
  for (double v : r) ss += (v - mean) * (v - mean);
  return {mean, std::sqrt(ss / (cycles - 1)) / std::sqrt(double(cycles))};
}

RiseRecorder3::RiseRecorder3(RiseSettings3 s) : s_(std::move(s)) {
  x_ = &series_.add("com_x_m", "m");
  y_ = &series_.add("com_y_m", "m");
  z_ = &series_.add("rise_z_m", "m");
  phase_ = &series_.add("phase", "");
  flux_ = &series_.add("mouth_flux_m_per_s", "m/s");
}

void RiseRecorder3::start(const rigid::RigidData& data) {
  const double* c = data.subtreeCom(s_.body);
  start_ = {c[0], c[1], c[2]};
}

void RiseRecorder3::record(const rigid::RigidData& data) {
  const double* c = data.subtreeCom(s_.body);
  x_->push_back(c[0]);
  y_->push_back(c[1]);
  z_->push_back(c[2]);
  // The phase the frame ran in: that at its start (time_s is its end).
  const double t = data.time_s() - data.model().timestep_s() * 0.5;
  const int phase = coupling::phaseAt(s_.schedule, t);
  phase_->push_back(phase);
  flux_->push_back(s_.flux_m_per_s.empty() ? 0.0 : s_.flux_m_per_s[phase]);
}

std::vector<NamedValue> RiseRecorder3::measure(double density_ratio) const {
  std::vector<double> z{start_[2]};
  z.insert(z.end(), z_->begin(), z_->end());
  const CycleRise rise = cycleRise(z, s_.frames_per_cycle, s_.cycles);
  const double dx = x_->empty() ? 0.0 : x_->back() - start_[0];
  const double dy = y_->empty() ? 0.0 : y_->back() - start_[1];
  return {
      {"rise_per_cycle_m", "m", rise.mean_m},
      {"rise_per_cycle_m_stderr", "m", rise.stderr_m},
      {"rise_total_m", "m", z.back() - z.front()},
      {"drift_m", "m", std::hypot(dx, dy)},
      {"creature_density_ratio", "", density_ratio},
  };
}

}  // namespace creaturelab::control
