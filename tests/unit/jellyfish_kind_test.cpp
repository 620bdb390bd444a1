// The jellyfish kind's parameters, declared once (kinds/describe.hpp): the schema's defaults are the
// swimmer structs' in-class defaults, what the kind derives from them (segments, box, kernels) is what a
// SwimmerConfig{} holds, and the rules across fields name the parameters. No solver runs.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <utility>

#include "kinds/jellyfish.hpp"
#include "kinds/jellyfish_render_params.hpp"

namespace creaturelab::kinds {
namespace {

Params defaults() { return withDefaults(JellyfishKind(), {}); }

std::string problem(const std::string& name, Value value) {
  Params p = defaults();
  p[name] = std::move(value);
  return JellyfishKind().validate(p);
}

// A solver struct built in code (a test, a benchmark) runs what the kind's user runs by default.
TEST(JellyfishKind, DefaultsSetUpTheSwimmerStructsInClassDefaults) {
  const jellyfish::SwimmerConfig run = readParams<JellyfishKindParams>(defaults()).setup();
  const jellyfish::SwimmerConfig in_class;
  EXPECT_EQ(run.bell.segments, in_class.bell.segments);
  EXPECT_EQ(run.bell.tentacle_root_spacing_m, in_class.bell.tentacle_root_spacing_m);
  EXPECT_EQ(run.bell.tentacle_permeability_m, in_class.bell.tentacle_permeability_m);
  EXPECT_EQ(run.bell.tentacle_axial_permeability_m, in_class.bell.tentacle_axial_permeability_m);
  EXPECT_EQ(run.bell.bending_rigidity_n_m, in_class.bell.bending_rigidity_n_m);
  EXPECT_TRUE(run.bell.muscle_model == in_class.bell.muscle_model);
  EXPECT_TRUE(run.activation.shape == in_class.activation.shape);
  EXPECT_EQ(run.activation.knots.size(), in_class.activation.knots.size());
  EXPECT_EQ(run.fluid.cells_x, in_class.fluid.cells_x);
  EXPECT_EQ(run.fluid.cells_y, in_class.fluid.cells_y);
  EXPECT_EQ(run.fluid.domain_height_m, in_class.fluid.domain_height_m);
  EXPECT_EQ(run.fluid.fixed_step_s, in_class.dt_s);
  EXPECT_EQ(run.fluid.kinematic_viscosity_m2_per_s, in_class.fluid.kinematic_viscosity_m2_per_s);
  EXPECT_TRUE(run.fluid.time_step_policy == in_class.fluid.time_step_policy);
  EXPECT_EQ(run.coupling.kernel_scale, in_class.coupling.kernel_scale);
  EXPECT_EQ(run.coupling.implicit_theta, in_class.coupling.implicit_theta);
  EXPECT_EQ(run.tentacle_kernel_scale, in_class.tentacle_kernel_scale);
  EXPECT_EQ(run.dt_s, in_class.dt_s);
  EXPECT_EQ(run.start_y_fraction, in_class.start_y_fraction);
  EXPECT_EQ(JellyfishKind().validate(defaults()), "");
}

TEST(JellyfishKind, ReadsItsParametersIntoTheStructs) {
  Params p = defaults();
  p["bell_segments"] = std::int64_t(0);  // follow the grid: markers at most half a cell apart
  p["stiffness_scale"] = 2.0;
  p["kinematic_viscosity_m2_per_s"] = 1e-5;
  p["activation_shape"] = std::string("hermite");
  p["contraction_knots"] = std::int64_t(3);
  p["knot2_phase"] = 0.6;
  p["knot2_value"] = 0.8;
  const JellyfishKindParams q = readParams<JellyfishKindParams>(p);
  const jellyfish::SwimmerConfig c = q.setup();
  jellyfish::BellParams coarser = c.bell;
  coarser.segments -= 2;
  const double half_cell_m = 0.5 * c.fluid.domain_width_m / c.fluid.cells_x;
  EXPECT_LE(jellyfish::buildBell(c.bell).segment_m, half_cell_m);
  EXPECT_GT(jellyfish::buildBell(coarser).segment_m, half_cell_m);
  EXPECT_EQ(c.bell.bell_modulus_pa, 2 * 1186.0);
  EXPECT_EQ(c.fluid.kinematic_viscosity_m2_per_s, 1e-5);
  EXPECT_TRUE(c.activation.shape == jellyfish::ActivationShape::hermite);
  ASSERT_EQ(c.activation.knots.size(), 3u);
  EXPECT_EQ(c.activation.knots[2].value, 0.8);
  EXPECT_EQ(paramsOf(q), p);  // and back
}

// model = "paper" presets the paper's muscles, activation, bending and tentacles (Rudolf & Mould 2009 §3.2-3.3, Fig. 12)
// where the file leaves them auto; a value the file sets wins, in either model.
TEST(JellyfishKind, ModelPresetsMusclesShapeAndBendingAndTheFileWins) {
  const auto setup = [](std::initializer_list<std::pair<const std::string, Value>> given) {
    Params p = defaults();
    for (const auto& [name, value] : given) p[name] = value;
    EXPECT_EQ(JellyfishKind().validate(p), "");
    return readParams<JellyfishKindParams>(p).setup();
  };
  const jellyfish::SwimmerConfig in_class;
  EXPECT_EQ(defaults().at("model"), Value(std::string("ours")));
  EXPECT_EQ(defaults().at("bending_rigidity_n_m"), Value(std::string("auto")));

  const jellyfish::SwimmerConfig paper = setup({{"model", std::string("paper")}});
  EXPECT_TRUE(paper.bell.muscle_model == jellyfish::MuscleModel::rest_length);
  EXPECT_TRUE(paper.activation.shape == jellyfish::ActivationShape::hermite);
  EXPECT_EQ(paper.bell.bending_rigidity_n_m, 2.352e-3);
  EXPECT_EQ(paper.bell.muscle_tension_n_per_m2, in_class.bell.muscle_tension_n_per_m2);  // the rest is shared
  EXPECT_EQ(paper.fluid.cells_x, in_class.fluid.cells_x);
  // the paper's tentacles are made as the subumbrella is (§3.2): impermeable, on the bell's kernel
  EXPECT_EQ(paper.bell.tentacle_permeability_m, 0.0);
  EXPECT_EQ(paper.bell.tentacle_axial_permeability_m, 0.0);
  EXPECT_EQ(paper.tentacle_kernel_scale, paper.coupling.kernel_scale);
  EXPECT_EQ(paper.bell.tentacle_root_spacing_m, 0.008);
  const jellyfish::SwimmerConfig paper_filaments =
      setup({{"model", std::string("paper")}, {"tentacle_permeability_m", 1.7e-3}, {"tentacle_kernel_radius_m", jellyfish::kFilamentKernelRadius_m}});
  EXPECT_EQ(paper_filaments.bell.tentacle_permeability_m, in_class.bell.tentacle_permeability_m);
  EXPECT_EQ(paper_filaments.bell.tentacle_axial_permeability_m, 0.0);
  EXPECT_EQ(paper_filaments.tentacle_kernel_scale, in_class.tentacle_kernel_scale);

  const jellyfish::SwimmerConfig paper_set = setup({{"model", std::string("paper")},
                                                    {"bending_rigidity_n_m", 5e-4},
                                                    {"muscle_model", std::string("active_tension")},
                                                    {"activation_shape", std::string("pulse")}});
  EXPECT_EQ(paper_set.bell.bending_rigidity_n_m, 5e-4);
  EXPECT_TRUE(paper_set.bell.muscle_model == jellyfish::MuscleModel::active_tension);
  EXPECT_TRUE(paper_set.activation.shape == jellyfish::ActivationShape::pulse);

  // A value equal to ours' default still wins over the paper's preset: set is set.
  const jellyfish::SwimmerConfig paper_ours_b =
      setup({{"model", std::string("paper")}, {"bending_rigidity_n_m", in_class.bell.bending_rigidity_n_m}});
  EXPECT_EQ(paper_ours_b.bell.bending_rigidity_n_m, in_class.bell.bending_rigidity_n_m);
  EXPECT_TRUE(paper_ours_b.bell.muscle_model == jellyfish::MuscleModel::rest_length);

  const jellyfish::SwimmerConfig ours_set =
      setup({{"muscle_model", std::string("rest_length")}, {"activation_shape", std::string("hermite")},
             {"bending_rigidity_n_m", 2e-3}, {"stiffness_scale", 2.0}});
  EXPECT_TRUE(ours_set.bell.muscle_model == jellyfish::MuscleModel::rest_length);
  EXPECT_TRUE(ours_set.activation.shape == jellyfish::ActivationShape::hermite);
  EXPECT_EQ(ours_set.bell.bending_rigidity_n_m, 4e-3);  // stiffness_scale applies to the value set
}

TEST(JellyfishKind, RulesAcrossFieldsNameTheParameters) {
  EXPECT_NE(problem("knot3_value", 0.7).find("knot3_* is set but contraction_knots = 2"), std::string::npos);
  EXPECT_NE(problem("bell_segments", std::int64_t(31)).find("segments must be even"), std::string::npos);
  EXPECT_NE(problem("kernel_radius_m", 0.0045).find("kernel_radius_m = 0.0045 m must be a whole multiple"),
            std::string::npos);
  EXPECT_NE(problem("tentacle_kernel_radius_m", 0.008).find("must not exceed kernel_radius_m"), std::string::npos);
  // the filaments' Darcy coefficient is their permeability over rho nu: an inviscid fluid is refused with them
  EXPECT_NE(problem("kinematic_viscosity_m2_per_s", 0.0).find("permeable tentacles"), std::string::npos);
  // the filaments' 4/3 mm kernel is 4/3 reaches of 1/2 mm cells: refused with them, not for the bell alone
  Params fine = defaults();
  fine["cells"] = std::int64_t(500);
  EXPECT_NE(JellyfishKind().validate(fine).find("tentacle_kernel_radius_m = 0.00133333 m must be a whole multiple"),
            std::string::npos);
  fine["tentacles"] = false;
  EXPECT_EQ(JellyfishKind().validate(fine), "");
  EXPECT_NE(problem("box_aspect", 1.45).find("whole number of cells"), std::string::npos);
  EXPECT_NE(problem("bell_diameter_m", 0.09).find("three bell diameters"), std::string::npos);
  EXPECT_NE(problem("duration_s", 1e-3).find("dt_s is longer than duration_s"), std::string::npos);
}

TEST(JellyfishRenderSettings, DefaultsAreRenderParamsAndAutoIsTheRunsThickness) {
  Params p;
  for (const ParamSpec& spec : renderParamSpecs()) p[spec.name] = spec.default_value;
  const render::RenderParams got = renderParams(p, 0.003), in_class;
  EXPECT_EQ(got.thickness.apex_m, 0.003);
  EXPECT_EQ(got.rings, in_class.rings);
  EXPECT_EQ(got.noise_seed, in_class.noise_seed);
  EXPECT_TRUE(got.structural_shape == in_class.structural_shape);
  p["thickness_m"] = 0.005;
  p["structural_shape"] = std::string("sin");
  const render::RenderParams set = renderParams(p, 0.003);
  EXPECT_EQ(set.thickness.apex_m, 0.005);
  EXPECT_TRUE(set.structural_shape == render::StructuralShape::sin);
}

}  // namespace
}  // namespace creaturelab::kinds
