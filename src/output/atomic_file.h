// Files written whole or not at all: write a temporary sibling, flush, rename. A crash
// or a failed run never leaves a half-written output behind.
#pragma once
#include <string>

namespace essaim {

/// Whether `path` may be (re)placed by WriteFileAtomic: absent, or a regular file. A FIFO,
/// a device (even /dev/full as root), a folder or a socket is refused: renaming over it
/// would replace it with a regular file. A symlink is written through: its final target
/// must itself be a regular file (a dangling link is refused), and that file is replaced
/// while the link stays. The folder must exist. The error names the path and the reason.
bool CheckOutputFile(const std::string& path, std::string* error);
/// The file a write to `path` lands in: `path` itself, or a symlink's final target (for a
/// writer other than WriteFileAtomic, such as a program writing it, to rename onto).
bool ResolveOutput(const std::string& path, std::string* target, std::string* error);
/// Writes `content` to `path` atomically (after CheckOutputFile); false with an error
/// naming the path and the system's reason (e.g. "No space left on device").
bool WriteFileAtomic(const std::string& path, const std::string& content, std::string* error);
/// mkdir -p
bool MakeDirs(const std::string& path, std::string* error);

}  // namespace essaim
