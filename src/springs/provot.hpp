#pragma once
// Strain limiting after Provot 1995, as used in thesis §5.1 (Mehla 2005,
// Fig. 5.2): after integration, every spring longer than (1 + max_strain) * rest is shortened to
// that length by moving its free ends towards each other along the spring (both halves if both
// are free, all of it on the free end otherwise). Velocities are left as they are.
// The thesis notes the result depends on the order and need not converge: sweeps run in spring
// index order, `passes` times (deterministic), and stop early once a sweep corrects nothing.
#include <string>

#include "springs/network.hpp"

namespace creaturelab::springs {

struct ProvotOptions {
  bool enabled = false;
  double max_strain = 0.1;  // allowed (|l| - r) / r, dimensionless, >= 0
  int passes = 10;          // sweeps over all springs, >= 1
  std::string validate() const;
};

// Returns the number of corrections made (0 when disabled).
template <int D> int applyProvot(const Network<D>& network, const ProvotOptions& options, State<D>& s);

// max over springs of (|l| - r) / r; 0 for a network without springs.
template <int D> double maxStrain(const Network<D>& network, const State<D>& s);

}  // namespace creaturelab::springs
