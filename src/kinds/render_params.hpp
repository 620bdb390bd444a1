#pragma once
// The parameter schema of `creaturelab render` (render/render_params.hpp): name, unit, default,
// range and doc of every render.* setting, so that the command checks a `key=value` as the runner
// checks an experiment's [params] (kinds/params.hpp), and `creaturelab list render` documents them.
// Rendering is not a kind: it reads a recorded run rather than running a solver (runner/render_run.hpp).
#include <vector>

#include "kinds/params.hpp"
#include "render/render_params.hpp"

namespace creaturelab::kinds {

const std::vector<ParamSpec>& renderParamSpecs();

/// RenderParams from a resolved set (every spec present); `run_thickness_m` is the recorded bell's
/// thickness, used when thickness_m = "auto".
render::RenderParams renderParams(const Params& params, double run_thickness_m);

}  // namespace creaturelab::kinds
