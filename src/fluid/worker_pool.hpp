#pragma once
// Threads inside one fluid step that cannot change its results (DESIGN.md: parallelism inside a
// solver "only where the result cannot change"; Box2D v3 runs its solver stages on workers the
// same way and checks it by a hash over 1..32 workers).
//
// The rule that makes results independent of the thread count: work is cut into pieces by
// index alone (rows, lanes, modes), every piece computes exactly what the serial loop computed
// for it and writes only its own outputs, and a reduction is either order-free (maxima) or
// kept per row and summed afterwards in row order. Which thread runs a piece, and how many
// threads there are, then only changes the time. tests/unit/fluid_threads_test.cpp compares
// the state after many steps bitwise for 1, 2 and 3 threads.
//
// One pool per solver; its workers spin for a short while after a task (a step runs a few
// dozen short parallel loops) and then sleep on a condition variable. The spinning is CPU time
// and is counted by the benchmarks (tests/bench/bench_fluid.cpp reports process CPU time).

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace creaturelab::fluid {

/// A loop is cut into kPartsPerThread pieces per thread. Thread t owns the contiguous parts
/// t k .. t k + k − 1 (k = kPartsPerThread) and runs them first, so that in every loop of a step
/// the same rows go to the same core and stay in its cache; a thread done with its own takes
/// those the others have not started, so that on a machine whose cores are shared with other
/// work a thread that loses its core holds up only a small piece.
inline constexpr int kPartsPerThread = 4;
/// Most pieces of a loop: per-piece partial results of reductions live in fixed arrays of this
/// size, so that no step allocates.
inline constexpr int kMaxParts = 64;
/// Most threads a pool runs (FluidParams::validate checks it).
inline constexpr int kMaxThreads = kMaxParts / kPartsPerThread;

class WorkerPool {
 public:
  /// The calling thread plus threads − 1 workers (threads clamped to 1 .. kMaxThreads).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return threads_; }
  /// Parts of each task: 1 with one thread, else kPartsPerThread per thread.
  int parts() const { return parts_; }

  /// Calls task(part) once for each part = 0 .. parts() − 1 and returns when all have
  /// finished: each on its owner (the calling thread is thread 0), or on whichever thread claims
  /// it first when its owner is slow to start. Tasks must not throw. Not reentrant.
  template <class Task>
  void run(Task&& task) {
    if (threads_ == 1) {
      task(0);
      return;
    }
    using T = std::remove_reference_t<Task>;
    dispatch([](void* t, int part) { (*static_cast<T*>(t))(part); }, const_cast<void*>(static_cast<const void*>(&task)));
  }

  /// Piece `part` of [begin, end) cut into `parts` contiguous pieces of nearly equal size.
  static std::pair<int, int> piece(int begin, int end, int part, int parts) {
    const long n = end - begin;
    return {begin + static_cast<int>(n * part / parts), begin + static_cast<int>(n * (part + 1) / parts)};
  }

 private:
  void dispatch(void (*function)(void*, int), void* task);
  void runParts(int thread);
  void work(int thread);

  int threads_ = 1;
  int parts_ = 1;
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::atomic<std::uint64_t> generation_{0};
  // next_[t]: the next unclaimed one of thread t's parts [t k, (t + 1) k), k = kPartsPerThread;
  // each counter on its own cache line.
  struct alignas(64) Counter {
    std::atomic<int> value{0};
  };
  Counter next_[kMaxThreads];
  std::atomic<int> done_{0};       // parts finished in this task
  std::atomic<bool> stop_{false};
  void (*function_)(void*, int) = nullptr;
  void* task_ = nullptr;
};

/// Runs body(begin_k, end_k, part) over [begin, end) cut into pool->parts() pieces (serially,
/// as one piece, when pool is null). body must give each index the same result whatever piece
/// it falls in.
template <class Body>
void forPieces(WorkerPool* pool, int begin, int end, Body&& body) {
  if (pool == nullptr || pool->parts() == 1) {
    if (begin < end) body(begin, end, 0);
    return;
  }
  const int parts = pool->parts();
  pool->run([&](int part) {
    const auto [lo, hi] = WorkerPool::piece(begin, end, part, parts);
    if (lo < hi) body(lo, hi, part);
  });
}

/// forPieces() with one piece per thread (the rest of the pool's parts idle): for loops whose
/// inner vectors shorten with the piece, such as the fast pressure solver's lane-split FFT, where
/// kPartsPerThread pieces of a few lanes each cost more in loop overhead than they gain in balance.
/// Inner boundaries fall on multiples of `quantum` from begin: with quantum = one cache line of
/// doubles and cache-aligned rows (Array2), no two threads write into one line of a row.
/// Any split gives the same values (each lane gets the serial arithmetic).
template <class Body>
void forThreadPieces(WorkerPool* pool, int begin, int end, int quantum, Body&& body) {
  if (pool == nullptr || pool->parts() == 1) {
    if (begin < end) body(begin, end, 0);
    return;
  }
  const int pieces = pool->threads();
  const int units = (end - begin + quantum - 1) / quantum;
  pool->run([&](int part) {
    if (part % kPartsPerThread != 0) return;  // one piece per thread: the first of its parts
    const int piece = part / kPartsPerThread;
    const auto [u0, u1] = WorkerPool::piece(0, units, piece, pieces);
    const int lo = begin + u0 * quantum;
    const int hi = std::min(end, begin + u1 * quantum);
    if (lo < hi) body(lo, hi, piece);
  });
}

/// Number of pieces forThreadPieces() uses: one per thread, so per-piece scratch is indexed by part.
inline int threadPieceCount(const WorkerPool* pool) { return pool == nullptr ? 1 : pool->threads(); }

/// Number of pieces forPieces() uses (≤ kMaxParts): per-piece scratch is indexed by part.
inline int pieceCount(const WorkerPool* pool) { return pool == nullptr ? 1 : pool->parts(); }

}  // namespace creaturelab::fluid
