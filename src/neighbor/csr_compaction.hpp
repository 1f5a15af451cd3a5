#pragma once
// Removing rows from a CSR list in place (the Verlet pair list and the barrier candidates when
// particles are removed between rebuilds): what a build over the remaining rows would give, in the
// same order, without a search.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace mpdem {

inline constexpr std::uint32_t kDroppedEntry = std::numeric_limits<std::uint32_t>::max();

// Keeps the rows i with keep[i] != 0 (offset [rows + 1], index [entries]), in order; within them
// each entry e becomes map(e), or is dropped when map(e) is kDroppedEntry. from, when given,
// receives the old position of every kept entry (ascending: an entry never moves up).
template <class Map>
void compact_rows(std::vector<std::uint32_t>& offset, std::vector<std::uint32_t>& index, const std::vector<char>& keep,
                  Map map, std::vector<std::uint32_t>* from = nullptr) {
  if (offset.size() != keep.size() + 1) throw std::logic_error("compact_rows: keep does not match the rows");
  if (from) from->clear();
  std::uint32_t begin = offset[0], written = 0;
  std::size_t row = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const std::uint32_t end = offset[i + 1];  // read before offset[row + 1] (row <= i) is written
    if (keep[i]) {
      for (std::uint32_t k = begin; k < end; ++k) {
        const std::uint32_t e = map(index[k]);
        if (e == kDroppedEntry) continue;
        index[written++] = e;
        if (from) from->push_back(k);
      }
      offset[++row] = written;
    }
    begin = end;
  }
  offset.resize(row + 1);
  index.resize(written);
}

// New index of each kept row (kDroppedEntry for a removed one).
inline std::vector<std::uint32_t> kept_row_numbers(const std::vector<char>& keep) {
  std::vector<std::uint32_t> to(keep.size(), kDroppedEntry);
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) to[i] = next++;
  return to;
}

}  // namespace mpdem
