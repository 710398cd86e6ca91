#pragma once
// FNV-1a, the 64-bit Fowler-Noll-Vo hash: keys for what the flesh files on disk (volumes, states).
#include <cstddef>
#include <cstdint>

namespace lacrima::flesh {

class Fnv1a {
 public:
  Fnv1a() = default;
  explicit Fnv1a(uint64_t start) : hash_(start) {}

  void add(const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
  }
  template <typename T>
  void add(const T& value) {
    add(&value, sizeof value);
  }
  uint64_t value() const { return hash_; }

 private:
  uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace lacrima::flesh
