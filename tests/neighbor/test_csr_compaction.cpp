// compact_rows (neighbor/csr_compaction.hpp): rows and entries dropped from a CSR list in place,
// against a list built afresh from the kept rows.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "neighbor/csr_compaction.hpp"

namespace mpdem {
namespace {

TEST(CsrCompaction, MatchesTheListOfTheKeptRowsAndEntries) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t rows = 1 + rng() % 200;
    std::vector<std::vector<std::uint32_t>> list(rows);
    for (auto& r : list)
      for (std::uint64_t k = rng() % 9; k > 0; --k) r.push_back(static_cast<std::uint32_t>(rng() % rows));
    std::vector<char> keep(rows);
    for (auto& k : keep) k = static_cast<char>(rng() % 3 != 0);
    // Entries name rows: a dropped row's entries go, the others are renumbered.
    const std::vector<std::uint32_t> to = kept_row_numbers(keep);
    std::vector<std::uint32_t> offset{0}, index, expect_offset{0}, expect_index, expect_from;
    for (std::size_t i = 0; i < rows; ++i) {
      for (const std::uint32_t e : list[i]) {
        if (keep[i] && keep[e]) {
          expect_index.push_back(to[e]);
          expect_from.push_back(static_cast<std::uint32_t>(index.size()));
        }
        index.push_back(e);
      }
      offset.push_back(static_cast<std::uint32_t>(index.size()));
      if (keep[i]) expect_offset.push_back(static_cast<std::uint32_t>(expect_index.size()));
    }
    std::vector<std::uint32_t> from;
    compact_rows(
        offset, index, keep, [&](std::uint32_t e) { return to[e]; }, &from);
    EXPECT_EQ(offset, expect_offset);
    EXPECT_EQ(index, expect_index);
    EXPECT_EQ(from, expect_from);
  }
}

TEST(CsrCompaction, RefusesAKeepOfAnotherLength) {
  std::vector<std::uint32_t> offset{0, 1, 2}, index{0, 1};
  EXPECT_THROW(compact_rows(offset, index, std::vector<char>(3, 1), [](std::uint32_t e) { return e; }),
               std::logic_error);
}

}  // namespace
}  // namespace mpdem
