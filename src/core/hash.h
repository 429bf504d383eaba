// FNV-1a 64-bit: identifies an experiment file's content in summaries and state hashes
// in determinism tests. Not cryptographic; it only has to notice change.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace essaim {

class Fnv1a64 {
 public:
  void Add(const void* data, size_t n) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ull;
  }
  template <class T>
  void AddValue(const T& v) {
    Add(&v, sizeof v);
  }
  uint64_t Value() const { return h_; }
  std::string Hex() const;

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace essaim
