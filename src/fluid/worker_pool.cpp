#include "fluid/worker_pool.hpp"

#include <algorithm>
#include <chrono>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace creaturelab::fluid {
namespace {

void cpuRelax() {
#if defined(__SSE2__)
  _mm_pause();
#endif
}

// How long an idle worker spins before it sleeps: longer than the gaps between the parallel
// loops of one step (a few microseconds of serial work), much shorter than a step.
constexpr auto kSpin = std::chrono::microseconds(50);

}  // namespace

WorkerPool::WorkerPool(int threads)
    : threads_(std::clamp(threads, 1, kMaxThreads)), parts_(threads_ == 1 ? 1 : threads_ * kPartsPerThread) {
  workers_.reserve(static_cast<std::size_t>(threads_ - 1));
  for (int worker = 1; worker < threads_; ++worker) workers_.emplace_back([this, worker] { work(worker); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_.store(true, std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

// Each thread claims its own parts first, then the others' (worker_pool.hpp, kPartsPerThread).
// On a machine whose cores are busy with other work a worker may wait long for a core; the
// caller does not wait for it to start but takes its parts. Which thread runs a part never
// changes what the part computes.
void WorkerPool::dispatch(void (*function)(void*, int), void* task) {
  function_ = function;
  task_ = task;
  done_.store(0, std::memory_order_relaxed);
  // Release: a worker still in the previous task's run_parts that claims one of these parts
  // sees function_, task_ and done_ as set above.
  for (int t = 0; t < threads_; ++t) next_[t].value.store(t * kPartsPerThread, std::memory_order_release);
  {
    std::lock_guard<std::mutex> lock(mutex_);  // no lost wake-up: sleepers test under the lock
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  runParts(0);
  for (int spins = 0; done_.load(std::memory_order_acquire) != parts_; ++spins) {
    if (spins < 4096) {
      cpuRelax();
    } else {
      std::this_thread::yield();  // a worker is still running its part
    }
  }
}

void WorkerPool::runParts(int thread) {
  for (int k = 0; k < threads_; ++k) {
    const int owner = (thread + k) % threads_;
    const int end = (owner + 1) * kPartsPerThread;
    for (;;) {
      if (next_[owner].value.load(std::memory_order_relaxed) >= end) break;
      const int part = next_[owner].value.fetch_add(1, std::memory_order_acq_rel);
      if (part >= end) break;
      function_(task_, part);
      done_.fetch_add(1, std::memory_order_release);
    }
  }
}

void WorkerPool::work(int thread) {
  std::uint64_t seen = 0;
  for (;;) {
    std::uint64_t now = generation_.load(std::memory_order_acquire);
    if (now == seen) {
      const auto start = std::chrono::steady_clock::now();
      for (int spins = 1; (now = generation_.load(std::memory_order_acquire)) == seen; ++spins) {
        if (spins % 64 == 0 && std::chrono::steady_clock::now() - start > kSpin) {
          std::unique_lock<std::mutex> lock(mutex_);
          wake_.wait(lock, [&] { return generation_.load(std::memory_order_acquire) != seen; });
        } else {
          cpuRelax();
        }
      }
    }
    seen = now;
    if (stop_.load(std::memory_order_relaxed)) return;  // ordered by the generation's acquire
    runParts(thread);
  }
}

}  // namespace creaturelab::fluid
