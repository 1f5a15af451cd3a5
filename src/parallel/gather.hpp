#pragma once
// Gathers of typed values and of AttachedRecords onto one rank (checkpoints of a decomposed run,
// docs/parallel.md), concatenated in rank order; the best of the ranks' values on every rank.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "parallel/attached_records.hpp"
#include "parallel/communicator.hpp"

namespace mpdem {

// The ranks' byte blocks (Communicator::gather, all_gather) as one array of T, in rank order.
template <class T>
std::vector<T> concatenated(const std::vector<std::vector<std::byte>>& blocks) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::vector<T> all;
  for (const auto& bytes : blocks) {
    const std::size_t at = all.size(), n = bytes.size() / sizeof(T);
    all.resize(at + n);
    if (n > 0) std::memcpy(all.data() + at, bytes.data(), n * sizeof(T));
  }
  return all;
}

// Every rank's values, in rank order, on `root` (empty elsewhere). Collective.
template <class T>
std::vector<T> gather_values(const Communicator& comm, std::span<const T> mine, int root) {
  return concatenated<T>(comm.gather(std::as_bytes(mine), root));
}

// Every rank's values, in rank order, on every rank. Collective.
template <class T>
std::vector<T> all_gather_values(const Communicator& comm, std::span<const T> mine) {
  return concatenated<T>(comm.all_gather(std::as_bytes(mine)));
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
  const std::vector<std::byte> all = comm.all_gather_fixed(std::as_bytes(std::span(&mine, 1)));
  for (int r = 0; r < comm.size(); ++r) {
    T v;
    std::memcpy(&v, all.data() + static_cast<std::size_t>(r) * sizeof v, sizeof v);
    if (r == 0 || better(v, best.first)) best = {v, r};
  }
  return best;
}

// The lowest of the ranks' ids (-1: none) and the rank that holds it, on every rank: a culprit
// named the same on every rank and on any rank count. Collective.
inline std::pair<std::int64_t, int> lowest_id_across(const Communicator& comm, std::int64_t id) {
  return best_across(comm, id, [](std::int64_t a, std::int64_t b) { return a >= 0 && (b < 0 || a < b); });
}

// " (on rank r of N)": where a failure happened, for its message on several ranks; "" on one
// (comm null) or for no rank (-1).
inline std::string rank_note(const Communicator* comm, int rank) {
  if (!comm || rank < 0) return {};
  return " (on rank " + std::to_string(rank) + " of " + std::to_string(comm->size()) + ")";
}

}  // namespace mpdem
