#pragma once
// Progress on stderr.
// Progress: of one sweep, a line per finished point, with points done/total, elapsed and ETA; on a
// terminal a status line is redrawn in place, otherwise only plain lines are written. Without
// point lines (a run of a list) only the terminal's status line is drawn, after a label.
// ListProgress: of a list of experiments (`creaturelab reproduce`), one line per experiment.
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

namespace creaturelab::runner {

class Progress {
 public:
  Progress(int total, int already_done, std::FILE* out = stderr, bool point_lines = true, std::string label = "");
  // Thread-safe: called by workers as points finish.
  void pointFinished(const std::string& description, bool ok, double seconds);
  void finish();

 private:
  double elapsed() const;
  std::string status() const;

  std::FILE* out_;
  bool tty_, point_lines_;
  std::string label_;  // before the status line
  int total_, done_, ran_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

// "12.3 s" under a minute, "4 min" (rounded) from then on.
std::string roughDuration(double seconds);

// The line printed as each experiment of a list finishes (k counts finished entries; entries may
// run side by side and finish out of order):
//   [k/N] name: P points, wall 12.3 s, ETA of the whole list 4 min (from the list's minutes)
// The ETA is the listed time (an entry's `minutes`, measured) of the entries left, scaled by the
// pace so far (time since the list started / listed time of the entries done, once a minute of
// listed time is done); when some entry lists no time, the time so far per entry done times the
// entries left.
class ListProgress {
 public:
  // listed_s: each entry's listed time in seconds, 0 where it lists none.
  explicit ListProgress(std::vector<double> listed_s, std::FILE* out = stderr);
  // "[k/N] name", k counted from 1, for the entry about to run (alone) or finishing.
  std::string label(const std::string& name) const;
  // Prints the entry's line and moves to the next entry. `problems` ("" or e.g. "2 points FAILED")
  // goes after the point count.
  void experimentFinished(const std::string& name, int points, const std::string& problems, double wall_s);
  // The remaining time of the list after the entries done, and how it was estimated.
  double etaSeconds() const;
  bool etaFromListedTimes() const;

 private:
  std::vector<double> listed_s_;
  std::FILE* out_;
  bool tty_;
  int done_ = 0;
  std::chrono::steady_clock::time_point start_;
  double elapsed_s_ = 0;  // since the list started, when the last entry finished
};

}  // namespace creaturelab::runner
