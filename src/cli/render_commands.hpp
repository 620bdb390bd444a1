#pragma once
// `creaturelab render`: a recorded jellyfish swim as a 3-D animated mesh (runner/render_run.hpp).
#include "runner/render_run.hpp"

namespace creaturelab::cli {

/// Renders and prints what was written; returns the exit code: 0, or 3 when the render failed after
/// its input was accepted (a write, povray). Bad input is thrown (ExperimentError: exit 2).
int render(const runner::RenderRunOptions& options);

}  // namespace creaturelab::cli
