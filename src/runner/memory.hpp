#pragma once
// How much memory this process may use, read before a run so that a sweep or a grid too large for
// the machine is refused before it starts instead of being killed by the kernel (OOM) half-way.
#include <string>

namespace creaturelab::runner {

struct MemoryBudget {
  double bytes = 0;    // the smallest of the limits below that is set
  std::string source;  // which one, for the message: "MemAvailable", "ulimit -v", "cgroup memory limit"
};

// The smallest of: MemAvailable (/proc/meminfo), the address-space limit (ulimit -v) and the
// cgroup's memory limit (v2 memory.max or v1 memory.limit_in_bytes). {0, ""} if none can be read.
MemoryBudget memoryBudget();

}  // namespace creaturelab::runner
