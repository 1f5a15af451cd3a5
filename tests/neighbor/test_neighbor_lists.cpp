// Neighbour lists through the engine (physics.md section 11): the lists NeighborSearch keeps and the contacts
// Interactions finds against brute force across rebuilds, springs across a reordering, the domain-exit policy.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "integrate/integrator_policy.hpp"
#include "integrate/verlet.hpp"
#include "model/material_variants.hpp"
#include "interact/interactions.hpp"
#include "neighbor/neighbor_search.hpp"
#include "contact/particle_contacts.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/scene_builder.hpp"

namespace mpdem {
namespace {

using test::add_particle;
using test::add_rect;
using test::dense_scene;
using test::make_scene;
using test::set_contact_law;
using IdPair = std::pair<std::int64_t, std::int64_t>;

std::map<std::int64_t, std::size_t> index_of(const Particles& p) {
  std::map<std::int64_t, std::size_t> m;
  for (std::size_t i = 0; i < p.size(); ++i) m[p.id[i]] = i;
  return m;
}

IdPair ordered(std::int64_t a, std::int64_t b) { return a < b ? IdPair{a, b} : IdPair{b, a}; }

// Listed pairs of the search, by ids.
std::set<IdPair> listed_pairs(const NeighborSearch& ns, const Particles& p) {
  std::set<IdPair> s;
  const auto& off = ns.pairs().offsets();
  const auto& idx = ns.pairs().indices();
  for (std::size_t i = 0; i + 1 < off.size(); ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) s.insert(ordered(p.id[i], p.id[idx[k]]));
  return s;
}

// The documented list criterion |x_i - x_j|^2 < (R_i + R_j + skin)^2 over all pairs (skin = 0:
// the touching pairs), by ids.
std::set<IdPair> brute_pairs(const Particles& p, double skin) {
  std::set<IdPair> s;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double cut = p.radius[i] + p.radius[j] + 0.0 + skin;
      if (norm2(p.x[j] - p.x[i]) < cut * cut) s.insert(ordered(p.id[i], p.id[j]));
    }
  return s;
}

// ---------------------------------------------------------------------------------------------
// 1. Lists and contacts against brute force, polydisperse 1:5, with barriers, across rebuilds.

// Random polydisperse cloud (radii uniform in [r0, 5 r0]) in the box [0, L]^3, with a floor and a
// wall so that particles also touch barriers.
Scene random_cloud(std::size_t n, double r0, double L, unsigned seed) {
  Scene s = make_scene(1e-6, 1.0);
  s.model.params.fields.gravity = {};
  set_contact_law(s, 0.5);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, L), ur(r0, 5.0 * r0);
  for (std::size_t i = 0; i < n; ++i)
    add_particle(s, static_cast<std::int64_t>(7 * i + 1), ur(rng), {u(rng), u(rng), u(rng)});
  std::int64_t next = 1;
  add_rect(s, next, {-L, -L, 0.1 * L}, {2 * L, -L, 0.1 * L}, {2 * L, 2 * L, 0.1 * L}, {-L, 2 * L, 0.1 * L});
  add_rect(s, next, {0.5 * L, -L, -L}, {0.5 * L, 2 * L, -L}, {0.5 * L, 2 * L, 2 * L}, {0.5 * L, -L, 2 * L});
  return s;
}

// Brute-force force on every particle (by id) for a state at rest with no spring history: Hertz
// 4/3 E* sqrt(r*) delta^(3/2) along the centre line (49), (51)-(52) for every touching pair and
// against the two infinite planes z = 0.1 L and x = 0.5 L (r* = R, barrier of the same material).
std::map<std::int64_t, Vec3> brute_forces(const Model& model, const Particles& p, double L) {
  std::map<std::int64_t, Vec3> f;
  const double E = model.materials[p.material[0]].young, nu = model.materials[p.material[0]].poisson;
  const double Estar = E / (2.0 * (1.0 - nu * nu));  // two equal materials
  for (std::size_t i = 0; i < p.size(); ++i) f[p.id[i]] = Vec3{};
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const Vec3 d = p.x[i] - p.x[j];
      const double dist = std::sqrt(norm2(d));
      const double overlap = p.radius[i] + p.radius[j] - dist;
      if (!(overlap > 0.0)) continue;
      const double rs = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
      const Vec3 fij = (4.0 / 3.0 * Estar * std::sqrt(rs) * std::pow(overlap, 1.5) / dist) * d;
      f[p.id[i]] += fij;
      f[p.id[j]] -= fij;
    }
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double R = p.radius[i];
    for (int axis = 0; axis < 2; ++axis) {
      const double h = axis == 0 ? p.x[i].z - 0.1 * L : p.x[i].x - 0.5 * L;
      const double overlap = R - std::abs(h);
      if (!(overlap > 0.0)) continue;
      const double fn = 4.0 / 3.0 * Estar * std::sqrt(R) * std::pow(overlap, 1.5) * (h > 0 ? 1.0 : -1.0);
      (axis == 0 ? f[p.id[i]].z : f[p.id[i]].x) += fn;
    }
  }
  return f;
}

// Evaluates the rates (at rest, no history) and compares every particle's force with brute force.
// Tolerance 1e-9 of the largest force: the sums differ only in the order of the terms.
void expect_forces_match(Interactions& in, Scene& s, double L, const char* when) {
  Particles& p = s.particles;
  std::fill(p.v.begin(), p.v.end(), Vec3{});
  std::fill(p.w.begin(), p.w.end(), Vec3{});
  in.evaluate(p, s.barriers, EvalRequest{0.0, 0.0, 1.0, false});
  const auto ref = brute_forces(s.model, p, L);
  double fmax = 0.0;
  for (const auto& [id, f] : ref) fmax = std::max(fmax, std::sqrt(norm2(f)));
  ASSERT_GT(fmax, 0.0);
  double worst = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) worst = std::max(worst, std::sqrt(norm2(p.force[i] - ref.at(p.id[i]))));
  EXPECT_LE(worst, 1e-9 * fmax) << when;
  // Contact count: brute-force touching pairs.
  EXPECT_EQ(in.stats().contacts_pp, brute_pairs(p, 0.0).size()) << when;
}

// The rebuild decision from a displacement measured elsewhere (the trapezoidal rule's passes,
// Interactions::set_measured_displacement) is the search's own on both sides of the threshold:
// with barriers (whose rule takes the displacement itself) and without (the squared rule).
TEST(NeighborEngine, MeasuredDisplacementGivesTheSearchsOwnDecision) {
  const double r0 = 1e-3, L = 0.08, skin = 0.2 * r0;  // m
  Scene s = random_cloud(300, r0, L, 3);
  Particles& p = s.particles;
  resolve_material_variants(s.model, p, s.barriers, "");
  const Barriers none;
  for (const Barriers* b : std::vector<const Barriers*>{&s.barriers, &none}) {
    NeighborSearch ns(skin, 0.0);
    ns.rebuild(p, *b);
    const std::vector<Vec3> x_build = ns.pairs().build_positions();
    std::set<bool> seen;
    for (const double f : {0.5, 1.0 - 1e-15, 1.0, 1.0 + 1e-15, 1.0 + 1e-9, 2.0}) {
      Particles q = p;
      q.x[17] = x_build[17] + Vec3{0.5 * skin * f, 0.0, 0.0};
      double max2 = 0.0;
      for (std::size_t i = 0; i < q.size(); ++i) max2 = std::max(max2, norm2(q.x[i] - x_build[i]));
      const bool own = ns.needs_rebuild(q, *b);
      EXPECT_EQ(ns.needs_rebuild(q, *b, max2), own) << "displacement " << f << " x skin/2";
      seen.insert(own);
    }
    EXPECT_EQ(seen.size(), 2u) << "both decisions occur";
    Particles more = p;  // a particle added since the build: stale whatever the displacement
    more.add(100000, 0, r0, 1000.0, {0.5 * L, 0.5 * L, 0.5 * L}, {});
    EXPECT_TRUE(ns.needs_rebuild(more, *b, 0.0));
  }
}

TEST(NeighborEngine, ListsAndContactsEqualBruteForceAcrossRebuilds) {
  const double r0 = 1e-3, L = 0.08;  // m
  Scene s = random_cloud(1200, r0, L, 11);
  const double skin = 0.2 * r0;
  s.model.params.neighbor.skin = skin;
  Particles& p = s.particles;
  resolve_material_variants(s.model, p, s.barriers, "");
  Interactions in(s.model, p, s.barriers, integrator_policy(s.model.params));
  ASSERT_DOUBLE_EQ(in.skin(), skin);
  in.force_rebuild(p, s.barriers, true);
  const std::set<IdPair> list0 = listed_pairs(in.search(), p);
  EXPECT_EQ(list0, brute_pairs(p, skin));
  ASSERT_GT(brute_pairs(p, 0.0).size(), 300u);  // a dense set: many contacts to miss
  expect_forces_match(in, s, L, "after the first build");

  // Moves below skin/2: no rebuild, and the old list still holds every touching pair.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (auto& x : p.x) x += Vec3{u(rng), u(rng), u(rng)} * (0.45 * skin / std::sqrt(3.0));
  ASSERT_FALSE(in.search().needs_rebuild(p, s.barriers));
  const std::uint64_t builds = in.search().rebuilds();
  const std::set<IdPair> touching = brute_pairs(p, 0.0);
  EXPECT_TRUE(std::includes(list0.begin(), list0.end(), touching.begin(), touching.end()));
  expect_forces_match(in, s, L, "moved < skin/2, no rebuild");
  EXPECT_EQ(in.search().rebuilds(), builds);

  // Moves beyond skin/2: the search must rebuild (here inside evaluate, as within a step), and
  // then with a reordering between steps; each time the list equals brute force again.
  for (auto& x : p.x) x += Vec3{u(rng), u(rng), u(rng)} * (3.0 * skin);
  ASSERT_TRUE(in.search().needs_rebuild(p, s.barriers));
  expect_forces_match(in, s, L, "moved > skin/2, rebuilt inside evaluate");
  EXPECT_EQ(in.search().rebuilds(), builds + 1);
  EXPECT_EQ(listed_pairs(in.search(), p), brute_pairs(p, skin));
  for (auto& x : p.x) x += Vec3{u(rng), u(rng), u(rng)} * (3.0 * skin);
  in.prepare_step(p, s.barriers);
  EXPECT_EQ(in.search().rebuilds(), builds + 2);
  EXPECT_EQ(listed_pairs(in.search(), p), brute_pairs(p, skin));
  expect_forces_match(in, s, L, "moved > skin/2, rebuilt and reordered in prepare_step");
}

// ---------------------------------------------------------------------------------------------
// 2. A tangential spring survives a forced rebuild with reordering.

TEST(NeighborEngine, SpringsSurviveRebuildAndReordering) {
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = dense_scene(8, 8, 4, r0, 0.05, 2.12 * r0, 0.15, 9, dt);
  // Shuffle the particles so that the spatial reordering moves (almost) every index.
  Particles& p = s.particles;
  std::vector<std::uint32_t> order(p.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(4));
  p.permute(order);
  // A skin wide enough that the steps below need no rebuild: a rebuild at a commit evaluation
  // would already reorder the particles, and the forced reordering below must move most.
  s.model.params.neighbor.skin = 1e-3;
  resolve_material_variants(s.model, p, s.barriers, "");
  Interactions in(s.model, p, s.barriers, integrator_policy(s.model.params));
  in.force_rebuild(p, s.barriers, false);
  in.evaluate(p, s.barriers, EvalRequest{0.0, 0.0, 1.0, true});
  VerletIntegrator verlet(s.model);
  const std::uint64_t builds = in.search().rebuilds();
  for (int k = 0; k < 200; ++k) verlet.step(p, s.barriers, in, k * dt, dt);
  ASSERT_EQ(in.search().rebuilds(), builds) << "the particles must still be in the shuffled order";

  const NeighborSearch& ns = in.search();
  std::map<IdPair, Vec3> before;  // spring acting on the pair's first id
  const auto idx0 = index_of(p);
  for (const IdPair& pr : brute_pairs(p, 0.0)) {
    const auto& idx = idx0;
    const Vec3 sp = in.particle_contacts().spring_between(ns, idx.at(pr.first), idx.at(pr.second));
    if (norm2(sp) > 0.0) before[pr] = sp;
  }
  ASSERT_GT(before.size(), 50u);
  const std::vector<std::int64_t> ids_before = p.id;

  in.force_rebuild(p, s.barriers, true);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < p.size(); ++i) moved += p.id[i] != ids_before[i];
  EXPECT_GT(moved, p.size() / 2) << "the reordering should move most particles";
  const auto idx = index_of(p);
  std::size_t flipped = 0;
  for (const auto& [pr, sp] : before) {
    const std::size_t i = idx.at(pr.first), j = idx.at(pr.second);
    flipped += i > j;  // the half list now stores the pair under the other member
    const Vec3 after = in.particle_contacts().spring_between(in.search(), i, j);
    EXPECT_EQ(after.x, sp.x) << pr.first << "-" << pr.second;
    EXPECT_EQ(after.y, sp.y);
    EXPECT_EQ(after.z, sp.z);
  }
  EXPECT_GT(flipped, 0u) << "some pairs must change orientation for the sign handling to be tested";
}

// What a rebuild recomputes is freed before the old contact history is copied out (the peak
// memory of a run is at its rebuilds): the search keeps only its pairs, the contacts keep
// neither springs nor per-particle terms nor cross-pair shares; the list's hook runs before the
// build positions, barrier candidates and blocks exist again.
TEST(NeighborEngine, RebuildFreesWhatItRecomputesBeforeTheHistoryIsCarried) {
  const double r0 = 1e-3;
  Scene s = dense_scene(16, 16, 6, r0, 0.05, 2.12 * r0, 0.15, 9, 4e-6);
  Particles& p = s.particles;
  resolve_material_variants(s.model, p, s.barriers, "");
  Interactions in(s.model, p, s.barriers, integrator_policy(s.model.params));
  in.force_rebuild(p, s.barriers, false);
  in.evaluate(p, s.barriers, EvalRequest{0.0, 0.0, 1.0, true});
  VerletIntegrator verlet(s.model);
  for (int k = 0; k < 50; ++k) verlet.step(p, s.barriers, in, k * 4e-6, 4e-6);  // springs load
  ParticleContacts& pc = in.particle_contacts();
  const std::size_t held = pc.memory_bytes();
  ASSERT_GT(held, p.size() * sizeof(ParticleContacts::Terms));
  NeighborSearch ns(in.skin(), 0.0);
  ns.rebuild(p, s.barriers);
  const std::size_t pairs = ns.pairs().num_pairs();
  ASSERT_GT(pairs, 500u);
  ASSERT_GT(ns.blocks().num_blocks(), 0u);
  ns.release_for_rebuild();
  EXPECT_EQ(ns.pairs().num_pairs(), pairs) << "the old pairs stay readable for the carried history";
  EXPECT_EQ(ns.pairs().size(), 0u);
  EXPECT_EQ(ns.blocks().num_blocks(), 0u);
  EXPECT_EQ(ns.barrier_candidates().size(), 0u);
  EXPECT_TRUE(ns.needs_rebuild(p, s.barriers));
  bool hooked = false;
  ns.rebuild(p, s.barriers, [&] {
    hooked = true;
    EXPECT_EQ(ns.pairs().num_pairs(), pairs);
    EXPECT_EQ(ns.pairs().owned(), p.size());
    EXPECT_EQ(ns.pairs().size(), 0u);
    EXPECT_EQ(ns.blocks().num_blocks(), 0u);
  });
  EXPECT_TRUE(hooked);
  EXPECT_EQ(ns.pairs().size(), p.size());
  EXPECT_GT(ns.blocks().num_blocks(), 0u);

  const ParticleContacts::CarriedHistory h = pc.carry_history(in.search());
  EXPECT_GT(h.second.size(), 100u);
  EXPECT_LT(pc.memory_bytes(), held / 10) << "springs, terms and cross shares are freed";
}

// ---------------------------------------------------------------------------------------------
// 3. Domain exit policy, through the mpdem executable.

struct ProcessResult {
  int status = -1;
  std::string err;
};

ProcessResult run_mpdem(const std::filesystem::path& dir, const std::string& args) {
  const std::filesystem::path err = dir / "stderr.txt";
  const std::string cmd = std::string("\"") + MPDEM_BINARY + "\" " + args + " 2> \"" + err.string() + "\" > /dev/null";
  const int raw = std::system(cmd.c_str());
  ProcessResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  r.err = ss.str();
  return r;
}

// Two particles at rest and one (id 7) shot along +x at 2 m/s from x = 0.005 m; the domain ends
// at x = 0.02 m, so it leaves at t_exit = 0.0075 s and is caught at the end of that step.
std::filesystem::path write_exit_scene(const std::string& policy) {
  const auto dir = std::filesystem::temp_directory_path() / ("mpdem_exit_" + policy + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "particles.csv") << "id,x,y,z,vx,vy,vz,radius\n"
                                          "3,0.0,0.0,0.0,0,0,0,0.001\n"
                                          "7,0.005,0.0,0.0,2.0,0,0,0.001\n"
                                          "11,-0.005,0.0,0.0,0,0,0,0.001\n";
  std::ofstream(dir / "scene.toml") << "[time]\nduration = 0.01\nintegrator = \"verlet\"\ndt = 1e-5\n"
                                       "[gravity]\nvector = [0.0, 0.0, 0.0]\n"
                                       "[[material]]\nname = \"m\"\n"
                                       "[[particles]]\nfile = \"particles.csv\"\n"
                                       "[domain]\nmin = [-0.02, -0.02, -0.02]\nmax = [0.02, 0.02, 0.02]\n"
                                       "on_exit = \""
                                    << policy << "\"\n[output]\ndir = \"out\"\nlog_every = 100\n";
  return dir;
}

TEST(NeighborEngine, DomainExitRemoveReportsIdAndTime) {
  const auto dir = write_exit_scene("remove");
  const ProcessResult r = run_mpdem(dir, "run \"" + (dir / "scene.toml").string() + "\"");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("removed particle id 7"), std::string::npos) << r.err;
  std::ifstream csv(dir / "out" / "removed.csv");
  ASSERT_TRUE(csv.good()) << "removed.csv missing";
  std::string header, row, extra;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_FALSE(std::getline(csv, extra) && !extra.empty()) << "only particle 7 leaves";
  EXPECT_EQ(header.rfind("time,id", 0), 0u) << header;
  double t = 0.0;
  long id = 0;
  ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%ld", &t, &id), 2) << row;
  EXPECT_EQ(id, 7);
  // Free flight: x = 0.005 + 2 t > 0.02 first at the end of the step containing t_exit = 7.5 ms
  // (steps of 10 us; 1e-9 s allows for the rounding of the accumulated time).
  EXPECT_GE(t, 0.0075 - 1e-9);
  EXPECT_LE(t, 0.0075 + 1e-5 + 1e-9);
  std::filesystem::remove_all(dir);
}

TEST(NeighborEngine, DomainExitStopFailsNamingTheParticle) {
  const auto dir = write_exit_scene("stop");
  const ProcessResult r = run_mpdem(dir, "run -q \"" + (dir / "scene.toml").string() + "\"");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("particle id 7"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mpdem
