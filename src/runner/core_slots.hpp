#pragma once
// Cores shared by experiments that run side by side (`creaturelab reproduce`): a point computes
// only while it holds a slot, so the points of every experiment in flight use at most the slots
// together, and the cores one experiment leaves idle (a single point, a sweep's last points) go to
// the next experiment of the list.
#include <condition_variable>
#include <mutex>

namespace creaturelab::runner {

class CoreSlots {
 public:
  explicit CoreSlots(int count) : free_(count) {}
  CoreSlots(const CoreSlots&) = delete;
  CoreSlots& operator=(const CoreSlots&) = delete;

  void acquire() {
    std::unique_lock lock(mutex_);
    freed_.wait(lock, [&] { return free_ > 0; });
    --free_;
  }
  void release() {
    {
      std::lock_guard lock(mutex_);
      ++free_;
    }
    freed_.notify_one();
  }

 private:
  std::mutex mutex_;
  std::condition_variable freed_;
  int free_;
};

// Holds one slot of `slots` while alive; nothing when `slots` is null (a run on its own).
class SlotHold {
 public:
  explicit SlotHold(CoreSlots* slots) : slots_(slots) {
    if (slots_) slots_->acquire();
  }
  ~SlotHold() {
    if (slots_) slots_->release();
  }
  SlotHold(const SlotHold&) = delete;
  SlotHold& operator=(const SlotHold&) = delete;

 private:
  CoreSlots* slots_;
};

}  // namespace creaturelab::runner
