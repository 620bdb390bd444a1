#include "jellyfish/jellyfish_body.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace creaturelab::jellyfish {
namespace {
void validateOrThrow(const ActivationParams& activation) {
  if (const std::string err = activation.validate(); !err.empty()) throw std::invalid_argument(err);
}
}  // namespace

JellyfishBody::JellyfishBody(const BellModel& model, ActivationParams activation, double dynamic_viscosity_pa_s)
    : model_((validateOrThrow(activation), model)),
      activation_(std::move(activation)),
      expansion_(expansionWindow(activation_.knots)),
      system_(model.network),
      state_(springs::zeroState<2>(model.network.particleCount())) {
  lowest_knot_ = activation_.knots.front().value;  // validate() guarantees at least one knot
  for (const Knot& k : activation_.knots) lowest_knot_ = std::min(lowest_knot_, k.value);
  // Darcy: α = κ / μ, the permeability over the dynamic viscosity.
  if (!model.tentacle_chains.empty() && (model.tentacle_permeability_m > 0 || model.tentacle_axial_permeability_m > 0)) {
    if (!(dynamic_viscosity_pa_s > 0 && std::isfinite(dynamic_viscosity_pa_s)))
      throw std::invalid_argument("permeable tentacles need a fluid viscosity > 0");
    porosity_m_per_pa_s_ = model.tentacle_permeability_m / dynamic_viscosity_pa_s;
    axial_porosity_m_per_pa_s_ = model.tentacle_axial_permeability_m / dynamic_viscosity_pa_s;
  }
}

double JellyfishBody::muscleFactor(int m, double t_s) const {
  const MuscleSpring& muscle = model_.muscles[m];
  const double delay_s = activation_.synaptic_delay_s * muscle.order_from_aperture;
  const double t = t_s - delay_s;
  if (activation_.active_cycles > 0 && t * activation_.contraction_hz >= activation_.active_cycles) return 1.0;
  if (activation_.shape == ActivationShape::pulse) return 1.0 - (1.0 - lowest_knot_) * activation(m, t_s);
  const double stagger = activation_.expansion == Expansion::staggered ? activation_.stagger : 0.0;
  return jellyfish::muscleFactor(activation_.knots, activation_.contraction_hz * t, expansion_, stagger,
                                 muscle.aperture_position);
}

double JellyfishBody::activation(int m, double t_s) const {
  const double t = t_s - activation_.synaptic_delay_s * model_.muscles[m].order_from_aperture;
  if (t < 0) return 0.0;
  if (activation_.active_cycles > 0 && t * activation_.contraction_hz >= activation_.active_cycles) return 0.0;
  if (activation_.shape == ActivationShape::hermite)
    return std::clamp((1.0 - muscleFactor(m, t_s)) / (1.0 - lowest_knot_), 0.0, 1.0);
  double since_s = wrapPhase(activation_.contraction_hz * t) / activation_.contraction_hz;
  const double half_s = 0.5 * activation_.pulse_duration_s;
  if (since_s > half_s && activation_.pulse_stagger > 0)  // the staggered release (jellyfish_params.hpp)
    since_s = half_s + (since_s - half_s) / (1.0 - activation_.pulse_stagger * (1.0 - model_.muscles[m].aperture_position));
  if (since_s >= activation_.pulse_duration_s) return 0.0;
  const double s = std::sin(M_PI * since_s / activation_.pulse_duration_s);
  return s * s;
}

void JellyfishBody::toState(std::span<const fluid::Vec2> x_m) const {
  for (std::size_t i = 0; i < x_m.size(); ++i) state_.x_m.col(static_cast<long>(i)) << x_m[i].x, x_m[i].y;
}

void JellyfishBody::muscleTensions(double t_s, std::span<const fluid::Vec2> x_m,
                                   std::vector<double>& tension_n_per_m) const {
  tension_n_per_m.resize(model_.muscles.size());
  for (std::size_t m = 0; m < model_.muscles.size(); ++m)
    tension_n_per_m[m] = muscleState(static_cast<int>(m), t_s, x_m).tension_n_per_m;
}

double JellyfishBody::elasticEnergy(double t_s, std::span<const fluid::Vec2> x_m) const {
  toState(x_m);
  double energy = system_.elasticEnergy(state_);
  std::vector<double> tension;
  muscleTensions(t_s, x_m, tension);
  // An active tension stores no energy: it is a force the muscle makes, not a spring.
  if (model_.muscle_model == MuscleModel::rest_length)
    for (std::size_t m = 0; m < tension.size(); ++m)
      energy += 0.5 * tension[m] * tension[m] / model_.muscles[m].stiffness_n_per_m;
  return energy;
}

JellyfishBody::MuscleState JellyfishBody::muscleState(int m, double t_s, std::span<const fluid::Vec2> x_m) const {
  const MuscleSpring& s = model_.muscles[m];
  MuscleState out;
  out.lx = x_m[s.a].x - x_m[s.b].x;
  out.ly = x_m[s.a].y - x_m[s.b].y;
  out.length_m = std::hypot(out.lx, out.ly);
  if (model_.muscle_model == MuscleModel::active_tension) {
    out.tension_n_per_m = s.tension_max_n_per_m * activation(m, t_s);
    return out;
  }
  const double rest = s.relaxed_length_m * muscleFactor(m, t_s);
  if (out.length_m > rest) {  // a slack muscle (|l| < r) exerts no force and has no stiffness
    out.tension_n_per_m = s.stiffness_n_per_m * (out.length_m - rest);
    out.axial_stiffness_n_per_m = s.stiffness_n_per_m;
  }
  return out;
}

void JellyfishBody::forces(double t_s, std::span<const fluid::Vec2> x_m, std::span<fluid::Vec2> force) const {
  toState(x_m);
  system_.conservativeForces(state_, scratch_);
  for (std::size_t i = 0; i < x_m.size(); ++i) force[i] = {scratch_(0, long(i)), scratch_(1, long(i))};
  // Muscles pull only (§3.1: "the circumferential muscle has no opposing muscle"; the bell re-opens
  // by the elasticity of its mesoglea alone): f_a = -T l/|l| (l = x_a - x_b), f_b = -f_a, with T
  // the tension of muscleState (a taut spring's k (|l| - r), or the active T_max a(t)).
  for (std::size_t m = 0; m < model_.muscles.size(); ++m) {
    const MuscleSpring& s = model_.muscles[m];
    const MuscleState e = muscleState(static_cast<int>(m), t_s, x_m);
    if (e.tension_n_per_m == 0.0 || e.length_m == 0.0) continue;
    const double magnitude = -e.tension_n_per_m / e.length_m;
    force[s.a].x += magnitude * e.lx;
    force[s.a].y += magnitude * e.ly;
    force[s.b].x -= magnitude * e.lx;
    force[s.b].y -= magnitude * e.ly;
  }
}

void JellyfishBody::porousSlips(std::span<const fluid::Vec2> x, std::vector<ib::PorousSlip>& out) const {
  out.clear();
  const double alpha = porosity_m_per_pa_s_;
  const double alpha_axial = axial_porosity_m_per_pa_s_;
  if (!(alpha > 0) && !(alpha_axial > 0)) return;
  for (const std::vector<int>& chain : model_.tentacle_chains)
    for (std::size_t m = 1; m < chain.size(); ++m) {
      const fluid::Vec2 here = x[chain[m]], before = x[chain[m - 1]];
      const bool tip = m + 1 == chain.size();
      const fluid::Vec2 after = tip ? here : x[chain[m + 1]];
      // Tangent by the central difference (one-sided at the tip); ds = half of the two segments.
      const double tx = after.x - before.x, ty = after.y - before.y, t = std::hypot(tx, ty);
      const double ds = 0.5 * (std::hypot(here.x - before.x, here.y - before.y) + std::hypot(after.x - here.x, after.y - here.y));
      if (!(t > 0 && ds > 0)) continue;  // a collapsed joint has no normal: impermeable this step
      out.push_back({chain[m], -ty / t, tx / t, alpha / ds, alpha_axial / ds});
    }
}

std::vector<int> JellyfishBody::solveOrder() const {
  std::vector<int> order;
  const auto& tentacle = model_.tentacle_markers;  // the left chains root → tip, then the right ones
  const int per_side = static_cast<int>(tentacle.size()) / 2;
  for (int m = per_side - 1; m >= 0; --m) {
    order.push_back(tentacle[m]);
    order.push_back(tentacle[per_side + m]);
  }
  const int last = model_.bell_markers - 1;
  for (int k = 0; k < last - k; ++k) {
    order.push_back(k);
    order.push_back(last - k);
  }
  if (last % 2 == 0) order.push_back(last / 2);
  return order;
}

void JellyfishBody::stiffness(double t_s, std::span<const fluid::Vec2> x_m, double scale,
                              std::vector<Eigen::Triplet<double>>& out) const {
  toState(x_m);
  system_.addStiffnessTriplets(state_, scale, out, /*clamp_compression=*/true);
  // ∂f_a/∂x_a = −[k_axial ûûᵀ + (T/|l|)(I − ûûᵀ)]: a spring's k_axial = k and T/|l| = k (1 − r/|l|);
  // an active tension has no axial stiffness. Blocks (a,a), (b,b) = that, (a,b), (b,a) = minus it;
  // both terms are negative semi-definite, as the coupling requires (ib/coupling.hpp).
  for (std::size_t m = 0; m < model_.muscles.size(); ++m) {
    const MuscleSpring& s = model_.muscles[m];
    const MuscleState e = muscleState(static_cast<int>(m), t_s, x_m);
    if (e.tension_n_per_m == 0.0 || e.length_m == 0.0) continue;
    const double ux = e.lx / e.length_m, uy = e.ly / e.length_m;
    const double axial = -scale * e.axial_stiffness_n_per_m, transverse = -scale * e.tension_n_per_m / e.length_m;
    const double block[2][2] = {{axial * ux * ux + transverse * (1 - ux * ux), axial * ux * uy - transverse * ux * uy},
                                {axial * uy * ux - transverse * uy * ux, axial * uy * uy + transverse * (1 - uy * uy)}};
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) {
        out.emplace_back(2 * s.a + r, 2 * s.a + c, block[r][c]);
        out.emplace_back(2 * s.b + r, 2 * s.b + c, block[r][c]);
        out.emplace_back(2 * s.a + r, 2 * s.b + c, -block[r][c]);
        out.emplace_back(2 * s.b + r, 2 * s.a + c, -block[r][c]);
      }
  }
}

}  // namespace creaturelab::jellyfish
