#include "fluid/diagnostics2.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "fluid/boundary2.hpp"

namespace creaturelab::fluid {
namespace {

// acc.add over i < nx of the flux sums (u[i+1] − u[i]) + (v_n[i] − v_s[i]) of one row of cells.
void addFluxRow(MaxAbsAccumulator& acc, const double* u, const double* v_s, const double* v_n, int nx) {
  auto flux = [&](int i) { return (u[i + 1] - u[i]) + (v_n[i] - v_s[i]); };
  int i = 0;
#if defined(__SSE2__)
  auto flux2 = [&](int k) {  // flux(k), flux(k + 1): the same arithmetic in each lane
    return _mm_add_pd(_mm_sub_pd(_mm_loadu_pd(u + k + 1), _mm_loadu_pd(u + k)),
                      _mm_sub_pd(_mm_loadu_pd(v_n + k), _mm_loadu_pd(v_s + k)));
  };
  for (; i + 4 <= nx; i += 4) acc.add2x2(flux2(i), flux2(i + 2));
#else
  for (; i + 4 <= nx; i += 4) acc.add4(flux(i), flux(i + 1), flux(i + 2), flux(i + 3));
#endif
  for (; i < nx; ++i) acc.add(flux(i));
}

}  // namespace

double maxDivergence_per_s(const MacGrid2& grid) { return maxAbsFluxSum_m_per_s(grid) / grid.dx_m; }

double maxAbsFluxSum_m_per_s(const MacGrid2& grid, WorkerPool* workers) {
  // A maximum does not depend on the order in which the values meet: one accumulator per piece.
  std::array<MaxAbsAccumulator, kMaxParts> acc{};
  forPieces(workers, 0, grid.ny, [&](int j0, int j1, int part) {
    for (int j = j0; j < j1; ++j) {
      addFluxRow(acc[part], grid.u_m_per_s.row(j), grid.v_m_per_s.row(j), grid.v_m_per_s.row(j + 1), grid.nx);
    }
  });
  for (int part = 1; part < pieceCount(workers); ++part) acc[0].merge(acc[part]);
  const double m = acc[0].result();
  return m == m ? m : std::numeric_limits<double>::infinity();
}

double kineticEnergy_joule_per_m(const MacGrid2& grid, double density_kg_per_m3) {
  // Trapezoidal weights: ½ on the faces lying on walls.
  double sum_u = 0.0;
  for (int j = 0; j < grid.ny; ++j) {
    const double* u = grid.u_m_per_s.row(j);
    sum_u += dot(u, u, grid.nx + 1) - 0.5 * (u[0] * u[0] + u[grid.nx] * u[grid.nx]);
  }
  double sum_v = 0.0;
  for (int j = 0; j <= grid.ny; ++j) {
    const double* v = grid.v_m_per_s.row(j);
    const double row = dot(v, v, grid.nx);
    sum_v += (j == 0 || j == grid.ny) ? 0.5 * row : row;
  }
  return 0.5 * density_kg_per_m3 * grid.dx_m * grid.dx_m * (sum_u + sum_v);
}

double maxVelocityComponent_m_per_s(const MacGrid2& grid, WorkerPool* workers) {
  std::array<MaxAbsAccumulator, kMaxParts> u{}, v{};
  forPieces(workers, 0, grid.ny + 1, [&](int j0, int j1, int part) {
    if (j1 > grid.ny) {  // u has ny rows, v ny + 1
      j1 = grid.ny;
      v[part].merge(partialMaxAbs(grid.v_m_per_s.row(grid.ny), static_cast<std::size_t>(grid.nx)));
    }
    for (int j = j0; j < j1; ++j) {
      u[part].merge(partialMaxAbs(grid.u_m_per_s.row(j), static_cast<std::size_t>(grid.nx) + 1));
      v[part].merge(partialMaxAbs(grid.v_m_per_s.row(j), static_cast<std::size_t>(grid.nx)));
    }
  });
  for (int part = 1; part < pieceCount(workers); ++part) u[0].merge(u[part]), v[0].merge(v[part]);
  const double mu = u[0].result();
  const double mv = v[0].result();
  const double big = std::numeric_limits<double>::max();
  return (mu <= big && mv <= big) ? std::max(mu, mv) : std::numeric_limits<double>::infinity();
}

FlowSummary summarizeFlow(const MacGrid2& grid, double density_kg_per_m3, WorkerPool* workers) {
  std::vector<double> row_energies;
  return summarizeFlow(grid, density_kg_per_m3, workers, row_energies);
}

FlowSummary summarizeFlow(const MacGrid2& grid, double density_kg_per_m3, WorkerPool* workers,
                           std::vector<double>& row_energies) {
  const int nx = grid.nx;
  const int ny = grid.ny;
  auto add_row = [](MaxAbsAccumulator& acc, const double* p, int n) {
    int i = 0;
    for (; i + 4 <= n; i += 4) acc.add4(p + i);
    for (; i < n; ++i) acc.add(p[i]);
  };
  // Maxima per piece of rows (order-free); the energy of each row is stored and the rows are
  // summed afterwards in row order, the serial order (so any thread count gives the same bits).
  std::array<MaxAbsAccumulator, kMaxParts> speed{}, flux{};
  row_energies.resize(2 * static_cast<std::size_t>(ny) + 1);
  double* e_u = row_energies.data();  // e_u[j]: row j of u
  double* e_v = e_u + ny;             // e_v[j]: row j of v, j = 0..ny
  forPieces(workers, 0, ny, [&](int j0, int j1, int part) {
    if (j0 == 0) {
      const double* v = grid.v_m_per_s.row(0);
      add_row(speed[part], v, nx);
      e_v[0] = 0.5 * dot(v, v, nx);
    }
    for (int j = j0; j < j1; ++j) {
      const double* u = grid.u_m_per_s.row(j);
      const double* v_s = grid.v_m_per_s.row(j);
      const double* v_n = grid.v_m_per_s.row(j + 1);
      add_row(speed[part], u, nx + 1);
      add_row(speed[part], v_n, nx);
      e_u[j] = dot(u, u, nx + 1) - 0.5 * (u[0] * u[0] + u[nx] * u[nx]);
      e_v[j + 1] = (j + 1 == ny ? 0.5 : 1.0) * dot(v_n, v_n, nx);
      addFluxRow(flux[part], u, v_s, v_n, nx);
    }
  });
  for (int part = 1; part < pieceCount(workers); ++part) speed[0].merge(speed[part]), flux[0].merge(flux[part]);
  double sum_u = 0.0, sum_v = e_v[0];
  for (int j = 0; j < ny; ++j) {
    sum_u += e_u[j];
    sum_v += e_v[j + 1];
  }
  const double infinity = std::numeric_limits<double>::infinity();
  const double big = std::numeric_limits<double>::max();
  const double max_speed = speed[0].result();
  const double max_flux = flux[0].result();
  FlowSummary summary;
  summary.max_velocity_component_m_per_s = max_speed <= big ? max_speed : infinity;
  summary.max_divergence_per_s = max_flux <= big ? max_flux / grid.dx_m : infinity;
  summary.kinetic_energy_joule_per_m = 0.5 * density_kg_per_m3 * grid.dx_m * grid.dx_m * (sum_u + sum_v);
  return summary;
}

double cflNumber(const MacGrid2& grid, double dt_s) { return maxVelocityComponent_m_per_s(grid) * dt_s / grid.dx_m; }

void vorticityAtCorners(const MacGrid2& grid, const Walls& walls, Array2& omega_per_s) {
  const int nx = grid.nx;
  const int ny = grid.ny;
  const Array2& u = grid.u_m_per_s;
  const Array2& v = grid.v_m_per_s;
  const double inv_dx = 1.0 / grid.dx_m;
  omega_per_s.resize(nx + 1, ny + 1);
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double v_right = i < nx ? v(i, j) : tangentialGhost(walls.right, v(nx - 1, j));
      const double v_left = i > 0 ? v(i - 1, j) : tangentialGhost(walls.left, v(0, j));
      const double u_above = j < ny ? u(i, j) : tangentialGhost(walls.top, u(i, ny - 1));
      const double u_below = j > 0 ? u(i, j - 1) : tangentialGhost(walls.bottom, u(i, 0));
      omega_per_s(i, j) = ((v_right - v_left) - (u_above - u_below)) * inv_dx;
    }
  }
}

void vorticityAtCentres(const MacGrid2& grid, const Walls& walls, Array2& omega_per_s) {
  Array2 corners;
  vorticityAtCorners(grid, walls, corners);
  omega_per_s.resize(grid.nx, grid.ny);
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      omega_per_s(i, j) = 0.25 * ((corners(i, j) + corners(i + 1, j)) + (corners(i, j + 1) + corners(i + 1, j + 1)));
    }
  }
}

void velocityAtCentres(const MacGrid2& grid, Array2& u_m_per_s, Array2& v_m_per_s) {
  u_m_per_s.resize(grid.nx, grid.ny);
  v_m_per_s.resize(grid.nx, grid.ny);
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      u_m_per_s(i, j) = 0.5 * (grid.u_m_per_s(i, j) + grid.u_m_per_s(i + 1, j));
      v_m_per_s(i, j) = 0.5 * (grid.v_m_per_s(i, j) + grid.v_m_per_s(i, j + 1));
    }
  }
}

}  // namespace creaturelab::fluid
