#include "springs/provot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace creaturelab::springs {

std::string ProvotOptions::validate() const {
  std::ostringstream msg;
  if (!(max_strain >= 0) || !std::isfinite(max_strain)) {
    msg << "provot max_strain is " << max_strain << "; it must be zero or positive";
  } else if (passes < 1) {
    msg << "provot passes is " << passes << "; at least one pass is needed";
  } else if (!(tolerance >= 0 && tolerance <= 1e-3)) {
    msg << "provot tolerance is " << tolerance << "; it must lie in [0, 1e-3]";
  }
  return msg.str();
}

namespace {

// One sweep in spring index order. Returns the number of springs shortened; worst_strain gets the
// largest strain seen before any correction of that spring in this sweep.
template <int D>
long sweep(const Network<D>& network, double max_strain, double tolerance, State<D>& s, double& worst_strain) {
  long corrected = 0;
  worst_strain = 0;
  for (int e = 0; e < network.springCount(); ++e) {
    const int a = network.spring_a[e], b = network.spring_b[e];
    const bool free_a = !network.pinned[a], free_b = !network.pinned[b];
    const Vec<D> l = s.x_m.col(a) - s.x_m.col(b);
    const double len = l.norm();
    const double rest = network.rest_length_m[e];
    const double max_len = (1.0 + max_strain) * rest;
    const double strain = (len - rest) / rest;
    worst_strain = e == 0 ? strain : std::max(worst_strain, strain);
    if (!(len > max_len * (1.0 + tolerance)) || (!free_a && !free_b)) continue;
    // Keep the direction (Provot: the direction of motion is taken as right), cut the excess.
    const Vec<D> shift = (len - max_len) / len * l;
    if (free_a && free_b) {
      s.x_m.col(a) -= 0.5 * shift;
      s.x_m.col(b) += 0.5 * shift;
    } else if (free_a) {
      s.x_m.col(a) -= shift;
    } else {
      s.x_m.col(b) += shift;
    }
    ++corrected;
  }
  return corrected;
}

}  // namespace

template <int D>
ProvotResult applyProvot(const Network<D>& network, const ProvotOptions& options, State<D>& s,
                         const Points<D>* step_start_x_m, double dt_s) {
  ProvotResult r;
  if (!options.enabled) return r;
  const bool set_velocity = step_start_x_m != nullptr && dt_s > 0;
  const Points<D> before = set_velocity ? s.x_m : Points<D>();
  r.converged = false;
  double worst = 0;
  while (r.passes < options.passes) {
    const long corrected = sweep(network, options.max_strain, options.tolerance, s, worst);
    ++r.passes;
    r.corrections += corrected;
    if (corrected == 0) {  // this sweep measured every spring within the limit and moved nothing
      r.converged = true;
      break;
    }
  }
  r.max_strain = r.converged ? worst : maxStrain(network, s);
  if (set_velocity && r.corrections > 0) {
    for (int p = 0; p < network.particleCount(); ++p)
      if (s.x_m.col(p) != before.col(p)) s.v_m_per_s.col(p) = (s.x_m.col(p) - step_start_x_m->col(p)) / dt_s;
  }
  return r;
}

template <int D> double maxStrain(const Network<D>& network, const State<D>& s) {
  double worst = 0;
  for (int e = 0; e < network.springCount(); ++e) {
    const double len = (s.x_m.col(network.spring_a[e]) - s.x_m.col(network.spring_b[e])).norm();
    const double strain = (len - network.rest_length_m[e]) / network.rest_length_m[e];
    worst = e == 0 ? strain : std::max(worst, strain);
  }
  return worst;
}

template ProvotResult applyProvot<2>(const Network<2>&, const ProvotOptions&, State<2>&, const Points<2>*, double);
template ProvotResult applyProvot<3>(const Network<3>&, const ProvotOptions&, State<3>&, const Points<3>*, double);
template double maxStrain<2>(const Network<2>&, const State<2>&);
template double maxStrain<3>(const Network<3>&, const State<3>&);

}  // namespace creaturelab::springs
