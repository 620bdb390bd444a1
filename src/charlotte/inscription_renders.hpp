#pragma once
// Renders of an inscription as PNG bytes (A. Mehla, Modeling and Animation of Orb Webs, MSc thesis
// 2005, §6): the settled web (Fig. 6.7), the target over it with the segments to remove in red
// (Figs. 6.3, 6.10), the web just after the cut, and the result after it settled again (Figs. 6.4,
// 6.11-6.18). No I/O: the caller decides where the bytes go.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "charlotte/inscribe.hpp"
#include "web/web_model.hpp"

namespace creaturelab::charlotte {

// "web.png", "overlay.png", "cut.png", "result.png" -> PNG bytes. `settled_x_m` is model's web at
// rest, `final_x_m` the pruned web settled again, `spring_segment` springSegments(ins).
std::map<std::string, std::vector<std::uint8_t>> renderInscription(
    const web::WebModel& model, const springs::Points<3>& settled_x_m, const Inscription& ins, const Raster& target,
    const CanvasMap& map, const Pruned& pruned, const springs::Points<3>& final_x_m,
    const std::vector<std::int64_t>& spring_segment);

}  // namespace creaturelab::charlotte
