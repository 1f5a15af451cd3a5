// Sphere - triangle-mesh contact detection at corners, box edges, holes and a convex polyhedron (physics.md
// section 7, docs/barrier_contacts.md); bitwise determinism over candidate order and precomputed triangles.
// Expected values are analytic (plane / edge / vertex distances); the tolerance of each check is
// stated next to it. 1e-12 m is used for positions/overlaps of O(0.1 m) geometry (about 1e4 ulps).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "physics/barrier_contact_detect.hpp"
#include "state/barrier_topology.hpp"
#include "state/barriers.hpp"
#include "support/barrier_meshes.hpp"
#include "support/closest_point_oracle.hpp"
#include "support/solid_meshes.hpp"
#include "support/vec3_near.hpp"

namespace mpdem {
namespace {

using namespace test;  // Mesh, Plate, add_grid, gv, all_of, detect, brute_closest, ...

constexpr double kTol = 1e-12;  // m (positions, overlaps) or - (unit normal components)

// ---------------------------------------------------------------- corners, edges, holes
TEST(BarrierContacts, ConcaveCornerGivesBothWalls) {
  Mesh m;
  const double h = 0.1;
  add_grid(m, {0, 0, 0}, h, 4);  // floor z = 0, x, y in [0, 0.4]
  for (int j = 0; j < 4; ++j)    // wall x = 0, y, z in [0, 0.4]; shares the line x = z = 0
    for (int k = 0; k < 4; ++k)
      m.quad({0, j * h, k * h}, {0, (j + 1) * h, k * h}, {0, (j + 1) * h, (k + 1) * h}, {0, j * h, (k + 1) * h});
  const BarrierTopology t = BarrierTopology::build(m.b);
  EXPECT_EQ(t.num_vertices(), 25u + 25u - 5u);  // welded along the corner line
  const double R = 0.05;
  std::vector<BarrierContact> out;
  const auto cand = all_of(m.b);
  for (int s = 0; s < 1000; ++s) {
    const double y = 0.05 + 0.3 * s / 999.0;  // passes over the shared corner vertices
    const Vec3 x{0.04, y, 0.045};
    detect_barrier_contacts(m.b, t, x, R, cand, out);
    ASSERT_EQ(out.size(), 2u) << s;
    const BarrierContact& fl = out[0].normal.z > 0.5 ? out[0] : out[1];
    const BarrierContact& wl = out[0].normal.z > 0.5 ? out[1] : out[0];
    ASSERT_NEAR(norm(fl.normal - Vec3{0, 0, 1}), 0.0, kTol);
    ASSERT_NEAR(norm(wl.normal - Vec3{1, 0, 0}), 0.0, kTol);
    ASSERT_NEAR(fl.overlap, R - 0.045, kTol);
    ASSERT_NEAR(wl.overlap, R - 0.04, kTol);
  }
}

// Unit cube, each face a 2 x 2 grid (8 triangles per face).
Mesh cube() {
  Mesh m;
  auto face = [&](const Vec3& o, const Vec3& du, const Vec3& dv) {
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        m.quad(o + du * (0.5 * i) + dv * (0.5 * j), o + du * (0.5 * (i + 1)) + dv * (0.5 * j),
               o + du * (0.5 * (i + 1)) + dv * (0.5 * (j + 1)), o + du * (0.5 * i) + dv * (0.5 * (j + 1)));
  };
  const Vec3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1}, O{0, 0, 0};
  face(O, Y, X);
  face(Z, X, Y);
  face(O, X, Z);
  face(Y, Z, X);
  face(O, Z, Y);
  face(X, Y, Z);
  return m;
}

TEST(BarrierContacts, ConvexEdgeAndCornerOfBox) {
  Mesh m = cube();
  const BarrierTopology t = BarrierTopology::build(m.b);
  EXPECT_EQ(t.num_vertices(), 26u);  // 8 corners + 12 edge midpoints + 6 face centres
  const double R = 0.05, rho = 0.04;
  std::vector<BarrierContact> out;
  const auto cand = all_of(m.b);
  // Around the edge x = z = 1 at a distance rho: angle th from the top face's normal (+z).
  for (int s = 0; s < 1000; ++s) {
    const double th = (-40.0 + 170.0 * s / 999.0) * M_PI / 180.0;
    const double y = 0.2 + 0.6 * s / 999.0;  // passes the vertex at y = 0.5
    const Vec3 x{1 + rho * std::sin(th), y, 1 + rho * std::cos(th)};
    detect_barrier_contacts(m.b, t, x, R, cand, out);
    ASSERT_EQ(out.size(), 1u) << s;
    double dist;
    Vec3 n;
    if (th < 0) dist = rho * std::cos(th), n = {0, 0, 1};              // over the top face
    else if (th > M_PI / 2) dist = rho * std::sin(th), n = {1, 0, 0};  // beside the side face
    else dist = rho, n = {std::sin(th), 0, std::cos(th)};              // the edge
    ASSERT_NEAR(out[0].overlap, R - dist, kTol) << s;
    ASSERT_NEAR(norm(out[0].normal - n), 0.0, kTol) << s;
  }
  // 45 degrees: one edge contact with the edge normal.
  const auto e = detect(m.b, t, {1.03, 0.3, 1.03}, R);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].kind, Feature::Edge);
  EXPECT_NEAR(e[0].overlap, R - 0.03 * std::sqrt(2.0), kTol);
  expect_vec_near(e[0].normal, Vec3{1, 0, 1} / std::sqrt(2.0), kTol);
  // Outside the corner: one vertex contact along the diagonal.
  const auto c = detect(m.b, t, {1.02, 1.02, 1.02}, R);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].kind, Feature::Vertex);
  EXPECT_NEAR(c[0].overlap, R - 0.02 * std::sqrt(3.0), kTol);
  expect_vec_near(c[0].normal, Vec3{1, 1, 1} / std::sqrt(3.0), kTol);
}

// Plate with a square hole of side 0.12 (1.2 d for d = 0.1) in the middle of an n x n grid of
// spacing h, the hole being cells [lo, lo + cells).
struct HolePlate {
  Mesh m;
  BarrierTopology topo;
  Vec3 centre;  // m, hole centre (plate height 0)
  HolePlate(double h, int n, int lo, int cells) {
    const Vec3 o{-0.3, -0.2, 0};
    add_grid(m, o, h, n, [&](int i, int j) { return i >= lo && i < lo + cells && j >= lo && j < lo + cells; });
    topo = BarrierTopology::build(m.b);
    centre = o + Vec3{(lo + 0.5 * cells) * h, (lo + 0.5 * cells) * h, 0};
  }
};

TEST(BarrierContacts, SphereFallsThroughHoleLargerThanIt) {
  for (const auto& hp : {HolePlate(0.03, 12, 4, 4), HolePlate(0.04, 9, 3, 3)}) {
    const double d = 0.1;
    // At the plate's height and all along the way through: nothing.
    for (int s = 0; s <= 200; ++s)
      EXPECT_TRUE(detect(hp.m.b, hp.topo, hp.centre + Vec3{0, 0, -0.1 + 0.2 * s / 200.0}, d / 2).empty()) << s;
    // A sphere slightly wider than the hole (R = 0.065) is stopped by the 4 rim sides.
    const auto c = detect(hp.m.b, hp.topo, hp.centre, 0.065);
    ASSERT_EQ(c.size(), 4u);
    for (const auto& k : c) EXPECT_NEAR(k.overlap, 0.005, kTol);
  }
}

TEST(BarrierContacts, LargeSphereRestsOnHoleRim) {
  for (const auto& hp : {HolePlate(0.03, 12, 4, 4), HolePlate(0.04, 9, 3, 3)}) {
    const double R = 0.1, z = 0.07, half = 0.06;  // 2d sphere, hole half-side
    const double dist = std::sqrt(half * half + z * z);
    const auto c = detect(hp.m.b, hp.topo, hp.centre + Vec3{0, 0, z}, R);
    ASSERT_EQ(c.size(), 4u);
    Vec3 sum{};
    for (const auto& k : c) {
      EXPECT_NEAR(k.overlap, R - dist, kTol);
      EXPECT_NE(k.kind, Feature::Face);
      EXPECT_NEAR(k.point.z, 0.0, kTol);
      // On the rim, at the middle of a side.
      const Vec3 r = k.point - hp.centre;
      EXPECT_NEAR(std::max(std::abs(r.x), std::abs(r.y)), half, kTol);
      EXPECT_NEAR(std::min(std::abs(r.x), std::abs(r.y)), 0.0, kTol);
      EXPECT_NEAR(k.normal.z, z / dist, kTol);
      sum += k.normal;
    }
    EXPECT_NEAR(sum.x, 0.0, kTol);
    EXPECT_NEAR(sum.y, 0.0, kTol);
    EXPECT_NEAR(sum.z, 4 * z / dist, kTol);
  }
}

// Geodesic sphere (icosahedron subdivided twice, 320 triangles, vertices on the unit sphere): a
// convex polyhedron, so a sphere outside it has exactly one local minimum of distance, i.e.
// exactly one contact, whose overlap is R minus the distance to the nearest triangle (brute force).
Mesh geodesic_sphere() {
  const TriangleMesh s = icosphere(2, 1.0);
  Mesh m;
  for (std::size_t t = 0; t < s.size(); ++t) m.tri(s.corner(t, 0), s.corner(t, 1), s.corner(t, 2));
  return m;
}

TEST(BarrierContacts, OutsideConvexPolyhedronOneContact) {
  Mesh m = geodesic_sphere();
  const BarrierTopology t = BarrierTopology::build(m.b);
  ASSERT_EQ(m.b.size(), 320u);
  ASSERT_EQ(t.num_vertices(), 162u);
  ASSERT_EQ(t.num_edges(), 480u);
  const double R = 0.3;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0), Rad(1.0, 1.29);
  std::vector<BarrierContact> out;
  const auto cand = all_of(m.b);
  int features[3] = {0, 0, 0};
  for (int s = 0; s < 20000; ++s) {
    Vec3 dir;
    const int k = s % 4;
    const std::size_t e = static_cast<std::size_t>(s / 4) % m.b.size();
    if (k == 0) dir = m.b.p0[e];                           // over a vertex
    else if (k == 1) dir = (m.b.p0[e] + m.b.p1[e]) * 0.5;  // over an edge midpoint
    else if (k == 2) dir = m.b.centre(e);                  // over a face centre
    else dir = {U(rng), U(rng), U(rng)};                   // anywhere
    const Vec3 x = dir * (Rad(rng) / norm(dir));
    double dmin = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < m.b.size(); ++j)
      dmin = std::min(dmin, norm(x - brute_closest(x, m.b.p0[j], m.b.p1[j], m.b.p2[j])));
    detect_barrier_contacts(m.b, t, x, R, cand, out);
    if (dmin >= R) {
      ASSERT_TRUE(out.empty()) << s;
      continue;
    }
    ASSERT_EQ(out.size(), 1u) << s;
    ASSERT_NEAR(out[0].overlap, R - dmin, kTol) << s;
    ++features[static_cast<int>(out[0].kind)];
  }
  // All three kinds of features were exercised.
  EXPECT_GT(features[0], 100);
  EXPECT_GT(features[1], 100);
  EXPECT_GT(features[2], 100);
}

// ---------------------------------------------------------------- determinism
TEST(BarrierContacts, IndependentOfCandidateOrder) {
  Plate p;
  Mesh box = cube();
  const BarrierTopology box_topo = BarrierTopology::build(box.b);
  HolePlate hp(0.03, 12, 4, 4);
  struct Case {
    const Barriers* b;
    const BarrierTopology* t;
    Vec3 x;
    double R;
  };
  const Vec3 v = gv(p.o, p.h, 3, 4);
  const Case cases[] = {{&p.m.b, &p.topo, {v.x, v.y, 0.04}, 0.05},
                        {&p.m.b, &p.topo, {v.x + 0.05, v.y, 0.04}, 0.05},
                        {&box.b, &box_topo, {1.02, 0.5, 1.02}, 0.05},
                        {&box.b, &box_topo, {0.5, 0.5, 0.5}, 0.6},  // inside, touching all 6 faces
                        {&hp.m.b, &hp.topo, hp.centre + Vec3{0, 0, 0.07}, 0.1}};
  std::mt19937 rng(3);
  for (const Case& k : cases) {
    std::vector<std::uint32_t> cand = all_of(*k.b);
    std::vector<BarrierContact> ref, out;
    detect_barrier_contacts(*k.b, *k.t, k.x, k.R, cand, ref);
    ASSERT_FALSE(ref.empty());
    EXPECT_TRUE(std::is_sorted(ref.begin(), ref.end(),
                               [](const BarrierContact& a, const BarrierContact& b) { return a.element < b.element; }));
    for (int rep = 0; rep < 20; ++rep) {
      std::shuffle(cand.begin(), cand.end(), rng);
      std::vector<std::uint32_t> c2 = cand;
      c2.insert(c2.end(), cand.begin(), cand.begin() + 5);  // repeated candidates too
      detect_barrier_contacts(*k.b, *k.t, k.x, k.R, c2, out);
      ASSERT_EQ(out.size(), ref.size());
      for (std::size_t i = 0; i < out.size(); ++i) {  // bitwise identical
        EXPECT_EQ(out[i].element, ref[i].element);
        EXPECT_EQ(out[i].kind, ref[i].kind);
        EXPECT_EQ(out[i].feature, ref[i].feature);
        EXPECT_EQ(out[i].point, ref[i].point);
        EXPECT_EQ(out[i].normal, ref[i].normal);
        EXPECT_EQ(out[i].overlap, ref[i].overlap);
      }
    }
  }
}

TEST(BarrierContacts, InsideBoxTouchesAllSixFaces) {
  Mesh box = cube();
  const BarrierTopology t = BarrierTopology::build(box.b);
  const auto c = detect(box.b, t, {0.45, 0.47, 0.52}, 0.6);
  ASSERT_EQ(c.size(), 6u);
  Vec3 sum{};
  for (const auto& k : c) {
    EXPECT_EQ(k.kind, Feature::Face);
    sum += k.normal * (0.6 - k.overlap);  // normal * distance = x - p
  }
  // Sum of (x - p) over opposite face pairs: (x - 0) + (x - 1) per axis.
  expect_vec_near(sum, {2 * 0.45 - 1, 2 * 0.47 - 1, 2 * 0.52 - 1}, kTol);
}

// The per-evaluation triangles (current_triangle, as BarrierContacts uses them) give bit for bit
// the contacts of on-the-spot detection: faces, edges and vertices of convex and concave meshes,
// spheres inside and outside, and a moved mesh.
TEST(BarrierContacts, PrecomputedTrianglesGiveIdenticalContacts) {
  Mesh sphere = geodesic_sphere();
  Mesh box = cube();
  Mesh moving;
  moving.law.a = {0.01, -0.02, 0.5};  // m/s
  add_grid(moving, {-0.4, -0.4, 0}, 0.1, 8);
  moving.b.move_to(0.2);
  const Mesh* meshes[] = {&sphere, &box, &moving};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1.4, 1.4), Rad(0.05, 0.6);
  std::vector<BarrierContact> ref, out;
  std::size_t contacts = 0;
  for (const Mesh* m : meshes) {
    const BarrierTopology t = BarrierTopology::build(m->b);
    std::vector<CurrentTriangle> tris;
    for (std::size_t e = 0; e < m->b.size(); ++e) tris.push_back(current_triangle(m->b, e));
    const auto cand = all_of(m->b);
    for (int s = 0; s < 5000; ++s) {
      const std::size_t e = static_cast<std::size_t>(s) % m->b.size();
      // Over a vertex, an edge midpoint, a face centre of the moved mesh, or anywhere.
      const Vec3 at[4] = {
          m->b.vertex(e, 0), (m->b.vertex(e, 0) + m->b.vertex(e, 1)) * 0.5, m->b.centre(e), {U(rng), U(rng), U(rng)}};
      const Vec3 x = at[s % 4] + Vec3{U(rng), U(rng), U(rng)} * 0.1;
      const double R = Rad(rng);
      detect_barrier_contacts(m->b, t, x, R, cand, ref);
      detect_barrier_contacts(m->b, t, tris, x, R, cand, out);
      ASSERT_EQ(out.size(), ref.size()) << s;
      contacts += ref.size();
      for (std::size_t i = 0; i < out.size(); ++i) {
        ASSERT_EQ(out[i].element, ref[i].element) << s;
        ASSERT_EQ(out[i].kind, ref[i].kind) << s;
        ASSERT_EQ(out[i].feature, ref[i].feature) << s;
        ASSERT_EQ(out[i].point, ref[i].point) << s;
        ASSERT_EQ(out[i].normal, ref[i].normal) << s;
        ASSERT_EQ(out[i].overlap, ref[i].overlap) << s;
      }
    }
  }
  EXPECT_GT(contacts, 3000u);  // the comparison saw many contacts, not only misses
}

}  // namespace
}  // namespace mpdem
