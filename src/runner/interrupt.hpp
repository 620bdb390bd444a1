#pragma once
// SIGINT/SIGTERM during a run. The handler only records the signal (nothing else is safe in a
// handler); the runner polls interrupted() between points, stops starting new ones, removes its
// temporary files, writes a consistent index and then ends the process by the same signal with
// its default action, so the shell still sees 130 (SIGINT) or 143 (SIGTERM).
namespace creaturelab::runner {

// Installs the handlers while alive; restores the previous ones on destruction. Guards nest (and may
// live on several threads at once): the outermost installs and restores.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// The signal received since the guard was installed, 0 if none.
int interrupted();
// Ends the process by `signal` with its default action (after the caller cleaned up).
[[noreturn]] void endBySignal(int signal);

}  // namespace creaturelab::runner
