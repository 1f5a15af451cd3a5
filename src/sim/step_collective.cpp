#include "sim/step_collective.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <span>
#include <utility>
#include <vector>

#include "parallel/communicator.hpp"

namespace mpdem {

namespace {
constexpr std::size_t kStatSums = kRankSummedStatCount;
constexpr std::size_t kSums = kStatSums + kScanSums;

// One rank's totals as a message of fixed size (every rank's the same: one all-gather).
struct Message {
  double sum[kSums];
  std::uint64_t particles;
  OverlapReport deepest;
  std::int64_t stop;
  std::uint64_t due[5];  // vtu, csv, vtu_index, body_csv, bonds
  std::uint64_t bond_breaks;
};
}  // namespace

StepCollective combine_over_ranks(const Communicator& comm, const StepCollective& mine) {
  Message m{};  // value-initialised: the padding too, so the message's bytes are all defined
  const HealthScan& s = mine.scan;
  const double scan[kScanSums] = {s.energy.kinetic,
                                  s.energy.rotational,
                                  s.energy.potential,
                                  s.electric,
                                  static_cast<double>(s.nonfinite),
                                  static_cast<double>(s.outside)};
  const auto stats = rank_summed_values(mine.stats);
  std::copy(stats.begin(), stats.end(), m.sum);
  std::copy(std::begin(scan), std::end(scan), m.sum + kStatSums);
  m.particles = mine.particles;
  m.deepest = mine.deepest;
  m.stop = mine.stop;
  m.due[0] = mine.vtu ? 1 : 0;
  m.due[1] = mine.csv ? 1 : 0;
  m.due[2] = mine.vtu_index;
  m.due[3] = mine.body_csv ? 1 : 0;
  m.due[4] = mine.bonds ? 1 : 0;
  m.bond_breaks = mine.bond_breaks;

  // The message, then the loads.
  const std::size_t n_loads = mine.loads.size(), each = sizeof m + n_loads * sizeof(double);
  std::vector<std::byte> bytes(each);
  std::memcpy(bytes.data(), &m, sizeof m);
  if (n_loads > 0) std::memcpy(bytes.data() + sizeof m, mine.loads.data(), n_loads * sizeof(double));
  const std::vector<std::byte> all = comm.all_gather_fixed(bytes);
  Message t{};
  std::vector<double> loads(n_loads), x_loads(n_loads);
  int deepest_rank = 0;
  for (int r = 0; r < comm.size(); ++r) {
    Message x;
    const std::byte* at = all.data() + static_cast<std::size_t>(r) * each;
    std::memcpy(&x, at, sizeof x);
    if (n_loads > 0) std::memcpy(x_loads.data(), at + sizeof x, n_loads * sizeof(double));
    if (r == 0) {
      t = x;  // rank 0's decision on the snapshots stands
      loads = x_loads;
      continue;
    }
    for (std::size_t k = 0; k < n_loads; ++k) loads[k] = loads[k] + x_loads[k];
    for (std::size_t k = 0; k < kSums; ++k) t.sum[k] = t.sum[k] + x.sum[k];
    t.particles += x.particles;
    if (x.deepest.ratio > t.deepest.ratio) {
      t.deepest = x.deepest;
      deepest_rank = r;
    }
    t.stop = std::max(t.stop, x.stop);
    t.bond_breaks += x.bond_breaks;
  }

  StepCollective out = mine;
  set_rank_summed_values(out.stats, t.sum);
  const double* sc = t.sum + kStatSums;
  out.scan = {{sc[0], sc[1], sc[2]}, sc[3], static_cast<std::size_t>(sc[4]), static_cast<std::size_t>(sc[5])};
  out.particles = t.particles;
  out.deepest = t.deepest;
  out.deepest.rank = deepest_rank;
  out.stop = static_cast<int>(t.stop);
  out.vtu = t.due[0] != 0;
  out.csv = t.due[1] != 0;
  out.vtu_index = t.due[2];
  out.body_csv = t.due[3] != 0;
  out.bonds = t.due[4] != 0;
  out.bond_breaks = t.bond_breaks;
  out.loads = std::move(loads);
  return out;
}

}  // namespace mpdem
