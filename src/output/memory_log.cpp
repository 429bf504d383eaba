#include "output/memory_log.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace essaim {

uint64_t ResidentBytes() {
  // statm's second field: resident pages. One small read, no allocation.
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long long size = 0, resident = 0;
  int n = std::fscanf(f, "%llu %llu", &size, &resident);
  std::fclose(f);
  return n == 2 ? resident * static_cast<uint64_t>(sysconf(_SC_PAGESIZE)) : 0;
}

MemoryLog::~MemoryLog() {
  if (file_) std::fclose(file_);
}

bool MemoryLog::Open(const std::string& path, uint64_t every, std::string* error) {
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) {
    *error = "cannot write " + path + ": " + std::strerror(errno);
    return false;
  }
  path_ = path;
  every_ = every;
  write_errno_ = 0;
  errno = 0;
  if (std::fputs("tick,rss_bytes,lua_bytes,lua_peak_bytes,loop_lua_bytes\n", file_) < 0 || std::fflush(file_) != 0)
    write_errno_ = errno ? errno : EIO;
  return true;
}

void MemoryLog::Sample(const World& world) {
  if (!file_ || every_ == 0 || world.tick % every_ != 0) return;
  uint64_t lua = 0, peak = 0;
  for (const auto& c : world.controllers) {
    lua += c->Memory().bytes;
    peak += c->Memory().peak;
  }
  std::fprintf(file_, "%llu,%llu,%llu,%llu,%llu\n", static_cast<unsigned long long>(world.tick),
               static_cast<unsigned long long>(ResidentBytes()), static_cast<unsigned long long>(lua),
               static_cast<unsigned long long>(peak),
               static_cast<unsigned long long>(world.loop_functions.Memory().bytes));
  if (std::fflush(file_) != 0 && write_errno_ == 0) write_errno_ = errno ? errno : EIO;
}

bool MemoryLog::Close(std::string* error) {
  if (!file_) return true;
  if (std::fclose(file_) != 0 && write_errno_ == 0) write_errno_ = errno ? errno : EIO;
  file_ = nullptr;
  if (write_errno_ == 0) return true;
  *error = "cannot write " + path_ + ": " + std::strerror(write_errno_);
  return false;
}

}  // namespace essaim
