#include "output/recording_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/paths.h"

namespace essaim {

// ---- whole file -------------------------------------------------------------------

bool Recording::Read(const std::string& path, Recording* out, std::string* error) {
  std::string bytes;
  if (!ReadFile(path, &bytes)) {
    *error = "cannot read " + path;
    return false;
  }
  if (!Parse(std::move(bytes), out, error)) {
    *error = path + ": " + *error;
    return false;
  }
  return true;
}

bool Recording::Parse(std::string bytes, Recording* out, std::string* error) {
  Recording r;
  r.bytes_ = std::move(bytes);
  RecordingHeader h;
  if (!ParseRecordingHeader(reinterpret_cast<const uint8_t*>(r.bytes_.data()), r.bytes_.size(), &h, error))
    return false;
  r.scene_ = std::move(h.scene);
  r.header_bytes_ = h.header_bytes;
  r.frame_bytes_ = h.frame_bytes;
  r.frame_count_ = (r.bytes_.size() - r.header_bytes_) / r.frame_bytes_;
  if (r.frame_count_ == 0) {
    *error = "recording has no frame";
    return false;
  }
  *out = std::move(r);
  return true;
}

size_t Recording::FrameAtOrBefore(uint64_t tick) const {
  return LastFrameAtOrBefore(frame_count_, tick, [this](size_t k) { return Tick(k); });
}

// ---- one frame at a time ----------------------------------------------------------

RecordingStream::~RecordingStream() {
  if (fd_ >= 0) ::close(fd_);
}

namespace {
/// Reads exactly `n` bytes at `offset` (short only at the end of the file).
bool ReadAt(int fd, uint8_t* out, size_t n, uint64_t offset) {
  size_t got = 0;
  while (got < n) {
    ssize_t r = ::pread(fd, out + got, n - got, static_cast<off_t>(offset + got));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    got += static_cast<size_t>(r);
  }
  return true;
}
}  // namespace

bool RecordingStream::Open(const std::string& path, std::string* error) {
  path_ = path;
  if (fd_ >= 0) ::close(fd_);
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st {};
  if (fd_ < 0 || ::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    *error = "cannot read " + path + (fd_ < 0 ? std::string(": ") + std::strerror(errno) : "");
    return false;
  }
  const uint64_t size = static_cast<uint64_t>(st.st_size);
  uint8_t preamble[kRecordingPreambleBytes] = {};
  const size_t header_bytes = ReadAt(fd_, preamble, sizeof preamble, 0) ? HeaderBytesOf(preamble, sizeof preamble) : 0;
  // A damaged size is never allocated beyond the file: the parser then finds it corrupt.
  std::vector<uint8_t> head(header_bytes > 0 && header_bytes <= size ? header_bytes : sizeof preamble);
  const bool read = ReadAt(fd_, head.data(), head.size(), 0);
  if (!read) *error = "not an essaim recording";  // shorter than a preamble
  if (!read || !ParseRecordingHeader(head.data(), head.size(), &header_, error)) {
    *error = path + ": " + *error;
    return false;
  }
  frame_count_ = static_cast<size_t>((size - header_.header_bytes) / header_.frame_bytes);
  if (frame_count_ == 0) {
    *error = path + ": recording has no frame";
    return false;
  }
  return true;
}

bool RecordingStream::ReadFrame(size_t frame, std::vector<uint8_t>* bytes, std::string* error) const {
  bytes->resize(header_.frame_bytes);
  if (frame < frame_count_ &&
      ReadAt(fd_, bytes->data(), bytes->size(), header_.header_bytes + uint64_t{frame} * header_.frame_bytes))
    return true;
  *error = "cannot read frame " + std::to_string(frame) + " of " + path_;
  return false;
}

uint64_t RecordingStream::TickOf(size_t frame) const {
  uint8_t b[kFrameTickBytes];
  if (frame >= frame_count_ || !ReadAt(fd_, b, sizeof b, header_.header_bytes + uint64_t{frame} * header_.frame_bytes))
    return UINT64_MAX;
  return Get32(b);
}

size_t RecordingStream::FrameAtOrBefore(uint64_t tick) const {
  return LastFrameAtOrBefore(frame_count_, tick, [this](size_t k) { return TickOf(k); });
}

}  // namespace essaim
