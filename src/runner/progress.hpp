#pragma once
// Progress of a sweep on stderr: a line per finished point, with points done/total, elapsed and
// ETA. On a terminal a status line is redrawn in place; otherwise only plain lines are written.
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace creaturelab::runner {

class Progress {
 public:
  Progress(int total, int already_done, std::FILE* out = stderr);
  // Thread-safe: called by workers as points finish.
  void pointFinished(const std::string& description, bool ok, double seconds);
  void finish();

 private:
  double elapsed() const;
  std::string status() const;

  std::FILE* out_;
  bool tty_;
  int total_, done_, ran_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

}  // namespace creaturelab::runner
