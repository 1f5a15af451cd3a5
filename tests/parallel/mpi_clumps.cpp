// Clumps over several ranks (docs/parallel.md "Clumps"), run under mpirun -np 1, 2, 3, 4; every
// rank also runs the one-rank reference itself and compares its own particles and bodies with it,
// by id:
//  - tetrahedra and dumbbells falling and colliding in a box that the bricks cut, both
//    integrators: bodies cross the cuts (migrating with their members and, under the trapezoidal
//    rule, their rate history), and the run follows the one-rank run within 1e-10;
//  - a dumbbell whose centre is on one side of the cut and whose member reaches across it hits a
//    sphere on the other side: the member is a ghost there, the contact is the one-rank contact;
//  - a checkpoint written on two ranks (one under -np 1) resumes on one and on all to the
//    uninterrupted one-rank run;
//  - the body CSV snapshots are the one-rank run's;
//  - periodic axes with clumps are refused on several ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/run_error.hpp"
#include "neighbor/neighbor_search.hpp"
#include "parallel/communicator.hpp"
#include "sim/simulation.hpp"
#include "support/clump_scenes.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/shared_temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kDt = 2e-6;   // s
constexpr double kR = 0.6e-3;  // m, member radius

// 5 x 5 x 4 bodies on a lattice of 2.8 mm (wider than a body's bounding sphere, 2.67 mm),
// alternately tetrahedra (members 1.2 mm apart, touching) and dumbbells, random orientations,
// velocities (0.2 m/s) and spins (100 rad/s), falling under gravity in an open box.
Scene falling_bodies(Integrator integ) {
  Scene s = make_scene(kDt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  s.model.params.checks.max_overlap = 0.2;
  set_contact_law(s, 0.4);
  const double e = 1.2e-3;  // m, tetrahedron edge
  const double c = e / std::sqrt(8.0);
  const int tetra = add_template(s, "tetra",
                                 {{{c, c, c}, kR}, {{c, -c, -c}, kR}, {{-c, c, -c}, kR}, {{-c, -c, c}, kR}});
  const int dumbbell = add_template(s, "dumbbell", {{{kR, 0.0, 0.0}, kR}, {{-kR, 0.0, 0.0}, kR}});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g;
  const double a = 2.8e-3;  // m
  std::int64_t id = 10;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) {
        const Vec3 x{a * (i + 0.5), a * (j + 0.5), a * (k + 0.5)};
        const Vec3 v{0.2 * u(rng), 0.2 * u(rng), 0.2 * u(rng)};
        const Vec3 w{100.0 * u(rng), 100.0 * u(rng), 100.0 * u(rng)};
        const Quat q = quat_normalized(Quat{g(rng), g(rng), g(rng), g(rng)});
        add_clump(s, id, (i + j + k) % 2 ? tetra : dumbbell, x, v, w, q);
        id += 3;
      }
  finish_clumps(s);
  add_box(s, 5 * a, 6 * a);
  return s;
}

struct Deviation {
  double worst = 0.0;
  std::uint64_t matched = 0, bodies = 0;
};

// The largest deviation of p's particles and bodies from ref's (x to a member radius, v and w to
// the reference's largest speed and spin), and how many of each it compared.
Deviation deviation(const Particles& p, const Particles& ref) {
  double vmax = 0.0, wmax = 0.0;
  std::map<std::int64_t, std::size_t> at, body_at;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    at[ref.id[i]] = i;
    vmax = std::max(vmax, norm(ref.v[i]));
    wmax = std::max(wmax, norm(ref.w[i]));
  }
  for (std::size_t b = 0; b < ref.bodies.size(); ++b) body_at[ref.bodies.id[b]] = b;
  Deviation d;
  const auto worst = [&](const Vec3& x, const Vec3& rx, const Vec3& v, const Vec3& rv, const Vec3& w, const Vec3& rw) {
    d.worst = std::max({d.worst, norm(x - rx) / kR, norm(v - rv) / vmax, norm(w - rw) / wmax});
  };
  for (std::size_t i = 0; i < p.size(); ++i)
    if (const auto it = at.find(p.id[i]); it != at.end()) {
      const std::size_t j = it->second;
      ++d.matched;
      worst(p.x[i], ref.x[j], p.v[i], ref.v[j], p.w[i], ref.w[j]);
    }
  const Bodies& B = p.bodies;
  const Bodies& R = ref.bodies;
  for (std::size_t b = 0; b < B.size(); ++b)
    if (const auto it = body_at.find(B.id[b]); it != body_at.end()) {
      const std::size_t r = it->second;
      ++d.bodies;
      worst(B.x[b], R.x[r], B.v[b], R.v[r], B.w[b], R.w[r]);
      const Quat& q = B.q[b];
      const Quat& rq = R.q[r];  // q and -q are one orientation
      const auto dist = [&](double s) {
        return std::sqrt((q.w - s * rq.w) * (q.w - s * rq.w) + (q.x - s * rq.x) * (q.x - s * rq.x) +
                         (q.y - s * rq.y) * (q.y - s * rq.y) + (q.z - s * rq.z) * (q.z - s * rq.z));
      };
      d.worst = std::max(d.worst, std::min(dist(1.0), dist(-1.0)));
    }
  return d;
}

// Over all ranks (collective).
Deviation across(const Communicator& world, Deviation d) {
  d.worst = world.max(d.worst);
  d.matched = world.sum(d.matched);
  d.bodies = world.sum(d.bodies);
  return d;
}

// The trapezoidal predictor's history of the bodies of `s` (this rank's) against the one-rank
// run's, by body id: the largest deviation (to the largest acceleration and angular rate) and how
// many bodies had one, over all ranks (collective).
struct History {
  double worst = 0.0;
  std::uint64_t found = 0;
};

History history_deviation(const Communicator& world, Simulation& s, Simulation& one) {
  std::map<std::int64_t, RateRecord> reference;
  double scale_a = 0.0, scale_b = 0.0;  // m/s^2; rad/s^2 or N m (TrapezoidalBodies)
  for (const RateRecord& r : one.trapezoidal().bodies().records(one.particles().bodies)) {
    reference[r.id] = r;
    scale_a = std::max(scale_a, norm(r.a));
    scale_b = std::max(scale_b, norm(r.b));
  }
  History h;
  for (const RateRecord& r : s.trapezoidal().bodies().records(s.particles().bodies))
    if (const auto it = reference.find(r.id); it != reference.end()) {
      ++h.found;
      h.worst = std::max({h.worst, norm(r.a - it->second.a) / scale_a, norm(r.b - it->second.b) / scale_b});
    }
  if (reference.size() != one.particles().bodies.size()) h.worst = 1.0;  // the reference has none
  h.worst = world.max(h.worst);
  h.found = world.sum(h.found);
  return h;
}

double log_value(const Simulation& s, const std::string& column) {
  for (const auto& [name, v] : s.log_values())
    if (name == column) return v;
  ADD_FAILURE() << "no log column " << column;
  return 0.0;
}

// `mine` (this rank's particles and bodies) against the one-rank run's `ref`: nobody lost or
// duplicated over the ranks, every particle and body within 1e-10 (deviation()). Collective.
void expect_follows(const Communicator& world, const Particles& mine, const Particles& ref, const char* what,
                    Integrator integ) {
  const Deviation d = across(world, deviation(mine, ref));
  const std::uint64_t held = world.sum(static_cast<std::uint64_t>(mine.size()));
  const std::uint64_t bodies = world.sum(static_cast<std::uint64_t>(mine.bodies.size()));
  if (world.rank() == 0)
    std::printf("[%d ranks, %s, %s] max rel diff %.2e over %llu particles and %llu bodies\n", world.size(), what,
                integ == Integrator::Verlet ? "verlet" : "trapezoidal", d.worst,
                static_cast<unsigned long long>(d.matched), static_cast<unsigned long long>(d.bodies));
  EXPECT_EQ(held, ref.size());
  EXPECT_EQ(bodies, ref.bodies.size());
  EXPECT_EQ(d.matched, ref.size());
  EXPECT_EQ(d.bodies, ref.bodies.size());
  EXPECT_LT(d.worst, 1e-10);
}

std::string integrator_name(const ::testing::TestParamInfo<Integrator>& p) {
  return p.param == Integrator::Verlet ? "Verlet" : "Trapezoidal";
}

}  // namespace

class ClumpsAcrossRanks : public ::testing::TestWithParam<Integrator> {};

TEST_P(ClumpsAcrossRanks, FallingBodiesFollowTheOneRankRun) {
  const Communicator& world = Communicator::world();
  Simulation one(falling_bodies(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  Simulation many(falling_bodies(GetParam()), RunOptions{{}, false, false, &world});
  constexpr int kSteps = 3000;
  std::uint64_t touching = 0, on_walls = 0;  // contacts summed over the steps (one rank)
  for (int k = 0; k < kSteps; ++k) {
    one.advance(kDt);
    many.advance(kDt);
    touching += one.interactions().stats().contacts_pp;
    on_walls += one.interactions().stats().contacts_pb;
  }
  const Particles& ref = one.particles();
  const Deviation d = across(world, deviation(many.particles(), ref));
  const HaloExchange* halo = many.interactions().search().halo();
  const std::uint64_t moved = world.sum(halo ? halo->migrated_bodies() : std::uint64_t{0});
  const std::uint64_t held = world.sum(static_cast<std::uint64_t>(many.particles().size()));
  const std::uint64_t bodies = world.sum(static_cast<std::uint64_t>(many.particles().bodies.size()));
  const double kinetic = log_value(many, "kinetic"), kinetic_ref = log_value(one, "kinetic");
  const double bodies_logged = log_value(many, "bodies"), members_logged = log_value(many, "members");
  const InteractionStats serial = one.interactions().stats(), decomposed = many.interactions().global_stats();
  if (world.rank() == 0)
    std::printf(
        "[%d ranks, %s] %d steps: max rel diff %.2e over %llu particles and %llu bodies; %llu bodies "
        "migrated; contacts pp %zu vs %zu, pb %zu vs %zu (contact steps %llu and %llu); kinetic %.9g vs %.9g J\n",
        world.size(), GetParam() == Integrator::Verlet ? "verlet" : "trapezoidal", kSteps, d.worst,
        static_cast<unsigned long long>(d.matched), static_cast<unsigned long long>(d.bodies),
        static_cast<unsigned long long>(moved), serial.contacts_pp, decomposed.contacts_pp, serial.contacts_pb,
        decomposed.contacts_pb, static_cast<unsigned long long>(touching), static_cast<unsigned long long>(on_walls),
        kinetic, kinetic_ref);
  EXPECT_EQ(held, ref.size());  // nobody lost or duplicated
  EXPECT_EQ(d.matched, ref.size());
  EXPECT_EQ(bodies, ref.bodies.size());
  EXPECT_EQ(d.bodies, ref.bodies.size());
  EXPECT_LT(d.worst, 1e-10);
  EXPECT_EQ(decomposed.contacts_pp, serial.contacts_pp);
  EXPECT_EQ(decomposed.contacts_pb, serial.contacts_pb);
  EXPECT_GT(touching, 1000u);  // the bodies collide
  EXPECT_GT(on_walls, 1000u);  // and hit the box
  EXPECT_EQ(bodies_logged, static_cast<double>(ref.bodies.size()));
  EXPECT_EQ(members_logged, static_cast<double>(ref.size()));
  EXPECT_NEAR(kinetic, kinetic_ref, 1e-9 * kinetic_ref);
  if (world.size() > 1) {
    EXPECT_GT(moved, 5u);  // bodies crossed the cuts
  }
  if (GetParam() == Integrator::Trapezoidal) {  // the bodies' predictor history followed them
    const History h = history_deviation(world, many, one);
    EXPECT_EQ(h.found, ref.bodies.size());
    EXPECT_LT(h.worst, 1e-10);
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, ClumpsAcrossRanks, ::testing::Values(Integrator::Verlet, Integrator::Trapezoidal),
                         integrator_name);

// A dumbbell along x (members 1 mm from its centre) whose centre stays at x < 0 and whose leading
// member reaches across x = 0, the cut of two ranks in a domain [-10, 10] mm along x, meets a
// sphere coming from x > 0: the owner of the sphere sees the member as a ghost.
TEST(ClumpsAcrossRanksContact, MemberBeyondTheCutTouchesTheNeighboursSphere) {
  const auto make = [] {
    Scene s = make_scene(kDt, 1.0);
    s.model.params.checks.max_overlap = 0.2;
    s.model.params.fields.gravity = {};
    set_contact_law(s, 0.3);
    DomainParams& d = s.model.params.domain;
    d.bounded = true;
    d.min = {-10e-3, -5e-3, -5e-3};
    d.max = {10e-3, 5e-3, 5e-3};
    const int dumbbell = add_template(s, "dumbbell", {{{1e-3, 0.0, 0.0}, 1e-3}, {{-1e-3, 0.0, 0.0}, 1e-3}});
    add_particle(s, 1, 1e-3, {3.0e-3, 0.2e-3, 0.0}, {-0.5, 0.0, 0.0}, {});
    add_clump(s, 2, dumbbell, {-0.5e-3, 0.0, 0.0}, {0.5, 0.0, 0.0});
    finish_clumps(s);
    return s;
  };
  const Communicator& world = Communicator::world();
  Simulation one(make(), RunOptions{{}, false, false, &Communicator::single()});
  Simulation many(make(), RunOptions{{}, false, false, &world});
  double centre_max = -1.0;    // m, the dumbbell centre's largest x
  std::uint64_t touching = 0;  // steps with the contact
  for (int k = 0; k < 1000; ++k) {
    one.advance(kDt);
    many.advance(kDt);
    centre_max = std::max(centre_max, one.particles().bodies.x[0].x);
    touching += one.interactions().stats().contacts_pp;
  }
  const Particles& ref = one.particles();
  const Deviation d = across(world, deviation(many.particles(), ref));
  const std::size_t sphere = static_cast<std::size_t>(std::find(ref.id.begin(), ref.id.end(), 1) - ref.id.begin());
  if (world.rank() == 0)
    std::printf("[%d ranks] dumbbell centre x <= %.3g mm, %llu steps in contact; sphere v_x %.6g m/s; max rel diff "
                "%.2e\n",
                world.size(), centre_max * 1e3, static_cast<unsigned long long>(touching), ref.v[sphere].x, d.worst);
  EXPECT_LT(centre_max, 0.0);  // the body stayed on the first rank's side
  EXPECT_GT(touching, 10u);
  EXPECT_GT(ref.v[sphere].x, 0.0);  // the sphere bounced back
  EXPECT_EQ(d.matched, ref.size());
  EXPECT_LT(d.worst, 1e-10);
  if (world.size() == 2) {  // the body and its members on rank 0, the sphere on rank 1
    EXPECT_EQ(many.particles().bodies.size(), world.rank() == 0 ? 1u : 0u);
    EXPECT_EQ(many.particles().size(), world.rank() == 0 ? 2u : 1u);
  }
}

// Written on two ranks (one under -np 1) after 1500 steps, resumed on one rank and on all for 1500
// more: both end where the uninterrupted one-rank run ends.
TEST_P(ClumpsAcrossRanks, CheckpointOnTwoRanksResumesOnOneAndOnAll) {
  const Communicator& world = Communicator::world();
  constexpr int kBefore = 1500, kAfter = 1500;
  Simulation ref(falling_bodies(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  for (int k = 0; k < kBefore + kAfter; ++k) ref.advance(kDt);
  const SharedTempDir dir(world, "clump_ckp");
  const auto file = dir.path / "checkpoint.bin";
  const int writers = std::min(2, world.size());
  if (const auto few = world.first_ranks(writers)) {
    Simulation writer(falling_bodies(GetParam()), RunOptions{{}, false, false, few.get()});
    for (int k = 0; k < kBefore; ++k) writer.advance(kDt);
    writer.write_checkpoint(file);  // collective over the writers
  }
  world.barrier();
  Simulation alone(falling_bodies(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  alone.resume_from(file);
  for (int k = 0; k < kAfter; ++k) alone.advance(kDt);
  Simulation all(falling_bodies(GetParam()), RunOptions{{}, false, false, &world});
  all.resume_from(file);
  for (int k = 0; k < kAfter; ++k) all.advance(kDt);
  const Deviation d1 = deviation(alone.particles(), ref.particles());
  const Deviation dn = across(world, deviation(all.particles(), ref.particles()));
  const double worst1 = world.max(d1.worst);
  if (world.rank() == 0)
    std::printf("[%d ranks -> 1 and %d] max rel diff %.2e and %.2e\n", writers, world.size(), worst1, dn.worst);
  EXPECT_EQ(d1.matched, ref.particles().size());
  EXPECT_EQ(d1.bodies, ref.particles().bodies.size());
  EXPECT_EQ(dn.matched, ref.particles().size());
  EXPECT_EQ(dn.bodies, ref.particles().bodies.size());
  EXPECT_LT(worst1, 1e-10);
  EXPECT_LT(dn.worst, 1e-10);
  if (GetParam() == Integrator::Trapezoidal) {  // the bodies' predictor history was restored
    const History h1 = history_deviation(world, alone, ref), hn = history_deviation(world, all, ref);
    EXPECT_EQ(h1.found, world.size() * ref.particles().bodies.size());  // every rank resumed alone
    EXPECT_LT(h1.worst, 1e-10);
    EXPECT_EQ(hn.found, ref.particles().bodies.size());
    EXPECT_LT(hn.worst, 1e-10);
  }
}

namespace {
// The fields of each line of a CSV file.
std::vector<std::vector<std::string>> csv_rows(const std::filesystem::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    rows.push_back(std::move(f));
  }
  return rows;
}
}  // namespace

// The body CSV snapshots of a run on all ranks are the one-rank run's: the same files, rows (ids
// ascending) and template names, every number within 1e-10 of its column's largest magnitude.
TEST(ClumpsAcrossRanksContact, BodyCsvSnapshotsAreTheOneRankRuns) {
  const Communicator& world = Communicator::world();
  const SharedTempDir dir(world, "clump_csv");
  const auto make = [] {
    Scene s = falling_bodies(Integrator::Verlet);
    s.model.params.time.duration = 600 * kDt;
    s.model.params.output.body_csv_every = 200 * kDt;
    return s;
  };
  {
    Simulation many(make(), RunOptions{dir.path / "many", false, true, &world, false});
    many.run();
  }
  if (world.rank() == 0) {
    Simulation one(make(), RunOptions{dir.path / "one", false, true, &Communicator::single(), false});
    one.run();
    std::size_t files = 0;
    double worst = 0.0;
    for (const auto& e : std::filesystem::directory_iterator(dir.path / "one" / "bodies_csv")) {
      ++files;
      const auto ref = csv_rows(e.path());
      const auto got = csv_rows(dir.path / "many" / "bodies_csv" / e.path().filename());
      ASSERT_EQ(got.size(), ref.size()) << e.path().filename();
      ASSERT_EQ(ref.size(), 101u);  // the header and 100 bodies
      EXPECT_EQ(got[0], ref[0]);
      std::vector<double> scale(ref[0].size(), 0.0);
      for (std::size_t r = 1; r < ref.size(); ++r)
        for (std::size_t c = 0; c < ref[r].size(); ++c)
          if (c != 2) scale[c] = std::max(scale[c], std::abs(std::stod(ref[r][c])));
      for (std::size_t r = 1; r < ref.size(); ++r) {
        ASSERT_EQ(got[r].size(), ref[r].size());
        EXPECT_EQ(got[r][1], ref[r][1]);  // id
        EXPECT_EQ(got[r][2], ref[r][2]);  // template name
        for (std::size_t c = 0; c < ref[r].size(); ++c)
          if (c != 2 && scale[c] > 0.0)
            worst = std::max(worst, std::abs(std::stod(got[r][c]) - std::stod(ref[r][c])) / scale[c]);
      }
    }
    std::printf("[%d ranks] %zu body CSV snapshots, max rel diff %.2e\n", world.size(), files, worst);
    EXPECT_EQ(files, 4u);  // t = 0, 200, 400 and 600 steps
    EXPECT_LT(worst, 1e-10);
  }
}

// A migration wraps the particles one by one along a periodic axis, which would tear a body
// across the period: several ranks refuse clumps with periodic axes at the start, in one message.
// The falling bodies without side walls in a domain periodic along x and y (period 14 mm, the
// lattice's width), drifting at 0.5 m/s along x and 0.3 m/s along y over a floor, so that bodies
// straddle and cross the periodic faces and the cuts: 2 to 4 ranks follow one rank within 1e-10.
TEST(ClumpsAcrossRanksContact, PeriodicBodiesFollowTheOneRankRun) {
  const auto make = [](Integrator integ) {
    Scene s = falling_bodies(integ);
    s.barriers = Barriers{};
    for (std::size_t b = 0; b < s.particles.bodies.size(); ++b) s.particles.bodies.v[b] += Vec3{0.5, 0.3, 0.0};
    place_members(s.model.clumps, s.particles);
    add_floor(s, 0.0, 0.05);
    DomainParams& d = s.model.params.domain;
    d.bounded = true;
    d.min = {0.0, 0.0, -5e-3};
    d.max = {14e-3, 14e-3, 30e-3};
    d.periodic = {true, true, false};
    return s;
  };
  const Communicator& world = Communicator::world();
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(integ == Integrator::Verlet ? "verlet" : "trapezoidal");
    Simulation one(make(integ), RunOptions{{}, false, false, &Communicator::single()});
    Simulation many(make(integ), RunOptions{{}, false, false, &world});
    std::uint64_t touching = 0;
    for (int k = 0; k < 3000; ++k) {
      one.advance(kDt);
      many.advance(kDt);
      touching += one.interactions().stats().contacts_pp;
    }
    const Particles& ref = one.particles();
    int crossings = 0;  // sum of |image| over the bodies (one rank)
    for (std::size_t b = 0; b < ref.bodies.size(); ++b)
      crossings += std::abs(ref.bodies.image[b][0]) + std::abs(ref.bodies.image[b][1]);
    expect_follows(world, many.particles(), ref, "periodic", integ);
    if (world.rank() == 0)
      std::printf("  %d face crossings, %llu contact steps\n", crossings, static_cast<unsigned long long>(touching));
    EXPECT_GT(crossings, 10);
    EXPECT_GT(touching, 1000u);
  }
}

// The falling bodies in their box, fed from above by an inlet of tetrahedra and dumbbells (0.6,
// 0.4) every 2 ms: every rank places the same bodies among the same neighbours and keeps those
// whose centre is in its brick; 2 to 4 ranks follow one rank within 1e-10, both integrators.
TEST(ClumpsAcrossRanksContact, InletOfClumpsFollowsTheOneRankRun) {
  const auto make = [](Integrator integ) {
    Scene s = falling_bodies(integ);
    InletSpec in;
    in.name = "feed";
    in.volume.region.shape = RegionShape::Box;
    in.volume.region.min = {1.5e-3, 1.5e-3, 12e-3};
    in.volume.region.max = {12.5e-3, 12.5e-3, 16e-3};
    in.count_rate = 4000.0;  // 1/s: 8 bodies every 2 ms
    in.interval = 2e-3;
    in.seed = 3;
    in.velocity = {0.0, 0.0, -0.3};
    in.clump.clumps = {0, 1};
    in.clump.fractions = {0.6, 0.4};
    in.radius.law = RadiusLaw::Discrete;  // the members' radii, as the scene reader sets them
    in.radius.radii = {kR};
    in.radius.fractions = {1.0};
    s.model.params.inlets.push_back(in);
    return s;
  };
  const Communicator& world = Communicator::world();
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(integ == Integrator::Verlet ? "verlet" : "trapezoidal");
    Simulation one(make(integ), RunOptions{{}, false, false, &Communicator::single()});
    Simulation many(make(integ), RunOptions{{}, false, false, &world});
    for (int k = 0; k < 4000; ++k) {  // 8 ms: four insertion times
      one.advance(kDt);
      many.advance(kDt);
    }
    const Particles& ref = one.particles();
    EXPECT_GT(ref.bodies.size(), 120u);  // the inlet inserted bodies
    expect_follows(world, many.particles(), ref, "inlet", integ);
  }
}
