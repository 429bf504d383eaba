// Files written whole or not at all: write a temporary sibling, flush, rename. A crash
// or a failed run never leaves a half-written output behind.
#pragma once
#include <string>

namespace essaim {

bool WriteFileAtomic(const std::string& path, const std::string& content, std::string* error);
/// mkdir -p
bool MakeDirs(const std::string& path, std::string* error);

}  // namespace essaim
