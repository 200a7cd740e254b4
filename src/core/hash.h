#pragma once
// 64-bit FNV-1a: stable across runs and platforms, used for cache keys and scene fingerprints.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace hipr {

class Hasher {
 public:
  Hasher& add(const void* data, size_t size) {
    const auto* bytes = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < size; ++i) m_state = (m_state ^ bytes[i]) * 0x100000001b3ull;
    return *this;
  }
  Hasher& add(std::string_view text) {
    add(text.data(), text.size());
    // A terminator keeps ("ab","c") and ("a","bc") apart.
    const uint8_t separator = 0xff;
    return add(&separator, 1);
  }
  uint64_t value() const { return m_state; }
  std::string hex() const;

 private:
  uint64_t m_state = 0xcbf29ce484222325ull;
};

}  // namespace hipr
