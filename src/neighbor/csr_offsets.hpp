#pragma once
// CSR offsets of the neighbour list and the barrier candidates: 32-bit, so at most 2^32 - 1
// entries per process (more is refused, as more than 2^32 - 1 particles is).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

namespace mpdem {

// offset[i + 1] holds the count of row i (offset[0] = 0); scans them into offsets in place and
// returns the total, or nothing when it exceeds 2^32 - 1 (offset is then left part-scanned).
inline std::optional<std::size_t> counts_to_offsets(std::span<std::uint32_t> offset) {
  std::size_t total = 0;
  for (std::size_t i = 1; i < offset.size(); ++i) {
    total += offset[i];
    if (total > std::numeric_limits<std::uint32_t>::max()) return std::nullopt;
    offset[i] = static_cast<std::uint32_t>(total);
  }
  return total;
}

}  // namespace mpdem
