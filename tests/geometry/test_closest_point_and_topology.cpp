// The building blocks of sphere - triangle-mesh contact detection (physics.md section 7): the exact
// closest point on a triangle, and the mesh topology (welded vertices, edges, their elements).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>

#include "geometry/triangle_closest_point.hpp"
#include "state/barrier_topology.hpp"
#include "support/barrier_meshes.hpp"
#include "support/closest_point_oracle.hpp"
#include "support/vec3_near.hpp"

namespace mpdem {
namespace {

using namespace test;  // Mesh, add_grid, gv, brute_closest, expect_vec_near

// ---------------------------------------------------------------- closest point on a triangle
TEST(TriangleClosestPoint, RegionsOfRightTriangle) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  struct Case {
    Vec3 x, p;
    Feature kind;
    int index;
  };
  const Case cases[] = {
      {{0.2, 0.2, 0.5}, {0.2, 0.2, 0}, Feature::Face, 0}, {{0.5, -1, 0.3}, {0.5, 0, 0}, Feature::Edge, 0},
      {{1, 1, 0.2}, {0.5, 0.5, 0}, Feature::Edge, 1},     {{-1, 0.5, -2}, {0, 0.5, 0}, Feature::Edge, 2},
      {{-1, -1, 2}, {0, 0, 0}, Feature::Vertex, 0},       {{2, -0.5, 0}, {1, 0, 0}, Feature::Vertex, 1},
      {{-0.1, 2, 0.1}, {0, 1, 0}, Feature::Vertex, 2},    {{0.5, 0, 1}, {0.5, 0, 0}, Feature::Edge, 0},
  };
  for (const Case& k : cases) {
    const TriangleClosestPoint r = closest_point_on_triangle(k.x, a, b, c);
    EXPECT_EQ(r.kind, k.kind) << k.x.x << " " << k.x.y << " " << k.x.z;
    EXPECT_EQ(r.index, k.index);
    expect_vec_near(r.point, k.p, 1e-15);
  }
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
      EXPECT_TRUE(std::count(ev, ev + 3, t.edge_vertex[2 * g]) == 1 &&
                  std::count(ev, ev + 3, t.edge_vertex[2 * g + 1]) == 1);
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

}  // namespace
}  // namespace mpdem
