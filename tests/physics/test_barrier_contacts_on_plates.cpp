// Sphere - flat triangle-mesh contact detection (physics.md section 7, Departure): each physical contact
// counted once over plates, slim fans and tilted plates; thickness; a moving plate; output-buffer reuse.
// Expected values are analytic (plane / edge / vertex distances); the tolerance of each check is
// stated next to it. 1e-12 m is used for positions/overlaps of O(0.1 m) geometry (about 1e4 ulps).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "physics/barrier_contact_detect.hpp"
#include "state/barrier_topology.hpp"
#include "support/barrier_meshes.hpp"
#include "support/vec3_near.hpp"

namespace mpdem {
namespace {

using namespace test;  // Mesh, Plate, add_grid, gv, all_of, detect, expect_vec_near

constexpr double kTol = 1e-12;  // m (positions, overlaps) or - (unit normal components)

// ---------------------------------------------------------------- flat plate
TEST(BarrierContacts, PlateCount) {
  Plate p;
  EXPECT_GE(p.m.b.size(), 32u);
}

TEST(BarrierContacts, SphereOverVertexEdgeAndFaceOfPlate) {
  Plate p;
  const double R = 0.05, z = 0.043;   // analytic overlap R - z
  const Vec3 v = gv(p.o, p.h, 3, 4);  // interior vertex, 6 triangles
  const Vec3 w = gv(p.o, p.h, 4, 4), u = gv(p.o, p.h, 4, 5);
  const Vec3 spots[] = {
      v,                                       // vertex
      (v + w) * 0.5,                           // horizontal edge
      (v + u) * 0.5,                           // diagonal edge
      (w + u) * 0.5,                           // vertical edge
      v + Vec3{0.03, 0.01, 0},                 // face interior
      v + Vec3{1e-9, 2e-9, 0},                 // face, next to a vertex
      (v + w) * 0.5 + Vec3{0, 1e-10, 0},       // face, next to an edge
      (v + u) * 0.5 + Vec3{1e-13, -1e-13, 0},  // a rounding-level distance from an edge
  };
  for (const Vec3& s : spots) {
    const Vec3 x{s.x, s.y, z};
    const auto c = detect(p.m.b, p.topo, x, R);
    ASSERT_EQ(c.size(), 1u) << x.x << " " << x.y;
    EXPECT_NEAR(c[0].overlap, R - z, kTol);
    expect_vec_near(c[0].normal, {0, 0, 1}, kTol);
    expect_vec_near(c[0].point, {x.x, x.y, 0}, kTol);
  }
  // Exactly over the vertex the vertex itself is the contact feature.
  const auto c = detect(p.m.b, p.topo, {v.x, v.y, z}, R);
  EXPECT_EQ(c[0].kind, Feature::Vertex);
  // Below the plate (two-sided surface): normal points down.
  const auto below = detect(p.m.b, p.topo, {v.x, v.y, -z}, R);
  ASSERT_EQ(below.size(), 1u);
  expect_vec_near(below[0].normal, {0, 0, -1}, kTol);
}

TEST(BarrierContacts, ThicknessOffsetsBothSides) {
  const double tb = 0.02, R = 0.05;
  Plate p(tb);
  const Vec3 v = gv(p.o, p.h, 5, 2);
  for (const double z : {0.055, -0.055, 0.0449}) {
    const auto c = detect(p.m.b, p.topo, {v.x, v.y, z}, R);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_NEAR(c[0].overlap, R + tb / 2 - std::abs(z), kTol);
    EXPECT_NEAR(c[0].normal.z, z > 0 ? 1.0 : -1.0, kTol);
  }
  EXPECT_TRUE(detect(p.m.b, p.topo, {v.x, v.y, 0.0601}, R).empty());
}

// 1000 positions along a line: exactly one contact, same as on one big triangle.
void sweep(const Plate& p, const Vec3& from, const Vec3& to, double z, double R) {
  std::vector<BarrierContact> out, ref;
  const auto cand = all_of(p.m.b);
  const auto big_cand = all_of(p.big.b);
  for (int s = 0; s < 1000; ++s) {
    const Vec3 q = from + (to - from) * (s / 999.0);
    const Vec3 x{q.x, q.y, z};
    detect_barrier_contacts(p.m.b, p.topo, x, R, cand, out);
    detect_barrier_contacts(p.big.b, p.big_topo, x, R, big_cand, ref);
    ASSERT_EQ(ref.size(), 1u);
    ASSERT_EQ(out.size(), 1u) << "sample " << s << " at " << x.x << " " << x.y;
    ASSERT_NEAR(out[0].overlap, ref[0].overlap, kTol) << s;
    ASSERT_NEAR(out[0].overlap, R + p.m.thickness / 2 - std::abs(z), kTol) << s;
    ASSERT_NEAR(norm(out[0].normal - ref[0].normal), 0.0, kTol) << s;
  }
}

TEST(BarrierContacts, SweepsAcrossPlateFeelOneContact) {
  Plate p;
  const double R = 0.05, z = 0.041;
  const Vec3 v11 = gv(p.o, p.h, 1, 1), v77 = gv(p.o, p.h, 7, 7), v17 = gv(p.o, p.h, 1, 7), v71 = gv(p.o, p.h, 7, 1);
  sweep(p, v11, v77, z, R);                                // along diagonal edges through vertices
  sweep(p, v17, v71, z, R);                                // across diagonals, through vertices
  sweep(p, gv(p.o, p.h, 0, 3), gv(p.o, p.h, 8, 3), z, R);  // along a row of horizontal edges
  sweep(p, {-0.37, -0.31, 0}, {0.33, 0.29, 0}, z, R);      // generic
  sweep(p, {-0.3, -0.35, 0}, {-0.3, 0.35, 0}, -z, R);      // along vertical edges, from below
  Plate thick(0.01);
  sweep(thick, v11, v77, z, R);
}

// A fan of 64 slim triangles around one vertex (a square made of a fan).
TEST(BarrierContacts, FanOfSlimTrianglesFeelsOneContact) {
  Mesh m;
  const Vec3 centre{0.013, -0.021, 0.0};
  std::vector<Vec3> rim;
  const double L = 0.4;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 16; ++k) {
      const double s = -L + 2 * L * k / 16.0;
      const Vec3 local[4] = {{s, -L, 0}, {L, s, 0}, {-s, L, 0}, {-L, -s, 0}};
      rim.push_back(local[side]);
    }
  for (std::size_t k = 0; k < rim.size(); ++k) m.tri(centre, rim[k], rim[(k + 1) % rim.size()]);
  const BarrierTopology t = BarrierTopology::build(m.b);
  ASSERT_EQ(m.b.size(), 64u);
  const double R = 0.05, z = 0.047;
  std::vector<BarrierContact> out;
  const auto cand = all_of(m.b);
  for (int s = 0; s < 1000; ++s) {
    // a circle and a line through the fan centre
    const double a = 2 * M_PI * s / 1000.0;
    const Vec3 xs[2] = {centre + Vec3{0.01 * std::cos(a), 0.01 * std::sin(a), z},
                        centre + Vec3{-0.3 + 0.6 * s / 999.0, 0.0, z}};
    for (const Vec3& x : xs) {
      detect_barrier_contacts(m.b, t, x, R, cand, out);
      ASSERT_EQ(out.size(), 1u) << s;
      ASSERT_NEAR(out[0].overlap, R - z, kTol);
      ASSERT_NEAR(out[0].normal.z, 1.0, kTol);
    }
  }
  const auto c = detect(m.b, t, centre + Vec3{0, 0, z}, R);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].kind, Feature::Vertex);
}

// A plate rotated in space: its triangles are coplanar only up to rounding of the coordinates.
TEST(BarrierContacts, TiltedPlateFeelsOneContact) {
  const Vec3 axis = Vec3{1, 2, 0} / std::sqrt(5.0);
  const double ang = 0.3, ca = std::cos(ang), sa = std::sin(ang);
  auto rot = [&](const Vec3& p) {  // Rodrigues rotation
    return p * ca + cross(axis, p) * sa + axis * (dot(axis, p) * (1 - ca));
  };
  Mesh m;
  const Vec3 o{-0.4, -0.4, 0};
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      m.quad(rot(gv(o, 0.1, i, j)), rot(gv(o, 0.1, i + 1, j)), rot(gv(o, 0.1, i + 1, j + 1)),
             rot(gv(o, 0.1, i, j + 1)));
  const BarrierTopology t = BarrierTopology::build(m.b);
  ASSERT_EQ(t.num_vertices(), 81u);
  const Vec3 nrm = rot({0, 0, 1});
  const double R = 0.05, z = 0.044;
  std::vector<BarrierContact> out;
  const auto cand = all_of(m.b);
  for (int s = 0; s < 1000; ++s) {
    const Vec3 q = gv(o, 0.1, 1, 1) + (gv(o, 0.1, 7, 7) - gv(o, 0.1, 1, 1)) * (s / 999.0);
    const Vec3 x = rot(q) + nrm * z;
    detect_barrier_contacts(m.b, t, x, R, cand, out);
    ASSERT_EQ(out.size(), 1u) << s;
    ASSERT_NEAR(out[0].overlap, R - z, kTol);
    ASSERT_NEAR(norm(out[0].normal - nrm), 0.0, kTol);
  }
  // Rounding-level offsets (1e-17 .. 1e-11 m) from every interior vertex and edge midpoint.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1.0, 1.0), E(-17.0, -11.0);
  for (int i = 1; i < 8; ++i)
    for (int j = 1; j < 8; ++j)
      for (int rep = 0; rep < 30; ++rep) {
        const Vec3 base = rep % 3 == 0   ? gv(o, 0.1, i, j)
                          : rep % 3 == 1 ? (gv(o, 0.1, i, j) + gv(o, 0.1, i + 1, j + 1)) * 0.5
                                         : (gv(o, 0.1, i, j) + gv(o, 0.1, i, j + 1)) * 0.5;
        const double r = std::pow(10.0, E(rng));
        const Vec3 x = rot(base + Vec3{U(rng), U(rng), 0} * r) + nrm * z;
        detect_barrier_contacts(m.b, t, x, R, cand, out);
        ASSERT_EQ(out.size(), 1u) << i << " " << j << " " << rep;
        ASSERT_NEAR(out[0].overlap, R - z, kTol);
      }
}

// ---------------------------------------------------------------- motion, output buffer
TEST(BarrierContacts, MovingMeshUsesCurrentOffset) {
  Mesh m;
  m.law.a = {0.0, 0.0, 0.5};  // m/s
  add_grid(m, {-0.4, -0.4, 0}, 0.1, 8);
  m.law = MotionLaw{};
  add_grid(m, {-0.4, -0.4, 0}, 0.1, 8);  // a fixed copy at the same place: not welded
  const BarrierTopology t = BarrierTopology::build(m.b);
  EXPECT_EQ(t.num_vertices(), 2u * 81u);
  const Vec3 v = gv({-0.4, -0.4, 0}, 0.1, 4, 4);
  // At t = 0 both meshes coincide: one contact per mesh.
  EXPECT_EQ(detect(m.b, t, {v.x, v.y, 0.04}, 0.05).size(), 2u);
  m.b.move_to(0.2);  // moving mesh now at z = 0.1
  const auto c = detect(m.b, t, {v.x, v.y, 0.14}, 0.05);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_LT(c[0].element, 128u);
  EXPECT_NEAR(c[0].overlap, 0.01, kTol);
  EXPECT_NEAR(c[0].point.z, 0.1, kTol);
}

TEST(BarrierContacts, OutputBufferIsReusedWithoutReallocation) {
  Plate p;
  std::vector<BarrierContact> out;
  out.reserve(8);
  const auto cand = all_of(p.m.b);
  const BarrierContact* data = out.data();
  for (int s = 0; s < 100; ++s) {
    detect_barrier_contacts(p.m.b, p.topo, {-0.3 + 0.006 * s, 0.1, 0.04}, 0.05, cand, out);
    ASSERT_EQ(out.size(), 1u);
    ASSERT_EQ(out.data(), data);
  }
}

}  // namespace
}  // namespace mpdem
