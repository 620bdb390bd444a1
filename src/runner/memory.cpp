#include "runner/memory.hpp"

#include <sys/resource.h>

#include <fstream>
#include <sstream>

namespace creaturelab::runner {
namespace {

void consider(MemoryBudget& budget, double bytes, const char* source) {
  if (bytes > 0 && (budget.bytes == 0 || bytes < budget.bytes)) budget = {bytes, source};
}

double memAvailableBytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    double kib = 0;
    if (s >> key >> kib && key == "MemAvailable:") return kib * 1024;
  }
  return 0;
}

// A cgroup limit file: a number of bytes, or "max" (v2) / a huge number (v1) when unlimited.
double cgroupLimitBytes(const char* path) {
  std::ifstream in(path);
  double bytes = 0;
  if (!(in >> bytes) || bytes >= 1e18) return 0;
  return bytes;
}

}  // namespace

MemoryBudget memoryBudget() {
  MemoryBudget budget;
  consider(budget, memAvailableBytes(), "MemAvailable in /proc/meminfo");
  struct rlimit as {};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    consider(budget, double(as.rlim_cur), "the address-space limit (ulimit -v)");
  consider(budget, cgroupLimitBytes("/sys/fs/cgroup/memory.max"), "the cgroup memory limit");
  consider(budget, cgroupLimitBytes("/sys/fs/cgroup/memory/memory.limit_in_bytes"), "the cgroup memory limit");
  return budget;
}

}  // namespace creaturelab::runner
