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

void StaggeredComponent2::fillGhosts(const Walls& walls) {
  if (axis_ == FaceAxis::x) {
    const int nx = padded_.nx() - 1;
    const int ny = padded_.ny() - 2;
    for (int i = 0; i <= nx; ++i) {
      padded_(i, 0) = tangentialGhost(walls.bottom, padded_(i, 1));
      padded_(i, ny + 1) = tangentialGhost(walls.top, padded_(i, ny));
    }
  } else {
    const int nx = padded_.nx() - 2;
    const int ny = padded_.ny() - 1;
    for (int j = 0; j <= ny; ++j) {
      double* row = padded_.row(j);
      row[0] = tangentialGhost(walls.left, row[1]);
      row[nx + 1] = tangentialGhost(walls.right, row[nx]);
    }
  }
}

void StaggeredComponent2::finish(const Walls& walls) {
  if (axis_ == FaceAxis::x) {
    const int nx = padded_.nx() - 1;
    const int ny = padded_.ny() - 2;
    for (int j = 0; j < ny; ++j) {
      if (isSolid(walls.left)) interiorRow(j)[0] = solidWallNormalVelocity(walls.left, false);
      if (isSolid(walls.right)) interiorRow(j)[nx] = solidWallNormalVelocity(walls.right, true);
    }
  } else {
    const int nx = padded_.nx() - 2;
    const int ny = padded_.ny() - 1;
    if (isSolid(walls.bottom))
      std::fill(interiorRow(0), interiorRow(0) + nx, solidWallNormalVelocity(walls.bottom, false));
    if (isSolid(walls.top))
      std::fill(interiorRow(ny), interiorRow(ny) + nx, solidWallNormalVelocity(walls.top, true));
  }
  fillGhosts(walls);
}

void StaggeredComponent2::assign(FaceAxis axis, const Array2& values, const Walls& walls) {
  const int nx = axis == FaceAxis::x ? values.nx() - 1 : values.nx();
  const int ny = axis == FaceAxis::x ? values.ny() : values.ny() - 1;
  prepare(axis, nx, ny);
  copyRows(values, 0, values.ny());
  fillGhosts(walls);
}

void StaggeredComponent2::copyRows(const Array2& values, int j0, int j1) {
  for (int j = j0; j < j1; ++j) std::copy(values.row(j), values.row(j) + values.nx(), interiorRow(j));
}

}  // namespace creaturelab::fluid
