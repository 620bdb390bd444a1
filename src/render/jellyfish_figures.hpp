#pragma once
// Rudolf & Mould 2009 Figs. 7, 9, 10 from a recorded swim, as POV-Ray scene text (render/pov_scene):
// Fig. 7 the contracted slice's point pairs and discs, Fig. 9 naive extrapolation and each
// variation, Fig. 10 one contraction-expansion cycle. Text only: the runner writes the files and
// runs povray.
#include <vector>

#include "render/pov_scene.hpp"
#include "render/render_params.hpp"
#include "render/slice_recording.hpp"

namespace creaturelab::render {

/// The frames the figures draw (the last whole cycle's eight, the first, the most contracted), so
/// that each can be checked before anything is drawn.
std::vector<int> jellyfishFigureFrames(const SliceRecording& swim);

/// Figs. 7, 9, 10 in that order. Throws OutlineError for a frame that cannot be rendered.
std::vector<PovFigure> jellyfishFigures(const SliceRecording& swim, const RenderParams& params);

}  // namespace creaturelab::render
