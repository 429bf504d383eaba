#include "argos/lua_linkage.h"

#include <dlfcn.h>
#include <elf.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <lua.hpp>

namespace essaim {

namespace {
bool IsLuaCall(const char* name) {
  return !std::strncmp(name, "lua_", 4) || !std::strncmp(name, "luaL_", 5) || !std::strncmp(name, "luaopen_", 8);
}

// A string of the string table `strtab` at `offset`, or "" past its end.
std::string StringAt(const std::string& file, const Elf64_Shdr& strtab, uint64_t offset) {
  if (offset >= strtab.sh_size || strtab.sh_offset + offset >= file.size()) return "";
  return std::string(file.c_str() + strtab.sh_offset + offset);
}

const Elf64_Shdr* Section(const std::string& file, const Elf64_Ehdr& header, size_t k) {
  const size_t at = header.e_shoff + k * sizeof(Elf64_Shdr);
  if (k >= header.e_shnum || at + sizeof(Elf64_Shdr) > file.size()) return nullptr;
  return reinterpret_cast<const Elf64_Shdr*>(file.data() + at);
}

// Entries of section `s` (dynamic entries or symbols) that lie inside the file.
template <typename Entry>
size_t EntryCount(const std::string& file, const Elf64_Shdr& s) {
  if (s.sh_offset > file.size()) return 0;
  return std::min<uint64_t>(s.sh_size, file.size() - s.sh_offset) / sizeof(Entry);
}

void ReadSection(const std::string& file, const Elf64_Ehdr& header, const Elf64_Shdr& s, LuaLinkage* out) {
  const Elf64_Shdr* strtab = Section(file, header, s.sh_link);
  if (!strtab) return;
  if (s.sh_type == SHT_DYNAMIC) {
    const auto* dyn = reinterpret_cast<const Elf64_Dyn*>(file.data() + s.sh_offset);
    for (size_t i = 0; i < EntryCount<Elf64_Dyn>(file, s); ++i)
      if (dyn[i].d_tag == DT_NEEDED) out->needed.push_back(StringAt(file, *strtab, dyn[i].d_un.d_val));
  } else if (s.sh_type == SHT_DYNSYM) {
    const auto* sym = reinterpret_cast<const Elf64_Sym*>(file.data() + s.sh_offset);
    for (size_t i = 0; i < EntryCount<Elf64_Sym>(file, s); ++i) {
      if (sym[i].st_shndx != SHN_UNDEF) continue;
      const std::string name = StringAt(file, *strtab, sym[i].st_name);
      if (IsLuaCall(name.c_str())) out->lua_calls.push_back(name);
    }
  }
}
}  // namespace

bool ReadLuaLinkage(const std::string& path, LuaLinkage* out, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Elf64_Ehdr header;
  if (file.size() < sizeof(header) || std::memcmp(file.data(), ELFMAG, SELFMAG) != 0 || file[EI_CLASS] != ELFCLASS64) {
    *error = path + ": not a 64-bit ELF shared library";
    return false;
  }
  std::memcpy(&header, file.data(), sizeof(header));
  for (size_t k = 0; k < header.e_shnum; ++k)
    if (const Elf64_Shdr* s = Section(file, header, k)) ReadSection(file, header, *s, out);
  return true;
}

namespace {
// The Lua 5.4 library this process runs, opened again to look its functions up.
void* ProcessLua() {
  static void* handle = [] {
    Dl_info info;
    if (!dladdr(reinterpret_cast<void*>(&lua_newstate), &info) || !info.dli_fname) return static_cast<void*>(nullptr);
    return dlopen(info.dli_fname, RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD);
  }();
  return handle;
}

bool IsOtherLua(const std::string& needed) {
  if (needed.rfind("libluajit", 0) == 0) return true;
  if (needed.rfind("liblua", 0) != 0) return false;
  return needed.find("5.4") == std::string::npos;
}
}  // namespace

std::string LuaMismatch(const std::string& library, const LuaLinkage& linkage) {
  if (linkage.lua_calls.empty()) return "";
  const std::string how =
      ": essaim's controllers run Lua 5.4; build the library with Lua 5.4's headers and library "
      "(docs/loop-functions.md, \"C++ loop functions\")";
  for (const std::string& needed : linkage.needed)
    if (IsOtherLua(needed))
      return library + " calls Lua (" + linkage.lua_calls.front() + ") and is linked against " + needed + how;
  void* lua = ProcessLua();
  for (const std::string& name : linkage.lua_calls)
    if (!lua || !dlsym(lua, name.c_str()))
      return library + " calls " + name + ", which Lua 5.4 does not have (built with another Lua's headers)" + how;
  return "";
}

}  // namespace essaim
