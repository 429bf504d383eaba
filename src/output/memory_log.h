// `essaim run --memory-log N`: every N ticks one line of memory.csv (tick, resident set of
// the process, bytes held by the controllers' Lua states, their peak, and the loop functions'
// state), so that long runs (the soak in bench/) can
// show that memory stays flat. Streamed and flushed per line: a killed run still shows how
// it grew.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

#include "sim/world.h"

namespace essaim {

constexpr const char* kMemoryLogFile = "memory.csv";

class MemoryLog {
 public:
  MemoryLog() = default;
  MemoryLog(const MemoryLog&) = delete;
  MemoryLog& operator=(const MemoryLog&) = delete;
  ~MemoryLog();
  bool Open(const std::string& path, uint64_t every, std::string* error);
  /// Appends a line when the world's tick is a multiple of `every` (no heap allocation).
  void Sample(const World& world);
  bool IsOpen() const { return file_ != nullptr; }
  /// Closes the file; false, with the first write failure's reason (a full disk), when a
  /// line could not be written.
  bool Close(std::string* error);

 private:
  FILE* file_ = nullptr;
  std::string path_;
  uint64_t every_ = 0;
  int write_errno_ = 0;  // the first failed write's errno; 0 while all went through
};

/// Resident set size of this process in bytes (0 when /proc is not there).
uint64_t ResidentBytes();

}  // namespace essaim
