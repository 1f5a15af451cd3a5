#pragma once
// Gathers of typed values and of AttachedRecords onto one rank (checkpoints of a decomposed run,
// docs/parallel.md), concatenated in rank order.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
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

}  // namespace mpdem
