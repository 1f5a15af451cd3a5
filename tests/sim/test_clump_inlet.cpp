// An [[inlet]] of clumps (src/sim/inlets.cpp, src/sim/inlet_bodies.cpp; docs/scene.md "[[inlet]]"):
// whole bodies inserted at once, member by member clear of the particles there and of each other,
// each member at x + R(q) d_k, ids after the largest, the inlet's velocity, the material's
// temperature and charge; the inserted mass (or count) within half a body of what is due at every
// insertion time (or exactly what is due less the shortfall); bitwise reproducible by seed; and a
// run checkpointed between or right after insertion times resumes bitwise under both integrators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/inlets.hpp"
#include "sim/simulation.hpp"
#include "support/clump_scenes.hpp"
#include "support/open_system_scenes.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kR = 1e-3;  // m, member radius
// Round-off of a member's centre x + R d (coordinates up to 0.02 m): a few ulps of 0.02 m.
constexpr double kRoundOff = 1e-15;  // m
constexpr double kRigid = 1e-12;     // m, members on their body's rigid placement

// The fed box of open_system_scenes.hpp, its inlet inserting tetrahedra (0.7) and dumbbells (0.3)
// at mass_rate (kg/s; count_rate when `by_count`, 1/s) with seed `seed`.
Scene fed_bodies(Integrator integ, double rate, std::uint64_t seed, bool by_count = false) {
  Scene s = fed_box_scene(0.03, rate);
  s.model.params.time.integrator = integ;
  s.model.materials.front().temperature = 310.0;
  s.model.materials.front().charge = 1e-12;
  const double a = 0.7 * kR;
  const int tet = add_template(s, "tetra", {{{a, a, a}, kR}, {{a, -a, -a}, kR}, {{-a, a, -a}, kR}, {{-a, -a, a}, kR}});
  const int db = add_template(s, "dumbbell", {{{0, 0, -kR}, kR}, {{0, 0, kR}, 0.8 * kR}});
  InletSpec& in = s.model.params.inlets[0];
  in.clump.clumps = {tet, db};
  in.clump.fractions = {0.7, 0.3};
  in.radius.law = RadiusLaw::Discrete;  // the members' radii, as the scene reader sets them
  in.radius.radii = {0.8 * kR, kR};
  in.radius.fractions = {1.0, 1.0};
  in.velocity = {0.0, 0.0, -0.3};
  in.seed = seed;
  if (by_count) {
    in.count_rate = rate;
    in.mass_rate = 0.0;
  }
  return s;
}

void run_steps(Simulation& sim, std::uint64_t steps) {
  while (sim.steps() < steps) sim.advance(sim.model().params.time.dt);
}

}  // namespace

// One insertion time into an inlet box holding free spheres and a body already: more is due than
// fits, so the bodies pack as far as random placement gets, and every member is checked against
// every other sphere by brute force.
TEST(ClumpInlet, InsertsWholeBodiesApartInsideAndRigid) {
  Scene s = fed_bodies(Integrator::Verlet, 1e5, 7, true);  // 100 bodies due at t = 0
  s.model.params.inlets[0].max_attempts = 20000;
  for (int k = 0; k < 6; ++k) add_particle(s, 40 + k, kR, {0.006 + 0.002 * k, 0.01, 0.008 + 0.001 * k});
  add_clump(s, 12, 1, {0.01, 0.006, 0.012});
  finish_clumps(s);
  const InletSpec& spec = s.model.params.inlets[0];
  Inlets inlets(s.model, s.particles);
  Particles fresh = inlets.insert(0.0, s.particles, s.barriers);
  const Bodies& B = fresh.bodies;
  ASSERT_GT(B.size(), 8u);
  EXPECT_GT(inlets.states()[0].shortfall, 0.0);  // packed: the rest is carried
  EXPECT_EQ(inlets.states()[0].inserted, B.size());
  // Body ids after the largest (12), member ids after the largest particle id, in body and
  // template order.
  std::int64_t next_member = *std::max_element(s.particles.id.begin(), s.particles.id.end()) + 1;
  std::size_t members = 0, tetrahedra = 0;
  for (std::size_t b = 0; b < B.size(); ++b) {
    EXPECT_EQ(B.id[b], 13 + static_cast<std::int64_t>(b));
    const ClumpTemplate& t = s.model.clumps[static_cast<std::size_t>(B.clump[b])];
    tetrahedra += B.clump[b] == 0 ? 1 : 0;
    EXPECT_EQ(B.v[b], spec.velocity);
    EXPECT_EQ(B.w[b], Vec3{});
    EXPECT_EQ(B.T[b], 310.0);
    EXPECT_EQ(B.charge[b], 1e-12);
    EXPECT_EQ(B.mass[b], t.body_mass(2500.0));
    const Mat3 R = quat_matrix(B.q[b]);  // principal frame -> world
    for (std::uint32_t k = 0; k < t.members().size(); ++k) {
      const std::size_t i = member_of(fresh, B.id[b], k);
      EXPECT_EQ(fresh.id[i], next_member++);
      EXPECT_LT(norm(fresh.x[i] - (B.x[b] + mat_apply(R, t.members()[k].x))), kRigid);
      EXPECT_EQ(fresh.radius[i], t.members()[k].r);
      ++members;
    }
  }
  EXPECT_EQ(members, fresh.size());
  EXPECT_GT(tetrahedra, 0u);
  EXPECT_LT(tetrahedra, B.size());
  // Every member inside the inlet box, and apart from every sphere of another body or free.
  const RegionSpec& box = spec.volume.region;
  double worst = INFINITY;  // m, smallest surface gap
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(fresh.x[i][a] - fresh.radius[i], box.min[a] - kRoundOff);
      EXPECT_LE(fresh.x[i][a] + fresh.radius[i], box.max[a] + kRoundOff);
    }
    for (std::size_t j = 0; j < s.particles.size(); ++j)
      worst = std::min(worst, norm(fresh.x[i] - s.particles.x[j]) - fresh.radius[i] - s.particles.radius[j]);
    for (std::size_t j = i + 1; j < fresh.size(); ++j)
      if (fresh.body[i] != fresh.body[j])
        worst = std::min(worst, norm(fresh.x[i] - fresh.x[j]) - fresh.radius[i] - fresh.radius[j]);
  }
  EXPECT_GE(worst, -kRoundOff);
  EXPECT_LT(worst, 0.2 * kR);  // packed: some bodies come close, so the check is not vacuous
  std::printf("%zu bodies placed of 100 due, smallest surface gap %.3g m\n", B.size(), worst);
  // Orientations differ (uniformly random ones are checked for generated bodies, which draw them alike).
  EXPECT_NE(B.q[0].w, B.q[1].w);
}

// A rectangle face inlet in a tilted frame: every member inside the slab, and the templates drawn
// with the number fractions: the count of tetrahedra among N bodies is binomial (N, 0.7), within
// 3 standard deviations sqrt(N 0.7 0.3) of 0.7 N (the seed is fixed: deterministic).
TEST(ClumpInlet, TiltedRectInletKeepsMembersInsideAndDrawsTheFractions) {
  constexpr std::size_t kN = 1000;
  Scene s = fed_bodies(Integrator::Verlet, 1e6, 17, true);  // 1000 bodies due at t = 0
  InsertionVolume& vol = s.model.params.inlets[0].volume;
  vol.shape = "rect";
  vol.region.min = {};
  vol.region.max = {0.1, 0.1, 0.02};  // m: edge1, edge2, depth
  vol.origin = {0.01, -0.02, 0.03};
  vol.u = {1.0, 0.0, 0.0};
  vol.v = {0.0, 0.8, 0.6};
  vol.w = {0.0, -0.6, 0.8};
  Inlets inlets(s.model, s.particles);
  const Particles fresh = inlets.insert(0.0, s.particles, s.barriers);
  ASSERT_EQ(fresh.bodies.size(), kN);
  EXPECT_EQ(inlets.states()[0].shortfall, 0.0);
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    const Vec3 d = fresh.x[i] - vol.origin;
    const Vec3 local{dot(vol.u, d), dot(vol.v, d), dot(vol.w, d)};  // m, in the slab's frame
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(local[a] - fresh.radius[i], -kRoundOff);
      EXPECT_LE(local[a] + fresh.radius[i], vol.region.max[a] + kRoundOff);
    }
  }
  std::size_t tetra = 0;
  for (const int c : fresh.bodies.clump) tetra += c == 0 ? 1 : 0;
  const double sigma = std::sqrt(kN * 0.7 * 0.3);
  EXPECT_LT(std::abs(static_cast<double>(tetra) - 0.7 * kN), 3.0 * sigma) << tetra << " tetrahedra";
  std::printf("%zu tetrahedra of %zu bodies (0.7 N = %.0f, sigma %.1f)\n", tetra, kN, 0.7 * kN, sigma);
}

// Through a run: the inlet's totals follow its rule at every insertion time, the bodies fall as
// rigid bodies and the neighbour lists keep a body's members out of contact with each other.
TEST(ClumpInlet, InsertedMassAndCountFollowTheRate) {
  for (const bool by_count : {false, true}) {
    SCOPED_TRACE(by_count ? "count_rate" : "mass_rate");
    const double rate = by_count ? 700.0 : 0.03;  // 1/s or kg/s: about 0.7 bodies per interval
    Simulation sim(fed_bodies(Integrator::Verlet, rate, 3, by_count), RunOptions{{}, false, false});
    const InletSpec& spec = sim.model().params.inlets[0];
    double m_max = 0.0;  // kg, the heavier body of the mix
    for (const ClumpTemplate& t : sim.model().clumps) m_max = std::max(m_max, t.body_mass(2500.0));
    std::uint64_t checked = 0, short_steps = 0;
    for (std::uint64_t n = 1; n <= 600; ++n) {
      run_steps(sim, n);
      const Inlets::State& st = sim.inlets()->states()[0];
      if (st.next_k == 0) continue;
      const double due = rate * std::min(static_cast<double>(st.next_k) * spec.interval, 0.03);  // kg or bodies
      const double done = by_count ? static_cast<double>(st.inserted) : st.inserted_mass;
      const double half = by_count ? 0.5 : 0.5 * m_max;  // half a body (the heavier one)
      if (st.shortfall > 0.0) {
        EXPECT_NEAR(done + st.shortfall, due, 1e-12 * due);
        ++short_steps;
      } else {
        EXPECT_LE(done - due, half * (1.0 + 1e-12));
        EXPECT_GT(done - due, -half);
        ++checked;
      }
    }
    EXPECT_GT(checked, 550u);  // the inlet box stays free enough: the rule is checked nearly throughout
    std::printf("%llu steps within half a body of what is due, %llu with a shortfall\n",
                static_cast<unsigned long long>(checked), static_cast<unsigned long long>(short_steps));
    const Particles& p = sim.particles();
    EXPECT_GT(p.bodies.size(), 6u);
    // No contact joins two members of one body (a tetrahedron's members overlap each other): the
    // last evaluation's contacts are the overlapping members of different bodies (at the positions
    // it saw, the step's end under velocity Verlet).
    std::size_t across = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j)
        across += p.body[i] != p.body[j] && norm(p.x[i] - p.x[j]) < p.radius[i] + p.radius[j] ? 1 : 0;
    EXPECT_EQ(sim.interactions().stats().contacts_pp, across);
    // The members stay on their bodies after integration (place_members).
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t b = static_cast<std::size_t>(p.bodies.find(p.body[i]));
      const ClumpTemplate& t = sim.model().clumps[static_cast<std::size_t>(p.bodies.clump[b])];
      EXPECT_LT(norm(p.x[i] - (p.bodies.x[b] + mat_apply(quat_matrix(p.bodies.q[b]), t.members()[p.member[i]].x))),
                kRigid);
    }
  }
}

TEST(ClumpInlet, SameSeedSameBodiesBitwiseOtherSeedDifferent) {
  Simulation a(fed_bodies(Integrator::Trapezoidal, 0.08, 5), RunOptions{{}, false, false});
  Simulation b(fed_bodies(Integrator::Trapezoidal, 0.08, 5), RunOptions{{}, false, false});
  Simulation c(fed_bodies(Integrator::Trapezoidal, 0.08, 6), RunOptions{{}, false, false});
  run_steps(a, 300);
  run_steps(b, 300);
  run_steps(c, 300);
  const Bodies &A = a.particles().bodies, &Bb = b.particles().bodies, &C = c.particles().bodies;
  ASSERT_GT(A.size(), 5u);
  expect_same_bodies(A, Bb);
  ASSERT_GT(C.size(), 0u);
  EXPECT_NE(A.x[0], C.x[0]);
}

// Cut right after an insertion time (the trapezoidal predictor's body history then has fewer
// bodies than there are) and between two.
TEST(ClumpInlet, CheckpointResumeIsBitwise) {
  TempDir dir("mpdem_clump_inlet_resume");
  constexpr std::uint64_t kTotal = 1000;
  // Faster bodies, so that they reach the floor and each other within the run.
  const auto scene = [](Integrator integ) {
    Scene s = fed_bodies(integ, 0.08, 11);
    s.model.params.inlets[0].velocity = {0.0, 0.0, -0.5};
    return s;
  };
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    Simulation whole(scene(integ), RunOptions{{}, false, false});
    run_steps(whole, kTotal);
    for (const std::uint64_t cut : {150u, 275u}) {  // t = 3 ms (an insertion time), 5.5 ms (between)
      SCOPED_TRACE(std::string(integ == Integrator::Verlet ? "verlet" : "trapezoidal") + ", cut at step " +
                   std::to_string(cut));
      {
        Simulation first(scene(integ), RunOptions{{}, false, false});
        run_steps(first, cut);
        ASSERT_GT(first.particles().bodies.size(), 0u);
        first.write_checkpoint(dir.path / "ck.bin");
      }
      Simulation resumed(scene(integ), RunOptions{{}, false, false});
      resumed.resume_from(dir.path / "ck.bin");
      run_steps(resumed, kTotal);
      const Particles &p = whole.particles(), &q = resumed.particles();
      ASSERT_GT(p.bodies.size(), 15u);
      expect_same_run(p, q);
      EXPECT_EQ(whole.inlets()->states()[0].inserted_mass, resumed.inlets()->states()[0].inserted_mass);
      EXPECT_EQ(whole.interactions().stats().contacts_pp, resumed.interactions().stats().contacts_pp);
      // Bodies on the floor and on each other: contact history is resumed too.
      EXPECT_GT(whole.interactions().stats().contacts_pb, 0u);
      EXPECT_GT(whole.interactions().stats().contacts_pp, 5u);
      std::printf("%zu bodies, %zu particle and %zu barrier contacts at the end\n", p.bodies.size(),
                  static_cast<std::size_t>(whole.interactions().stats().contacts_pp),
                  static_cast<std::size_t>(whole.interactions().stats().contacts_pb));
    }
  }
}
