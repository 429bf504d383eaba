// Per-lua_State free lists for small blocks. Lua's tables, strings and closures
// are mostly under 256 bytes and die young (a range-and-bearing message is four blocks per
// tick); glibc's malloc/free took ~14% of a foraging run. Lua tells the allocator each
// block's size on free and realloc, so a block needs no header: its size class comes from
// the size Lua passes. One state is used by one thread at a time, so there are no locks.
#pragma once
#include <cstddef>
#include <vector>

namespace essaim {

class SmallBlockPool {
 public:
  static constexpr size_t kGranule = 16;    // bytes: every class is a multiple (malloc's alignment)
  static constexpr size_t kMaxSmall = 256;  // larger blocks go to malloc
  static bool IsSmall(size_t size) { return size > 0 && size <= kMaxSmall; }

  SmallBlockPool() = default;
  ~SmallBlockPool() { Release(); }
  SmallBlockPool(const SmallBlockPool&) = delete;
  SmallBlockPool& operator=(const SmallBlockPool&) = delete;

  /// A block of at least `size` (≤ kMaxSmall) bytes; null if memory is exhausted.
  void* Allocate(size_t size) {
    if (void* p = TakeFree(size)) return p;
    return Carve(Class(size));
  }
  /// A block from the free list of `size`'s class, or null if that list is empty (no call:
  /// the allocator's fast path).
  void* TakeFree(size_t size) {
    void*& head = free_[Class(size)];
    void* p = head;
    if (p) {
      head = *static_cast<void**>(p);
      // The next pop reads that block's first word: a state's blocks are cold when its
      // turn comes (the other robots' states ran since), and each pop would wait for the
      // miss before Lua could go on. Prefetching a null head does nothing.
      __builtin_prefetch(head, 1);
    }
    return p;
  }
  /// Returns a block obtained with Allocate(`size`) (the same size class).
  void Free(void* p, size_t size) {
    void*& head = free_[Class(size)];
    *static_cast<void**>(p) = head;
    head = p;
  }
  static bool SameClass(size_t a, size_t b) { return Class(a) == Class(b); }
  /// Gives every chunk back to malloc (after lua_close: no block is in use any more).
  void Release();

 private:
  static size_t Class(size_t size) { return (size - 1) / kGranule; }
  void* Carve(size_t cls);

  static constexpr size_t kClasses = kMaxSmall / kGranule;
  void* free_[kClasses] = {};
  char* cursor_ = nullptr;  // unused tail of the newest chunk
  char* end_ = nullptr;
  size_t next_chunk_ = 16 * 1024;  // doubles up to 64 KiB: small states stay small
  std::vector<void*> chunks_;
};

}  // namespace essaim
