#include "runner/progress.hpp"

#include <unistd.h>

namespace creaturelab::runner {

namespace {
std::string seconds(double s) {
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1f s", s);
  else std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  return buf;
}
}  // namespace

Progress::Progress(int total, int already_done, std::FILE* out)
    : out_(out), tty_(isatty(fileno(out)) != 0), total_(total), done_(already_done),
      start_(std::chrono::steady_clock::now()) {}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string Progress::status() const {
  const double e = elapsed();
  std::string s = std::to_string(done_) + "/" + std::to_string(total_) + " points, elapsed " + seconds(e);
  if (ran_ > 0 && done_ < total_) s += ", ETA " + seconds(e / ran_ * (total_ - done_));
  return s;
}

void Progress::pointFinished(const std::string& description, bool ok, double secs) {
  std::lock_guard lock(mutex_);
  ++done_;
  ++ran_;
  if (tty_) std::fputs("\r\033[K", out_);
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

}  // namespace creaturelab::runner
