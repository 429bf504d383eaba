#include "debug/checkpoints.h"

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <ctime>

#include "core/fd_io.h"
#include "core/stopwatch.h"

namespace essaim {

namespace {
constexpr double kIntervalSeconds = 0.2;
constexpr size_t kMaxCheckpoints = 48;  // thinned past this: every other one ended

}  // namespace

bool Checkpoints::Due() const { return last_cpu_ < 0 || ProcessCpuSeconds() - last_cpu_ >= kIntervalSeconds; }

bool Checkpoints::Take(long long tick, std::string* order) {
  last_cpu_ = ProcessCpuSeconds();
  int p[2];
  if (pipe(p) != 0) return false;
  // What this process's files hold now, for the copy that will go on from here.
  std::vector<FileOffset> files;
  if (DIR* dir = opendir("/proc/self/fd")) {
    while (dirent* e = readdir(dir)) {
      const int fd = std::atoi(e->d_name);
      struct stat st {};
      if (e->d_name[0] == '.' || fd == dirfd(dir) || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) continue;
      const int mode = fcntl(fd, F_GETFL) & O_ACCMODE;
      files.push_back({fd, lseek(fd, 0, SEEK_CUR), mode != O_RDONLY});
    }
    closedir(dir);
  }
  const pid_t pid = fork();
  if (pid < 0) {
    close(p[0]);
    close(p[1]);
    return false;
  }
  if (pid > 0) {
    close(p[0]);
    entries_.push_back({tick, pid, p[1]});
    Thin();
    return false;
  }
  // The checkpoint: frozen here until woken.
  files_ = files;
  Entry self{tick, getpid(), p[1]};
  const int wait_fd = p[0];
  while (true) {
    pollfd w{wait_fd, POLLIN, 0};
    const int ready = poll(&w, 1, 1000);
    if (ready == 0) {
      if (kill(front_, 0) != 0) _exit(0);  // the session is gone
      continue;
    }
    uint32_t size = 0;
    if (ready < 0 || !ReadAll(wait_fd, &size, sizeof size)) _exit(0);
    order->assign(size, '\0');
    if (!ReadAll(wait_fd, order->data(), size)) _exit(0);
    const pid_t copy = fork();
    if (copy != 0) continue;  // stays reusable (SIGCHLD ignored: no zombies)
    close(wait_fd);
    entries_.push_back(self);
    RestoreFiles();
    last_cpu_ = ProcessCpuSeconds();
    return true;
  }
}

void Checkpoints::RestoreFiles() const {
  for (const FileOffset& f : files_) {
    if (f.offset < 0) continue;
    if (f.writable && ftruncate(f.fd, f.offset) != 0) continue;
    lseek(f.fd, f.offset, SEEK_SET);
  }
}

int Checkpoints::NewestAtOrBefore(long long tick) const {
  for (size_t i = entries_.size(); i-- > 0;)
    if (entries_[i].tick <= tick) return static_cast<int>(i);
  return -1;
}

void Checkpoints::Wake(int index, const std::string& order) {
  while (entries_.size() > static_cast<size_t>(index) + 1) {
    kill(entries_.back().pid, SIGKILL);
    close(entries_.back().fd);
    entries_.pop_back();
  }
  const Entry& e = entries_[static_cast<size_t>(index)];
  const auto size = static_cast<uint32_t>(order.size());
  WriteAll(e.fd, &size, sizeof size);
  WriteAll(e.fd, order.data(), order.size());
}

void Checkpoints::EndAll() {
  for (const Entry& e : entries_) {
    kill(e.pid, SIGKILL);
    close(e.fd);
  }
  entries_.clear();
}

// Past kMaxCheckpoints, every other one after the first goes: they thin out into the past.
void Checkpoints::Thin() {
  if (entries_.size() <= kMaxCheckpoints) return;
  std::vector<Entry> kept;
  for (size_t i = 0; i < entries_.size(); ++i) {
    if (i == 0 || i + 1 == entries_.size() || i % 2 == 0) {
      kept.push_back(entries_[i]);
      continue;
    }
    kill(entries_[i].pid, SIGKILL);
    close(entries_[i].fd);
  }
  entries_ = kept;
}

}  // namespace essaim
