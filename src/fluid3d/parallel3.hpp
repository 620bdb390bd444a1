#pragma once
// Slab-parallel loops of the 3-D solver on the 2-D solver's WorkerPool (fluid/worker_pool.hpp):
// work is cut by slab index k alone and every slab computes what the serial loop computes, so
// results are bitwise the same for any thread count; sums are kept per slab and added in slab order.

#include <vector>

#include "fluid/worker_pool.hpp"

namespace creaturelab::fluid3d {

using fluid::WorkerPool;

/// Calls body(k0, k1) on pieces of [0, slabs) (serially, as one piece, when pool is null).
template <class Body>
void forSlabs(WorkerPool* pool, int slabs, Body&& body) {
  if (pool == nullptr || pool->parts() == 1) {
    if (slabs > 0) body(0, slabs);
    return;
  }
  const int parts = pool->parts();
  pool->run([&](int part) {
    const auto [lo, hi] = WorkerPool::piece(0, slabs, part, parts);
    if (lo < hi) body(lo, hi);
  });
}

/// Σ_k per_slab[k] in slab order.
inline double sumInOrder(const std::vector<double>& per_slab) {
  double s = 0.0;
  for (double v : per_slab) s += v;
  return s;
}

/// max_k per_slab[k] (NaN wins, so a blow-up is never hidden).
inline double maxInOrder(const std::vector<double>& per_slab) {
  double m = 0.0;
  for (double v : per_slab) {
    if (v != v) return v;
    if (v > m) m = v;
  }
  return m;
}

}  // namespace creaturelab::fluid3d
