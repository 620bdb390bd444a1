// The membrane kind on its described parameters (kinds/membrane.hpp): its schema is the composed
// structs' with this test's defaults, the solver structs it builds, and its validation.
#include <gtest/gtest.h>

#include <string>

#include "kinds/membrane.hpp"

namespace {

using namespace creaturelab::kinds;
namespace ib = creaturelab::ib;

TEST(MembraneKind, ListsItsStructsDefaultsAndBuildsTheSolversStructs) {
  const MembraneKind kind;
  const Params defaults = withDefaults(kind, {});
  EXPECT_EQ(defaults, paramsOf(MembraneKindParams{}));
  EXPECT_EQ(std::get<std::string>(defaults.at("kernel")), "bilinear");
  EXPECT_EQ(std::get<double>(defaults.at("kinematic_viscosity_m2_per_s")), 1e-2);
  EXPECT_EQ(std::get<double>(defaults.at("stiffness_n_per_m")), ib::MembraneParams{}.stiffness_n_per_m);
  EXPECT_EQ(kind.validate(defaults), "");

  Params p = defaults;
  p["domain_m"] = 2.0;
  p["cells"] = std::int64_t(50);
  p["kernel"] = std::string("peskin4");
  p["kernel_radius_m"] = 0.16;  // two cells of 0.04 m: twice Peskin's reach
  p["dt_s"] = 0.002;
  const MembraneKindParams q = readParams<MembraneKindParams>(p);
  const auto fluid = q.fluidParams();
  EXPECT_EQ(fluid.domain_height_m, 2.0);
  EXPECT_EQ(fluid.cells_y, 50);
  EXPECT_EQ(fluid.fixed_step_s, 0.002);
  EXPECT_EQ(fluid.blowup_speed_m_per_s, 10.0);
  EXPECT_EQ(q.membraneParams().centre_x_m, 1.0);
  EXPECT_EQ(q.membraneParams().centre_y_m, 1.0);
  EXPECT_EQ(q.couplingParams().kernel, ib::Kernel::peskin4);
  EXPECT_EQ(q.couplingParams().kernel_scale, 2);
}

// The shared structs' docs, each with this test's reason where its default differs (kinds/describe_notes.hpp).
TEST(MembraneKind, ItsOwnDefaultsOfSharedFieldsSayWhy) {
  const MembraneKind kind;
  for (const ParamSpec& spec : kind.params()) {
    const bool noted = spec.doc.find("; default ") != std::string::npos;
    const bool shared_with_own_default = spec.name == "kernel" || spec.name == "implicit_theta" ||
                                         spec.name == "domain_m" || spec.name == "cells" ||
                                         spec.name == "kinematic_viscosity_m2_per_s" ||
                                         spec.name == "blowup_speed_m_per_s";
    EXPECT_EQ(noted, shared_with_own_default) << spec.name << ": " << spec.doc;
  }
  EXPECT_EQ(schemaOf<MembraneKindParams>().size(), kind.params().size());
}

TEST(MembraneKind, ValidationNamesTheParametersThatDisagree) {
  const MembraneKind kind;
  Params p = withDefaults(kind, {});
  p["semi_axis_x_m"] = 0.48;
  EXPECT_NE(kind.validate(p).find("must stay at least 4 cells"), std::string::npos) << kind.validate(p);
  p = withDefaults(kind, {});
  p["kernel_radius_m"] = 0.015;  // 1.5 cells of the bilinear hat
  EXPECT_NE(kind.validate(p).find("kernel_radius_m = 0.015 m must be a whole multiple"), std::string::npos)
      << kind.validate(p);
  p = withDefaults(kind, {});
  p["frame_rate_hz"] = 200.0;
  EXPECT_EQ(kind.validate(p), "frame_rate_hz asks for more than one frame per step");
  p = withDefaults(kind, {});
  p["markers"] = std::int64_t(2);  // values the runner did not check: the ranges first
  EXPECT_EQ(kind.validate(p), "markers: got 2, expected a value in [3, 1e+05]");
}

}  // namespace
