// Neighbour search through the engine (physics.md section 11): the lists NeighborSearch keeps
// against an O(N^2) brute force, contacts found by Interactions against brute-force touching
// pairs, independence of the results from the skin (i.e. from when the lists are rebuilt),
// contact history across a rebuild with reordering, the domain-exit policy of the `mpdem`
// executable, and bitwise identical results for 1 and 2 OpenMP threads.
#include <gtest/gtest.h>
#include <omp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/parallel.hpp"
#include "neighbor/pair_blocks.hpp"
#include "contact/pair_batch.hpp"
#include "integrate/integrator_policy.hpp"
#include "integrate/verlet.hpp"
#include "model/material_variants.hpp"
#include "sim/interactions.hpp"
#include "neighbor/neighbor_search.hpp"
#include "contact/particle_contacts.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

namespace mpdem {
namespace {

using test::add_particle;
using test::make_scene;
using IdPair = std::pair<std::int64_t, std::int64_t>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Rectangle a-b-c-d as two triangles of one group (barriers work from both sides).
void add_rect(Scene& s, std::int64_t& next, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Material& m = s.model.materials.front();
  const int g = s.barriers.group_index("box");
  s.barriers.add(next++, a, b, c, g, m.young, m.poisson, MotionLaw{}, 0.0, kNaN);
  s.barriers.add(next++, a, c, d, g, m.young, m.poisson, MotionLaw{}, 0.0, kNaN);
}

// Open box [0, L]^2 x [0, H]: floor and four walls.
void add_box(Scene& s, double L, double H) {
  std::int64_t next = 1;
  add_rect(s, next, {0, 0, 0}, {L, 0, 0}, {L, L, 0}, {0, L, 0});
  add_rect(s, next, {0, 0, 0}, {0, L, 0}, {0, L, H}, {0, 0, H});
  add_rect(s, next, {L, 0, 0}, {L, 0, H}, {L, L, H}, {L, L, 0});
  add_rect(s, next, {0, 0, 0}, {0, 0, H}, {L, 0, H}, {L, 0, 0});
  add_rect(s, next, {0, L, 0}, {L, L, 0}, {L, L, H}, {0, L, H});
}

void set_contact_law(Scene& s, double mu) {
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->restitution = 0.5;
    c->mu_static = mu;
    c->mu_dynamic = mu;
    c->mu_rolling = 0.0;
  }
}

// A dense granular scene: particles on a jittered cubic lattice of spacing `a` (radii in
// [r0, r0 (1 + spread)]), random velocities up to v0 and spins, in an open box with gravity.
// Spacing near 2 r0 (overlaps below the engine's 5 % check) makes contacts and springs form at once.
Scene dense_scene(int nx, int ny, int nz, double r0, double spread, double a, double v0, unsigned seed,
                  double dt) {
  Scene s = make_scene(dt, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  set_contact_law(s, 0.5);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> ur(0.0, 1.0);
  std::int64_t id = 100;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double r = r0 * (1.0 + spread * ur(rng));
        const Vec3 x{a * (i + 0.5) + 0.01 * a * u(rng), a * (j + 0.5) + 0.01 * a * u(rng), a * (k + 0.5)};
        const Vec3 v{v0 * u(rng), v0 * u(rng), v0 * u(rng)};
        const Vec3 w{v0 / r0 * u(rng), v0 / r0 * u(rng), v0 / r0 * u(rng)};
        add_particle(s, id, r, x, v, w);
        id += 3;  // ids are not indices
      }
  add_box(s, a * std::max(nx, ny), a * (nz + 2));
  return s;
}

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
  for (std::size_t i = 0; i < n; ++i) add_particle(s, static_cast<std::int64_t>(7 * i + 1), ur(rng), {u(rng), u(rng), u(rng)});
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
// 2. Trajectories do not depend on the skin (i.e. on when the lists are rebuilt).

struct Snapshot {
  std::map<std::int64_t, std::array<Vec3, 3>> xvw;  // id -> x [m], v [m/s], w [rad/s]
  std::uint64_t rebuilds = 0;
  std::size_t contacts_pp = 0, contacts_pb = 0;
};

// States by id plus the counters, at the end of a run.
Snapshot snapshot_of(Simulation& sim) {
  Snapshot out;
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) out.xvw[p.id[i]] = {p.x[i], p.v[i], p.w[i]};
  out.rebuilds = sim.interactions().stats().rebuilds;
  out.contacts_pp = sim.interactions().stats().contacts_pp;
  out.contacts_pb = sim.interactions().stats().contacts_pb;
  return out;
}

Snapshot run_dense(double skin, Integrator integ, int steps, int nx, int ny, int nz, unsigned seed) {
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = dense_scene(nx, ny, nz, r0, 0.05, 2.12 * r0, 0.15, seed, dt);
  s.model.params.time.integrator = integ;
  s.model.params.neighbor.skin = skin;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  return snapshot_of(sim);
}

// max over particles |a - b| / max over particles |a|, per field.
std::array<double, 3> relative_difference(const Snapshot& a, const Snapshot& b) {
  std::array<double, 3> diff{}, scale{};
  for (const auto& [id, f] : a.xvw) {
    const auto& g = b.xvw.at(id);
    for (int k = 0; k < 3; ++k) {
      diff[k] = std::max(diff[k], std::sqrt(norm2(f[k] - g[k])));
      scale[k] = std::max(scale[k], std::sqrt(norm2(f[k])));
    }
  }
  for (int k = 0; k < 3; ++k) diff[k] /= scale[k];
  return diff;
}

TEST(NeighborEngine, TrajectoriesIndependentOfSkin) {
  const double d = 2e-3;  // m, nominal diameter
  const int steps = 3000;
  const Snapshot thin = run_dense(0.05 * d, Integrator::Verlet, steps, 6, 6, 5, 3);
  const Snapshot thick = run_dense(0.5 * d, Integrator::Verlet, steps, 6, 6, 5, 3);
  // The scene must really exercise the lists: contacts with particles and walls, and rebuilds
  // at different times.
  EXPECT_GT(thin.contacts_pp, 60u);  // of 180 particles, after settling
  EXPECT_GT(thin.contacts_pb, 10u);
  EXPECT_GT(thin.rebuilds, thick.rebuilds);
  EXPECT_GT(thick.rebuilds, 1u);
  ASSERT_EQ(thin.xvw.size(), thick.xvw.size());
  const auto rel = relative_difference(thin, thick);
  EXPECT_LE(rel[0], 1e-9) << "positions";
  EXPECT_LE(rel[1], 1e-9) << "velocities";
  EXPECT_LE(rel[2], 1e-9) << "angular velocities";
  RecordProperty("rel_x", std::to_string(rel[0]));
  std::printf("skin 0.05 d vs 0.5 d after %d steps: rebuilds %llu vs %llu, relative difference x %.3g v %.3g w %.3g\n",
              steps, static_cast<unsigned long long>(thin.rebuilds), static_cast<unsigned long long>(thick.rebuilds),
              rel[0], rel[1], rel[2]);
}

// ---------------------------------------------------------------------------------------------
// 3. A tangential spring survives a forced rebuild with reordering.

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

// ---------------------------------------------------------------------------------------------
// 4. Domain exit policy, through the mpdem executable.

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

// ---------------------------------------------------------------------------------------------
// 5. Bitwise identical results for 1 and 2 threads (> kParallelThreshold particles).

Snapshot run_threads(int threads, Integrator integ, int steps) {
  omp_set_num_threads(threads);
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = dense_scene(20, 20, 14, r0, 0.05, 2.12 * r0, 0.15, 21, dt);  // 5600 particles
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  return snapshot_of(sim);
}

void expect_bitwise_equal(const Snapshot& a, const Snapshot& b) {
  ASSERT_EQ(a.xvw.size(), b.xvw.size());
  std::size_t differ = 0;
  for (const auto& [id, f] : a.xvw) {
    const auto& g = b.xvw.at(id);
    for (int k = 0; k < 3; ++k) differ += f[k].x != g[k].x || f[k].y != g[k].y || f[k].z != g[k].z;
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_EQ(a.contacts_pp, b.contacts_pp);
  EXPECT_EQ(a.contacts_pb, b.contacts_pb);
  EXPECT_EQ(a.rebuilds, b.rebuilds);
}

// The AVX-512 candidate selection (when built in) selects bit for bit what the scalar one does.
Snapshot run_selection(bool vector, Integrator integ, int steps) {
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = dense_scene(20, 20, 14, r0, 0.05, 2.12 * r0, 0.15, 21, dt);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.interactions().particle_contacts().use_vector_select(vector);
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  return snapshot_of(sim);
}

TEST(NeighborEngine, VectorAndScalarCandidateSelectionAgreeBitwise) {
  if (!kVectorSelect) GTEST_SKIP() << "built without AVX-512: only the scalar selection exists";
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const int steps = integ == Integrator::Verlet ? 100 : 25;
    const Snapshot vec = run_selection(true, integ, steps);
    const Snapshot sca = run_selection(false, integ, steps);
    EXPECT_GT(vec.contacts_pp, 50u);
    expect_bitwise_equal(vec, sca);
  }
}

TEST(NeighborEngine, BitwiseIdenticalForOneAndTwoThreads) {
  static_assert(20 * 20 * 14 > 2 * kParallelThreshold, "the scene must take the parallel paths");
  static_assert(20 * 20 * 14 > PairBlocks::kBlock, "the scene must have pairs across blocks, one block per thread");
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const int steps = integ == Integrator::Verlet ? 100 : 25;
    const Snapshot one = run_threads(1, integ, steps);
    const Snapshot two = run_threads(2, integ, steps);
    // Contacts exist (few yet after 25 trapezoidal steps: the lattice starts nearly touching).
    EXPECT_GT(one.contacts_pp, 50u);
    EXPECT_GT(one.contacts_pb, 20u);
    expect_bitwise_equal(one, two);
  }
  omp_set_num_threads(omp_get_num_procs());
}

}  // namespace
}  // namespace mpdem
