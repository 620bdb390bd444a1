#include "runner/interrupt.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <mutex>

namespace creaturelab::runner {
namespace {

volatile sig_atomic_t g_signal = 0;
struct sigaction g_old_int, g_old_term;
// Guards alive (experiments of a list run side by side each hold one): the first installs the
// handlers, the last restores the old ones.
std::mutex g_guards_mutex;
int g_guards = 0;

extern "C" void recordSignal(int signal) { g_signal = signal; }

}  // namespace

InterruptGuard::InterruptGuard() {
  const std::lock_guard lock(g_guards_mutex);
  if (g_guards++ > 0) return;
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = recordSignal;
  sigemptyset(&sa.sa_mask);
  // SA_RESTART: a worker's read or write that the signal lands in goes on instead of failing with
  // EINTR; the runner's main thread polls the flag, it does not rely on being woken.
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
  // A signal the parent chose to ignore (nohup, a background job of a script) stays ignored.
  if (g_old_int.sa_handler == SIG_IGN) sigaction(SIGINT, &g_old_int, nullptr);
  if (g_old_term.sa_handler == SIG_IGN) sigaction(SIGTERM, &g_old_term, nullptr);
}

InterruptGuard::~InterruptGuard() {
  const std::lock_guard lock(g_guards_mutex);
  if (--g_guards > 0) return;
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
}

int interrupted() { return g_signal; }

void endBySignal(int signal) {
  struct sigaction sa {};
  sa.sa_handler = SIG_DFL;
  sigemptyset(&sa.sa_mask);
  sigaction(signal, &sa, nullptr);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, signal);
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  ::kill(::getpid(), signal);  // the whole process, not only this thread
  std::_Exit(128 + signal);    // not reached
}

}  // namespace creaturelab::runner
