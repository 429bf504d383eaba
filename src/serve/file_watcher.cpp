#include "serve/file_watcher.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

namespace essaim {

namespace {
constexpr uint32_t kEvents = IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE | IN_DELETE | IN_ATTRIB;

std::string Absolute(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  return (ec ? std::filesystem::path(path) : p).lexically_normal().string();
}

long long NowMs() {
  using namespace std::chrono;
  return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
}
}  // namespace

FileWatcher::FileWatcher() {
  fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd_ < 0) error_ = std::string("cannot watch files (inotify): ") + std::strerror(errno);
}

FileWatcher::~FileWatcher() {
  if (fd_ >= 0) ::close(fd_);
}

void FileWatcher::Watch(const std::vector<std::string>& files) {
  if (fd_ < 0) return;
  files_.clear();
  std::set<std::string> folders;
  for (const std::string& f : files) {
    std::string abs = Absolute(f);
    files_.insert(abs);
    folders.insert(std::filesystem::path(abs).parent_path().string());
  }
  for (auto it = folders_.begin(); it != folders_.end();) {
    if (folders.count(it->second)) {
      ++it;
      continue;
    }
    inotify_rm_watch(fd_, it->first);
    it = folders_.erase(it);
  }
  error_.clear();
  for (const std::string& folder : folders) {
    int wd = inotify_add_watch(fd_, folder.c_str(), kEvents);
    if (wd < 0)
      error_ += (error_.empty() ? "" : "; ") + ("cannot watch " + folder + ": " + std::strerror(errno));
    else
      folders_[wd] = folder;
  }
}

void FileWatcher::Drain(std::set<std::string>* changed) {
  alignas(inotify_event) char buffer[16384];
  while (true) {
    ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n <= 0) return;  // EAGAIN: nothing more waiting
    for (char* p = buffer; p < buffer + n;) {
      const auto* e = reinterpret_cast<const inotify_event*>(p);
      p += sizeof(inotify_event) + e->len;
      auto folder = folders_.find(e->wd);
      if (folder == folders_.end() || e->len == 0) continue;
      std::string path = folder->second + "/" + e->name;
      if (files_.count(path)) changed->insert(path);
    }
  }
}

bool FileWatcher::WaitForChange(int timeout_ms, std::vector<std::string>* changed, int settle_ms) {
  if (fd_ < 0) return false;
  std::set<std::string> seen;
  long long deadline = NowMs() + timeout_ms;
  while (true) {
    long long left = seen.empty() ? deadline - NowMs() : settle_ms;
    if (left < 0) left = 0;
    pollfd pfd{fd_, POLLIN, 0};
    int ready = ::poll(&pfd, 1, static_cast<int>(left));
    if (ready < 0 && errno != EINTR) return false;
    if (ready < 0) break;  // a signal (Ctrl-C): the caller decides what it means
    if (ready == 0 && (!seen.empty() || NowMs() >= deadline)) break;
    Drain(&seen);
  }
  if (seen.empty()) return false;
  if (changed) changed->assign(seen.begin(), seen.end());
  return true;
}

}  // namespace essaim
