// Speed of the immersed-boundary transfer: locate + spread + interpolate of one coupled step,
// and each stage alone, for 80 markers on the paper's 100 × 100 grid (Rudolf & Mould 2009 Fig. 12:
// a 0.4 m box, a 40 mm jellyfish), with both kernels. "per_marker" is the time per marker
// per call. The force field is not cleared between iterations (the caller does that once a step).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "fluid/mac_grid2.hpp"
#include "ib/kernel.hpp"
#include "ib/transfer.hpp"

namespace creaturelab::ib {
namespace {

constexpr int kCells = 100;
constexpr double kBox_m = 0.4;
constexpr int kMarkers = 80;

// A bell-shaped arc of markers, 20 mm radius, around the middle of the box.
std::vector<fluid::Vec2> bell() {
  std::vector<fluid::Vec2> p;
  for (int k = 0; k < kMarkers; ++k) {
    const double angle = std::numbers::pi * (0.1 + 0.8 * k / (kMarkers - 1.0));
    p.push_back({0.5 * kBox_m + 0.02 * std::cos(angle), 0.5 * kBox_m + 0.02 * std::sin(angle)});
  }
  return p;
}

fluid::MacGrid2 swirling_grid() {
  fluid::MacGrid2 grid(kCells, kCells, kBox_m / kCells);
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i <= grid.nx; ++i) grid.u_m_per_s(i, j) = std::sin(0.1 * i) * std::cos(0.07 * j);
  for (int j = 0; j <= grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) grid.v_m_per_s(i, j) = std::cos(0.05 * i) * std::sin(0.11 * j);
  return grid;
}

enum class Stage { all, locate, spread, interpolate };

void run(benchmark::State& state, Kernel kernel, Stage stage) {
  const fluid::MacGrid2 grid = swirling_grid();
  const std::vector<fluid::Vec2> positions = bell();
  std::vector<fluid::Vec2> forces(kMarkers);
  for (int k = 0; k < kMarkers; ++k) forces[k] = {1e-3 * std::cos(0.3 * k), 1e-3 * std::sin(0.2 * k)};
  std::vector<fluid::Vec2> velocities(kMarkers);
  fluid::FaceVectorField2 density(kCells, kCells);
  Transfer transfer;
  transfer.locate(grid, kernel, positions);
  for (auto _ : state) {
    if (stage == Stage::all || stage == Stage::locate) transfer.locate(grid, kernel, positions);
    if (stage == Stage::all || stage == Stage::spread) transfer.spread(forces, density);
    if (stage == Stage::all || stage == Stage::interpolate) transfer.interpolate(grid, velocities);
    benchmark::DoNotOptimize(velocities.data());
    benchmark::DoNotOptimize(density.x.data());
    benchmark::ClobberMemory();
  }
  state.counters["per_marker"] =
      benchmark::Counter(kMarkers, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_IbStep_Bilinear(benchmark::State& s) { run(s, Kernel::bilinear, Stage::all); }
void BM_IbStep_Peskin4(benchmark::State& s) { run(s, Kernel::peskin4, Stage::all); }
void BM_IbLocate_Bilinear(benchmark::State& s) { run(s, Kernel::bilinear, Stage::locate); }
void BM_IbLocate_Peskin4(benchmark::State& s) { run(s, Kernel::peskin4, Stage::locate); }
void BM_IbSpread_Bilinear(benchmark::State& s) { run(s, Kernel::bilinear, Stage::spread); }
void BM_IbSpread_Peskin4(benchmark::State& s) { run(s, Kernel::peskin4, Stage::spread); }
void BM_IbInterpolate_Bilinear(benchmark::State& s) { run(s, Kernel::bilinear, Stage::interpolate); }
void BM_IbInterpolate_Peskin4(benchmark::State& s) { run(s, Kernel::peskin4, Stage::interpolate); }

BENCHMARK(BM_IbStep_Bilinear)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IbStep_Peskin4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IbLocate_Bilinear)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IbLocate_Peskin4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IbSpread_Bilinear)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IbSpread_Peskin4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IbInterpolate_Bilinear)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IbInterpolate_Peskin4)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace creaturelab::ib
