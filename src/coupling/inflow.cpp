#include "coupling/inflow.hpp"

namespace creaturelab::coupling {

std::string validate(const InflowParams& p, const fluid::FluidParams& f) {
  using fluid::WallType;
  if (p.stream_m_per_s != 0) {
    if (p.stream_columns < 1 || p.stream_columns >= f.cells_x / 2)
      return "stream_columns must be at least 1 and less than half the cells across";
    if (f.walls.right.type != WallType::open) return "a stream needs an open right wall for the fluid to leave";
  }
  if (p.source_m_per_s != 0) {
    if (p.source_rows < 1 || p.source_rows >= f.cells_y / 2)
      return "source_rows must be at least 1 and less than half the cells up";
    if (f.walls.top.type != WallType::open) return "a floor source needs an open top for the fluid to leave";
    if (f.walls.bottom.type != WallType::open)
      return "a floor source needs an open bottom wall (the source is held there as an inflow)";
  }
  return "";
}

void applyInflow(fluid::MacGrid2& g, const InflowParams& p) {
  if (p.stream_m_per_s != 0) {
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i <= p.stream_columns; ++i) g.u_m_per_s(i, j) = p.stream_m_per_s;
    for (int j = 1; j < g.ny; ++j)
      for (int i = 0; i < p.stream_columns; ++i) g.v_m_per_s(i, j) = 0.0;
  }
  if (p.source_m_per_s != 0) {
    for (int j = 0; j <= p.source_rows; ++j)
      for (int i = 0; i < g.nx; ++i) g.v_m_per_s(i, j) = p.source_m_per_s;
  }
}

void fillStream(fluid::MacGrid2& g, double speed) {
  g.u_m_per_s.fill(speed);
  g.v_m_per_s.fill(0.0);
}

}  // namespace creaturelab::coupling
