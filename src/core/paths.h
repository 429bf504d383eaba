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
std::string CanonicalPath(const std::string& path);
/// The whole file; false when it is missing, unreadable or not a regular file.
bool ReadFile(const std::string& path, std::string* out);

}  // namespace essaim
