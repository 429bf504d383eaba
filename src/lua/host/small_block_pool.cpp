#include "lua/host/small_block_pool.h"

#include <cstdlib>

namespace essaim {

void* SmallBlockPool::Carve(size_t cls) {
  const size_t size = (cls + 1) * kGranule;
  if (static_cast<size_t>(end_ - cursor_) < size) {
    // The old chunk's tail (< 256 bytes) is abandoned: simpler than splitting it.
    void* chunk = std::malloc(next_chunk_);
    if (!chunk) return nullptr;
    chunks_.push_back(chunk);
    cursor_ = static_cast<char*>(chunk);
    end_ = cursor_ + next_chunk_;
    if (next_chunk_ < 64 * 1024) next_chunk_ *= 2;
  }
  void* p = cursor_;
  cursor_ += size;
  return p;
}

void SmallBlockPool::Release() {
  for (void* c : chunks_) std::free(c);
  chunks_.clear();
  for (void*& head : free_) head = nullptr;
  cursor_ = end_ = nullptr;
  next_chunk_ = 16 * 1024;
}

}  // namespace essaim
