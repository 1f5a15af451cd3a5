// HaloExchange on 1 to N ranks (run by ctest under mpirun -np 1, 2, 3, 4; parallel/halo_exchange.hpp):
// the ghosts cover every pair within reach, the pairs each rank keeps (owned first member, the
// lower id first across ranks) partition the serial pair set exactly, refresh copies the
// sources bit for bit (the temperatures only with heat transfer), fold returns every ghost's share
// to its source, and migration hands every particle to the owner of its brick with its whole state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <utility>

#include "parallel/brick_grid.hpp"
#include "parallel/communicator.hpp"
#include "parallel/halo_exchange.hpp"

using namespace mpdem;

namespace {

const Vec3 kLo{0.0, 0.0, 0.0}, kHi{1.0, 0.8, 0.6};  // m
constexpr double kRmax = 0.03;                      // m
constexpr double kSkin = 0.01;                      // m
constexpr double kReach = 2.0 * kRmax + kSkin;      // m, the pair criterion's largest distance
constexpr double kWidth = kReach + kSkin;           // m, the halo width (a skin for the drift)

// The same cloud on every rank: 700 spheres at random in the box (overlaps allowed: only
// distances matter here), ids shuffled, every array filled with a value of its id.
Particles cloud() {
  Particles p;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 700;
  std::vector<std::int64_t> ids(n);
  for (int k = 0; k < n; ++k) ids[static_cast<std::size_t>(k)] = 5 + 3 * k;
  std::shuffle(ids.begin(), ids.end(), rng);
  for (int k = 0; k < n; ++k) {
    const Vec3 x{kLo.x + u(rng) * (kHi.x - kLo.x), kLo.y + u(rng) * (kHi.y - kLo.y), kLo.z + u(rng) * (kHi.z - kLo.z)};
    const double r = 0.02 + 0.01 * u(rng);
    const std::int64_t id = ids[static_cast<std::size_t>(k)];
    p.add(id, static_cast<int>(id % 3), r, 2500.0, x, {1e-3 * static_cast<double>(id), -2e-3, 0.5});
    p.w.back() = {0.1, 0.2 * static_cast<double>(id), 0.3};
    p.T.back() = 300.0 + static_cast<double>(id);
    p.charge.back() = 1e-9 * static_cast<double>(id);
  }
  return p;
}

Particles owned_part(Particles& all, const BrickGrid& g, int rank) {
  std::vector<char> keep(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) keep[i] = g.owner(all.x[i]) == rank;
  Particles p = all;
  p.compact(keep);
  return p;
}

// Distance vector x_j - x_i to the nearest image along the periodic axes.
Vec3 nearest(const Vec3& xi, const Vec3& xj, const std::array<bool, 3>& periodic) {
  Vec3 d = xj - xi;
  for (int c = 0; c < 3; ++c)
    if (periodic[static_cast<std::size_t>(c)]) {
      const double L = kHi[c] - kLo[c];
      d[c] -= L * std::round(d[c] / L);
    }
  return d;
}

using PairSet = std::set<std::array<std::int64_t, 2>>;

PairSet serial_pairs(const Particles& all, const std::array<bool, 3>& periodic) {
  PairSet s;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (norm(nearest(all.x[i], all.x[j], periodic)) < kReach)
        s.insert({std::min(all.id[i], all.id[j]), std::max(all.id[i], all.id[j])});
  return s;
}

// Every rank's pairs, gathered: (owned, owned) by index, (owned, ghost) when the owned id is lower.
using IdPair = std::array<std::int64_t, 2>;
IdPair ordered(std::int64_t a, std::int64_t b) { return {std::min(a, b), std::max(a, b)}; }

std::vector<IdPair> kept_pairs(const Particles& p, const Communicator& comm) {
  std::vector<IdPair> mine;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size_with_ghosts(); ++j) {
      if (j >= p.size() && !(p.id[i] < p.id[j])) continue;
      if (norm(p.x[j] - p.x[i]) < kReach) mine.push_back(ordered(p.id[i], p.id[j]));
    }
  std::vector<IdPair> all;
  for (const auto& b : comm.all_gather(std::as_bytes(std::span(mine)))) {
    const std::size_t n = b.size() / sizeof(mine[0]);
    const std::size_t at = all.size();
    all.resize(at + n);
    if (n > 0) std::memcpy(&all[at], b.data(), b.size());
  }
  return all;
}

// The cloud on every rank, this rank's part of it and a halo exchange over the bricks.
struct Split {
  // ghosts: with the halo of width kWidth built.
  Split(const Communicator& comm, const std::array<bool, 3>& periodic, bool ghosts)
      : all(cloud()), grid(comm.size(), kLo, kHi, periodic), p(owned_part(all, grid, comm.rank())), halo(comm, grid) {
    if (ghosts) halo.build(p, kWidth);
  }
  Particles all;
  BrickGrid grid;
  Particles p;
  HaloExchange halo;
};

const std::array<std::array<bool, 3>, 3> kPeriodicCases{
    {{false, false, false}, {true, true, false}, {true, true, true}}};

}  // namespace

TEST(HaloExchange, GhostPairsPartitionTheSerialPairs) {
  const Communicator& comm = Communicator::world();
  for (const auto& periodic : kPeriodicCases) {
    Split sp(comm, periodic, true);
    Particles& p = sp.p;
    EXPECT_EQ(sp.halo.size(), p.n_ghost);
    const PairSet expected = serial_pairs(sp.all, periodic);
    const auto kept = kept_pairs(p, comm);
    const PairSet got(kept.begin(), kept.end());
    EXPECT_EQ(kept.size(), got.size()) << "a pair kept twice (periodic " << periodic[0] << periodic[1] << periodic[2]
                                       << ")";
    EXPECT_EQ(got, expected) << "periodic " << periodic[0] << periodic[1] << periodic[2];
    EXPECT_GT(expected.size(), 300u);  // the cloud is dense enough to test something
    // Every ghost is a copy of its particle, at an image of it.
    std::map<std::int64_t, std::size_t> where;
    for (std::size_t i = 0; i < sp.all.size(); ++i) where[sp.all.id[i]] = i;
    for (std::size_t g = p.size(); g < p.size_with_ghosts(); ++g) {
      const std::size_t s = where.at(p.id[g]);
      EXPECT_EQ(p.radius[g], sp.all.radius[s]);
      EXPECT_EQ(p.v[g], sp.all.v[s]);
      EXPECT_EQ(p.T[g], sp.all.T[s]);
      EXPECT_LT(norm(nearest(sp.all.x[s], p.x[g], periodic)), 1e-12);
    }
  }
}

namespace {
// With temperatures (heat transfer on) a refresh carries T and the fold heat flows; without, the
// ghosts keep the build's T and no heat goes back, while x, v and the forces travel as before.
void refresh_and_fold(bool temperatures) {
  const Communicator& comm = Communicator::world();
  for (const auto& periodic : kPeriodicCases) {
    Split sp(comm, periodic, true);
    sp.halo.temperatures(temperatures);
    Particles& p = sp.p;
    const std::vector<double> T_built(p.T.begin(), p.T.end());
    // New state on the owned particles (a step): the ghosts must follow exactly.
    std::vector<Vec3> shift(p.size_with_ghosts());
    for (std::size_t g = p.size(); g < p.size_with_ghosts(); ++g) shift[g] = p.x[g];
    std::map<std::int64_t, std::size_t> owned;
    for (std::size_t i = 0; i < p.size(); ++i) {
      owned[p.id[i]] = i;
      p.x[i] += Vec3{1e-4, -2e-4, 3e-4};
      p.v[i] = {std::sqrt(static_cast<double>(p.id[i])), 1.0 / 3.0, -0.7};
      p.T[i] += 0.125;
    }
    for (std::size_t g = p.size(); g < p.size_with_ghosts(); ++g) {
      p.force[g] = {1.0, 0.0, 0.0};
      p.torque[g] = {0.0, 2.0, 0.0};
      p.heat[g] = 3.0;
    }
    sp.halo.refresh(p);
    for (std::size_t g = p.size(); g < p.size_with_ghosts(); ++g) {
      EXPECT_EQ(p.v[g], (Vec3{std::sqrt(static_cast<double>(p.id[g])), 1.0 / 3.0, -0.7}));
      EXPECT_EQ(p.force[g], Vec3{});                                      // accumulators start empty
      EXPECT_EQ(p.T[g], temperatures ? T_built[g] + 0.125 : T_built[g]);  // the sources gained 0.125 K
      EXPECT_LT(norm(p.x[g] - shift[g] - Vec3{1e-4, -2e-4, 3e-4}), 1e-14);
    }
    // Fold: one unit per ghost copy; each particle must receive as many as it has copies anywhere.
    for (std::size_t g = p.size(); g < p.size_with_ghosts(); ++g) {
      p.force[g] = {1.0, 0.0, 0.0};
      p.torque[g] = {0.0, 2.0, 0.0};
      p.heat[g] = 3.0;
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.force[i] = {};
      p.torque[i] = {};
      p.heat[i] = 0.0;
    }
    sp.halo.fold(p);
    std::vector<std::int64_t> ghost_ids(p.id.begin() + static_cast<std::ptrdiff_t>(p.size()), p.id.end());
    std::map<std::int64_t, int> copies;
    for (const auto& b : comm.all_gather(std::as_bytes(std::span(ghost_ids))))
      for (std::size_t k = 0; k < b.size() / sizeof(std::int64_t); ++k) {
        std::int64_t id = 0;
        std::memcpy(&id, b.data() + k * sizeof id, sizeof id);
        ++copies[id];
      }
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto it = copies.find(p.id[i]);
      const double n = it == copies.end() ? 0.0 : it->second;
      EXPECT_EQ(p.force[i], (Vec3{n, 0.0, 0.0})) << "id " << p.id[i];
      EXPECT_EQ(p.torque[i], (Vec3{0.0, 2.0 * n, 0.0}));
      EXPECT_EQ(p.heat[i], temperatures ? 3.0 * n : 0.0);
    }
  }
}
}  // namespace

TEST(HaloExchange, RefreshCopiesTheSourcesAndFoldReturnsEveryShare) { refresh_and_fold(true); }

TEST(HaloExchange, WithoutHeatTransferNoTemperatureOrHeatCrosses) { refresh_and_fold(false); }

TEST(HaloExchange, MigrationHandsEveryParticleToItsOwner) {
  const Communicator& comm = Communicator::world();
  for (const auto& periodic : kPeriodicCases) {
    Split sp(comm, periodic, false);
    Particles& p = sp.p;
    // Everyone moves by up to 0.08 m per axis (less than a brick: 0.3 m at 4 ranks), some
    // through the periodic faces; the expected state is computed from the cloud itself.
    auto move = [](std::int64_t id) {
      std::mt19937_64 r(static_cast<std::uint64_t>(id));
      std::uniform_real_distribution<double> u(-0.08, 0.08);
      return Vec3{u(r), u(r), u(r)};
    };
    for (std::size_t i = 0; i < p.size(); ++i) p.x[i] += move(p.id[i]);
    // Contact history rides along: two or three records per particle (three for every third id,
    // so that leaving and staying records interleave), each naming its anchor and its rank.
    struct Record {
      std::int64_t id;
      std::int64_t k;
    };
    AttachedRecords records = AttachedRecords::of<Record>();
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::int64_t k = 0; k < 2 + (p.id[i] % 3 == 0 ? 1 : 0); ++k) records.push(p.id[i], Record{p.id[i], k});
    AttachedRecords* const attached[] = {&records};
    sp.halo.migrate(p, attached);
    std::map<std::int64_t, std::vector<std::int64_t>> held;  // anchor -> record ks, in order
    for (std::size_t r = 0; r < records.size(); ++r) {
      const Record rec = records.get<Record>(r);
      EXPECT_EQ(rec.id, records.anchor[r]) << "a record arrived under another particle's id";
      held[records.anchor[r]].push_back(rec.k);
    }
    std::size_t mine_with_records = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::vector<std::int64_t> want = p.id[i] % 3 == 0 ? std::vector<std::int64_t>{0, 1, 2}
                                                              : std::vector<std::int64_t>{0, 1};
      EXPECT_EQ(held[p.id[i]], want) << "records of id " << p.id[i];
      ++mine_with_records;
    }
    EXPECT_EQ(held.size(), mine_with_records);  // no record of a particle held elsewhere
    std::vector<std::int64_t> ids(p.id.begin(), p.id.end());
    std::size_t total = 0;
    std::set<std::int64_t> seen;
    for (const auto& b : comm.all_gather(std::as_bytes(std::span(ids))))
      for (std::size_t k = 0; k < b.size() / sizeof(std::int64_t); ++k) {
        std::int64_t id = 0;
        std::memcpy(&id, b.data() + k * sizeof id, sizeof id);
        seen.insert(id);
        ++total;
      }
    EXPECT_EQ(total, sp.all.size());  // nobody lost or duplicated
    EXPECT_EQ(seen.size(), sp.all.size());
    std::map<std::int64_t, std::size_t> where;
    for (std::size_t i = 0; i < sp.all.size(); ++i) where[sp.all.id[i]] = i;
    std::size_t wrapped = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t s = where.at(p.id[i]);
      EXPECT_EQ(sp.grid.owner(p.x[i]), comm.rank());
      Vec3 unwrapped = p.x[i];
      for (int c = 0; c < 3; ++c) unwrapped[c] += p.image[i][static_cast<std::size_t>(c)] * (kHi[c] - kLo[c]);
      EXPECT_LT(norm(unwrapped - (sp.all.x[s] + move(p.id[i]))), 1e-12);
      wrapped += p.image[i] != std::array<std::int32_t, 3>{};
      EXPECT_EQ(p.v[i], sp.all.v[s]);
      EXPECT_EQ(p.w[i], sp.all.w[s]);
      EXPECT_EQ(p.radius[i], sp.all.radius[s]);
      EXPECT_EQ(p.mass[i], sp.all.mass[s]);
      EXPECT_EQ(p.material[i], sp.all.material[s]);
      EXPECT_EQ(p.charge[i], sp.all.charge[s]);
      EXPECT_EQ(p.T[i], sp.all.T[s]);
      for (int c = 0; c < 3; ++c) {
        if (!periodic[static_cast<std::size_t>(c)]) {
          EXPECT_EQ(p.image[i][static_cast<std::size_t>(c)], 0);
        }
      }
    }
    const std::uint64_t wrapped_total = comm.sum(static_cast<std::uint64_t>(wrapped));
    if (periodic[0]) {
      EXPECT_GT(wrapped_total, 20u);
    }
  }
}
