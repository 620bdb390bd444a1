#include "kinds/jellyfish_render_params.hpp"

namespace creaturelab::kinds {

const std::vector<ParamSpec>& renderParamSpecs() {
  static const std::vector<ParamSpec> specs = schemaOf<JellyfishRenderSettings>();
  return specs;
}

render::RenderParams renderParams(const Params& params, double run_thickness_m) {
  const JellyfishRenderSettings s = readParams<JellyfishRenderSettings>(params);
  render::RenderParams p = s.render;
  p.thickness.apex_m = s.thickness_m.is_auto ? run_thickness_m : s.thickness_m.value;
  return p;
}

}  // namespace creaturelab::kinds
