#pragma once
// Gathers of typed values and of AttachedRecords onto one rank (checkpoints of a decomposed run,
// docs/parallel.md), concatenated in rank order; the best of the ranks' values on every rank.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "parallel/attached_records.hpp"
#include "parallel/communicator.hpp"

namespace mpdem {

// Every rank's values, in rank order, on `root` (empty elsewhere). Collective.
template <class T>
std::vector<T> gather_values(const Communicator& comm, std::span<const T> mine, int root) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::vector<T> all;
  for (const auto& bytes : comm.gather(std::as_bytes(mine), root)) {
    const std::size_t at = all.size(), n = bytes.size() / sizeof(T);
    all.resize(at + n);
    if (n > 0) std::memcpy(all.data() + at, bytes.data(), n * sizeof(T));
  }
  return all;
}

// Every rank's records (of one record size), in rank order, on `root` (none elsewhere). Collective.
inline AttachedRecords gather_records(const Communicator& comm, const AttachedRecords& mine, int root) {
  AttachedRecords all;
  all.bytes = mine.bytes;
  all.anchor = gather_values<std::int64_t>(comm, mine.anchor, root);
  all.data = gather_values<std::byte>(comm, mine.data, root);
  return all;
}

// The best of every rank's `mine` (better(a, b): a is strictly better than b) and the rank that
// holds it, on every rank; on a tie the lowest rank's, so every rank names the same one. Collective.
template <class T, class Better>
std::pair<T, int> best_across(const Communicator& comm, const T& mine, Better better) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::pair<T, int> best{mine, comm.rank()};
  int r = 0;
  for (const auto& bytes : comm.all_gather(std::as_bytes(std::span(&mine, 1)))) {
    T v;
    std::memcpy(&v, bytes.data(), sizeof v);
    if (r == 0 || better(v, best.first)) best = {v, r};
    ++r;
  }
  return best;
}

}  // namespace mpdem
