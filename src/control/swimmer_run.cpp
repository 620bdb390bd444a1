#include "control/swimmer_run.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace creaturelab::control {

void SwimmerPhases::apply(FluidController& controller) const {
  const int phase = coupling::phaseAt(schedule, controller.data().time_s());
  if (!senses.empty()) controller.setSenses(senses[phase]);
  if (!strengths_rad_per_s.empty()) controller.setStrength(strengths_rad_per_s[phase]);
}

double densityRatio(const rigid::RigidModel& model, const coupling::RigidFluidCoupling& c, double rho) {
  // Outline areas by the shoelace formula over each geom's markers (in outline order, geom frame).
  const auto& mk = c.markers();
  double area = 0, mass = 0;
  for (std::size_t k = 0; k < c.mouthBegin();) {
    std::size_t e = k;
    double a = 0;
    while (e < c.mouthBegin() && mk[e].geom == mk[k].geom) ++e;
    for (std::size_t i = k; i < e; ++i) {
      const auto& p = mk[i].local_m;
      const auto& q = mk[i + 1 < e ? i + 1 : k].local_m;
      a += 0.5 * (p[0] * q[2] - q[0] * p[2]);
    }
    if (mk[k].body > 0) area += std::abs(a);
    k = e;
  }
  for (int b = 1; b < model.bodies(); ++b) mass += model.bodyMass_kg(b);
  return area > 0 ? mass / (rho * area * c.params().depth_m) : 0.0;
}

std::string stabilityHint(double ratio) {
  return " [creature mass / displaced fluid mass = " + std::to_string(ratio) +
         "; free bodies coupled explicitly (the staggered step) are unstable when too light for the fluid they "
         "move (added mass): experiments/control/swimmer.toml measures the limit; make the creature denser or "
         "hold its root]";
}

RiseRecorder::RiseRecorder(RiseSettings s) : s_(std::move(s)) {
  if (!active()) return;
  z_ = &series_.add("rise_z_m", "m");
  phase_ = &series_.add("phase", "");
  flux_ = &series_.add("mouth_flux_m_per_s", "m/s");
}

void RiseRecorder::start(const rigid::RigidData& data) {
  if (active()) z0_ = data.subtreeCom(s_.body)[2];
}

void RiseRecorder::record(const rigid::RigidData& data) {
  if (!active()) return;
  z_->push_back(data.subtreeCom(s_.body)[2]);
  // The phase the frame ran in: that at its start (time_s is its end).
  const double t = data.time_s() - data.model().timestep_s() * 0.5;
  phase_->push_back(coupling::phaseAt(s_.mouth.schedule, t));
  flux_->push_back(coupling::mouthFlux_m_per_s(s_.mouth, t));
}

std::vector<NamedValue> RiseRecorder::measure(double density_ratio) const {
  std::vector<NamedValue> out{{"creature_density_ratio", "", density_ratio}};
  if (!active() || z_->empty()) return out;
  const auto& z = *z_;
  const int per_cycle = s_.frames_per_cycle;
  const int back = std::min<int>(s_.cycles * per_cycle, int(z.size()) - 1);
  const double rise = back > 0 ? (z.back() - z[z.size() - 1 - back]) / (double(back) / per_cycle) : 0.0;
  out.push_back({"rise_per_cycle_m", "m", rise});
  out.push_back({"rise_total_m", "m", z.back() - z0_});
  return out;
}

}  // namespace creaturelab::control
