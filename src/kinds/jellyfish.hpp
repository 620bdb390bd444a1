#pragma once
#include <cstdint>
#include <string>

#include "jellyfish/swim_observer.hpp"
#include "jellyfish/swimmer.hpp"
#include "kinds/describe_kind.hpp"
#include "kinds/describe_notes.hpp"
#include "kinds/ib_params.hpp"

namespace creaturelab::kinds {

// The jellyfish kind's parameters: the swimmer's structs (their in-class defaults are this kind's),
// the knots of the contraction curve, the measured window, and the rules by which the kind fits the
// body to the grid (segments, kernel radii, box aspect) and derives what the structs take.
struct JellyfishKindParams {
  jellyfish::SwimmerConfig swimmer;
  jellyfish::KnotTable knots;
  jellyfish::SwimWindow window;
  double marker_spacing_cells = 0.5;
  double stiffness_scale = 1.0;
  double kernel_radius_m = 0.004;
  double box_aspect = 1.44;
  std::int64_t tracers_per_side = 0;
  // The model and the settings it presets (jellyfish::modelPreset); "auto" takes the model's, a
  // value set in the file wins over it.
  jellyfish::Model model = jellyfish::Model::ours;
  std::string muscle_model = "auto";
  std::string activation_shape = "auto";
  RealOrAuto bending_rigidity_n_m;
  RealOrAuto tentacle_kernel_radius_m;
  RealOrAuto tentacle_permeability_m;
  RealOrAuto tentacle_axial_permeability_m;

  template <class V>
  void describe(V& v) {
    v.choice("model", model, {{"ours", jellyfish::Model::ours}, {"paper", jellyfish::Model::paper}},
             "ours: tension-pulse muscles (active_tension, pulse) and bending 7.3e-5 N m, so the stroke can "
             "resonate; paper: Rudolf & Mould 2009's, rest-length Hermite muscles (rest_length, hermite, §3.3) "
             "and bending 2.352e-3 N m (Fig. 12); ours' tentacles are porous filaments, the paper's impermeable chains "
             "(§3.2); it sets muscle_model, activation_shape, bending_rigidity_n_m and the tentacle_* kernel "
             "radius and permeabilities where those are auto");
    // --- activation (§3.3, Fig. 4)
    swimmer.activation.describe(v);
    v.choice("activation_shape", activation_shape, {"auto", "pulse", "hermite"},
             "auto: the model's (ours pulse, paper hermite); pulse: sin^2 over pulse_duration_s each cycle, then "
             "free recoil (Hoover, Porras & Miller 2019); hermite: the §3.3 curve, whose held tension does not "
             "converge in the grid");
    knots.describe(v);
    // --- bell (§3.2, Fig. 12)
    swimmer.bell.describeGeometry(v);
    v.integer("bell_segments", swimmer.bell.segments, 0, 2048,
              "springs along the subumbrella (even, >= 8); 0 = follow the grid (marker_spacing_cells); 256 keeps one "
              "body, markers <= 0.5 cells apart, in the grid study");
    v.real("marker_spacing_cells", marker_spacing_cells, "", 0.05, 4,
           "bell_segments = 0: largest marker spacing in cells; 0.5 is Peskin 2002's rule and keeps the membrane's "
           "leak small");
    swimmer.bell.describeElasticity(v);
    v.realOrAuto("bending_rigidity_n_m", bending_rigidity_n_m, "N m", 0, 1e6,
                 "bending rigidity B per metre of depth (a joint's angular spring is B / L); auto: the model's, "
                 "ours 7.3e-5 (not given by the paper: calibrated so that the bell alone's pluck rings at "
                 "§3.3's resonant 0.7 Hz), paper 2.352e-3 (Fig. 12's 1.186 N m/rad per 1.983 mm joint)");
    v.real("stiffness_scale", stiffness_scale, "", 1e-3, 1e3, "multiplies bell_modulus_pa and bending_rigidity_n_m together");
    v.choice("muscle_model", muscle_model, {"auto", "active_tension", "rest_length"},
             "auto: the model's (ours active_tension, paper rest_length); active_tension: a tension T_max a(t) "
             "that the elastic bell re-expands against, so the stroke can resonate; rest_length: the paper's "
             "rest-length curve (§3.3)");
    swimmer.bell.describeMuscle(v);
    swimmer.bell.describeTentacles(v);
    v.realOrAuto("tentacle_kernel_radius_m", tentacle_kernel_radius_m, "m", 0, 10,
                 "the tentacles' own kernel support radius (at most kernel_radius_m; 0 = the grid's kernel); auto: "
                 "the model's, ours 4/3 mm (filaments), paper the bell's kernel_radius_m (§3.2: made as the "
                 "subumbrella is)");
    v.realOrAuto("tentacle_permeability_m", tentacle_permeability_m, "m", 0, 10,
                 "Darcy permeability over thickness of a tentacle chain, slip = permeability / (rho nu) x normal "
                 "load per length (Kim & Peskin's porous boundary); 0 = impermeable; auto: the model's, ours "
                 "1.7e-3 (a ring of 16 filaments 0.5 mm thick in Stokes flow, h ln(h/d) / 4 pi), paper 0");
    v.realOrAuto("tentacle_axial_permeability_m", tentacle_axial_permeability_m, "m", 0, 10,
                 "the same along the chain, slip = permeability / (rho nu) x tangential load per length: a slice's "
                 "chain stands for sparse filaments the flow passes along, not a sheet; 0 = none; auto: the "
                 "model's, ours 3.4e-3 (slender filaments resist axial flow about half as much as transverse, Cox "
                 "1970), paper 0");
    // --- fluid (§3.2, Fig. 12) and coupling (§3.2; Peskin 2002): the shared structs' own fields, with why
    // this kind's defaults (jellyfish::jellyfishFluid, jellyfishCoupling) differ from theirs.
    DefaultNotes noted(v, {
        {"domain_m", "0.25 m, 6.25 bell diameters, close to the paper's 10-diameter box (§3.2) in distance per "
                     "cycle; the height is box_aspect times it"},
        {"cells", "375, 2/3 mm cells, the finest grid a default point affords in 60 s of CPU (convergence.toml refines it)"},
        {"kinematic_viscosity_m2_per_s", "5e-5, 38 times water (Re = f D^2 / nu = 22 at 0.7 Hz, within 2-D IB jellyfish "
                                         "studies' 10-300), so that the default cells put 4-5 across the Stokes layer at 0.7-1 Hz"},
        {"advection", "maccormack (Selle et al. 2008, second order in space)"},
        {"kernel", "peskin4: the hat's bell does not converge in its segments"},
        {"kernel_radius_m", "the bell's 4 mm thickness (Fig. 12), so that a grid study refines one body"},
        {"implicit_theta", "0.5, which doubles the step at the same accuracy"},
        {"blowup_speed_m_per_s", "5 m/s, 100x the swimming flow"},
    });
    describeFluidBox(noted, swimmer.fluid);
    swimmer.coupling.describe(noted);
    describeKernelRadius(noted, kernel_radius_m);
    swimmer.describeStep(v);
    swimmer.fluid.describeBlowupSpeed(noted);
    v.real("box_aspect", box_aspect, "", 0.25, 8,
           "box height / width; cells x box_aspect must be whole (1.44: cells a multiple of 25); tall enough that "
           "floor and top barely move the swim");
    // --- measurement
    window.describe(v);
    v.integer("tracers_per_side", tracers_per_side, 0, 200, "trace particles on an n x n lattice around the bell (Fig. 6)");
  }

  // The swimmer's structs as run: the model's preset where its keys are auto, the segments that follow the grid, the stiffness scaled, the box
  // stretched to box_aspect, the kernels stretched to their radii, the tentacles' roots and porosity.
  jellyfish::SwimmerConfig setup() const;
  // The tentacles' kernel radius and permeabilities as run: the model's preset where they are auto.
  struct TentacleCoupling {
    double kernel_radius_m, permeability_m, axial_permeability_m;
  };
  TentacleCoupling tentacleCoupling() const;
  jellyfish::SwimSchedule schedule() const;
  // Ranges; the knots, bell, activation and fluid structs' own validate(); then the rules across them
  // (kernel radii, the box around the bell, whole rows of cells, the step within the window).
  std::string validate() const;
};

// A 2-D jellyfish bell swimming in sea water, coupled by the immersed boundary method
// (Rudolf & Mould 2009 §3.1–3.3, Figs. 4, 5, 11, 12).
class JellyfishKind : public DescribedKind<JellyfishKindParams> {
 public:
  JellyfishKind();
  std::string name() const override { return "jellyfish"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
  // Defined in kinds/jellyfish_render.cpp: a recorded swim drawn in 3-D (Rudolf & Mould 2009 §3.4-3.5).
  const RenderHook* renderHook() const override;

  // The largest number of Hermite knots the schema declares (knot0_* .. knot{N-1}_*).
  static constexpr int kMaxKnots = jellyfish::KnotTable::kMax;
};

}  // namespace creaturelab::kinds
