#include "fluid/staggered_sampler2.hpp"

namespace creaturelab::fluid {

void StaggeredComponent2::assign(FaceAxis axis, const Array2& values, const Walls& walls) {
  if (axis == FaceAxis::x) {
    // values: (nx + 1) × ny, tangential to the bottom and top walls.
    const int nx = values.nx() - 1;
    const int ny = values.ny();
    padded_.resize(nx + 1, ny + 2);
    for (int j = 0; j < ny; ++j) {
      std::copy(values.row(j), values.row(j) + (nx + 1), padded_.row(j + 1));
    }
    for (int i = 0; i <= nx; ++i) {
      padded_(i, 0) = tangential_ghost(walls.bottom, values(i, 0));
      padded_(i, ny + 1) = tangential_ghost(walls.top, values(i, ny - 1));
    }
    view_ = SampleView{padded_.data(), nx + 1, 0.0, 0.5, static_cast<double>(nx), static_cast<double>(ny), nx - 1, ny};
  } else {
    // values: nx × (ny + 1), tangential to the left and right walls.
    const int nx = values.nx();
    const int ny = values.ny() - 1;
    padded_.resize(nx + 2, ny + 1);
    for (int j = 0; j <= ny; ++j) {
      const double* src = values.row(j);
      double* dst = padded_.row(j);
      std::copy(src, src + nx, dst + 1);
      dst[0] = tangential_ghost(walls.left, src[0]);
      dst[nx + 1] = tangential_ghost(walls.right, src[nx - 1]);
    }
    view_ = SampleView{padded_.data(), nx + 2, 0.5, 0.0, static_cast<double>(nx), static_cast<double>(ny), nx, ny - 1};
  }
}

}  // namespace creaturelab::fluid
