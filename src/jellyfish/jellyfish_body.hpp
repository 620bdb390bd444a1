#pragma once
// The jellyfish as the immersed boundary sees it (ib::ElasticBody): the bell and tentacle network
// (springs and angular springs, through springs::System) plus the circumferential muscle, whose
// rest lengths follow the activation curve of §3.3 (Rudolf & Mould 2009, Fig. 4).
#include <vector>

#include "ib/coupling.hpp"
#include "jellyfish/bell_model.hpp"
#include "springs/system.hpp"

namespace creaturelab::jellyfish {

class JellyfishBody : public ib::ElasticBody {
 public:
  /// dynamic_viscosity_pa_s: μ = ρ ν of the fluid around the body, Pa s, which turns the tentacles'
  /// permeabilities κ into Darcy coefficients κ / μ (> 0 when a chain is permeable).
  JellyfishBody(const BellModel& model, ActivationParams activation, double dynamic_viscosity_pa_s);

  int markerCount() const override { return system_.particleCount(); }
  void forces(double t_s, std::span<const fluid::Vec2> x_m, std::span<fluid::Vec2> force_n_per_m) const override;
  void stiffness(double t_s, std::span<const fluid::Vec2> x_m, double scale,
                 std::vector<Eigen::Triplet<double>>& out) const override;
  /// Tentacle tips to roots, then the bell from the aperture to the apex, each left/right pair side by
  /// side: a muscle joins a pair, and markers near each other in space are near in this order.
  std::vector<int> solveOrder() const override;
  /// The tentacle chains' markers (not their roots) are porous when the model's permeability is > 0:
  /// normal from the chain's neighbours, ds the marker's share of the chain's present arc.
  void porousSlips(std::span<const fluid::Vec2> x_m, std::vector<ib::PorousSlip>& out) const override;

  /// Activation of muscle `m` at time t, in [0, 1] (0 relaxed). Hermite shape: the §3.3 curve
  /// mapped so that its lowest knot is 1; pulse shape: sin²(π t / duration) at the cycle's start.
  /// Zero after `active_cycles` cycles.
  double activation(int m, double t_s) const;
  /// Rest-length factor of muscle `m` at time t (1 relaxed, 0.56 fully contracted by default);
  /// the rest_length model's control, 1 - (1 - lowest knot) a for the pulse shape.
  double muscleFactor(int m, double t_s) const;
  /// Elastic energy of bell, tentacles and muscles at positions x and time t, J per metre of depth.
  double elasticEnergy(double t_s, std::span<const fluid::Vec2> x_m) const;
  /// Tension of every muscle element at positions x and time t, N per metre of depth (> 0 pulls):
  /// a slack-free spring's k (|l| - r) in the rest_length model, T_max a(t) in active_tension.
  void muscleTensions(double t_s, std::span<const fluid::Vec2> x_m, std::vector<double>& tension_n_per_m) const;
  const BellModel& model() const { return model_; }
  const ActivationParams& activation() const { return activation_; }

 private:
  void toState(std::span<const fluid::Vec2> x_m) const;
  struct MuscleState {
    double lx = 0, ly = 0, length_m = 0;  // l = x_a - x_b
    double tension_n_per_m = 0;           // > 0 pulls the two ends together
    double axial_stiffness_n_per_m = 0;   // d tension / d length
  };
  MuscleState muscleState(int m, double t_s, std::span<const fluid::Vec2> x_m) const;

  BellModel model_;
  ActivationParams activation_;
  ExpansionWindow expansion_{};
  double lowest_knot_ = 0.56;  // the Hermite curve's full contraction
  double porosity_m_per_pa_s_ = 0;        // Darcy coefficient across the tentacle chains, κ / μ
  double axial_porosity_m_per_pa_s_ = 0;  // the same along them
  springs::System<2> system_;
  mutable springs::State<2> state_;     // scratch: positions in the springs module's layout
  mutable springs::Points<2> scratch_;  // scratch: network forces
};

}  // namespace creaturelab::jellyfish
