#pragma once
// Strain limiting after Provot 1995, as used in A. Mehla, Modeling and Animation of Orb Webs, MSc
// thesis 2005, §5.1 (Fig. 5.2): after integration, every spring longer than (1 + max_strain) * rest is
// shortened to that length by moving its free ends towards each other along the spring (both halves if
// both are free, all of it on the free end otherwise). Sweeps run in spring index order (deterministic)
// and repeat until no spring is longer than (1 + max_strain) * rest * (1 + tolerance), at most `passes`
// times: the thesis notes one sweep can over-extend another spring and the result need not converge, so a
// step that ends with a spring still too long is reported (ProvotResult::converged), not hidden.
// Given the positions at the start of the step and the step dt_s, every particle the sweeps moved gets
// the velocity of its whole step, v = (x - x_start) / dt_s (as in position-based dynamics): Provot 1995
// moves positions only, and with an integrator that carries velocities the kept velocity stretches the
// spring again on the next step, so the strand never settles.
#include <string>

#include "springs/network.hpp"

namespace creaturelab::springs {

struct ProvotOptions {
  bool enabled = false;
  double max_strain = 0.1;   // allowed (|l| - r) / r, dimensionless, >= 0
  int passes = 10;           // most sweeps over all springs per call, >= 1
  double tolerance = 1e-12;  // converged when every |l| <= (1 + max_strain) r (1 + tolerance); in [0, 1e-3]
  // When the sweeps end with a spring still too long, finish with a Newton projection (below) instead of
  // leaving it: the limit then holds to the tolerance. Not Provot's method (the thesis's Fig. 5.2 has none).
  bool exact_finish = false;
  std::string validate() const;

  // For the strand kind (kinds/describe.hpp), whose defaults these are; tolerance stays internal.
  template <class V>
  void describe(V& v) {
    v.boolean("provot", enabled, "apply Provot's strain constraint after every step (thesis §5.1, Fig. 5.2)");
    v.real("provot_max_strain", max_strain, "", 1e-6, 10, "Provot's maximum strain (Provot 1995 used 10%; thesis gives none)");
    v.integer("provot_passes", passes, 1, 1000000,
              "most Provot sweeps over the springs per step, repeated until no spring is over the limit (thesis: "
              "'run multiple times')");
    v.boolean("provot_exact", exact_finish,
              "finish a step whose Provot sweeps leave a spring over the limit with an exact projection "
              "(Goldenthal et al. 2007; not in the thesis)");
  }
};

struct ProvotResult {
  int passes = 0;          // sweeps made (the last one corrected nothing when converged)
  long corrections = 0;    // springs shortened, over all sweeps
  bool converged = true;          // every spring within the limit (with tolerance) at the end
  bool finished_exactly = false;  // the sweeps did not converge and the exact finish ran
  double max_strain = 0;   // largest (|l| - r) / r at the end
};

// The exact finish: Newton steps on |l_e| = (1 + max_strain) r_e for every spring at or over the limit
// (within 1e-6 of it), each solving (J W J^T) mu = -c for the constraint values c, J the length gradients
// and W the sweeps' weights (1 per free end, 0 pinned), then x += W J^T mu (the fast projection of
// Goldenthal et al. 2007, "Efficient simulation of inextensible cloth"). Every active spring
// ends at the limit; springs the step pushed over it join the next step. At most 20 steps.
// Disabled: does nothing and returns ProvotResult{} (max_strain 0 then means "not measured").
// step_start_x_m (the positions before the step, or nullptr) and dt_s > 0 set the moved particles' velocities.
template <int D>
ProvotResult applyProvot(const Network<D>& network, const ProvotOptions& options, State<D>& s,
                         const Points<D>* step_start_x_m = nullptr, double dt_s = 0);

// max over springs of (|l| - r) / r; 0 for a network without springs.
template <int D> double maxStrain(const Network<D>& network, const State<D>& s);

}  // namespace creaturelab::springs
