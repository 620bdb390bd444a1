// The jellyfish kind's water for tests that build a JellyfishBody without a fluid.
#pragma once

namespace creaturelab::test {

// μ = ρ ν of the kind's default fluid (1000 kg/m^3, 5e-5 m^2/s), Pa s: turns the tentacles' permeability
// into a Darcy coefficient.
inline constexpr double kWaterViscosity_pa_s = 1000.0 * 5e-5;

}  // namespace creaturelab::test
