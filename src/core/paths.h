// Paths and whole-file reads through std::filesystem (relative paths, "..", symlinks and
// non-ASCII names handled by the standard library, not by hand).
#pragma once
#include <string>

namespace essaim {

/// Folder part of a path ("" for a bare name, "/" for a file at the root).
std::string DirName(const std::string& path);
/// `rel` inside `dir`; an absolute `rel`, or an empty `dir`, gives `rel` unchanged.
std::string JoinPath(const std::string& dir, const std::string& rel);
/// A regular file (after following symlinks); false for folders and missing paths.
bool FileExists(const std::string& path);
/// Absolute, with symlinks, "." and ".." resolved (as far as the path exists).
std::string WeaklyCanonicalPath(const std::string& path);
/// Anything at `path` (after following symlinks), a folder or a device included.
bool PathExists(const std::string& path);
/// What `path` is when something is there but not a regular file (after symlinks):
/// "a folder", "a FIFO", "a character device", "a block device", "a socket"; else "".
std::string SpecialFileKind(const std::string& path);
/// `path` with every symlink and ".." resolved (realpath); "" when it does not exist.
std::string CanonicalPath(const std::string& path);
/// Whether canonical `path` lies in canonical folder `root` or below it.
bool IsInsideFolder(const std::string& path, const std::string& root);
/// The whole file; false when it is missing, unreadable or not a regular file.
bool ReadFile(const std::string& path, std::string* out);

}  // namespace essaim
