// Sphere - triangle-mesh contact detection (physics.md section 7, Departure): exact closest point,
// mesh topology, and the rule that counts each physical contact once (docs/barrier_contacts.md).
// Expected values are analytic (plane / edge / vertex distances); the tolerance of each check is
// stated next to it. 1e-12 m is used for positions/overlaps of O(0.1 m) geometry (about 1e4 ulps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <array>
#include <numeric>
#include <random>
#include <vector>

#include "physics/barrier_contact_detect.hpp"
#include "physics/triangle_closest_point.hpp"
#include "state/barrier_topology.hpp"
#include "state/barriers.hpp"

namespace mpdem {
namespace {

constexpr double kTol = 1e-12;  // m (positions, overlaps) or - (unit normal components)

// ---------------------------------------------------------------- mesh builders
struct Mesh {
  Barriers b;
  MotionLaw law{};
  double thickness = 0.0;  // m
  void tri(const Vec3& p, const Vec3& q, const Vec3& r) {
    ASSERT_TRUE(b.add(static_cast<std::int64_t>(b.size()), p, q, r, 0, 1e9, 0.3, law, thickness,
                      std::numeric_limits<double>::quiet_NaN()));
  }
  // Quad p00 p10 p11 p01 split along p00-p11.
  void quad(const Vec3& p00, const Vec3& p10, const Vec3& p11, const Vec3& p01) {
    tri(p00, p10, p11);
    tri(p00, p11, p01);
  }
};

// Grid vertex (i, j) of the plate z = z0, origin o, spacing h; computed identically everywhere so
// shared vertices are bit-identical.
Vec3 gv(const Vec3& o, double h, int i, int j) { return {o.x + i * h, o.y + j * h, o.z}; }

// n x n squares, each split in two (interior vertices are shared by 6 triangles). Cells with
// hole(i, j) true are left out.
template <class Hole>
void add_grid(Mesh& m, const Vec3& o, double h, int n, Hole hole) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (!hole(i, j)) m.quad(gv(o, h, i, j), gv(o, h, i + 1, j), gv(o, h, i + 1, j + 1), gv(o, h, i, j + 1));
}
void add_grid(Mesh& m, const Vec3& o, double h, int n) {
  add_grid(m, o, h, n, [](int, int) { return false; });
}

std::vector<std::uint32_t> all_of(const Barriers& b) {
  std::vector<std::uint32_t> c(b.size());
  std::iota(c.begin(), c.end(), 0u);
  return c;
}

std::vector<BarrierContact> detect(const Barriers& b, const BarrierTopology& t, const Vec3& x, double R) {
  std::vector<BarrierContact> out;
  const auto cand = all_of(b);
  detect_barrier_contacts(b, t, x, R, cand, out);
  return out;
}

void expect_vec_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// ---------------------------------------------------------------- closest point on a triangle
TEST(TriangleClosestPoint, RegionsOfRightTriangle) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  struct Case {
    Vec3 x, p;
    Feature kind;
    int index;
  };
  const Case cases[] = {
      {{0.2, 0.2, 0.5}, {0.2, 0.2, 0}, Feature::Face, 0},    {{0.5, -1, 0.3}, {0.5, 0, 0}, Feature::Edge, 0},
      {{1, 1, 0.2}, {0.5, 0.5, 0}, Feature::Edge, 1},        {{-1, 0.5, -2}, {0, 0.5, 0}, Feature::Edge, 2},
      {{-1, -1, 2}, {0, 0, 0}, Feature::Vertex, 0},          {{2, -0.5, 0}, {1, 0, 0}, Feature::Vertex, 1},
      {{-0.1, 2, 0.1}, {0, 1, 0}, Feature::Vertex, 2},       {{0.5, 0, 1}, {0.5, 0, 0}, Feature::Edge, 0},
  };
  for (const Case& k : cases) {
    const TriangleClosestPoint r = closest_point_on_triangle(k.x, a, b, c);
    EXPECT_EQ(r.kind, k.kind) << k.x.x << " " << k.x.y << " " << k.x.z;
    EXPECT_EQ(r.index, k.index);
    expect_vec_near(r.point, k.p, 1e-15);
  }
}

// Independent reference: minimum over the face projection (barycentric solve) and the three
// clamped segment projections.
Vec3 brute_closest(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a, w = x - a;
  const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), wu = dot(w, u), wv = dot(w, v);
  const double det = uu * vv - uv * uv;
  const double s = (wu * vv - wv * uv) / det, t = (wv * uu - wu * uv) / det;
  if (s >= 0 && t >= 0 && s + t <= 1) return a + u * s + v * t;
  Vec3 best{};
  double bd = std::numeric_limits<double>::infinity();
  const Vec3 P[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const Vec3 p = P[k], e = P[(k + 1) % 3] - P[k];
    const double tt = std::clamp(dot(x - p, e) / dot(e, e), 0.0, 1.0);
    const Vec3 q = p + e * tt;
    if (norm2(x - q) < bd) bd = norm2(x - q), best = q;
  }
  return best;
}

TEST(TriangleClosestPoint, RandomAndThinTrianglesMatchReference) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    Vec3 a{U(rng), U(rng), U(rng)}, b{U(rng), U(rng), U(rng)}, c{U(rng), U(rng), U(rng)};
    if (trial % 2 == 1) c = a + (b - a) * (0.5 + 0.4 * U(rng)) + Vec3{U(rng), U(rng), U(rng)} * 1e-5;  // needle
    const Vec3 x{2 * U(rng), 2 * U(rng), 2 * U(rng)};
    const TriangleClosestPoint r = closest_point_on_triangle(x, a, b, c);
    const Vec3 ref = brute_closest(x, a, b, c);
    // Distances agree to rounding (1e-12 m on O(1) geometry); the points too, except on needles
    // where nearly equidistant points exist (then distance agreement is the meaningful check).
    ASSERT_NEAR(norm(x - r.point), norm(x - ref), 1e-12) << trial;
    if (trial % 2 == 0) {
      ASSERT_LT(norm(r.point - ref), 1e-9) << trial;
    }
    // Feature consistency: vertex results are exact vertices; edge/face points are orthogonal feet.
    const Vec3 P[3] = {a, b, c};
    if (r.kind == Feature::Vertex) {
      ASSERT_EQ(r.point, P[r.index]);
    } else if (r.kind == Feature::Edge) {
      const Vec3 e = P[(r.index + 1) % 3] - P[r.index];
      ASSERT_NEAR(dot(x - r.point, e) / norm(e), 0.0, 1e-12);
    } else {
      const Vec3 n = cross(b - a, c - a);
      ASSERT_NEAR(norm(cross(x - r.point, n)) / norm(n), 0.0, 1e-12);
    }
  }
}

TEST(TriangleClosestPoint, NeedleTriangle) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, 1e-7, 0};
  const TriangleClosestPoint f = closest_point_on_triangle({0.5, 0.5e-7, 1}, a, b, c);
  EXPECT_EQ(f.kind, Feature::Face);
  expect_vec_near(f.point, {0.5, 0.5e-7, 0}, 1e-15);
  const TriangleClosestPoint e = closest_point_on_triangle({0.3, -1, 0.2}, a, b, c);
  EXPECT_EQ(e.kind, Feature::Edge);
  EXPECT_EQ(e.index, 0);
  expect_vec_near(e.point, {0.3, 0, 0}, 1e-15);
}

// ---------------------------------------------------------------- topology
TEST(BarrierTopology, GridCountsAndAdjacency) {
  Mesh m;
  const int n = 8;
  add_grid(m, {-0.4, -0.4, 0}, 0.1, n);
  const BarrierTopology t = BarrierTopology::build(m.b);
  ASSERT_EQ(t.num_elements(), 2u * n * n);
  EXPECT_EQ(t.num_vertices(), static_cast<std::size_t>((n + 1) * (n + 1)));
  EXPECT_EQ(t.num_edges(), static_cast<std::size_t>(3 * n * n + 2 * n));
  EXPECT_EQ(t.vertex_elem.size(), 3 * t.num_elements());
  EXPECT_EQ(t.edge_elem.size(), 3 * t.num_elements());
  std::size_t interior_edges = 0, boundary_edges = 0;
  for (std::int32_t g = 0; g < static_cast<std::int32_t>(t.num_edges()); ++g) {
    const auto el = t.elements_of_edge(g);
    (el.size() == 2 ? interior_edges : boundary_edges) += 1;
    EXPECT_TRUE(std::is_sorted(el.begin(), el.end()));
    for (const auto e : el) {  // the edge's ends are vertices of each adjacent element
      const auto* ev = &t.elem_vertex[3 * static_cast<std::size_t>(e)];
      EXPECT_TRUE(std::count(ev, ev + 3, t.edge_vertex[2 * g]) == 1 && std::count(ev, ev + 3, t.edge_vertex[2 * g + 1]) == 1);
    }
  }
  EXPECT_EQ(boundary_edges, static_cast<std::size_t>(4 * n));
  EXPECT_EQ(interior_edges, t.num_edges() - 4 * n);
  // Interior vertex (3, 4): 6 triangles and 6 edges.
  const Vec3 v = gv({-0.4, -0.4, 0}, 0.1, 3, 4);
  std::int32_t vid = -1;
  for (std::size_t k = 0; k < t.num_vertices(); ++k)
    if (t.vertex_rest[k] == v) vid = static_cast<std::int32_t>(k);
  ASSERT_GE(vid, 0);
  EXPECT_EQ(t.elements_of_vertex(vid).size(), 6u);
  EXPECT_EQ(t.edges_of_vertex(vid).size(), 6u);
}

TEST(BarrierTopology, DifferentMotionLawsAreNotWelded) {
  Mesh m;
  add_grid(m, {0, 0, 0}, 0.1, 2);
  m.law.a = {0, 0, 1e-3};
  add_grid(m, {0, 0, 0}, 0.1, 2);  // same coordinates, moving
  m.law = MotionLaw{};
  add_grid(m, {0.2, 0, 0}, 0.1, 2);  // fixed, shares the line x = 0.2 with the first grid
  const BarrierTopology t = BarrierTopology::build(m.b);
  EXPECT_EQ(t.num_vertices(), 9u + 9u + 9u - 3u);
  EXPECT_NE(t.elem_class[0], t.elem_class[8]);
  EXPECT_EQ(t.elem_class[0], t.elem_class[16]);
}

// ---------------------------------------------------------------- flat plate
struct Plate {
  Mesh m;
  BarrierTopology topo;
  Mesh big;  // one large triangle in the same plane: the reference surface
  BarrierTopology big_topo;
  static constexpr double h = 0.1;
  static constexpr int n = 8;
  Vec3 o{-0.4, -0.4, 0.0};
  explicit Plate(double thickness = 0.0) {
    m.thickness = big.thickness = thickness;
    add_grid(m, o, h, n);
    big.tri({-10, -10, 0}, {10, -10, 0}, {0, 10, 0});
    topo = BarrierTopology::build(m.b);
    big_topo = BarrierTopology::build(big.b);
  }
};

TEST(BarrierContacts, PlateCount) {
  Plate p;
  EXPECT_GE(p.m.b.size(), 32u);
}

TEST(BarrierContacts, SphereOverVertexEdgeAndFaceOfPlate) {
  Plate p;
  const double R = 0.05, z = 0.043;  // analytic overlap R - z
  const Vec3 v = gv(p.o, p.h, 3, 4);  // interior vertex, 6 triangles
  const Vec3 w = gv(p.o, p.h, 4, 4), u = gv(p.o, p.h, 4, 5);
  const Vec3 spots[] = {
      v,                                             // vertex
      (v + w) * 0.5,                                 // horizontal edge
      (v + u) * 0.5,                                 // diagonal edge
      (w + u) * 0.5,                                 // vertical edge
      v + Vec3{0.03, 0.01, 0},                       // face interior
      v + Vec3{1e-9, 2e-9, 0},                       // face, next to a vertex
      (v + w) * 0.5 + Vec3{0, 1e-10, 0},             // face, next to an edge
      (v + u) * 0.5 + Vec3{1e-13, -1e-13, 0},        // a rounding-level distance from an edge
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
  sweep(p, v11, v77, z, R);                                   // along diagonal edges through vertices
  sweep(p, v17, v71, z, R);                                   // across diagonals, through vertices
  sweep(p, gv(p.o, p.h, 0, 3), gv(p.o, p.h, 8, 3), z, R);     // along a row of horizontal edges
  sweep(p, {-0.37, -0.31, 0}, {0.33, 0.29, 0}, z, R);         // generic
  sweep(p, {-0.3, -0.35, 0}, {-0.3, 0.35, 0}, -z, R);         // along vertical edges, from below
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
      m.quad(rot(gv(o, 0.1, i, j)), rot(gv(o, 0.1, i + 1, j)), rot(gv(o, 0.1, i + 1, j + 1)), rot(gv(o, 0.1, i, j + 1)));
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
        const Vec3 base = rep % 3 == 0 ? gv(o, 0.1, i, j)
                          : rep % 3 == 1 ? (gv(o, 0.1, i, j) + gv(o, 0.1, i + 1, j + 1)) * 0.5
                                         : (gv(o, 0.1, i, j) + gv(o, 0.1, i, j + 1)) * 0.5;
        const double r = std::pow(10.0, E(rng));
        const Vec3 x = rot(base + Vec3{U(rng), U(rng), 0} * r) + nrm * z;
        detect_barrier_contacts(m.b, t, x, R, cand, out);
        ASSERT_EQ(out.size(), 1u) << i << " " << j << " " << rep;
        ASSERT_NEAR(out[0].overlap, R - z, kTol);
      }
}

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
    if (th < 0) dist = rho * std::cos(th), n = {0, 0, 1};                 // over the top face
    else if (th > M_PI / 2) dist = rho * std::sin(th), n = {1, 0, 0};     // beside the side face
    else dist = rho, n = {std::sin(th), 0, std::cos(th)};                 // the edge
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
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& p : v) p = p / norm(p);
  for (int level = 0; level < 2; ++level) {
    std::map<std::pair<int, int>, int> mid;  // one midpoint vertex per edge, so it is shared exactly
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const Vec3 m = (v[key.first] + v[key.second]) * 0.5;
      v.push_back(m / norm(m));
      return mid[key] = static_cast<int>(v.size() - 1);
    };
    std::vector<std::array<int, 3>> nf;
    for (const auto& t : f) {
      const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      nf.push_back({t[0], a, c});
      nf.push_back({t[1], b, a});
      nf.push_back({t[2], c, b});
      nf.push_back({a, b, c});
    }
    f = nf;
  }
  Mesh m;
  for (const auto& t : f) m.tri(v[t[0]], v[t[1]], v[t[2]]);
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
    if (k == 0) dir = m.b.p0[e];                                   // over a vertex
    else if (k == 1) dir = (m.b.p0[e] + m.b.p1[e]) * 0.5;          // over an edge midpoint
    else if (k == 2) dir = m.b.centre(e);                          // over a face centre
    else dir = {U(rng), U(rng), U(rng)};                           // anywhere
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

// ---------------------------------------------------------------- determinism, motion
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
    sum += k.normal * (0.6 - k.overlap);   // normal * distance = x - p
  }
  // Sum of (x - p) over opposite face pairs: (x - 0) + (x - 1) per axis.
  expect_vec_near(sum, {2 * 0.45 - 1, 2 * 0.47 - 1, 2 * 0.52 - 1}, kTol);
}

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
      const Vec3 at[4] = {m->b.vertex(e, 0), (m->b.vertex(e, 0) + m->b.vertex(e, 1)) * 0.5, m->b.centre(e),
                          {U(rng), U(rng), U(rng)}};
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
