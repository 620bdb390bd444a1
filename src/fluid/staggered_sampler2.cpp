#include "fluid/staggered_sampler2.hpp"

namespace creaturelab::fluid {

Array2& StaggeredComponent2::prepare(FaceAxis axis, int nx, int ny) {
  axis_ = axis;
  if (axis == FaceAxis::x) {
    // u: (nx + 1) × ny, tangential to the bottom and top walls: ghost rows 0 and ny + 1.
    padded_.resize(nx + 1, ny + 2);
    view_ = SampleView{padded_.data(), nx + 1, 0.0, 0.5, static_cast<double>(nx), static_cast<double>(ny), nx - 1, ny};
  } else {
    // v: nx × (ny + 1), tangential to the left and right walls: ghost columns 0 and nx + 1.
    padded_.resize(nx + 2, ny + 1);
    view_ = SampleView{padded_.data(), nx + 2, 0.5, 0.0, static_cast<double>(nx), static_cast<double>(ny), nx, ny - 1};
  }
  return padded_;
}

void StaggeredComponent2::fill_ghosts(const Walls& walls) {
  if (axis_ == FaceAxis::x) {
    const int nx = padded_.nx() - 1;
    const int ny = padded_.ny() - 2;
    for (int i = 0; i <= nx; ++i) {
      padded_(i, 0) = tangential_ghost(walls.bottom, padded_(i, 1));
      padded_(i, ny + 1) = tangential_ghost(walls.top, padded_(i, ny));
    }
  } else {
    const int nx = padded_.nx() - 2;
    const int ny = padded_.ny() - 1;
    for (int j = 0; j <= ny; ++j) {
      double* row = padded_.row(j);
      row[0] = tangential_ghost(walls.left, row[1]);
      row[nx + 1] = tangential_ghost(walls.right, row[nx]);
    }
  }
}

void StaggeredComponent2::finish(const Walls& walls) {
  if (axis_ == FaceAxis::x) {
    const int nx = padded_.nx() - 1;
    const int ny = padded_.ny() - 2;
    for (int j = 0; j < ny; ++j) {
      if (is_solid(walls.left)) interior_row(j)[0] = solid_wall_normal_velocity(walls.left, false);
      if (is_solid(walls.right)) interior_row(j)[nx] = solid_wall_normal_velocity(walls.right, true);
    }
  } else {
    const int nx = padded_.nx() - 2;
    const int ny = padded_.ny() - 1;
    if (is_solid(walls.bottom))
      std::fill(interior_row(0), interior_row(0) + nx, solid_wall_normal_velocity(walls.bottom, false));
    if (is_solid(walls.top))
      std::fill(interior_row(ny), interior_row(ny) + nx, solid_wall_normal_velocity(walls.top, true));
  }
  fill_ghosts(walls);
}

void StaggeredComponent2::assign(FaceAxis axis, const Array2& values, const Walls& walls) {
  const int nx = axis == FaceAxis::x ? values.nx() - 1 : values.nx();
  const int ny = axis == FaceAxis::x ? values.ny() : values.ny() - 1;
  prepare(axis, nx, ny);
  copy_rows(values, 0, values.ny());
  fill_ghosts(walls);
}

void StaggeredComponent2::copy_rows(const Array2& values, int j0, int j1) {
  for (int j = j0; j < j1; ++j) std::copy(values.row(j), values.row(j) + values.nx(), interior_row(j));
}

}  // namespace creaturelab::fluid
