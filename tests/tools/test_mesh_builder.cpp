// Mesh builder (`mpdem mesh`): total areas against closed forms, normals pointing into the region
// where particles live, closed shapes watertight, holes of exact size, transforms.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "io/barrier_csv.hpp"
#include "core/input_error.hpp"
#include "tools/mesh_builder.hpp"
#include "tools/mesh_output.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 centroid(const TriangleMesh& m, std::size_t t) { return (m.corner(t, 0) + m.corner(t, 1) + m.corner(t, 2)) / 3.0; }

// Every normal points towards `inside` (convex shapes: the normal side holds their interior).
void expect_normals_towards(const TriangleMesh& m, const Vec3& inside) {
  for (std::size_t t = 0; t < m.size(); ++t)
    EXPECT_GT(dot(m.normal(t), inside - centroid(m, t)), 0.0) << "triangle " << t;
}

void expect_watertight(const TriangleMesh& m) {
  const EdgeCounts e = count_edges(m);
  EXPECT_EQ(e.boundary, 0u);
  EXPECT_EQ(e.non_manifold, 0u);
  EXPECT_EQ(e.inconsistent, 0u);
  EXPECT_GT(e.manifold, 0u);
}

// Boundary edges (used by one triangle) as vertex pairs in their triangle's direction.
std::vector<std::pair<int, int>> boundary_edges(const TriangleMesh& m) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::vector<std::pair<int, int>> out;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      if (uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}] == 1)
        out.push_back({t[k], t[(k + 1) % 3]});
  return out;
}

double polygon_area(int n, double r) { return 0.5 * n * r * r * std::sin(2 * kPi / n); }  // regular n-gon in a circle

}  // namespace

TEST(MeshBuilder, RectangleSubdivided) {
  const TriangleMesh m = make_rectangle(0.3, 0.2, 3, 4);
  EXPECT_EQ(m.size(), 24u);
  EXPECT_NEAR(total_area(m), 0.06, 1e-15);
  for (std::size_t t = 0; t < m.size(); ++t) EXPECT_NEAR(m.normal(t).z, 1.0, 1e-15);
  const EdgeCounts e = count_edges(m);
  EXPECT_EQ(e.boundary, 2u * (3 + 4));  // the outline
  EXPECT_EQ(e.inconsistent + e.non_manifold, 0u);
}

TEST(MeshBuilder, OpenAndClosedBox) {
  const TriangleMesh open = make_box(0.4, 0.3, 0.2, false);
  EXPECT_EQ(open.size(), 10u);
  EXPECT_NEAR(total_area(open), 0.4 * 0.3 + 2 * 0.2 * (0.4 + 0.3), 1e-15);
  expect_normals_towards(open, {0, 0, 0.1});
  EXPECT_EQ(count_edges(open).boundary, 4u);  // the open rim
  EXPECT_EQ(count_edges(open).inconsistent, 0u);

  const TriangleMesh closed = make_box(0.4, 0.3, 0.2, true);
  EXPECT_NEAR(total_area(closed), 2 * (0.4 * 0.3 + 0.3 * 0.2 + 0.4 * 0.2), 1e-15);
  expect_normals_towards(closed, {0, 0, 0.1});
  expect_watertight(closed);
  EXPECT_NEAR(signed_volume(closed), -0.4 * 0.3 * 0.2, 1e-15);  // negative: normals point inward
}

TEST(MeshBuilder, Cylinder) {
  const int n = 24;
  const double R = 0.05, H = 0.12;
  const double side = n * 2 * R * std::sin(kPi / n) * H;
  const TriangleMesh open = make_cylinder(R, H, n, false);
  EXPECT_NEAR(total_area(open), side, 1e-14);
  EXPECT_EQ(count_edges(open).boundary, 2u * n);
  expect_normals_towards(open, {0, 0, H / 2});
  for (const Vec3& v : open.vertices) EXPECT_NEAR(std::hypot(v.x, v.y), R, 1e-16);

  const TriangleMesh closed = make_cylinder(R, H, n, true);
  EXPECT_NEAR(total_area(closed), side + 2 * polygon_area(n, R), 1e-14);
  expect_watertight(closed);
  expect_normals_towards(closed, {0, 0, H / 2});
  EXPECT_NEAR(signed_volume(closed), -polygon_area(n, R) * H, 1e-15);
}

TEST(MeshBuilder, FunnelHopper) {
  const int n = 32;
  const double r1 = 0.1, r0 = 0.02, h = 0.08, hw = 0.05;
  const TriangleMesh m = make_funnel(r1, r0, h, hw, n);
  // Each cone facet is a trapezoid: parallel chords 2 r sin(pi/n), apothem distance apart.
  const double c0 = 2 * r0 * std::sin(kPi / n), c1 = 2 * r1 * std::sin(kPi / n);
  const double slant = std::hypot(h, (r1 - r0) * std::cos(kPi / n));
  const double cone = n * 0.5 * (c0 + c1) * slant, wall = n * c1 * hw;
  EXPECT_NEAR(total_area(m), cone + wall, 1e-14);
  // Normals towards the axis, and on the cone upwards (particles rest on it).
  for (std::size_t t = 0; t < m.size(); ++t) {
    const Vec3 c = centroid(m, t), nn = m.normal(t);
    EXPECT_GT(dot(nn, Vec3{-c.x, -c.y, 0}), 0.0);
    if (c.z < h) EXPECT_GT(nn.z, 0.0);
    else EXPECT_NEAR(nn.z, 0.0, 1e-15);
  }
  // The outlet: 2n boundary edges (outlet and top rim), outlet vertices on the outlet circle.
  EXPECT_EQ(count_edges(m).boundary, 2u * n);
  EXPECT_EQ(count_edges(m).inconsistent + count_edges(m).non_manifold, 0u);
  int outlet = 0;
  for (const Vec3& v : m.vertices)
    if (v.z == 0.0) {
      ++outlet;
      EXPECT_NEAR(std::hypot(v.x, v.y), r0, 1e-17);
    }
  EXPECT_EQ(outlet, n);
}

TEST(MeshBuilder, ChuteWithTransitionAndWalls) {
  ChuteSpec s;
  s.incline_length = 1.2;
  s.angle_deg = 35;
  s.transition_radius = 0.3;
  s.runout_length = 0.8;
  s.width = 0.2;
  s.arc_segments = 10;
  s.wall_height = 0.1;
  const TriangleMesh m = make_chute(s);
  const double th = 35 * kPi / 180;
  const double arc = s.arc_segments * 2 * 0.3 * std::sin(th / (2 * s.arc_segments));  // chords of the arc
  const double floor = 0.2 * (1.2 + arc + 0.8);
  const double walls = 2 * 0.1 * (1.2 * std::cos(th) + 0.3 * std::sin(th) + 0.8);  // h x horizontal run
  EXPECT_NEAR(total_area(m), floor + walls, 1e-13);
  double floor_area = 0.0;
  int incline = 0, runout = 0;
  for (std::size_t t = 0; t < m.size(); ++t) {
    const Vec3 nn = m.normal(t), c = centroid(m, t);
    if (std::abs(nn.y) < 1e-12) {  // floor: normals up
      floor_area += m.area(t);
      EXPECT_GT(nn.z, 0.0);
      if (c.x < -0.3 * std::sin(th) - 1e-9) {  // incline facets: normal (sin th, 0, cos th)
        ++incline;
        EXPECT_NEAR(nn.x, std::sin(th), 1e-12);
        EXPECT_NEAR(nn.z, std::cos(th), 1e-12);
      }
      if (c.x > 0) {
        ++runout;
        EXPECT_NEAR(nn.z, 1.0, 1e-15);
      }
    } else {  // side walls: normals towards the centre line y = 0
      EXPECT_NEAR(std::abs(nn.y), 1.0, 1e-12);
      EXPECT_LT(nn.y * c.y, 0.0);
    }
  }
  EXPECT_NEAR(floor_area, floor, 1e-13);
  EXPECT_EQ(incline, 2);
  EXPECT_EQ(runout, 2);
  // Geometry: the incline's top at height R (1 - cos th) + L sin th, the run-out at z = 0.
  double top = 0.0;
  for (const Vec3& v : m.vertices) top = std::max(top, v.z);
  EXPECT_NEAR(top, 0.3 * (1 - std::cos(th)) + 1.2 * std::sin(th) + 0.1, 1e-14);
  // Tangency: the facet normals turn by th / arc_segments per arc facet, from the incline's to +z,
  // i.e. the arc's floor vertices (below the wall tops at >= 0.1) lie at distance R from the
  // centre (0, 0.3): 11 per side.
  int arc_vertices = 0;
  for (const Vec3& v : m.vertices) {
    if (v.x > -0.3 * std::sin(th) - 1e-12 && v.x <= 0 && v.z < 0.08) {
      ++arc_vertices;
      EXPECT_NEAR(std::hypot(v.x, v.z - 0.3), 0.3, 1e-15);
    }
  }
  EXPECT_EQ(arc_vertices, 2 * (s.arc_segments + 1));
  EXPECT_EQ(count_edges(m).inconsistent + count_edges(m).non_manifold, 0u);
}

TEST(MeshBuilder, PlateWithRectangularHole) {
  const TriangleMesh m = make_plate_with_rect_hole(0.5, 0.4, 0.1, 0.06);
  EXPECT_NEAR(total_area(m), 0.5 * 0.4 - 0.1 * 0.06, 1e-15);
  for (std::size_t t = 0; t < m.size(); ++t) EXPECT_NEAR(m.normal(t).z, 1.0, 1e-15);
  // The hole is the boundary loop inside the plate; its corners exactly at +-hx/2, +-hy/2.
  double shoelace = 0.0;
  int hole_edges = 0;
  for (const auto& [a, b] : boundary_edges(m)) {
    const Vec3 p = m.vertices[a], q = m.vertices[b];
    if (std::abs(p.x) < 0.25 && std::abs(q.x) < 0.25 && std::abs(p.y) < 0.2 && std::abs(q.y) < 0.2) {
      ++hole_edges;
      EXPECT_TRUE((std::abs(p.x) == 0.05 || std::abs(p.y) == 0.03));
      shoelace += p.x * q.y - q.x * p.y;
    }
  }
  EXPECT_EQ(hole_edges, 4);
  EXPECT_EQ(-0.5 * shoelace, 0.1 * 0.06);  // hole traversed clockwise; exact for these corners
  EXPECT_EQ(count_edges(m).inconsistent + count_edges(m).non_manifold, 0u);
}

TEST(MeshBuilder, PlateWithRoundHole) {
  for (int n : {3, 5, 8, 40}) {
    const double lx = 0.3, ly = 0.2, r = 0.06;
    const TriangleMesh m = make_plate_with_round_hole(lx, ly, r, n);
    EXPECT_NEAR(total_area(m), lx * ly - polygon_area(n, r), 1e-15) << n;
    for (std::size_t t = 0; t < m.size(); ++t) EXPECT_NEAR(m.normal(t).z, 1.0, 1e-12) << n;
    int hole_edges = 0, outline_edges = 0;
    for (const auto& [a, b] : boundary_edges(m)) {
      const Vec3 p = m.vertices[a];
      if (std::hypot(p.x, p.y) < 0.09) {
        ++hole_edges;
        EXPECT_NEAR(std::hypot(p.x, p.y), r, 1e-17) << n;  // hole vertices exactly on the circle
      } else {
        ++outline_edges;
        EXPECT_TRUE(std::abs(p.x) == lx / 2 || std::abs(p.y) == ly / 2) << n;  // exact outline
      }
    }
    EXPECT_EQ(hole_edges, n);
    EXPECT_GE(outline_edges, 4);
    EXPECT_EQ(count_edges(m).inconsistent + count_edges(m).non_manifold, 0u);
  }
}

TEST(MeshBuilder, TransformAndFlip) {
  TriangleMesh m = make_box(0.4, 0.3, 0.2, true);
  const double area = total_area(m);
  transform_mesh(m, 2.0, {0, 0, 90}, {1, 2, 3});  // scale, then a quarter turn about z, then shift
  EXPECT_NEAR(total_area(m), 4 * area, 1e-14);
  expect_normals_towards(m, {1, 2, 3.2});
  Vec3 lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
  for (const Vec3& v : m.vertices) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  // x extent 0.8 became the y extent: [2 - 0.4, 2 + 0.4].
  EXPECT_NEAR(lo.x, 0.7, 1e-15);
  EXPECT_NEAR(hi.x, 1.3, 1e-15);
  EXPECT_NEAR(lo.y, 1.6, 1e-15);
  EXPECT_NEAR(hi.y, 2.4, 1e-15);
  EXPECT_NEAR(hi.z, 3.4, 1e-15);
  // rotate_xyz_deg order: x first, then y, then z.
  const Vec3 p = rotate_xyz_deg({1, 0, 0}, {0, 90, 90});  // (1,0,0) -y-> (0,0,-1) -z-> (0,0,-1)
  EXPECT_NEAR(p.z, -1.0, 1e-15);
  const Vec3 q = rotate_xyz_deg({0, 1, 0}, {90, 0, 90});  // (0,1,0) -x-> (0,0,1) -z-> (0,0,1)
  EXPECT_NEAR(q.z, 1.0, 1e-15);
  m.flip();
  EXPECT_NEAR(signed_volume(m), 8 * 0.4 * 0.3 * 0.2, 1e-14);  // now outward
}

// Two generated meshes in one scene: --first-id keeps their triangle ids apart.
TEST(MeshBuilder, FirstIdLetsMeshesShareAScene) {
  const mpdem::test::TempDir tmp("mpdem_mesh");
  const auto& dir = tmp.path;
  const TriangleMesh floor = make_rectangle(0.1, 0.1, 2, 2);
  write_mesh_csv(dir / "floor.csv", floor, "floor");
  write_mesh_csv(dir / "lid.csv", floor, "lid", static_cast<std::int64_t>(floor.size()));
  mpdem::Model model;
  model.materials.push_back(mpdem::Material{});
  mpdem::Barriers b;
  mpdem::BarrierSource src;
  mpdem::read_barrier_csv(dir / "floor.csv", src, model, b);
  EXPECT_NO_THROW(mpdem::read_barrier_csv(dir / "lid.csv", src, model, b));
  ASSERT_EQ(b.size(), 2 * floor.size());
  for (std::size_t e = 0; e < b.size(); ++e) EXPECT_EQ(b.id[e], static_cast<std::int64_t>(e));
  // Without the offset the second file's ids clash and the reader says so.
  mpdem::Barriers c;
  mpdem::read_barrier_csv(dir / "floor.csv", src, model, c);
  EXPECT_THROW(mpdem::read_barrier_csv(dir / "floor.csv", src, model, c), mpdem::InputError);
}
