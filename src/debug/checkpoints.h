// Going back in time by simulating again: a Lua state cannot be copied, so the whole
// simulation process is (gdb's `checkpoint`): at tick boundaries, every ~0.2 s of simulation
// CPU time, the live process forks a frozen copy that waits on a pipe. Waking one makes it
// fork again (so it stays reusable); that copy becomes the live simulation and simulates
// silently to the target, and the process that woke it exits.
//
// A copy shares the open files' offsets with the process it came from, so each regular
// file's offset is noted at the checkpoint and restored (the file cut there) when a copy
// wakes: the outputs are written again exactly as the first time.
#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

namespace essaim {

class Checkpoints {
 public:
  /// `front`: the process that owns the client; a checkpoint whose front is gone exits.
  explicit Checkpoints(pid_t front) : front_(front) {}

  /// Whether a checkpoint is due at this boundary (the first one always, then every
  /// kIntervalSeconds of CPU time).
  bool Due() const;
  /// Forks a checkpoint at boundary `tick` (world.tick). In this process returns false.
  /// In the checkpoint's woken copy returns true with the order it was woken with: that copy
  /// is now the live simulation, its files' offsets restored.
  bool Take(long long tick, std::string* order);
  /// The newest checkpoint taken at boundary tick <= `tick`; -1 when none.
  int NewestAtOrBefore(long long tick) const;
  long long TickOf(int index) const { return entries_[static_cast<size_t>(index)].tick; }
  /// Ends the checkpoints after `index`, then wakes checkpoint `index` with `order`. The
  /// caller then exits (_exit): the woken copy goes on in its place.
  void Wake(int index, const std::string& order);
  /// Ends every checkpoint (the session ends).
  void EndAll();
  size_t Count() const { return entries_.size(); }

 private:
  struct Entry {
    long long tick = 0;
    pid_t pid = 0;
    int fd = -1;  // the write end of the pipe it waits on
  };
  struct FileOffset {
    int fd;
    off_t offset;
    bool writable;
  };
  [[noreturn]] void Wait(const Entry& self);
  void RestoreFiles() const;
  void Thin();

  pid_t front_;
  std::vector<Entry> entries_;
  std::vector<FileOffset> files_;  // noted at this process's own checkpoint
  double last_cpu_ = -1;
};

}  // namespace essaim
