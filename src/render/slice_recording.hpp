#pragma once
// A recorded 2-D jellyfish swim as the render reads it (Rudolf & Mould 2009 §3.4): per frame, the
// markers' positions and the muscles' activation, with the slice's topology. Plain data: the kind's
// render hook (kinds/jellyfish_render.cpp) fills it from what the runner read.
#include <span>
#include <vector>

#include "render/slice_model2.hpp"

namespace creaturelab::render {

struct SliceRecording {
  std::vector<double> time_s;      // per frame, s
  int markers = 0;
  std::vector<double> markers_xy;  // frames × markers × 2, m
  int muscles = 0;
  std::vector<double> activation;  // frames × muscles; empty when the run did not record it
  SliceTopology topology;
  double contraction_hz = 0;       // the swim's cycle (0: unknown, the whole run is one cycle)

  int frames() const { return int(time_s.size()); }
  SliceFrame frame(int k) const {
    SliceFrame f;
    f.time_s = time_s[k];
    f.markers_xy = std::span<const double>(markers_xy).subspan(std::size_t(k) * 2 * markers, 2 * std::size_t(markers));
    if (!activation.empty())
      f.muscle_activation = std::span<const double>(activation).subspan(std::size_t(k) * muscles, std::size_t(muscles));
    return f;
  }
};

}  // namespace creaturelab::render
