#include "fluid/diffusion_operator2.hpp"

#include <algorithm>

#include "fluid/boundary2.hpp"

namespace creaturelab::fluid {
namespace {

double ghostRhs(const Wall& wall) {
  return (wall.type == WallType::moving || wall.type == WallType::inflow) ? 2.0 * wall.tangential_velocity_m_per_s
                                                                          : 0.0;
}

bool sameWalls(const Walls& a, const Walls& b) {
  auto same = [](const Wall& p, const Wall& q) {
    return p.type == q.type && p.tangential_velocity_m_per_s == q.tangential_velocity_m_per_s &&
           p.inflow_m_per_s == q.inflow_m_per_s;
  };
  return same(a.left, b.left) && same(a.right, b.right) && same(a.bottom, b.bottom) && same(a.top, b.top);
}

}  // namespace

double diffusionGhostCount(const Wall& wall) {
  return (wall.type == WallType::no_slip || wall.type == WallType::moving || wall.type == WallType::inflow) ? 2.0
                                                                                                         : 0.0;
}

bool DiffusionBlock2::prepare(FaceAxis face_axis, int nx, int ny, const Walls& new_walls) {
  if (ready && axis == face_axis && sameWalls(walls, new_walls) && count.nx() == nx && count.ny() == ny) return false;
  ready = true;
  axis = face_axis;
  walls = new_walls;
  for (Array2* a : {&count, &wall_rhs}) {
    a->resize(0, 0);
    a->resize(nx, ny);
  }
  if (axis == FaceAxis::x) {
    const FaceRange r = unknownFaces(walls.left, walls.right, nx - 1);
    i_begin = r.begin, i_end = r.end, j_begin = 0, j_end = ny;
  } else {
    const FaceRange r = unknownFaces(walls.bottom, walls.top, ny - 1);
    i_begin = 0, i_end = nx, j_begin = r.begin, j_end = r.end;
  }
  // Neighbour counts d and wall right-hand sides (see the header).
  has_wall_rhs = false;
  max_row_sum = 0.0;
  auto unknown = [&](int i, int j) { return i >= i_begin && i < i_end && j >= j_begin && j < j_end; };
  for (int j = j_begin; j < j_end; ++j) {
    for (int i = i_begin; i < i_end; ++i) {
      double d = 0.0;
      double rhs = 0.0;
      // A tangential neighbour: a face inside, or the wall's ghost beyond the last one.
      auto tangential = [&](bool inside, const Wall& wall) {
        if (inside) {
          d += 1.0;
        } else {
          d += diffusionGhostCount(wall);
          rhs += ghostRhs(wall);
        }
      };
      // A neighbour along the component: an unknown face, a solid wall's face (known: zero or an
      // inflow wall's speed) or none beyond an open wall (∂u/∂n = 0).
      auto along = [&](bool exists, bool is_wall_face, const Wall& wall, bool high_wall) {
        if (!exists) return;
        d += 1.0;
        if (is_wall_face) rhs += solidWallNormalVelocity(wall, high_wall);
      };
      if (axis == FaceAxis::x) {
        along(i > 0, i - 1 == 0 && isSolid(walls.left), walls.left, false);
        along(i < nx - 1, i + 1 == nx - 1 && isSolid(walls.right), walls.right, true);
        tangential(j > 0, walls.bottom);
        tangential(j < ny - 1, walls.top);
      } else {
        along(j > 0, j - 1 == 0 && isSolid(walls.bottom), walls.bottom, false);
        along(j < ny - 1, j + 1 == ny - 1 && isSolid(walls.top), walls.top, true);
        tangential(i > 0, walls.left);
        tangential(i < nx - 1, walls.right);
      }
      count(i, j) = d;
      wall_rhs(i, j) = rhs;
      const int neighbours = unknown(i - 1, j) + unknown(i + 1, j) + unknown(i, j - 1) + unknown(i, j + 1);
      max_row_sum = std::max(max_row_sum, d + neighbours);
      has_wall_rhs = has_wall_rhs || rhs != 0.0;
    }
  }
  return true;
}

void applyDiffusionRows(const DiffusionBlock2& block, int jb, int je, double alpha, const Array2& x, Array2& y,
                          double* row_dots) {
  const int ib = block.i_begin;
  const int ie = block.i_end;
  const int nx = x.nx();
  const int ny = x.ny();
  for (int j = jb; j < je; ++j) {
    const double* __restrict__ c = x.row(j);
    const double* __restrict__ s = j > 0 ? x.row(j - 1) : nullptr;
    const double* __restrict__ n = j < ny - 1 ? x.row(j + 1) : nullptr;
    const double* __restrict__ d = block.count.row(j);
    double* __restrict__ out = y.row(j);
    // Interior of the row: all four neighbours exist in the array.
    const int lo = std::max(ib, 1);
    const int hi = std::min(ie, nx - 1);
    if (s != nullptr && n != nullptr) {
      const double diagonal = 1.0 + alpha * 4.0;
      for (int i = lo; i < hi; ++i) {
        out[i] = diagonal * c[i] - alpha * ((c[i - 1] + c[i + 1]) + (s[i] + n[i]));  // d = 4 here
      }
    } else {
      for (int i = lo; i < hi; ++i) {
        const double vertical = (s != nullptr ? s[i] : 0.0) + (n != nullptr ? n[i] : 0.0);
        out[i] = (1.0 + alpha * d[i]) * c[i] - alpha * ((c[i - 1] + c[i + 1]) + vertical);
      }
    }
    // The ends of the row.
    for (int i : {ib, ie - 1}) {
      if (i >= lo && i < hi) continue;
      double sum = 0.0;
      if (i > 0) sum += c[i - 1];
      if (i < nx - 1) sum += c[i + 1];
      if (s != nullptr) sum += s[i];
      if (n != nullptr) sum += n[i];
      out[i] = (1.0 + alpha * d[i]) * c[i] - alpha * sum;
    }
    row_dots[j] = dot(c + ib, out + ib, static_cast<std::size_t>(ie - ib));  // while the row is in cache
  }
}

}  // namespace creaturelab::fluid
