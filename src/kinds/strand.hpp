#pragma once
#include <cstdint>
#include <string>

#include "kinds/describe_kind.hpp"
#include "springs/provot.hpp"

namespace creaturelab::kinds {

// The strand kind's parameters (thesis §5.1, §5.2.1): the chain, its layout, Provot's constraint
// (springs::ProvotOptions, whose in-class defaults are this kind's), the forces and the run.
struct StrandParams {
  double span_m = 0.0;
  std::int64_t n_springs = 0;
  double mass_kg = 1e-8;
  double spring_k_n_per_m = 0.01;
  double spring_damping_ns_per_m = 0.0;
  double rest_length_m = 0.003;
  std::string layout = "overextended";
  double overextension = 1.5;
  springs::ProvotOptions provot;
  double drag_ns_per_m = 1e-8;
  double gravity_m_per_s2 = 9.81;
  std::string integrator = "rk4";
  RealOrAuto dt_s;  // "auto": half the stability limit
  double frame_interval_s = 0.02;
  double end_time_s = 15.0;
  double settling_fraction = 1e-4;
  double lagrangian_interval_s = 0.5;

  template <class V>
  void describe(V& v) {
    v.real("span_m", span_m, "m", 0, 100,
           "anchor separation; 0 = n_springs x placement length. When set, n_springs is derived from it");
    v.integer("n_springs", n_springs, 0, 100000, "springs in the chain; 0 = 50, or derived from span_m when span_m > 0");
    v.real("mass_kg", mass_kg, "kg", 1e-15, 1, "particle mass: 10 ug (thesis §5.1 and §5.2.1 table)");
    v.real("spring_k_n_per_m", spring_k_n_per_m, "N/m", 1e-9, 1e6, "spring constant (thesis §5.2.1: 0.01 N/m)");
    v.real("spring_damping_ns_per_m", spring_damping_ns_per_m, "N*s/m", 0, 1,
           "spring damping k_d of Eq. 4.14 (thesis gives none: 0)");
    v.real("rest_length_m", rest_length_m, "m", 1e-6, 10, "spring rest length (thesis §5.2.1: 3 mm)");
    v.choice("layout", layout, {"rest", "overextended"}, "lay springs at rest length (Fig. 5.1) or over-extended (§5.1)");
    v.real("overextension", overextension, "", 0, 5,
           "over-extension of the layout: placement = rest x (1 + this); thesis §5.1 uses 0.75-2.5");
    provot.describe(v);
    v.real("drag_ns_per_m", drag_ns_per_m, "N*s/m", 0, 1, "air friction (thesis §5.2.1: 0.00000001 Ns/m)");
    v.real("gravity_m_per_s2", gravity_m_per_s2, "m/s^2", 0, 1000, "gravity, pulling along -y (thesis Eq. 4.6)");
    v.choice("integrator", integrator, {"euler", "symplectic_euler", "rk4", "implicit_euler"},
             "time integrator (thesis uses rk4, Eq. 4.16-4.19)");
    v.realOrAuto("dt_s", dt_s, "s", 1e-9, 1, "substep; \"auto\" = half the stability limit from the springs' omega_max");
    v.real("frame_interval_s", frame_interval_s, "s", 1e-6, 10, "output frame (the thesis's 0.02 s 'time step', §5.2.1)");
    v.real("end_time_s", end_time_s, "s", 1e-3, 1e5, "simulated time");
    v.real("settling_fraction", settling_fraction, "", 1e-12, 1,
           "settled when kinetic energy stays below this fraction of its peak (1e-4 = 1% amplitude)");
    v.real("lagrangian_interval_s", lagrangian_interval_s, "s", 1e-6, 1e5, "interval between stored particle positions");
  }
  // Ranges, then: span_m or n_springs, not both; a substep within the frame.
  std::string validate() const;
};

// A single web strand (Mehla 2005 thesis §5.1, Figs. 5.1-5.2): a chain of masses between two pinned
// anchors under gravity and air drag, laid at rest length, over-extended, or constrained by Provot.
class StrandKind : public DescribedKind<StrandParams> {
 public:
  StrandKind();
  std::string name() const override { return "strand"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
