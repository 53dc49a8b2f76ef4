// Finds, for each of a sequence of values appended to an array, the index of the first equal
// value: how the OBJ reader shares positions, texture coordinates and normals written more than
// once. The values stay in the caller's array; a slot holds 32 bits of the value's hash and its
// index (8 bytes, a third of a slot holding six floats), so that a million values take 8 MiB
// and the table mostly stays in cache.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace obscura {

// A hash of a few 32-bit words, mixed so that its low bits are usable as a table index.
template <size_t N>
uint64_t hash_words(const std::array<uint32_t, N>& words) {
  uint64_t h = 0x9E3779B97F4A7C15ull;
  for (uint32_t word : words) {
    h ^= word;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
  }
  return h;
}

// The bits of floats as words, with −0 taken as +0 (they are the same position).
template <typename... F>
std::array<uint32_t, sizeof...(F)> float_words(F... values) {
  std::array<uint32_t, sizeof...(F)> words{};
  float v[] = {(values == 0 ? 0.f : values)...};
  std::memcpy(words.data(), v, sizeof v);
  return words;
}

class FirstIndexTable {
 public:
  // The index of the first value added with a value equal to that at `index`, which has hash
  // `hash`: `index` itself (now recorded) when there is none. `equal(j)` says whether the value
  // at j (an index added before) equals it.
  template <typename Equal>
  uint32_t find_or_add(uint64_t hash, uint32_t index, Equal&& equal) {
    if ((size_ + 1) * 2 > slots_.size()) grow();
    const auto tag = uint32_t(hash);
    const size_t mask = slots_.size() - 1;
    for (size_t i = tag & mask;; i = (i + 1) & mask) {
      Slot& s = slots_[i];
      if (s.index == kEmpty) {
        s = {tag, index};
        ++size_;
        return index;
      }
      if (s.tag == tag && equal(s.index)) return s.index;
    }
  }

  // Asks the processor to bring in the slot a later find_or_add(hash, …) starts at.
  void prefetch(uint64_t hash) const {
    if (!slots_.empty()) __builtin_prefetch(&slots_[uint32_t(hash) & (slots_.size() - 1)]);
  }

 private:
  static constexpr uint32_t kEmpty = ~uint32_t(0);
  struct Slot {
    uint32_t tag = 0;  // the hash's low 32 bits: the slot's place, and a quick inequality test
    uint32_t index = kEmpty;
  };

  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 64 : old.size() * 2, Slot{});
    const size_t mask = slots_.size() - 1;
    for (const Slot& s : old) {
      if (s.index == kEmpty) continue;
      size_t i = s.tag & mask;
      while (slots_[i].index != kEmpty) i = (i + 1) & mask;
      slots_[i] = s;
    }
  }

  std::vector<Slot> slots_;
  size_t size_ = 0;
};

}  // namespace obscura
