// The bonds a scene makes at t = 0 (contact/bond_making.hpp): the gap rule against the lattice's
// count and against an all-pairs search, [[bonds.pair]] entries (bonded = false, a pair's own gap),
// the minimum image across periodic faces, clump members, fixed particles, and the union with the
// listed bonds without duplicates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "contact/bond_making.hpp"
#include "support/clump_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {

constexpr double kR = 1e-3;  // m, sphere radius

// A scene with [bonds] young = 1 GPa and the given gap (m; < 0: none).
Scene bonded_scene(double gap) {
  Scene s = test::make_scene(1e-7, 1e-3);
  BondKeys k;
  k.young = 1e9;
  if (gap >= 0.0) k.gap = gap;
  s.model.params.bonds.defaults = k;
  return s;
}

// n^3 spheres of radius kR on a cubic lattice of spacing a (m), ids 1.. in reverse index order.
void add_lattice(Scene& s, int n, double a) {
  std::int64_t id = n * n * n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) test::add_particle(s, id--, kR, {i * a, j * a, k * a});
}

// The pairs (id, id) of the bonds, smaller id first.
std::vector<std::pair<std::int64_t, std::int64_t>> id_pairs(const Particles& p, const std::vector<MadeBond>& b) {
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  for (const MadeBond& m : b) out.emplace_back(p.id[m.i], p.id[m.j]);
  return out;
}

// Every bond names its smaller id first and the list is sorted by (id_i, id_j) without repeats.
void expect_ordered(const Particles& p, const std::vector<MadeBond>& b) {
  const auto ids = id_pairs(p, b);
  for (const auto& [i, j] : ids) EXPECT_LT(i, j);
  EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
  EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end());
}

}  // namespace

TEST(BondMaking, CubicLatticeBondsItsFaceNeighbours) {
  const int n = 6;
  const double s = 0.1 * kR, a = 2.0 * kR + s;  // m, surface gap and spacing
  for (const auto& [gap, expected] : {std::pair{1.001 * s, 3 * n * n * (n - 1)}, std::pair{0.999 * s, 0}}) {
    Scene sc = bonded_scene(gap);
    add_lattice(sc, n, a);
    const std::vector<MadeBond> b = make_bonds(sc.model, sc.particles);
    EXPECT_EQ(b.size(), static_cast<std::size_t>(expected)) << "gap " << gap;
    expect_ordered(sc.particles, b);
    for (const MadeBond& m : b) EXPECT_NEAR(bond_length(sc.model, sc.particles, m.i, m.j), a, 1e-12);
  }
}

TEST(BondMaking, GapRuleMatchesAllPairs) {
  // Radii 1..5 mm in a box where every sphere has a few neighbours within the gap.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 0.05), r(kR, 5.0 * kR);
  Scene s = bonded_scene(2e-3);
  for (std::int64_t id = 1; id <= 1500; ++id) test::add_particle(s, id, r(rng), {u(rng), u(rng), u(rng)});
  const Particles& p = s.particles;
  std::vector<std::pair<std::int64_t, std::int64_t>> all;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (norm(p.x[j] - p.x[i]) - p.radius[i] - p.radius[j] < 2e-3) all.emplace_back(std::minmax(p.id[i], p.id[j]));
  std::sort(all.begin(), all.end());
  ASSERT_GT(all.size(), 1000u);
  EXPECT_EQ(id_pairs(p, make_bonds(s.model, p)), all);
}

TEST(BondMaking, PairEntriesKeepMaterialsApartOrSetTheirGap) {
  // A chain a a b b c c along x with surface gaps of 0.1 mm.
  Scene s = bonded_scene(0.2 * kR);
  for (const char* name : {"b", "c"}) {
    Material m = s.model.materials.front();
    m.name = name;
    s.model.materials.push_back(m);
  }
  for (std::int64_t id = 1; id <= 6; ++id) {
    const std::size_t i = test::add_particle(s, id, kR, {static_cast<double>(id - 1) * 2.1 * kR, 0.0, 0.0});
    s.particles.material[i] = static_cast<int>((id - 1) / 2);
  }
  BondPairParams ab{"default", "b", {}, 0};
  ab.keys.bonded = false;
  BondPairParams cc{"c", "c", {}, 0};
  cc.keys.gap = 0.05 * kR;  // below the chain's gap: no c-c bond
  s.model.params.bonds.pairs = {ab, cc};
  using Ids = std::vector<std::pair<std::int64_t, std::int64_t>>;
  EXPECT_EQ(id_pairs(s.particles, make_bonds(s.model, s.particles)), (Ids{{1, 2}, {3, 4}, {4, 5}}));
  // Entries name their materials in either order; the last matching one wins.
  BondPairParams ba{"b", "default", {}, 0};
  ba.keys.bonded = true;
  s.model.params.bonds.pairs.push_back(ba);
  EXPECT_EQ(id_pairs(s.particles, make_bonds(s.model, s.particles)), (Ids{{1, 2}, {2, 3}, {3, 4}, {4, 5}}));
}

TEST(BondMaking, MaterialVariantsTakeTheirMaterialsLaw) {
  // Particle 2 has a variant of the first material (per-row CSV values): the entry naming the
  // material keeps it apart from "b" too.
  Scene s = bonded_scene(0.2 * kR);
  Material b = s.model.materials.front();
  b.name = "b";
  s.model.materials.push_back(b);
  Material variant = s.model.materials.front();
  variant.name = "default#1";
  variant.density *= 2.0;
  variant.variant_of = 0;
  s.model.materials.push_back(variant);
  for (std::int64_t id = 1; id <= 3; ++id)
    test::add_particle(s, id, kR, {static_cast<double>(id - 1) * 2.1 * kR, 0.0, 0.0});
  s.particles.material[1] = 2;  // the variant
  s.particles.material[2] = 1;  // "b"
  BondPairParams e{"b", "default", {}, 0};
  e.keys.bonded = false;
  s.model.params.bonds.pairs = {e};
  using Ids = std::vector<std::pair<std::int64_t, std::int64_t>>;
  EXPECT_EQ(id_pairs(s.particles, make_bonds(s.model, s.particles)), (Ids{{1, 2}}));
}

TEST(BondMaking, PeriodicFacesBondTheNearestImage) {
  // A ring of 8 spheres along x in a periodic box of length 8 a: the last is bonded to the first.
  const int n = 8;
  const double a = 2.1 * kR;
  for (const bool periodic : {true, false}) {
    Scene s = bonded_scene(0.2 * kR);
    DomainParams& d = s.model.params.domain;
    d.bounded = true;
    d.min = {-0.5 * a, -0.01, -0.01};
    d.max = {(n - 0.5) * a, 0.01, 0.01};
    d.periodic = {periodic, false, false};
    for (int k = 0; k < n; ++k) test::add_particle(s, k + 1, kR, {k * a, 0.0, 0.0});
    if (periodic)
      s.particles.x[n - 1].x -= static_cast<double>(n) * a;  // an unwrapped centre: an image of the same place
    const std::vector<MadeBond> b = make_bonds(s.model, s.particles);
    ASSERT_EQ(b.size(), static_cast<std::size_t>(periodic ? n : n - 1));
    for (const MadeBond& m : b) EXPECT_NEAR(bond_length(s.model, s.particles, m.i, m.j), a, 1e-12);
    if (periodic) {  // the wrap bond, after 1-2
      EXPECT_EQ(id_pairs(s.particles, {b[1]}).front(), std::make_pair(std::int64_t{1}, std::int64_t{8}));
    }
  }
}

TEST(BondMaking, ClumpMembersOfOneBodyAreNeverBonded) {
  // Two bodies of two overlapping members each, 0.1 mm apart at their nearest members.
  Scene s = bonded_scene(0.2 * kR);
  const int t = test::add_template(s, "pair", {{{-0.8 * kR, 0.0, 0.0}, kR}, {{0.8 * kR, 0.0, 0.0}, kR}});
  test::add_clump(s, 1, t, {0.0, 0.0, 0.0});
  test::add_clump(s, 2, t, {3.7 * kR, 0.0, 0.0});
  test::finish_clumps(s);
  const Particles& p = s.particles;
  const std::vector<MadeBond> b = make_bonds(s.model, p);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NE(p.body[b[0].i], p.body[b[0].j]);
  EXPECT_NEAR(bond_length(s.model, p, b[0].i, b[0].j), 2.1 * kR, 1e-12);
}

TEST(BondMaking, TwoFixedParticlesAreNotBonded) {
  Scene s = bonded_scene(0.2 * kR);
  for (std::int64_t id = 1; id <= 3; ++id)
    test::add_particle(s, id, kR, {static_cast<double>(id - 1) * 2.1 * kR, 0.0, 0.0});
  s.particles.fixed[0] = s.particles.fixed[1] = 1;
  using Ids = std::vector<std::pair<std::int64_t, std::int64_t>>;
  EXPECT_EQ(id_pairs(s.particles, make_bonds(s.model, s.particles)), (Ids{{2, 3}}));
  // A listed bond between the two fixed ones is left out too.
  s.model.params.bonds.listed = {{1, 2, 2}};
  EXPECT_EQ(id_pairs(s.particles, make_bonds(s.model, s.particles)), (Ids{{2, 3}}));
}

TEST(BondMaking, ListedAndGapBondsOnceEach) {
  Scene s = bonded_scene(0.2 * kR);
  for (std::int64_t id = 1; id <= 4; ++id)
    test::add_particle(s, 5 - id, kR, {static_cast<double>(id - 1) * 2.1 * kR, 0.0, 0.0});
  // Ids 4 3 2 1 along x: the gap rule bonds 4-3, 3-2, 2-1; the file lists 2-3 (either order) and 1-4.
  s.model.params.bonds.listed = {{3, 2, 2}, {4, 1, 3}};
  using Ids = std::vector<std::pair<std::int64_t, std::int64_t>>;
  EXPECT_EQ(id_pairs(s.particles, gap_bonds(s.model, s.particles)), (Ids{{1, 2}, {2, 3}, {3, 4}}));
  EXPECT_EQ(id_pairs(s.particles, listed_bonds(s.model, s.particles)), (Ids{{1, 4}, {2, 3}}));
  const std::vector<MadeBond> b = make_bonds(s.model, s.particles);
  EXPECT_EQ(id_pairs(s.particles, b), (Ids{{1, 2}, {1, 4}, {2, 3}, {3, 4}}));
  expect_ordered(s.particles, b);
  // Without a gap rule only the listed ones.
  s.model.params.bonds.defaults->gap.reset();
  EXPECT_EQ(id_pairs(s.particles, make_bonds(s.model, s.particles)), (Ids{{1, 4}, {2, 3}}));
}

TEST(BondMaking, NoBondsWithoutBondsTable) {
  Scene s = test::make_scene(1e-7, 1e-3);
  add_lattice(s, 3, 2.0 * kR);
  EXPECT_TRUE(make_bonds(s.model, s.particles).empty());
}
