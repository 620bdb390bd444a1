#include "web/web_builder.hpp"

#include <cmath>
#include <stdexcept>

namespace creaturelab::web {

StrandSpec strandSpec(const WebParams& p, StrandType type) {
  double placement = 0, rest = 0, k = 0;
  switch (type) {
    case StrandType::outer_frame:
      placement = p.outer_frame_placement_m, rest = p.outer_frame_rest_length_m, k = p.outer_frame_k_n_per_m;
      break;
    case StrandType::inner_frame:
      placement = p.frame_placement_m, rest = p.frame_rest_length_m, k = p.frame_k_n_per_m;
      break;
    case StrandType::primary_spoke:
    case StrandType::hub:
    case StrandType::secondary_spoke:
      placement = p.spoke_placement_m, rest = p.spoke_rest_length_m, k = p.spoke_k_n_per_m;
      break;
    case StrandType::spiral:
      placement = p.spiral_placement_m, rest = p.spiral_rest_length_m, k = p.spiral_k_n_per_m;
      break;
  }
  // Thesis §5.1: laid length = (1 + over-extension) * rest length.
  const double ratio = p.overextension ? 1.0 / (1.0 + *p.overextension) : rest / placement;
  return {placement, ratio, k};
}

WebBuilder::WebBuilder(const WebParams& params) : params_(params) {}

int WebBuilder::addParticle(const Point2& x_m, bool pinned) {
  x_m_.push_back(x_m);
  pinned_.push_back(pinned ? 1 : 0);
  return static_cast<int>(x_m_.size()) - 1;
}

std::vector<int> WebBuilder::layStrand(int a, int b, StrandType type) {
  const StrandSpec spec = strandSpec(params_, type);
  const Point2 xa = x_m_[a], xb = x_m_[b];
  const double d = (xb - xa).norm();
  if (!(d > 0)) throw std::logic_error("web: a strand between two particles at the same point");
  const long n = std::max(1L, std::lround(d / spec.placement_m));
  const double rest = spec.rest_over_laid * d / static_cast<double>(n);
  std::vector<int> chain;
  chain.reserve(n + 1);
  chain.push_back(a);
  for (long i = 1; i < n; ++i) chain.push_back(addParticle(xa + (xb - xa) * (double(i) / double(n)), false));
  chain.push_back(b);
  for (long i = 0; i < n; ++i) {
    spring_a_.push_back(chain[i]);
    spring_b_.push_back(chain[i + 1]);
    rest_m_.push_back(rest);
    k_n_per_m_.push_back(spec.k_n_per_m);
    type_.push_back(type);
  }
  return chain;
}

WebModel WebBuilder::finish() {
  WebModel m;
  const int n = particleCount();
  auto& net = m.network;
  net.mass_kg = Eigen::VectorXd::Constant(n, params_.particle_mass_kg);
  net.pinned = std::move(pinned_);
  net.spring_a = std::move(spring_a_);
  net.spring_b = std::move(spring_b_);
  net.rest_length_m = std::move(rest_m_);
  net.stiffness_n_per_m = std::move(k_n_per_m_);
  net.damping_ns_per_m.assign(net.spring_a.size(), 0.0);  // the thesis's springs have no damping term
  net.gravity_m_per_s2 = springs::Vec<3>(0, -params_.gravity_m_per_s2, 0);
  net.drag_ns_per_m = params_.air_drag_ns_per_m;
  m.spring_type = std::move(type_);

  m.state.x_m = springs::Points<3>::Zero(3, n);
  m.state.v_m_per_s = springs::Points<3>::Zero(3, n);
  for (int i = 0; i < n; ++i) m.state.x_m.col(i).head<2>() = x_m_[i];
  m.external_force_n = springs::Points<3>::Zero(3, n);
  return m;
}

}  // namespace creaturelab::web
