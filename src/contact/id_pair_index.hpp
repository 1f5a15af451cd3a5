#pragma once
// IdPairIndex: finds the record of an ordered pair of particle ids (lower id first) among n
// records in expected O(1): an open-addressing hash table of record indices. Used where contact
// history travels by ids (MPI rebuilds, checkpoints): a lookup per listed pair costs one or two
// cache misses, where a binary search over the sorted records costs about one per level.
//
// Each table entry is 8 bytes: the record index + 1 (0: empty) in the low half, the upper half of
// the pair's hash in the high half, so that a probe reads a record only when the hashes agree.
// With several records of one pair the first (lowest index) is found.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace mpdem {

class IdPairIndex {
 public:
  static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

  // key(r) gives the pair (lower id, higher id) of record r in [0, n).
  template <class Key>
  void build(std::size_t n, Key&& key) {
    // At most half full: probe runs stay short.
    const std::size_t cap = std::bit_ceil(std::max<std::size_t>(16, 2 * n));
    table_.assign(cap, 0);
    mask_ = cap - 1;
    for (std::size_t r = 0; r < n; ++r) {
      const auto [a, b] = key(r);
      const std::uint64_t h = hash(a, b);
      std::size_t s = h & mask_;
      while (table_[s] != 0) s = (s + 1) & mask_;
      table_[s] = (h & kHigh) | static_cast<std::uint64_t>(r + 1);
    }
  }

  // The first record r with key(r) == (a, b), or npos. key as given to build.
  template <class Key>
  std::size_t find(std::int64_t a, std::int64_t b, Key&& key) const {
    if (table_.empty()) return npos;
    const std::uint64_t h = hash(a, b);
    for (std::size_t s = h & mask_;; s = (s + 1) & mask_) {
      const std::uint64_t e = table_[s];
      if (e == 0) return npos;
      if ((e & kHigh) != (h & kHigh)) continue;
      const std::size_t r = static_cast<std::size_t>(e & ~kHigh) - 1;
      const auto [ka, kb] = key(r);
      if (ka == a && kb == b) return r;
    }
  }

 private:
  static constexpr std::uint64_t kHigh = 0xFFFFFFFF00000000ull;
  // A 64-bit mix of both ids (splitmix64's finaliser over a combination of the two).
  static std::uint64_t hash(std::int64_t a, std::int64_t b) {
    std::uint64_t x = static_cast<std::uint64_t>(a) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(b);
    x ^= x >> 30;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 27;
    x *= 0x94D049BB133111EBull;
    return x ^ (x >> 31);
  }

  std::vector<std::uint64_t> table_;  // [capacity] record index + 1 | upper hash bits; 0 empty
  std::size_t mask_ = 0;              // capacity - 1 (a power of 2)
};

}  // namespace mpdem
