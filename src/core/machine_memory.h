// How much memory this process may use: what an experiment's size is checked against
// before anything is allocated (docs/safety.md).
#pragma once
#include <cstdint>

namespace essaim {

/// The least of the machine's physical memory, the address-space limit (RLIMIT_AS) and the
/// cgroup's memory.max, in bytes; 0 when none of them could be read.
uint64_t UsableMemoryBytes();

}  // namespace essaim
