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
  JellyfishBody(const BellModel& model, ActivationParams activation);

  int markerCount() const override { return system_.particleCount(); }
  void forces(double t_s, std::span<const fluid::Vec2> x_m, std::span<fluid::Vec2> force_n_per_m) const override;
  void stiffness(double t_s, std::span<const fluid::Vec2> x_m, double scale,
                 std::vector<Eigen::Triplet<double>>& out) const override;

  /// Rest-length factor of muscle `m` at time t (1 relaxed, 0.56 fully contracted by default).
  double muscleFactor(int m, double t_s) const;
  /// Elastic energy of bell, tentacles and muscles at positions x and time t, J per metre of depth.
  double elasticEnergy(double t_s, std::span<const fluid::Vec2> x_m) const;
  /// Tension of every muscle spring at positions x and time t, N per metre of depth (> 0 pulls).
  void muscleTensions(double t_s, std::span<const fluid::Vec2> x_m, std::vector<double>& tension_n_per_m) const;
  const BellModel& model() const { return model_; }
  const ActivationParams& activation() const { return activation_; }

 private:
  void toState(std::span<const fluid::Vec2> x_m) const;

  BellModel model_;
  ActivationParams activation_;
  ExpansionWindow expansion_{};
  springs::System<2> system_;
  mutable springs::State<2> state_;     // scratch: positions in the springs module's layout
  mutable springs::Points<2> scratch_;  // scratch: network forces
};

}  // namespace creaturelab::jellyfish
