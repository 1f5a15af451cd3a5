// Clumps in a periodic domain (parallel/periodic_images.hpp, docs/physics.md section 19): a body's
// centre is wrapped and its members move with it, so a dumbbell crossing a periodic face keeps its
// shape (member - centre = R(q) d to round-off), momentum and spin, and never meets an image of
// itself; a member lying outside the period by its offset from the centre meets another body's
// member across the face (the image band widened by the offset); two dumbbells colliding across a
// face give the collision in the middle of the box
// (shifted by half a period) under both integrators; a periodic box of clumps does not depend on
// the thread count and resumes from a checkpoint bitwise.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "neighbor/neighbor_search.hpp"
#include "sim/simulation.hpp"
#include "support/clump_scenes.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kR = 0.0009765625;  // m, 2^-10: member radius and offset (dyadic positions)
constexpr double kL = 0.0625;        // m, 2^-4: the period along x
constexpr double kDt = 1e-6;         // s

const char* name_of(Integrator integ) { return integ == Integrator::Verlet ? "verlet" : "trapezoidal"; }

// A cube [0, kL]^3, periodic along x only; no gravity, e = 0.5, friction 0.3, soft (E = 1e7 Pa).
Scene periodic_scene(Integrator integ, bool periodic = true) {
  Scene s = make_scene(kDt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = {};
  s.model.params.checks.max_overlap = 0.2;
  set_contact_law(s, 0.3);
  Material& m = s.model.materials.front();
  m.density = 2500.0;
  m.young = 1e7;
  m.poisson = 0.3;
  if (periodic) {
    DomainParams& d = s.model.params.domain;
    d.bounded = true;
    d.min = {0.0, 0.0, 0.0};
    d.max = {kL, kL, kL};
    d.periodic = {true, false, false};
  }
  return s;
}

// Two touching spheres at -/+ kR along the template's y.
int dumbbell(Scene& s) { return add_template(s, "dumbbell", {{{0.0, -kR, 0.0}, kR}, {{0.0, kR, 0.0}, kR}}); }

// m, body b's unwrapped centre of mass.
Vec3 unwrapped(const Bodies& B, std::size_t b) { return B.x[b] + Vec3{B.image[b][0] * kL, 0.0, 0.0}; }

// Body index of id in B.
std::size_t body_of(const Bodies& B, std::int64_t id) {
  const std::ptrdiff_t b = B.find(id);
  EXPECT_GE(b, 0) << "no body " << id;
  return static_cast<std::size_t>(std::max<std::ptrdiff_t>(b, 0));
}

}  // namespace

// A spinning, tumbling dumbbell flies through x = kL in free space: after every step each member
// sits at centre + R(q) d_k (to 1e-12 of the offset), carries its body's image counter, feels no
// force (neither its body-mate nor any image of its own body is paired with it); the body's
// momentum stays, its orientation and spin are bitwise those of the same flight without the
// periodic domain, and its unwrapped centre follows that flight to 1e-12 of the distance flown.
TEST(ClumpPeriodic, DumbbellCrossingAFaceKeepsItsShapeAndMomentum) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name_of(integ));
    const auto make = [&](bool periodic) {
      Scene s = periodic_scene(integ, periodic);
      const int c = dumbbell(s);
      // Turned so that the axis is oblique to the face; spin about a non-principal axis (tumbling).
      add_clump(s, 7, c, {kL - 3.0 * kR, 0.5 * kL, 0.5 * kL}, {1.0, 0.1, -0.05}, {150.0, 80.0, 400.0},
                quat_normalized({1.0, 0.2, -0.3, 0.4}));
      finish_clumps(s);
      return s;
    };
    Simulation per(make(true), RunOptions{{}, false, false});
    Simulation free(make(false), RunOptions{{}, false, false});
    const Vec3 v0 = per.particles().bodies.v[0];
    const double M = per.particles().bodies.mass[0];
    double shape = 0.0, flown = 0.0;
    bool outside = false;  // a member was seen outside the box (its body's centre inside)
    for (int k = 0; k < 8000; ++k) {
      per.advance(kDt);
      free.advance(kDt);
      const Particles& p = per.particles();
      const Bodies& B = p.bodies;
      const Bodies& F = free.particles().bodies;
      const Mat3 R = quat_matrix(B.q[0]);
      const ClumpTemplate& t = per.model().clumps[0];
      ASSERT_EQ(p.size(), 2u);
      for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3 d = mat_apply(R, t.members()[p.member[i]].x);  // m
        shape = std::max(shape, norm(p.x[i] - B.x[0] - d) / norm(d));
        EXPECT_EQ(p.image[i], B.image[0]);
        EXPECT_EQ(norm(p.force[i]), 0.0) << "step " << k;
        outside = outside || p.x[i].x >= kL || p.x[i].x < 0.0;
      }
      EXPECT_EQ(per.interactions().stats().contacts_pp, 0u);
      EXPECT_EQ(M * B.v[0], M * v0);
      EXPECT_EQ(B.q[0].w, F.q[0].w);
      EXPECT_EQ(B.q[0].x, F.q[0].x);
      EXPECT_EQ(B.q[0].z, F.q[0].z);
      EXPECT_EQ(B.w[0], F.w[0]);
      flown = std::max(flown, norm(unwrapped(B, 0) - F.x[0]) / norm(F.x[0] - Vec3{kL - 3.0 * kR, 0.5 * kL, 0.5 * kL}));
    }
    const Bodies& B = per.particles().bodies;
    std::printf("%s: dumbbell flew %.4g m through x = L (image %d): |member - centre - R d| / |d| <= %.2e, unwrapped "
                "centre - free flight <= %.2e of the distance\n",
                name_of(integ), 8000 * kDt * v0.x, B.image[0][0], shape, flown);
    EXPECT_EQ(B.image[0][0], 1);    // it crossed once
    EXPECT_LT(B.x[0].x, 0.1 * kL);  // and was wrapped
    EXPECT_TRUE(outside);           // a member straddled the face
    EXPECT_LE(shape, 1e-12);
    EXPECT_LE(flown, 1e-12);
  }
}

// The pairs a build lists, by the ids of their owned particles or ghosts' sources (smaller first).
namespace {
std::set<std::pair<std::int64_t, std::int64_t>> listed_pairs(const NeighborSearch& ns, const Particles& p) {
  std::set<std::pair<std::int64_t, std::int64_t>> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (const std::uint32_t j : ns.pairs().neighbors(i))
      out.insert({std::min(p.id[i], p.id[j]), std::max(p.id[i], p.id[j])});
  return out;
}
}  // namespace

// A stick (two spheres of radius 0.25 mm, 3 mm either side of its centre) lies along x with its
// centre 0.5 mm inside x = kL, so its member id 1 is 2.5 mm outside the period; a ball (body 2,
// member id 2) touches that member's image 2.95 mm from x = 0. The pair is listed once when the
// band is widened by the member offset (3 mm), and lost without (the ball, 2.95 mm from the face,
// would get no image, and the member's smaller id lists the pair from the member's side). A lens
// of two overlapping members straddling the face lists no pair of its own members.
TEST(ClumpPeriodic, MemberOutsideThePeriodMeetsTheOtherSide) {
  Scene s = periodic_scene(Integrator::Verlet);
  const double r = 0.25e-3, skin = 0.05e-3;  // m
  const int stick = add_template(s, "stick", {{{0.0, -3e-3, 0.0}, r}, {{0.0, 3e-3, 0.0}, r}});
  const int ball = add_template(s, "ball", {{{0.0, 0.0, 0.0}, r}});
  const int lens = add_template(s, "lens", {{{0.0, -0.2e-3, 0.0}, r}, {{0.0, 0.2e-3, 0.0}, r}});
  const Quat along_x = quat_normalized({1.0, 0.0, 0.0, -1.0});  // template y -> world +x
  add_clump(s, 1, stick, {kL - 0.5e-3, 0.5 * kL, 0.5 * kL}, {}, {}, along_x);
  add_clump(s, 2, ball, {2.95e-3, 0.5 * kL, 0.5 * kL});
  add_clump(s, 3, lens, {kL - 0.05e-3, 0.3 * kL, 0.5 * kL}, {}, {}, along_x);
  finish_clumps(s);
  Particles& p = s.particles;
  ASSERT_GT(p.x[1].x, kL + 2.4e-3);  // member id 1, outside the period
  ASSERT_EQ(p.id[1], 1);
  ASSERT_EQ(p.id[2], 2);
  const double offset = largest_member_offset(s.model.clumps);
  EXPECT_NEAR(offset, 3e-3, 1e-15);
  const std::pair<std::int64_t, std::int64_t> across{1, 2};
  {
    NeighborSearch ns(skin, 0.0, s.model.params.domain, offset);
    ns.rebuild(p, s.barriers);
    const auto pairs = listed_pairs(ns, p);
    EXPECT_EQ(pairs.count(across), 1u);
    for (const auto& [a, b] : pairs) {
      std::int64_t ba = -2, bb = -2;  // their bodies
      for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.id[i] == a) ba = p.body[i];
        if (p.id[i] == b) bb = p.body[i];
      }
      EXPECT_NE(ba, bb) << "members " << a << " and " << b << " of one body are paired";
    }
    std::size_t listed = 0;  // the pair across the face, counted over the list's slots
    for (std::size_t i = 0; i < p.size(); ++i)
      for (const std::uint32_t j : ns.pairs().neighbors(i))
        listed += std::minmax(p.id[i], p.id[j]) == std::minmax<std::int64_t>(1, 2);
    EXPECT_EQ(listed, 1u);
    p.drop_ghosts();
  }
  NeighborSearch narrow(skin, 0.0, s.model.params.domain, 0.0);
  narrow.rebuild(p, s.barriers);
  EXPECT_EQ(listed_pairs(narrow, p).count(across), 0u);
  p.drop_ghosts();
}

namespace {

struct Collision {
  std::vector<Vec3> x, v, w;  // per body (ids 1, 2): unwrapped centre less the shift (m), m/s, rad/s
  std::vector<Vec3> force;    // per step, body 1's force (N)
  std::size_t touching = 0;   // steps with a member contact
};

// Dumbbell 1 lies along x and moves +x, dumbbell 2 stands along y (tilted) ahead of it and moves
// -x, off-centre; they meet where dumbbell 1's front member is at x0 + 2 kR. x0 = kL puts the
// contact across the periodic face (body 2 is loaded wrapped, one period down), x0 = kL / 2 in the
// middle of the box.
Collision collide(Integrator integ, double x0, int steps) {
  Scene s = periodic_scene(integ);
  const int c = dumbbell(s);
  const double y = 0.5 * kL, z = 0.5 * kL;
  const Quat along_x = quat_normalized({1.0, 0.0, 0.0, 1.0});  // template y -> world -x
  const double x2 = x0 + 2.5 * kR >= kL ? x0 + 2.5 * kR - kL : x0 + 2.5 * kR;
  add_clump(s, 1, c, {x0 - 0.5 * kR, y, z}, {0.5, 0.0, 0.0}, {}, along_x);
  add_clump(s, 2, c, {x2, y + 0.375 * kR, z + 0.125 * kR}, {-0.25, 0.0, 0.0}, {0.0, 0.0, 20.0},
            quat_normalized({1.0, 0.1, 0.0, 0.05}));
  finish_clumps(s);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Collision out;
  for (int k = 0; k < steps; ++k) {
    sim.advance(kDt);
    const Bodies& B = sim.particles().bodies;
    out.force.push_back(B.force[body_of(B, 1)]);
    out.touching += sim.interactions().stats().contacts_pp > 0;
  }
  const Bodies& B = sim.particles().bodies;
  for (const std::int64_t id : {1, 2}) {
    const std::size_t b = body_of(B, id);
    const double loaded = id == 2 && x2 < x0 ? kL : 0.0;  // m, body 2 was loaded one period down
    out.x.push_back(unwrapped(B, b) + Vec3{loaded - x0, 0.0, 0.0});
    out.v.push_back(B.v[b]);
    out.w.push_back(B.w[b]);
  }
  return out;
}

}  // namespace

// The same collision across the periodic face and in the middle of the box: the final centres
// within 1e-12 of the reach, velocities and spins within 1e-12 of their scale (0.5 m/s,
// 0.5 m/s / kR); body 1's force at every step within 1e-10 of its peak (the positions round at
// another magnitude near x = kL than near kL / 2, a few 1e-17 m a step, which the stiffness
// 1.5 F / delta turns into about 1e-11 of the peak force; measured 3e-11).
TEST(ClumpPeriodic, CollisionAcrossAFaceIsTheInteriorCollision) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name_of(integ));
    const int steps = 1500;
    const Collision face = collide(integ, kL, steps), mid = collide(integ, 0.5 * kL, steps);
    double df = 0.0, peak = 0.0, dx = 0.0, dv = 0.0, dw = 0.0;
    for (int k = 0; k < steps; ++k) {
      df = std::max(df, norm(face.force[k] - mid.force[k]));
      peak = std::max(peak, norm(mid.force[k]));
    }
    for (std::size_t b = 0; b < 2; ++b) {
      dx = std::max(dx, norm(face.x[b] - mid.x[b]) / (2.0 * kR));
      dv = std::max(dv, norm(face.v[b] - mid.v[b]) / 0.5);
      dw = std::max(dw, norm(face.w[b] - mid.w[b]) / (0.5 / kR));
    }
    std::printf("%s: %zu steps in contact; across the face - in the middle: force %.2e of the peak %.3g N, x %.2e, "
                "v %.2e, w %.2e; after: v1 = (%.6g, %.6g, %.6g) m/s, w2 = (%.6g, %.6g, %.6g) rad/s\n",
                name_of(integ), mid.touching, df / peak, peak, dx, dv, dw, mid.v[0].x, mid.v[0].y, mid.v[0].z,
                mid.w[1].x, mid.w[1].y, mid.w[1].z);
    EXPECT_EQ(face.touching, mid.touching);
    EXPECT_GT(mid.touching, 20u);
    EXPECT_GT(norm(mid.w[0]), 1.0);  // an off-centre hit: body 1 turns
    EXPECT_LE(df, 1e-10 * peak);
    EXPECT_LE(dx, 1e-12);
    EXPECT_LE(dv, 1e-12);
    EXPECT_LE(dw, 1e-12);
  }
}

namespace {

// Tetrahedral clumps (nx x ny x nz) over a floor in a box periodic along x and y, falling at
// 1 m/s with drifts of 0.4 .. 0.6 m/s along x (the rightmost column straddles x = max).
Scene periodic_pile(Integrator integ, int nx, int ny, int nz) {
  Scene s = periodic_scene(integ, false);
  s.model.params.time.dt = 2e-6;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  const double r = 1e-3, a = 0.7 * r, h = 4.2 * r;
  const int tet = add_template(s, "tetra", {{{a, a, a}, r}, {{a, -a, -a}, r}, {{-a, a, -a}, r}, {{-a, -a, a}, r}});
  const double Lx = (nx + 1) * h, Ly = (ny + 1) * h;  // m, the periods
  DomainParams& d = s.model.params.domain;
  d.bounded = true;
  d.min = {-0.5 * Lx, -0.5 * Ly, -0.01};
  d.max = {0.5 * Lx, 0.5 * Ly, 0.2};
  d.periodic = {true, true, false};
  std::int64_t id = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Quat q = quat_normalized({1.0, 0.1 * i, 0.2 * j, 0.3 * k});
        add_clump(s, id++, tet,
                  {h * (i - 0.5 * (nx - 1)) + 0.1 * r * j + 0.75 * h, h * (j - 0.5 * (ny - 1)), 3 * r + h * k},
                  {0.4 + 0.1 * ((i + j + k) % 3), 0.0, -1.0}, {0, 0, 3.0 * j}, q);
      }
  // The floor spans the period exactly (it ends on the periodic faces).
  const int g = s.barriers.group_index("floor");
  const Material& m = s.model.materials.front();
  const Vec3 lo{d.min.x, d.min.y, 0.0}, hi{d.max.x, d.max.y, 0.0};
  s.barriers.add(1, lo, {hi.x, lo.y, 0.0}, hi, g, m.young, m.poisson, {}, 0.0, NAN);
  s.barriers.add(2, lo, hi, {lo.x, hi.y, 0.0}, g, m.young, m.poisson, {}, 0.0, NAN);
  finish_clumps(s);
  return s;
}

struct PileState {
  std::map<std::int64_t, std::vector<double>> bodies;  // by id: unwrapped x, v, w, q (bits compared)
  int crossings = 0;                                   // sum of |image| over the bodies
  std::uint64_t contacts = 0;                          // member contacts summed over the steps
};

PileState pile_state(Simulation& sim) {
  PileState out;
  const Bodies& B = sim.particles().bodies;
  const DomainParams& d = sim.model().params.domain;
  for (std::size_t b = 0; b < B.size(); ++b) {
    const Vec3 u = B.x[b] + Vec3{B.image[b][0] * (d.max.x - d.min.x), B.image[b][1] * (d.max.y - d.min.y), 0.0};
    out.bodies[B.id[b]] = {u.x,      u.y,      u.z,      B.v[b].x, B.v[b].y, B.v[b].z, B.w[b].x,
                           B.w[b].y, B.w[b].z, B.q[b].w, B.q[b].x, B.q[b].y, B.q[b].z};
    out.crossings += std::abs(B.image[b][0]) + std::abs(B.image[b][1]);
  }
  return out;
}

PileState run_pile(Integrator integ, int threads, int steps) {
  omp_set_num_threads(threads);
  // 640 bodies, 2560 members: above the size from which the loops run in parallel.
  Simulation sim(periodic_pile(integ, 8, 8, 10), RunOptions{{}, false, false});
  std::uint64_t contacts = 0;
  for (int k = 0; k < steps; ++k) {
    sim.advance(2e-6);
    contacts += sim.interactions().stats().contacts_pp;
  }
  omp_set_num_threads(1);
  PileState out = pile_state(sim);
  out.contacts = contacts;
  return out;
}

}  // namespace

TEST(ClumpPeriodic, ThreadCountDoesNotChangeTheRun) {
  const PileState one = run_pile(Integrator::Verlet, 1, 1500), two = run_pile(Integrator::Verlet, 2, 1500);
  std::printf("periodic pile of 640 tetrahedra, 1500 steps: %d face crossings, %llu member contacts (summed)\n",
              one.crossings, static_cast<unsigned long long>(one.contacts));
  EXPECT_GT(one.crossings, 10);
  EXPECT_GT(one.contacts, 1000u);
  EXPECT_EQ(one.contacts, two.contacts);
  EXPECT_EQ(one.bodies, two.bodies);
}

TEST(ClumpPeriodic, CheckpointResumeIsBitwise) {
  TempDir dir("mpdem_clump_periodic_resume");
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name_of(integ));
    Simulation full(periodic_pile(integ, 4, 4, 3), RunOptions{{}, false, false});
    for (int k = 0; k < 1200; ++k) full.advance(2e-6);
    full.write_checkpoint(dir.path / "ck.bin");
    for (int k = 0; k < 1200; ++k) full.advance(2e-6);
    Simulation resumed(periodic_pile(integ, 4, 4, 3), RunOptions{{}, false, false});
    resumed.resume_from(dir.path / "ck.bin");
    for (int k = 0; k < 1200; ++k) resumed.advance(2e-6);
    const PileState a = pile_state(full), b = pile_state(resumed);
    EXPECT_GT(a.crossings, 3);
    EXPECT_EQ(a.bodies, b.bodies);
    EXPECT_EQ(full.interactions().stats().contacts_pp, resumed.interactions().stats().contacts_pp);
  }
}
