// Periodic boundaries ([domain] periodic, parallel/periodic_images.hpp): a particle crossing a
// periodic face keeps its velocity and meets the particles on the other side; a pair straddling
// the face has the force, spring, heat flow and near-field force of the same pair in the interior;
// an elastic frictionless periodic gas conserves energy as well as a walled one; trajectories do
// not depend on the thread count, on the ids, on when the lists are rebuilt, or on a checkpoint.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <map>
#include <random>

#include "contact/particle_contacts.hpp"
#include "io/particle_csv_writer.hpp"
#include "neighbor/neighbor_search.hpp"
#include "integrate/energy_balance.hpp"
#include "sim/simulation.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/scene_builder.hpp"
#include "support/run_command.hpp"

namespace mpdem {
namespace {

namespace fs = std::filesystem;

constexpr double kL = 0.0625;  // m, the period (a power of two: shifting by it is exact)

void make_periodic(Scene& s, const Vec3& min, const Vec3& max, std::array<bool, 3> axes) {
  DomainParams& d = s.model.params.domain;
  d.bounded = true;
  d.min = min;
  d.max = max;
  d.periodic = axes;
}

// Two equal spheres on the x axis, no gravity, e = 0.9, friction 0.5; optionally periodic along x.
Scene pair_scene(bool periodic, const Vec3& xa, const Vec3& va, const Vec3& xb, const Vec3& vb) {
  Scene s = test::make_scene(1e-6, 1.0);
  s.model.params.fields.gravity = {};
  s.model.params.analysis.rotation = true;
  ContactLawParams& c = s.model.params.contact.particle_particle;
  c.restitution = 0.9;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.5;
  Material& m = s.model.materials.front();
  m.density = 2500.0;
  m.young = 1e7;
  m.poisson = 0.3;
  s.model.params.checks.max_overlap = 0.2;  // soft spheres (the impacts are at up to 1 m/s)
  test::add_particle(s, 1, 0.001, xa, va);
  test::add_particle(s, 2, 0.001, xb, vb);
  if (periodic) make_periodic(s, {0, 0, 0}, {kL, kL, kL}, {true, false, false});
  return s;
}

std::size_t index_of(const Particles& p, std::int64_t id) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == id) return i;
  ADD_FAILURE() << "no particle id " << id;
  return 0;
}

Vec3 spring_of(Simulation& sim) {
  const auto h = sim.interactions().particle_contacts().export_history(sim.particles(), sim.interactions().search());
  return h.empty() ? Vec3{} : (h[0].id_first == 1 ? h[0].spring : -h[0].spring);
}

}  // namespace

// A sphere moving at 1 m/s leaves through x = L, comes back at x = 0 with its velocity, and hits
// a resting sphere there: the result is the interior collision's (the same pair, unwrapped).
TEST(PeriodicBoundaries, CrossingParticleKeepsVelocityAndMeetsTheOtherSide) {
  const double y = 0.03125, z = 0.03125;
  Simulation per(pair_scene(true, {kL - 0.002, y, z}, {1, 0, 0}, {0.004, y, z}, {}), RunOptions{{}, false, false});
  Simulation in(pair_scene(false, {kL - 0.002, y, z}, {1, 0, 0}, {kL + 0.004, y, z}, {}), RunOptions{{}, false, false});
  per.initialize();
  in.initialize();
  bool crossed = false;
  for (int k = 0; k < 8000; ++k) {  // 8 ms: the crossing after 2 ms, the impact at 4 ms
    per.advance(1e-6);
    in.advance(1e-6);
    const Particles& p = per.particles();
    const std::size_t a = index_of(p, 1);
    if (p.image[a][0] == 1 && !crossed) {
      crossed = true;
      EXPECT_GE(p.x[a].x, 0.0);  // wrapped
      EXPECT_LT(p.x[a].x, 0.002);
      EXPECT_EQ(p.v[a].x, 1.0);  // untouched so far
    }
  }
  ASSERT_TRUE(crossed);
  const Particles& p = per.particles();
  const Particles& q = in.particles();
  const std::size_t a = index_of(p, 1), b = index_of(p, 2), qa = index_of(q, 1), qb = index_of(q, 2);
  // The collision happened: B took most of A's momentum (e = 0.9: (1 + e)/2 = 0.95 m/s).
  EXPECT_NEAR(p.v[b].x, 0.95, 0.01);
  // The same collision as in the interior, up to round-off: the wrapped centres round differently
  // (1.7e-15 m apart after 4 mm of travel), and the first touch's overlap, a fraction of v dt,
  // amplifies that in the dashpot (delta^1/4): measured 6.8e-8 m/s on an impact at 1 m/s.
  EXPECT_LE(std::sqrt(norm2(p.v[a] - q.v[qa])), 1e-6);
  EXPECT_LE(std::sqrt(norm2(p.v[b] - q.v[qb])), 1e-6);
  // Unwrapped positions agree with the interior run's (measured 2.3e-10 m, from the above).
  const Vec3 ua = p.x[a] + Vec3{kL * p.image[a][0], 0, 0};
  EXPECT_LE(std::abs(ua.x - q.x[qa].x), 1e-9);
  EXPECT_LE(std::abs(p.x[b].x + kL - q.x[qb].x), 1e-9);
  std::printf("crossing: B after impact %.6f m/s (interior %.6f), A %.3e m/s\n", p.v[b].x, q.v[qb].x, p.v[a].x);
  // The particle CSV gives the image counts and the unwrapped centre.
  const fs::path dir = test::fresh_dir("periodic_csv");
  write_particles_csv(dir / "p.csv", p, per.time(), {kL, 0.0, 0.0});
  std::ifstream csv(dir / "p.csv");
  std::string header, row;
  std::getline(csv, header);
  EXPECT_NE(header.find(",ix,iy,iz,xu,yu,zu"), std::string::npos) << header;
  bool found = false;
  while (std::getline(csv, row)) {
    std::vector<std::string> cells;
    std::stringstream ss(row);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    if (cells.size() < 25 || cells[1] != "1") continue;
    found = true;
    EXPECT_EQ(cells[19], "1");                       // ix (after the fixed flag)
    EXPECT_NEAR(std::stod(cells[22]), ua.x, 1e-15);  // xu, m
  }
  EXPECT_TRUE(found);
  fs::remove_all(dir);
}

// A sliding pair straddling x = 0 (one centre just below L, the other just above 0) has, step by
// step through the whole contact, the force and spring of the same pair unwrapped (the second
// centre just above L, no periodic domain), and so do conduction and the Coulomb force: bitwise
// in the same state, within 1e-12 of their peak values over the first 20 steps, and within 1e-11
// over the whole contact (the centres round differently at x ~ 0 and x ~ L: measured 1.6e-12).
TEST(PeriodicBoundaries, StraddlingPairEqualsTheInteriorPair) {
  const double y = 0.03125, z = 0.03125, h = 0.0009765625;  // m, 2^-10: centres 2^-9 apart through the face
  for (const bool fields : {false, true}) {
    auto make = [&](bool periodic) {
      Scene s = pair_scene(periodic, {kL - h, y, z}, {-0.05, 0.2, 0.05}, {periodic ? h : kL + h, y, z},
                           {0.05, -0.2, 0.0});
      if (fields) {
        s.model.params.analysis.thermal = true;
        s.model.params.thermal.conduction = true;
        s.model.params.near_field.coulomb = true;
        s.model.params.near_field.cutoff = 0.004;
        s.particles.charge = {1e-9, -2e-9};
        s.particles.T = {300.0, 350.0};
      }
      return s;
    };
    Simulation per(make(true), RunOptions{{}, false, false});
    Simulation in(make(false), RunOptions{{}, false, false});
    per.initialize();
    in.initialize();
    double df = 0.0, ds = 0.0, dq = 0.0, peak_f = 0.0, peak_s = 0.0, peak_q = 0.0;
    int touching = 0;
    for (int k = 0; k < 400; ++k) {
      per.advance(1e-6);
      in.advance(1e-6);
      const Particles& p = per.particles();
      const Particles& q = in.particles();
      const std::size_t a = index_of(p, 1), qa = index_of(q, 1);
      if (k == 0) {  // the same state: the same bits
        EXPECT_EQ(p.force[a], q.force[qa]);
        EXPECT_EQ(p.heat[a], q.heat[qa]);
      }
      if (k == 20) {
        EXPECT_LE(df, 1e-12 * peak_f);
        EXPECT_LE(ds, 1e-12 * peak_s);
        EXPECT_LE(dq, 1e-12 * peak_q);
      }
      df = std::max(df, std::sqrt(norm2(p.force[a] - q.force[qa])));
      peak_f = std::max(peak_f, std::sqrt(norm2(q.force[qa])));
      ds = std::max(ds, std::sqrt(norm2(spring_of(per) - spring_of(in))));
      peak_s = std::max(peak_s, std::sqrt(norm2(spring_of(in))));
      dq = std::max(dq, std::abs(p.heat[a] - q.heat[qa]));
      peak_q = std::max(peak_q, std::abs(q.heat[qa]));
      touching += per.interactions().stats().contacts_pp == 1;
      ASSERT_EQ(per.interactions().stats().contacts_pp, in.interactions().stats().contacts_pp) << "step " << k;
    }
    const double rf = df / peak_f, rs = ds / peak_s, rq = fields ? dq / peak_q : 0.0;
    std::printf("straddling pair (%s): %d steps in contact, difference / peak: force %.2e spring %.2e heat %.2e\n",
                fields ? "with heat and Coulomb" : "contact only", touching, rf, rs, rq);
    EXPECT_GT(touching, 100);
    EXPECT_GT(peak_s, 0.0);
    EXPECT_LE(rf, 1e-11);
    EXPECT_LE(rs, 1e-11);
    EXPECT_LE(rq, 1e-11);
    if (fields) {
      EXPECT_GT(peak_q, 0.0);
    }
  }
}

namespace {
// 64 spheres with random velocities in a cube of side 4 a, no gravity, elastic (e = 1) and
// frictionless: walled (six rectangles) or periodic along all three axes.
Scene gas(bool periodic) {
  Scene s = test::make_scene(2e-6, 1.0);
  s.model.params.fields.gravity = {};
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->restitution = 1.0;
    c->mu_static = 0.0;
    c->mu_dynamic = 0.0;
  }
  Material& m = s.model.materials.front();
  m.density = 2500.0;
  m.young = 1e8;
  m.poisson = 0.3;
  s.model.params.checks.max_overlap = 0.2;
  const double L = 0.03, a = L / 4;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::int64_t id = 0;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        test::add_particle(s, ++id, 0.002, {a * (i + 0.5), a * (j + 0.5), a * (k + 0.5)}, {u(rng), u(rng), u(rng)});
  if (periodic) {
    make_periodic(s, {0, 0, 0}, {L, L, L}, {true, true, true});
  } else {
    std::int64_t next = 1;
    test::add_rect(s, next, {0, 0, 0}, {L, 0, 0}, {L, L, 0}, {0, L, 0});
    test::add_rect(s, next, {0, 0, L}, {0, L, L}, {L, L, L}, {L, 0, L});
    test::add_rect(s, next, {0, 0, 0}, {0, L, 0}, {0, L, L}, {0, 0, L});
    test::add_rect(s, next, {L, 0, 0}, {L, 0, L}, {L, L, L}, {L, L, 0});
    test::add_rect(s, next, {0, 0, 0}, {0, 0, L}, {L, 0, L}, {L, 0, 0});
    test::add_rect(s, next, {0, L, 0}, {L, L, 0}, {L, L, L}, {0, L, L});
  }
  return s;
}

struct GasRun {
  double drift = 0.0;           // -, largest |E(t) - E(0)| / E(0)
  std::uint64_t crossings = 0;  // sum of |image| at the end
  std::size_t collisions = 0;   // evaluations with some particle contact
};

GasRun run_gas(bool periodic, Integrator integ) {
  Scene s = gas(periodic);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  auto energy = [&] {
    const ParticleEnergy e = particle_energy(sim.particles(), Vec3{});
    return e.kinetic + e.rotational + sim.interactions().stats().elastic_energy;
  };
  sim.initialize();
  const double e0 = energy();
  GasRun r;
  for (int k = 0; k < 25000; ++k) {  // 50 ms: each sphere travels about 20 mm
    sim.advance(2e-6);
    r.drift = std::max(r.drift, std::abs(energy() - e0) / e0);
    r.collisions += sim.interactions().stats().contacts_pp > 0;
  }
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int c = 0; c < 3; ++c) r.crossings += static_cast<std::uint64_t>(std::abs(p.image[i][c]));
  return r;
}
}  // namespace

// Energy is conserved across the periodic faces as well as with walls: the drift (measured
// 1e-6 - 1e-5 both ways) stays below twice the walled gas's, or 1e-6 of the energy.
TEST(PeriodicBoundaries, ElasticGasConservesEnergyAsTheWalledOne) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const GasRun walled = run_gas(false, integ), periodic = run_gas(true, integ);
    std::printf("elastic gas (%s): drift walled %.2e, periodic %.2e (%llu face crossings, %zu steps with contacts)\n",
                integ == Integrator::Verlet ? "verlet" : "trapezoidal", walled.drift, periodic.drift,
                static_cast<unsigned long long>(periodic.crossings), periodic.collisions);
    EXPECT_GT(periodic.crossings, 20u);
    EXPECT_GT(periodic.collisions, 1000u);
    EXPECT_LE(periodic.drift, std::max(2.0 * walled.drift, 1e-6));
  }
}

namespace {
// A dense frictional packing, periodic along x and y, drifting along x at 0.3 m/s with random
// velocities and spins, so that particles cross the faces, contacts form across them and lists
// are rebuilt. No gravity and no barrier: a barrier ending on a periodic face acts on a particle
// that drifted past the face through its edge (docs/scene.md), which depends on when the
// particles are wrapped.
Scene periodic_bed(int nx, int ny, int nz, unsigned seed, double skin, std::int64_t id_step, bool periodic = true) {
  const double r0 = 1e-3, a = 2.12 * r0, dt = 4e-6;
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = {};
  s.model.params.neighbor.skin = skin;
  test::set_contact_law(s, 0.5);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), ur(0.0, 1.0);
  std::int64_t id = 5000;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double r = r0 * (1.0 + 0.05 * ur(rng));
        // The first column and row straddle the faces x = 0 and y = 0.
        const Vec3 x{a * (i + 0.05) + 0.01 * a * u(rng), a * (j + 0.05) + 0.01 * a * u(rng), a * (k + 0.5)};
        const Vec3 v{0.3 + 0.15 * u(rng), 0.15 * u(rng), 0.15 * u(rng)};
        test::add_particle(s, id, r, x, v, {150 * u(rng), 150 * u(rng), 150 * u(rng)});
        id += id_step;
      }
  const double Lx = a * nx, Ly = a * ny;
  if (periodic) make_periodic(s, {0, 0, -1.0}, {Lx, Ly, 1.0}, {true, true, false});
  return s;
}

struct State {
  // creation order -> unwrapped x [m], v [m/s], w [rad/s]
  std::map<std::int64_t, std::array<Vec3, 3>> xvw;
  std::size_t contacts = 0;
  std::uint64_t rebuilds = 0, crossings = 0;
};

State state_of(Simulation& sim, double Lx, double Ly, std::int64_t id_step = 3) {
  State st;
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 u = p.x[i] + Vec3{Lx * p.image[i][0], Ly * p.image[i][1], 0.0};
    st.xvw[(p.id[i] - 5000) / id_step] = {u, p.v[i], p.w[i]};
    st.crossings += static_cast<std::uint64_t>(std::abs(p.image[i][0]) + std::abs(p.image[i][1]));
  }
  st.contacts = sim.interactions().stats().contacts_pp;
  st.rebuilds = sim.interactions().stats().rebuilds;
  return st;
}

State run_bed(int nx, int ny, int nz, double skin, std::int64_t id_step, Integrator integ, int steps,
              bool periodic = true) {
  Scene s = periodic_bed(nx, ny, nz, 9, skin, id_step, periodic);
  s.model.params.time.integrator = integ;
  const double a = 2.12e-3;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < steps; ++k) sim.advance(4e-6);
  return state_of(sim, a * nx, a * ny, id_step);
}

// Largest difference of the unwrapped positions, velocities and spins, relative to the largest
// value of each, matched by order of creation.
std::array<double, 3> difference(const State& a, const State& b) {
  std::array<double, 3> d{}, s{};
  auto ia = a.xvw.begin();
  auto ib = b.xvw.begin();
  for (; ia != a.xvw.end() && ib != b.xvw.end(); ++ia, ++ib)
    for (int k = 0; k < 3; ++k) {
      d[k] = std::max(d[k], std::sqrt(norm2(ia->second[k] - ib->second[k])));
      s[k] = std::max(s[k], std::sqrt(norm2(ia->second[k])));
    }
  for (int k = 0; k < 3; ++k) d[k] /= s[k];
  return d;
}
}  // namespace

// 2560 spheres (more than the parallel threshold): 1 and 2 threads give the same bits.
TEST(PeriodicBoundaries, ThreadCountInvariance) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    omp_set_num_threads(1);
    const State one = run_bed(16, 16, 10, 2e-4, 3, integ, 300);
    omp_set_num_threads(2);
    const State two = run_bed(16, 16, 10, 2e-4, 3, integ, 300);
    EXPECT_GT(one.crossings, 5u);
    EXPECT_GT(one.contacts, 500u);
    const auto d = difference(one, two);
    EXPECT_EQ(d[0], 0.0);
    EXPECT_EQ(d[1], 0.0);
    EXPECT_EQ(d[2], 0.0);
    EXPECT_EQ(one.contacts, two.contacts);
  }
}

// Other ids (which decide which image of a pair across a face is listed), a thinner skin (other
// rebuild and wrap times, history carried across them): the same trajectories to round-off.
TEST(PeriodicBoundaries, RelabellingAndRebuildInvariance) {
  const int steps = 3000;
  const State base = run_bed(8, 8, 5, 4e-4, 3, Integrator::Verlet, steps);
  const State relabelled = run_bed(8, 8, 5, 4e-4, -7, Integrator::Verlet, steps);
  const State thin = run_bed(8, 8, 5, 4e-5, 3, Integrator::Verlet, steps);
  const State wb = run_bed(8, 8, 5, 4e-4, 3, Integrator::Verlet, steps, false);
  const State wt = run_bed(8, 8, 5, 4e-5, 3, Integrator::Verlet, steps, false);
  const auto dw = difference(wb, wt);
  std::printf("non-periodic: skin/10 x %.2e v %.2e w %.2e\n", dw[0], dw[1], dw[2]);
  EXPECT_GT(base.crossings, 20u);
  EXPECT_GT(thin.rebuilds, base.rebuilds);
  const auto dr = difference(base, relabelled), ds = difference(base, thin);
  std::printf("periodic bed, %d steps, %llu face crossings: relabelled x %.2e v %.2e w %.2e; skin /10 (%llu vs %llu "
              "rebuilds) x %.2e v %.2e w %.2e\n",
              steps, static_cast<unsigned long long>(base.crossings), dr[0], dr[1], dr[2],
              static_cast<unsigned long long>(thin.rebuilds), static_cast<unsigned long long>(base.rebuilds), ds[0],
              ds[1], ds[2]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(dr[k], 1e-9);
    EXPECT_LE(ds[k], 1e-9);
  }
}

// A checkpoint of a periodic run (images, ghosts' history) resumes bitwise.
TEST(PeriodicBoundaries, CheckpointResumesBitwise) {
  const fs::path dir = test::fresh_dir("periodic_checkpoint");
  const double a = 2.12e-3;
  Simulation full(periodic_bed(8, 8, 5, 9, 4e-4, 3), RunOptions{{}, false, false});
  for (int k = 0; k < 2000; ++k) full.advance(4e-6);
  Simulation first(periodic_bed(8, 8, 5, 9, 4e-4, 3), RunOptions{{}, false, false});
  for (int k = 0; k < 1200; ++k) first.advance(4e-6);
  first.write_checkpoint(dir / "ck.bin");
  Simulation resumed(periodic_bed(8, 8, 5, 9, 4e-4, 3), RunOptions{{}, false, false});
  resumed.resume_from(dir / "ck.bin");
  for (int k = 0; k < 800; ++k) resumed.advance(4e-6);
  const State f = state_of(full, 8 * a, 8 * a), r = state_of(resumed, 8 * a, 8 * a);
  EXPECT_GT(f.crossings, 10u);
  const auto d = difference(f, r);
  EXPECT_EQ(d[0], 0.0);
  EXPECT_EQ(d[1], 0.0);
  EXPECT_EQ(d[2], 0.0);
  fs::remove_all(dir);
}

// A period shorter than twice the neighbour reach is refused when the lists are built.
TEST(PeriodicBoundaries, TooShortPeriodIsRefused) {
  Scene s = pair_scene(true, {0.001, 0.03, 0.03}, {}, {0.0035, 0.03, 0.03}, {});
  s.model.params.domain.max.x = 0.004;  // 4 mm, two spheres of 2 mm
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  try {
    sim.initialize();
    sim.advance(1e-6);
    FAIL() << "expected the period to be refused";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("shorter than twice the neighbour range"), std::string::npos) << e.what();
  }
}

}  // namespace mpdem

namespace mpdem {

// Gravity along a periodic axis: a falling sphere wraps through the face several times, and the
// energy balance uses the unwrapped centre (before, each wrap added m g L and the energy-jump
// check stopped the run at the first one).
TEST(PeriodicBoundaries, FallingThroughAPeriodicFaceKeepsTheEnergyBalance) {
  Scene s = test::make_scene(1e-5, 0.1);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {9.81, 0.0, 0.0};
  test::add_particle(s, 1, 0.0005, {0.0085, 0.005, 0.005});
  make_periodic(s, {0, 0, 0}, {0.01, 0.01, 0.01}, {true, false, false});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.initialize();
  for (int k = 0; k < 10000; ++k) ASSERT_NO_THROW(sim.advance(1e-5)) << "step " << k;
  const Particles& p = sim.particles();
  EXPECT_GE(p.image[0][0], 3);  // 0.1 s of free fall: 49 mm, through the face 4 times
  const RunRecord& r = sim.record();
  const double mgL = p.mass[0] * 9.81 * 0.01;  // J, what one wrap added before
  EXPECT_LE(std::abs(r.balance - r.start_balance), 1e-6 * mgL) << r.balance << " vs " << r.start_balance;
}

}  // namespace mpdem
