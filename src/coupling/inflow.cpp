#include "coupling/inflow.hpp"

namespace creaturelab::coupling {

std::string InflowParams::validate(const fluid::FluidParams& f) const {
  const InflowParams& p = *this;
  using fluid::WallType;
  const bool left_inflow = f.walls.left.type == WallType::inflow;
  const bool floor_inflow = f.walls.bottom.type == WallType::inflow;
  if (left_inflow && (p.stream_m_per_s == 0 || f.walls.left.inflow_m_per_s != p.stream_m_per_s))
    return "an inflow left wall enters at stream_m_per_s, which must not be 0";
  if (floor_inflow && (p.source_m_per_s == 0 || f.walls.bottom.inflow_m_per_s != p.source_m_per_s))
    return "an inflow floor enters at source_m_per_s, which must not be 0";
  if (p.stream_m_per_s != 0) {
    const int least_columns = left_inflow ? 0 : 1;
    if (p.stream_columns < least_columns || p.stream_columns >= f.cells_x / 2)
      return left_inflow ? "stream_columns must be less than half the cells across"
                         : "stream_columns must be at least 1 (or the left wall an inflow) and less than half the "
                           "cells across";
    if (f.walls.right.type != WallType::open) return "a stream needs an open right wall for the fluid to leave";
  }
  if (p.source_m_per_s != 0) {
    if (f.walls.bottom.type != WallType::open && !floor_inflow)
      return "a floor source needs an inflow floor (wall_bottom = \"inflow\") or an open one held by a band";
    const int least_rows = floor_inflow ? 0 : 1;
    if (p.source_rows < least_rows || p.source_rows >= f.cells_y / 2)
      return floor_inflow ? "source_rows must be less than half the cells up"
                          : "source_rows must be at least 1 (or the floor an inflow) and less than half the cells up";
    if (f.walls.top.type != WallType::open) return "a floor source needs an open top for the fluid to leave";
  }
  return "";
}

void applyInflow(fluid::MacGrid2& g, const InflowParams& p) {
  if (p.stream_m_per_s != 0 && p.stream_columns > 0) {
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i <= p.stream_columns; ++i) g.u_m_per_s(i, j) = p.stream_m_per_s;
    for (int j = 1; j < g.ny; ++j)
      for (int i = 0; i < p.stream_columns; ++i) g.v_m_per_s(i, j) = 0.0;
  }
  if (p.source_m_per_s != 0 && p.source_rows > 0) {
    for (int j = 0; j <= p.source_rows; ++j)
      for (int i = 0; i < g.nx; ++i) g.v_m_per_s(i, j) = p.source_m_per_s;
  }
}

void fillStream(fluid::MacGrid2& g, double speed) {
  g.u_m_per_s.fill(speed);
  g.v_m_per_s.fill(0.0);
}

}  // namespace creaturelab::coupling
