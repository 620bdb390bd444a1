#pragma once
// The settings of the jellyfish's render hook (kinds/jellyfish_render.cpp; render/render_params.hpp):
// name, unit, default, range and doc of every render.* setting, so that `creaturelab render` checks
// a `key=value` as the runner checks an experiment's [params] (kinds/params.hpp), and
// `creaturelab list render` documents them.
#include <vector>

#include "kinds/params.hpp"
#include "render/render_params.hpp"

namespace creaturelab::kinds {

const std::vector<ParamSpec>& renderParamSpecs();

/// RenderParams from a resolved set (every spec present); `run_thickness_m` is the recorded bell's
/// thickness, used when thickness_m = "auto".
render::RenderParams renderParams(const Params& params, double run_thickness_m);

}  // namespace creaturelab::kinds
