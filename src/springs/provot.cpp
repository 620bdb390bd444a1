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
  }
  return msg.str();
}

template <int D> int applyProvot(const Network<D>& network, const ProvotOptions& options, State<D>& s) {
  if (!options.enabled) return 0;
  int corrections = 0;
  for (int pass = 0; pass < options.passes; ++pass) {
    int this_pass = 0;
    for (int e = 0; e < network.springCount(); ++e) {
      const int a = network.spring_a[e], b = network.spring_b[e];
      const bool free_a = !network.pinned[a], free_b = !network.pinned[b];
      if (!free_a && !free_b) continue;
      const Vec<D> l = s.x_m.col(a) - s.x_m.col(b);
      const double len = l.norm();
      const double max_len = (1.0 + options.max_strain) * network.rest_length_m[e];
      if (!(len > max_len)) continue;
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
      ++this_pass;
    }
    corrections += this_pass;
    if (this_pass == 0) break;
  }
  return corrections;
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

template int applyProvot<2>(const Network<2>&, const ProvotOptions&, State<2>&);
template int applyProvot<3>(const Network<3>&, const ProvotOptions&, State<3>&);
template double maxStrain<2>(const Network<2>&, const State<2>&);
template double maxStrain<3>(const Network<3>&, const State<3>&);

}  // namespace creaturelab::springs
