// Whole reads and writes on a file descriptor (pipes and sockets between essaim's own
// processes), retried when a signal interrupts them.
#pragma once
#include <cstddef>

namespace essaim {

/// Writes all `size` bytes; false when the other end is gone (or another error).
bool WriteAll(int fd, const void* data, size_t size);
/// Reads exactly `size` bytes; false at the end of the stream or on an error.
bool ReadAll(int fd, void* data, size_t size);

}  // namespace essaim
