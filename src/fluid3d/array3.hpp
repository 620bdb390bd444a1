#pragma once
// Dense 3-D array of doubles, the storage of every field of the 3-D fluid solver.

#include <cstddef>
#include <vector>

namespace creaturelab::fluid3d {

/// A dense nx × ny × nz array with x fastest: element (i, j, k) lives at data()[(k ny + j) nx + i].
class Array3 {
 public:
  Array3() = default;
  Array3(int nx, int ny, int nz, double value = 0.0)
      : nx_(nx), ny_(ny), nz_(nz), data_(static_cast<std::size_t>(nx) * ny * nz, value) {}

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  /// Extent along axis 0 (x), 1 (y) or 2 (z).
  int extent(int axis) const { return axis == 0 ? nx_ : axis == 1 ? ny_ : nz_; }
  std::size_t size() const { return data_.size(); }
  /// Elements in one slab of constant k.
  std::size_t slabSize() const { return static_cast<std::size_t>(nx_) * ny_; }

  double& operator()(int i, int j, int k) { return data_[index(i, j, k)]; }
  double operator()(int i, int j, int k) const { return data_[index(i, j, k)]; }
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * ny_ + static_cast<std::size_t>(j)) * nx_ + static_cast<std::size_t>(i);
  }

  double* data() { return data_.data(); }
  const double* data() const { return data_.data(); }
  double* row(int j, int k) { return data_.data() + index(0, j, k); }
  const double* row(int j, int k) const { return data_.data() + index(0, j, k); }

  void fill(double value) { data_.assign(data_.size(), value); }
  /// Reshapes (and zeroes) only when the shape changes, so scratch arrays are allocated once.
  void resize(int nx, int ny, int nz) {
    if (nx == nx_ && ny == ny_ && nz == nz_) return;
    nx_ = nx, ny_ = ny, nz_ = nz;
    data_.assign(static_cast<std::size_t>(nx) * ny * nz, 0.0);
  }
  bool sameShape(const Array3& other) const { return nx_ == other.nx_ && ny_ == other.ny_ && nz_ == other.nz_; }
  /// Exact comparison of shape and values (no tolerance).
  bool operator==(const Array3& other) const = default;

 private:
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<double> data_;
};

}  // namespace creaturelab::fluid3d
