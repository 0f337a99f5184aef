// 64-bit FNV-1a: the render identity's hash (image/render_identity.h) and the scene text's
// (the parser hashes what it reads).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace vkrt {

// 64-bit FNV-1a, fed in pieces: hashing "ab" equals hashing "a" then "b".
class Fnv1a64 {
 public:
  void add(std::string_view bytes);
  void add(const void* data, std::size_t size);
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;   // the offset basis
};

}  // namespace vkrt
