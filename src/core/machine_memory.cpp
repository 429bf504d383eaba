#include "core/machine_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace essaim {

namespace {
uint64_t PhysicalMemory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<uint64_t>(pages) * static_cast<uint64_t>(page) : 0;
}

uint64_t AddressSpaceLimit() {
  rlimit r{};
  if (getrlimit(RLIMIT_AS, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return 0;
  return static_cast<uint64_t>(r.rlim_cur);
}

// cgroup v2 (containers, SLURM jobs): "max" or a byte count.
uint64_t CgroupLimit() {
  std::ifstream f("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(f >> text) || text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return 0;
  try {
    return std::stoull(text);
  } catch (...) {
    return 0;  // out of range: no limit worth the name
  }
}
}  // namespace

uint64_t UsableMemoryBytes() {
  uint64_t least = 0;
  for (uint64_t v : {PhysicalMemory(), AddressSpaceLimit(), CgroupLimit()})
    if (v > 0) least = least == 0 ? v : std::min(least, v);
  return least;
}

}  // namespace essaim
