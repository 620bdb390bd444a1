#include "control/central_difference.hpp"

#include <stdexcept>
#include <string>

namespace creaturelab::control {

std::vector<double> centralDifferences(fluid::WorkerPool* pool, int n, double d, bool one_sided,
                                       const std::function<double(int, int, double)>& evaluate,
                                       const std::string& context) {
  std::vector<double> value(2 * n, 0.0);
  std::vector<std::string> error(fluid::threadPieceCount(pool));
  // One contiguous block of evaluations per thread (joint i's two on one thread when the threads
  // divide the joints), each in that thread's own copy of the state: as many copies as threads,
  // not kPartsPerThread times more (the 2-joint chain on 128^2, 2 threads: 25.5 MB resident against
  // 53.1). The evaluations cost about the same, so for_pieces' finer claimed pieces bought little
  // balance: the frame time did not change measurably (tests/bench/bench_control_fluid.cpp).
  fluid::forThreadPieces(pool, 0, 2 * n, 1, [&](int lo, int hi, int part) {
    try {
      for (int t = lo; t < hi; ++t) value[t] = evaluate(part, t / 2, t % 2 == 0 ? d : (one_sided ? 0.0 : -d));
    } catch (const std::exception& e) {
      error[part] = e.what();
    }
  });
  for (const auto& e : error)
    if (!e.empty()) throw std::runtime_error(context + ": " + e);
  std::vector<double> g(n);
  for (int i = 0; i < n; ++i) g[i] = (value[2 * i] - value[2 * i + 1]) / (one_sided ? d : 2 * d);
  return g;
}

}  // namespace creaturelab::control
