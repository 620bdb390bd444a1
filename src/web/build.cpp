#include "web/build.hpp"

#include <stdexcept>

#include "web/frame_forces.hpp"
#include "web/frame_stage.hpp"
#include "web/spiral_stage.hpp"
#include "web/spoke_stage.hpp"
#include "web/web_builder.hpp"

namespace creaturelab::web {
namespace {

void countUp(WebModel& m, int primary_spokes, int spiral_segments) {
  auto& c = m.counts;
  const auto& net = m.network;
  c.particles = net.particleCount();
  c.springs = net.springCount();
  c.spokes = static_cast<int>(m.spokes.size());
  c.primary_spokes = primary_spokes;
  c.spiral_segments = spiral_segments;
  c.spiral_springs = 0;
  c.silk_length_m = c.silk_laid_length_m = 0;
  for (int s = 0; s < net.springCount(); ++s) {
    c.silk_length_m += net.rest_length_m[s];
    c.silk_laid_length_m += (m.state.x_m.col(net.spring_a[s]) - m.state.x_m.col(net.spring_b[s])).norm();
    if (m.spring_type[s] == StrandType::spiral) ++c.spiral_springs;
  }
  c.web_mass_kg = net.mass_kg.sum();
}

}  // namespace

WebModel build(const WebParams& params) {
  if (const auto error = params.validate(); !error.empty()) throw std::invalid_argument(error);
  WebBuilder web(params);
  const FrameLayout frame = layFrame(web);
  const SpokeLayout spokes = laySpokesAndHub(web, frame);
  const SpiralResult spiral = laySpiral(web, spokes);

  WebModel m = web.finish();
  m.centre_m = frame.centre_m;
  m.hub_centre_m = spokes.hub_centre_m;
  m.attachment_particles = frame.attachment;
  m.inner_frame_particles = frame.chain;
  m.hub_particles = spokes.hub;
  m.spokes = spokes.radii;
  m.external_force_n = inwardFrameForces(frame.chain, m.state.x_m, frame.centre_m,
                                         params.inner_frame_inward_force_n_per_m, m.network.particleCount());
  countUp(m, static_cast<int>(spokes.primary.size()), spiral.segments);
  return m;
}

}  // namespace creaturelab::web
