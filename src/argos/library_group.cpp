#include "argos/library_group.h"

#include <dlfcn.h>
#include <elf.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstring>
#include <map>
#include <mutex>

namespace essaim {

namespace {
// The group's file: the ELF header, three program headers (one PT_LOAD mapping the whole file,
// PT_DYNAMIC, PT_GNU_STACK so that glibc does not make the stack executable), the dynamic
// section, a symbol table holding the null symbol, a hash table with one empty bucket (symbol
// lookups walk the group too) and the string table of the paths.
constexpr size_t kHeaders = sizeof(Elf64_Ehdr) + 3 * sizeof(Elf64_Phdr);
constexpr size_t kFixedDynamic = 6;  // DT_HASH, DT_STRTAB, DT_SYMTAB, DT_STRSZ, DT_SYMENT, DT_NULL

template <typename T>
void Put(std::string* out, size_t at, const T& value) {
  std::memcpy(&(*out)[at], &value, sizeof(T));
}

// The header of the object this code was linked into: the machine and flags to copy.
const Elf64_Ehdr& OwnHeader() {
  Dl_info info{};
  dladdr(reinterpret_cast<void*>(&GroupObject), &info);
  return *static_cast<const Elf64_Ehdr*>(info.dli_fbase);
}

Elf64_Ehdr Header() {
  Elf64_Ehdr h{};
  std::memcpy(h.e_ident, ELFMAG, SELFMAG);
  h.e_ident[EI_CLASS] = ELFCLASS64;
  h.e_ident[EI_DATA] = OwnHeader().e_ident[EI_DATA];
  h.e_ident[EI_VERSION] = EV_CURRENT;
  h.e_ident[EI_OSABI] = ELFOSABI_NONE;
  h.e_type = ET_DYN;
  h.e_machine = OwnHeader().e_machine;
  h.e_version = EV_CURRENT;
  h.e_flags = OwnHeader().e_flags;
  h.e_phoff = sizeof(Elf64_Ehdr);
  h.e_ehsize = sizeof(Elf64_Ehdr);
  h.e_phentsize = sizeof(Elf64_Phdr);
  h.e_phnum = 3;
  return h;
}

Elf64_Phdr Segment(Elf64_Word type, Elf64_Off offset, Elf64_Xword size, Elf64_Xword align) {
  Elf64_Phdr p{};
  p.p_type = type;
  p.p_flags = PF_R | PF_W;  // writable: glibc relocates the dynamic section's addresses in place
  p.p_offset = p.p_vaddr = p.p_paddr = offset;
  p.p_filesz = p.p_memsz = size;
  p.p_align = align;
  return p;
}
}  // namespace

std::string GroupObject(const std::vector<std::string>& libraries) {
  std::string strings(1, '\0');
  std::vector<Elf64_Dyn> dynamic;
  for (const std::string& library : libraries) {
    dynamic.push_back({DT_NEEDED, {strings.size()}});
    strings += library + '\0';
  }
  const size_t dynamic_at = kHeaders, count = dynamic.size() + kFixedDynamic;
  const size_t symbols_at = dynamic_at + count * sizeof(Elf64_Dyn);
  const size_t hash_at = symbols_at + sizeof(Elf64_Sym), strings_at = hash_at + 4 * sizeof(Elf64_Word);
  for (const auto& entry : {std::pair<Elf64_Sxword, Elf64_Xword>{DT_HASH, hash_at},
                            {DT_STRTAB, strings_at},
                            {DT_SYMTAB, symbols_at},
                            {DT_STRSZ, strings.size()},
                            {DT_SYMENT, sizeof(Elf64_Sym)},
                            {DT_NULL, 0}})
    dynamic.push_back({entry.first, {entry.second}});

  std::string out(strings_at + strings.size(), '\0');
  Put(&out, 0, Header());
  Put(&out, sizeof(Elf64_Ehdr), Segment(PT_LOAD, 0, out.size(), 0x1000));
  Put(&out, sizeof(Elf64_Ehdr) + sizeof(Elf64_Phdr), Segment(PT_DYNAMIC, dynamic_at, count * sizeof(Elf64_Dyn), 8));
  Put(&out, sizeof(Elf64_Ehdr) + 2 * sizeof(Elf64_Phdr), Segment(PT_GNU_STACK, 0, 0, 16));
  for (size_t i = 0; i < dynamic.size(); ++i) Put(&out, dynamic_at + i * sizeof(Elf64_Dyn), dynamic[i]);
  const Elf64_Word hash[4] = {1, 1, 0, 0};  // one bucket, one chain, both the null symbol
  Put(&out, hash_at, hash);
  out.replace(strings_at, strings.size(), strings);
  return out;
}

namespace {
// A group is opened by the name /proc/self/fd/N of an in-memory file. glibc knows loaded
// objects by name: were N closed and reused by a later group, that dlopen would answer the
// earlier group. So each group's file stays open, and each set of libraries gets one group.
std::mutex groups_lock;
std::map<std::vector<std::string>, void*>& Groups() {
  static std::map<std::vector<std::string>, void*> groups;
  return groups;
}

int GroupFile(const std::string& bytes, std::string* error) {
  const int fd = memfd_create("essaim-loop-functions-group", MFD_CLOEXEC);
  if (fd < 0) return *error = std::string("memfd_create: ") + std::strerror(errno), -1;
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + written, bytes.size() - written);
    if (n <= 0) return *error = std::string("writing the group: ") + std::strerror(errno), close(fd), -1;
    written += static_cast<size_t>(n);
  }
  return fd;
}
}  // namespace

bool OpenLibraryGroup(const std::vector<std::string>& libraries, std::string* error) {
  std::lock_guard<std::mutex> lock(groups_lock);
  if (libraries.empty() || Groups().count(libraries)) return true;
  const int fd = GroupFile(GroupObject(libraries), error);
  if (fd < 0) return false;
  void* handle = dlopen(("/proc/self/fd/" + std::to_string(fd)).c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    *error = why ? why : "unknown error";
    close(fd);
    return false;
  }
  Groups()[libraries] = handle;
  return true;
}

}  // namespace essaim
