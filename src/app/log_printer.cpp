#include "app/log_printer.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>

#include "app/commands.h"
#include "core/paths.h"
#include "output/atomic_file.h"  // MakeDirs

namespace essaim {

namespace {
constexpr size_t kBlock = 64 * 1024;  // bytes a robot's lines wait in memory before a write

// A robot id as a file name: an id is any XML text ("../x", "a/b"), a file must stay in DIR.
// A changed id gets its index, so two ids never share a file.
std::string FileNameFor(const std::string& id, size_t index) {
  std::string name = id;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
  if (name.empty() || name[0] == '.') name = "_" + name;
  return name == id ? name : name + "~" + std::to_string(index);
}
}  // namespace

LogPrinter::LogPrinter(const Model& model, bool prefix, std::string dir) : prefix_(prefix), dir_(std::move(dir)) {
  for (const RobotDef& r : model.robots) robot_ids_.push_back(r.id);
  if (!dir_.empty()) {
    pending_.resize(robot_ids_.size() + 1);
    started_.resize(robot_ids_.size() + 1, false);
  }
}

std::string LogPrinter::PathOf(size_t slot) const {
  std::string name = slot == 0 ? "loop_functions" : FileNameFor(robot_ids_[slot - 1], slot - 1);
  return JoinPath(dir_, name + ".log");
}

bool LogPrinter::Prepare(std::string* error) {
  if (dir_.empty()) return true;
  if (!MakeDirs(dir_, error)) return false;
  // A FIFO would block the run in open(), a device would take the lines: refused up front.
  for (size_t slot = 0; slot < pending_.size(); ++slot) {
    const std::string kind = SpecialFileKind(PathOf(slot));
    if (!kind.empty()) {
      *error = PathOf(slot) + " is " + kind + "; essaim writes a regular file of that name there";
      return false;
    }
  }
  return true;
}

std::string LogPrinter::Prefix(const LogOrigin& from) const {
  const std::string who = from.robot_id ? from.robot_id : "loop";
  return "[t=" + std::to_string(from.tick) + " " + who + "] ";
}

size_t LogPrinter::SlotOf(const LogOrigin& from) {
  if (from.robot < 0) return 0;
  const size_t robot = static_cast<size_t>(from.robot);
  if (robot >= robot_ids_.size()) {
    robot_ids_.resize(robot + 1);
    robot_ids_[robot] = from.robot_id ? from.robot_id : "robot" + std::to_string(robot);
    pending_.resize(robot + 2);
    started_.resize(robot + 2, false);
  }
  return robot + 1;
}

void LogPrinter::Print(char stream, const std::string& line, const LogOrigin& from) {
  bool from_script = from.robot != kLogHost;
  if (!dir_.empty() && from_script) {
    const size_t slot = SlotOf(from);
    std::string& p = pending_[slot];
    if (prefix_) p += Prefix(from);
    p += line;
    p += '\n';
    std::string error;
    if (p.size() >= kBlock && !WriteOut(slot, &error)) {
      if (progress_) progress_->Clear();
      std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    }
    return;
  }
  if (progress_) progress_->Clear();
  std::FILE* out = stream == 'E' ? stderr : stdout;
  if (prefix_ && from_script) std::fputs(Prefix(from).c_str(), out);
  std::fprintf(out, "%s\n", line.c_str());
  if (progress_) std::fflush(out);  // before the progress line comes back
}

bool LogPrinter::WriteOut(size_t slot, std::string* error) {
  const std::string path = PathOf(slot);
  // The first write replaces an old file: a run's folder holds only its own logs. Opened
  // without blocking and checked: a FIFO made there during the run is refused, not waited on.
  const int fd =
      ::open(path.c_str(), O_WRONLY | O_CREAT | O_NONBLOCK | O_CLOEXEC | (started_[slot] ? O_APPEND : O_TRUNC), 0644);
  struct stat st;
  if (fd >= 0 && (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))) {
    ::close(fd);
    if (error) *error = "cannot write " + path + ": not a regular file";
    started_[slot] = true;
    pending_[slot].clear();
    return false;
  }
  std::FILE* f = fd >= 0 ? ::fdopen(fd, "ab") : nullptr;
  if (fd >= 0 && !f) ::close(fd);
  bool ok = f && std::fwrite(pending_[slot].data(), 1, pending_[slot].size(), f) == pending_[slot].size();
  if (f && std::fclose(f) != 0) ok = false;
  if (!ok && error) *error = "cannot write " + path + ": " + std::strerror(errno);
  started_[slot] = true;
  pending_[slot].clear();
  return ok;
}

bool LogPrinter::Flush(std::string* error) {
  bool ok = true;
  for (size_t slot = 0; slot < pending_.size(); ++slot)
    if (!pending_[slot].empty() && !WriteOut(slot, error)) ok = false;
  return ok;
}

}  // namespace essaim
