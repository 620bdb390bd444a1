#include "jellyfish/jellyfish_body.hpp"

#include <cmath>
#include <stdexcept>

namespace creaturelab::jellyfish {
namespace {
void validateOrThrow(const ActivationParams& activation) {
  if (const std::string err = validate(activation); !err.empty()) throw std::invalid_argument(err);
}
}  // namespace

JellyfishBody::JellyfishBody(const BellModel& model, ActivationParams activation)
    : model_((validateOrThrow(activation), model)),
      activation_(std::move(activation)),
      expansion_(expansionWindow(activation_.knots)),
      system_(model.network),
      state_(springs::zeroState<2>(model.network.particleCount())) {}

double JellyfishBody::muscleFactor(int m, double t_s) const {
  const MuscleSpring& muscle = model_.muscles[m];
  const double delay_s = activation_.synaptic_delay_s * muscle.order_from_aperture;
  const double stagger = activation_.expansion == Expansion::staggered ? activation_.stagger : 0.0;
  return jellyfish::muscleFactor(activation_.knots, activation_.contraction_hz * (t_s - delay_s), expansion_, stagger,
                                 muscle.aperture_position);
}

void JellyfishBody::toState(std::span<const fluid::Vec2> x_m) const {
  for (std::size_t i = 0; i < x_m.size(); ++i) state_.x_m.col(static_cast<long>(i)) << x_m[i].x, x_m[i].y;
}

void JellyfishBody::muscleTensions(double t_s, std::span<const fluid::Vec2> x_m,
                                   std::vector<double>& tension_n_per_m) const {
  tension_n_per_m.resize(model_.muscles.size());
  for (std::size_t m = 0; m < model_.muscles.size(); ++m) {
    const MuscleSpring& s = model_.muscles[m];
    const double length = std::hypot(x_m[s.b].x - x_m[s.a].x, x_m[s.b].y - x_m[s.a].y);
    const double rest = s.relaxed_length_m * muscleFactor(static_cast<int>(m), t_s);
    tension_n_per_m[m] = s.stiffness_n_per_m * std::max(0.0, length - rest);
  }
}

double JellyfishBody::elasticEnergy(double t_s, std::span<const fluid::Vec2> x_m) const {
  toState(x_m);
  double energy = system_.elasticEnergy(state_);
  std::vector<double> tension;
  muscleTensions(t_s, x_m, tension);
  for (std::size_t m = 0; m < tension.size(); ++m) energy += 0.5 * tension[m] * tension[m] / model_.muscles[m].stiffness_n_per_m;
  return energy;
}

void JellyfishBody::forces(double t_s, std::span<const fluid::Vec2> x_m, std::span<fluid::Vec2> force) const {
  toState(x_m);
  system_.conservativeForces(state_, scratch_);
  for (std::size_t i = 0; i < x_m.size(); ++i) force[i] = {scratch_(0, long(i)), scratch_(1, long(i))};
  // Muscles: Hooke springs f_a = -k (|l| - r) l/|l| (l = x_a - x_b) with rest length r(t) that pull
  // only (§3.1: "the circumferential muscle has no opposing muscle"; the bell re-opens by the
  // elasticity of its mesoglea alone). A slack muscle (|l| < r) exerts no force.
  for (std::size_t m = 0; m < model_.muscles.size(); ++m) {
    const MuscleSpring& s = model_.muscles[m];
    const double lx = x_m[s.a].x - x_m[s.b].x, ly = x_m[s.a].y - x_m[s.b].y;
    const double length = std::hypot(lx, ly);
    const double rest = s.relaxed_length_m * muscleFactor(static_cast<int>(m), t_s);
    if (length <= rest) continue;
    const double magnitude = -s.stiffness_n_per_m * (length - rest) / length;
    force[s.a].x += magnitude * lx;
    force[s.a].y += magnitude * ly;
    force[s.b].x -= magnitude * lx;
    force[s.b].y -= magnitude * ly;
  }
}

void JellyfishBody::stiffness(double t_s, std::span<const fluid::Vec2> x_m, double scale,
                              std::vector<Eigen::Triplet<double>>& out) const {
  toState(x_m);
  system_.addStiffnessTriplets(state_, scale, out, /*clamp_compression=*/true);
  // ∂f_a/∂x_a = −k [ûûᵀ + (1 − r/|l|)(I − ûûᵀ)]; blocks (a,a), (b,b) = that, (a,b), (b,a) = minus it.
  for (std::size_t m = 0; m < model_.muscles.size(); ++m) {
    const MuscleSpring& s = model_.muscles[m];
    const double lx = x_m[s.a].x - x_m[s.b].x, ly = x_m[s.a].y - x_m[s.b].y;
    const double length = std::hypot(lx, ly);
    const double rest = s.relaxed_length_m * muscleFactor(static_cast<int>(m), t_s);
    if (length <= rest) continue;  // slack: no force, no stiffness
    const double ux = lx / length, uy = ly / length;
    const double transverse = 1.0 - rest / length;
    const double k = -scale * s.stiffness_n_per_m;
    const double block[2][2] = {{k * (ux * ux + transverse * (1 - ux * ux)), k * (ux * uy - transverse * ux * uy)},
                                {k * (uy * ux - transverse * uy * ux), k * (uy * uy + transverse * (1 - uy * uy))}};
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
