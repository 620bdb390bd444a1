#include "charlotte/resettle.hpp"

#include <cmath>

#include "springs/equilibrium.hpp"
#include "springs/simulate.hpp"

namespace creaturelab::charlotte {

void resettle(const web::WebModel& model, const Pruned& pruned, const ResettleParams& p, Resettled& out) {
  const double nan = std::nan("");
  springs::System<3> after(pruned.network);
  springs::Points<3> frame_force = springs::Points<3>::Zero(3, pruned.network.particleCount());
  for (int i = 0; i < pruned.network.particleCount(); ++i)  // the web's own masses keep their force; new ones have none
    if (pruned.particle_of[i] < model.network.particleCount())
      frame_force.col(i) = model.external_force_n.col(pruned.particle_of[i]);
  after.setConstantForce(frame_force);
  out.state = pruned.state;
  std::vector<int> hub_after;
  for (int h : model.hub_particles) hub_after.push_back(pruned.new_particle[h]);
  auto hubOf = [&](const springs::State<3>& s) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int h : hub_after) sum += s.x_m.col(h);
    return Eigen::Vector3d(sum / double(hub_after.size()));
  };
  const Eigen::Vector3d hub0 = hubOf(out.state);
  out.settling_time_s = nan;
  out.iterations = nan;
  if (p.dynamic) {
    springs::SimulationOptions opt;
    opt.integrator = springs::IntegratorKind::RK4;  // the thesis's integrator (§4.2, Eq. 4.16-4.19)
    opt.frame_interval_s = 0.02;                    // §5.2.1 'time step'
    opt.end_time_s = p.time_s;
    opt.settling_fraction = p.settling_fraction;
    const auto summary = springs::simulate<3>(after, out.state, opt, [&](int, double, const springs::State<3>& s) {
      out.hub_shift_m.push_back((hubOf(s) - hub0).norm());
    });
    out.settling_time_s = summary.settling_time_s.value_or(nan);
    out.time_s = summary.time_s;
    out.kinetic_energy_j = summary.kinetic_energy_j;
    out.converged = true;
  } else {
    const auto eq = springs::solveStaticEquilibrium(after, out.state);
    out.converged = eq.converged;
    if (!eq.converged) return;
    out.iterations = eq.iterations;
    out.time_s = {0.0};
    out.hub_shift_m.push_back((hubOf(out.state) - hub0).norm());
  }
}

}  // namespace creaturelab::charlotte
