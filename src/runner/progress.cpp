#include "runner/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <numeric>

namespace creaturelab::runner {

namespace {
std::string seconds(double s) {
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1f s", s);
  else std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  return buf;
}

// A listed time counts for the pace once this much of it is done: shorter entries are mostly
// start-up, whose pace says little about the long ones.
constexpr double kPaceAfterListedS = 60;
}  // namespace

Progress::Progress(int total, int already_done, std::FILE* out, bool point_lines, std::string label)
    : out_(out), tty_(isatty(fileno(out)) != 0), point_lines_(point_lines), label_(std::move(label)), total_(total),
      done_(already_done), start_(std::chrono::steady_clock::now()) {}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string Progress::status() const {
  const double e = elapsed();
  std::string s = std::to_string(done_) + "/" + std::to_string(total_) + " points, elapsed " + seconds(e);
  if (ran_ > 0 && done_ < total_) s += ", ETA " + seconds(e / ran_ * (total_ - done_));
  return label_.empty() ? s : label_ + ": " + s;
}

void Progress::pointFinished(const std::string& description, bool ok, double secs) {
  std::lock_guard lock(mutex_);
  ++done_;
  ++ran_;
  if (!point_lines_ && !tty_) return;
  if (tty_) std::fputs("\r\033[K", out_);
  if (point_lines_)
    std::fprintf(out_, "[%d/%d] %s %s in %s | %s\n", done_, total_, description.c_str(), ok ? "done" : "FAILED",
                 seconds(secs).c_str(), status().c_str());
  if (tty_ && done_ < total_) std::fputs(status().c_str(), out_);
  std::fflush(out_);
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  if (tty_) std::fputs("\r\033[K", out_);
  std::fflush(out_);
}

std::string roughDuration(double s) {
  char buf[32];
  if (s < 59.95) std::snprintf(buf, sizeof buf, "%.1f s", s);
  else std::snprintf(buf, sizeof buf, "%.0f min", std::round(s / 60));
  return buf;
}

ListProgress::ListProgress(std::vector<double> listed_s, std::FILE* out)
    : listed_s_(std::move(listed_s)), out_(out), tty_(isatty(fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()) {}

std::string ListProgress::label(const std::string& name) const {
  return "[" + std::to_string(done_ + 1) + "/" + std::to_string(listed_s_.size()) + "] " + name;
}

bool ListProgress::etaFromListedTimes() const {
  for (double s : listed_s_)
    if (!(s > 0)) return false;
  return true;
}

double ListProgress::etaSeconds() const {
  const int total = int(listed_s_.size());
  if (done_ >= total) return 0;
  if (etaFromListedTimes()) {
    const double listed_done = std::accumulate(listed_s_.begin(), listed_s_.begin() + done_, 0.0);
    const double listed_left = std::accumulate(listed_s_.begin() + done_, listed_s_.end(), 0.0);
    const double pace = listed_done >= kPaceAfterListedS ? elapsed_s_ / listed_done : 1.0;
    return listed_left * pace;
  }
  if (done_ == 0) return 0;
  return elapsed_s_ / done_ * (total - done_);
}

void ListProgress::experimentFinished(const std::string& name, int points, const std::string& problems,
                                      double wall_s) {
  const std::string head = label(name);
  ++done_;
  elapsed_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string eta;
  if (done_ < int(listed_s_.size()))
    eta = "ETA of the whole list " + roughDuration(etaSeconds()) +
          (etaFromListedTimes() ? " (from the list's minutes)" : " (from the elapsed fraction)");
  else
    eta = "the whole list took " + roughDuration(elapsed_s_);
  if (tty_) std::fputs("\r\033[K", out_);  // over a running entry's status line
  std::fprintf(out_, "%s: %d point%s%s, wall %s, %s\n", head.c_str(), points, points == 1 ? "" : "s",
               problems.empty() ? "" : (" (" + problems + ")").c_str(), roughDuration(wall_s).c_str(), eta.c_str());
  std::fflush(out_);
}

}  // namespace creaturelab::runner
