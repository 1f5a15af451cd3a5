// `mpdem clump` (docs/tools.md "mpdem clump"): the distance to the surface behind the candidate
// radii, the greedy fill (one sphere in a sphere, the volume error falling with the count on a
// box, determinism), and the command's printed exact values of a cube and of a triangulated
// sphere against independent computations (1e-9 relative), its template CSV and its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/mesh_solid.hpp"
#include "geometry/mesh_transform.hpp"
#include "geometry/triangle_closest_point.hpp"
#include "io/stl_reader.hpp"
#include "io/stl_writer.hpp"
#include "support/run_command.hpp"
#include "support/solid_meshes.hpp"
#include "tools/clump_fill.hpp"

namespace mpdem {
namespace {

constexpr double kPi = 3.14159265358979323846;

double brute_distance(const TriangleMesh& m, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < m.size(); ++t)
    best = std::min(best, norm(closest_point_on_triangle(p, m.corner(t, 0), m.corner(t, 1), m.corner(t, 2)).point - p));
  return best;
}

// The cell-shell search finds exactly the brute-force minimum, inside and outside the solid.
TEST(ClumpFill, DistanceToSurfaceIsTheNearestTriangle) {
  TriangleMesh box = test::solid_box(0.03, 0.01, 0.02);
  transform_mesh(box, 1.0, {10, 20, 30}, {0.1, 0.2, -0.3});
  for (const TriangleMesh& m : {test::icosphere(3, 0.01, {0.02, -0.01, 0.005}), box}) {
    const MeshSolid solid(m);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-0.2, 1.2);  // of the bounding box
    const Vec3 lo = solid.lo(), ext = solid.hi() - solid.lo();
    for (int n = 0; n < 2000; ++n) {
      const Vec3 p{lo.x + u(rng) * ext.x, lo.y + u(rng) * ext.y, lo.z + u(rng) * ext.z};
      ASSERT_EQ(solid.distance_to_surface(p), brute_distance(m, p)) << n;
    }
  }
}

// One sphere in a triangulated sphere: at the centre (the odd grid has a point there) with the
// polyhedron's inscribed radius; allowed: one grid spacing off in position and radius.
TEST(ClumpFill, SphereWithOneMember) {
  const Vec3 centre{0.02, -0.01, 0.005};
  const TriangleMesh m = test::icosphere(3, 0.01, centre);
  const ClumpFill f = fill_with_spheres(m, 1, 31);
  ASSERT_EQ(f.members.size(), 1u);
  const double inscribed = brute_distance(m, centre);
  EXPECT_LE(norm(f.members[0].x - centre), f.spacing);
  EXPECT_NEAR(f.members[0].r, inscribed, f.spacing);
  EXPECT_LE(f.members[0].r, brute_distance(m, f.members[0].x));  // inside the solid
  std::printf("offset %.3g m, radius %.9g m, inscribed %.9g m, spacing %.3g m\n", norm(f.members[0].x - centre),
              f.members[0].r, inscribed, f.spacing);
}

// Volume of a union of spheres by counting the midpoints of a fine grid over the box [lo, hi]
// (independent of physics/clump_mass; relative error ~1e-3 at 180 x 135 x 90 points).
double union_volume(const std::vector<ClumpMember>& s, const Vec3& lo, const Vec3& hi, int nx) {
  const double h = (hi.x - lo.x) / nx;
  const int ny = static_cast<int>(std::lround((hi.y - lo.y) / h)),
            nz = static_cast<int>(std::lround((hi.z - lo.z) / h));
  long inside = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const Vec3 p = lo + Vec3{i + 0.5, j + 0.5, k + 0.5} * h;
        inside += std::any_of(s.begin(), s.end(), [&](const ClumpMember& c) { return norm2(p - c.x) <= c.r * c.r; });
      }
  return static_cast<double>(inside) * h * h * h;
}

// A 20 x 15 x 10 mm box: every member inside it; the greedy's choices are nested (the first 8 of
// 27 are the 8), so the union grows with N and the volume deficit falls: N = 1 is the largest
// inscribed sphere (r = 5 mm, deficit 1 - 4/3 pi 5^3 / 3000 = 0.825), N = 8 and 27 bring the
// deficit to 0.34 and 0.22 (asserted: each at least 0.05 below the previous).
TEST(ClumpFill, BoxVolumeErrorFallsWithCount) {
  const Vec3 lo{0.1, -0.2, 0.3}, size{0.02, 0.015, 0.01};
  TriangleMesh m = test::solid_box(size.x, size.y, size.z);
  for (Vec3& v : m.vertices) v += lo;
  const Vec3 hi = lo + size;
  const double vol = size.x * size.y * size.z;
  std::vector<ClumpMember> previous;
  double previous_error = 1.0;
  for (const int n : {1, 8, 27}) {
    const ClumpFill f = fill_with_spheres(m, n, 31);
    ASSERT_EQ(f.members.size(), static_cast<std::size_t>(n));
    for (const ClumpMember& c : f.members) {
      const double clearance = std::min(
          {c.x.x - lo.x, hi.x - c.x.x, c.x.y - lo.y, hi.y - c.x.y, c.x.z - lo.z, hi.z - c.x.z});
      EXPECT_LE(c.r, clearance * (1 + 1e-12));
    }
    for (std::size_t k = 0; k < previous.size(); ++k) {
      EXPECT_EQ(f.members[k].x, previous[k].x);
      EXPECT_EQ(f.members[k].r, previous[k].r);
    }
    const double error = 1.0 - union_volume(f.members, lo, hi, 180) / vol;
    std::printf("N = %2d: volume deficit %.4f, sample points covered %.4f\n", n, error,
                static_cast<double>(f.covered) / static_cast<double>(f.samples));
    if (n == 1) {  // the odd grid has a point at the box's centre
      const double r = f.members[0].r;
      EXPECT_NEAR(r, 0.005, 1e-13);
      EXPECT_NEAR(error, 1 - 4.0 / 3.0 * kPi * r * r * r / vol, 3e-3);
    }
    EXPECT_LT(error, previous_error - 0.05) << "N = " << n;
    previous_error = error;
    previous = f.members;
  }
}

TEST(ClumpFill, DeterministicAndWindingIndependent) {
  TriangleMesh m = test::solid_box(0.02, 0.015, 0.01);
  transform_mesh(m, 1.0, {15, -25, 35}, {0.01, 0.02, 0.03});
  const ClumpFill a = fill_with_spheres(m, 10, 25), b = fill_with_spheres(m, 10, 25);
  m.flip();
  const ClumpFill c = fill_with_spheres(m, 10, 25);
  ASSERT_EQ(a.members.size(), 10u);
  for (const ClumpFill* o : {&b, &c}) {
    ASSERT_EQ(o->members.size(), a.members.size());
    for (std::size_t k = 0; k < a.members.size(); ++k) {
      EXPECT_EQ(o->members[k].x, a.members[k].x);
      EXPECT_EQ(o->members[k].r, a.members[k].r);
    }
  }
}

// A 2 x 2 x 2 grid in a cube: each sphere (r = a/4) holds its own point only, so 8 spheres cover
// every sample point and a request for 100 gets 8.
TEST(ClumpFill, StopsWhenEverySamplePointIsCovered) {
  const ClumpFill f = fill_with_spheres(test::solid_box(1, 1, 1), 100, 2);
  EXPECT_EQ(f.members.size(), 8u);
  EXPECT_EQ(f.samples, 8u);
  EXPECT_EQ(f.covered, 8u);
  for (const ClumpMember& c : f.members) EXPECT_NEAR(c.r, 0.25, 1e-15);
}

TEST(ClumpFill, RejectsOpenSurfacesAndBadCounts) {
  TriangleMesh open = test::solid_box(1, 1, 1);
  open.triangles.pop_back();
  EXPECT_THROW(fill_with_spheres(open, 1, 10), std::invalid_argument);
  EXPECT_THROW(fill_with_spheres(test::solid_box(1, 1, 1), 0, 10), std::invalid_argument);
  EXPECT_THROW(fill_with_spheres(test::solid_box(1, 1, 1), 1, 1), std::invalid_argument);
}

// ---------------------------------------------------------------- the command

// The numbers of the printed table's row `label`: solid (exact), template, relative error.
std::vector<double> table_row(const std::string& out, const std::string& label) {
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(label, 0) == 0) {
      std::istringstream rest(line.substr(label.size()));
      std::vector<double> v;
      for (double x; rest >> x;) v.push_back(x);
      return v;
    }
  ADD_FAILURE() << "no row '" << label << "' in:\n" << out;
  return {0, 0, 0};
}

struct Printed {
  double volume;
  Vec3 centroid;
  double moment[3];
};

Printed printed_solid(const std::string& out) {
  Printed p{};
  p.volume = table_row(out, "volume (m^3)")[0];
  const char* axis[3] = {"centroid x (m)", "centroid y (m)", "centroid z (m)"};
  for (int a = 0; a < 3; ++a) p.centroid[a] = table_row(out, axis[a])[0];
  const char* moment[3] = {"I1 (m^5)", "I2 (m^5)", "I3 (m^5)"};
  for (int k = 0; k < 3; ++k) p.moment[k] = table_row(out, moment[k])[0];
  return p;
}

std::vector<ClumpMember> read_template(const std::filesystem::path& file) {
  std::istringstream in(test::slurp(file));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "x,y,z,radius");
  std::vector<ClumpMember> out;
  while (std::getline(in, line)) {
    ClumpMember c;
    EXPECT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &c.x.x, &c.x.y, &c.x.z, &c.r), 4) << line;
    out.push_back(c);
  }
  return out;
}

// A 10 mm cube from `mpdem mesh box --closed` (normals inward, as barrier meshes have): volume
// a^3, centroid (0, 0, a/2), every moment a^5 / 6; the template is the library's fill of the same
// surface, written exactly.
TEST(ClumpCommand, CubePrintsExactValues) {
  const auto d = test::fresh_dir("clump_cube");
  ASSERT_EQ(test::run_mpdem("mesh box --size 0.01 0.01 0.01 --closed -o cube.stl --format stl-ascii", d).status, 0);
  const test::CommandResult r = test::run_mpdem("clump cube.stl -n 8 -o cube.csv", d);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("wound inward"), std::string::npos) << r.out;
  const Printed p = printed_solid(r.out);
  const double a = 0.01;
  EXPECT_NEAR(p.volume, a * a * a, 1e-9 * a * a * a);
  const Vec3 centroid{0, 0, a / 2};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.centroid[k], centroid[k], 1e-9 * a);
  for (const double moment : p.moment) EXPECT_NEAR(moment, std::pow(a, 5) / 6, 1e-9 * std::pow(a, 5) / 6);

  const std::vector<ClumpMember> written = read_template(d / "cube.csv");
  const ClumpFill f = fill_with_spheres(weld(read_stl(d / "cube.stl").triangles), 8, 31);
  ASSERT_EQ(written.size(), f.members.size());
  for (std::size_t k = 0; k < written.size(); ++k) {
    EXPECT_EQ(written[k].x, f.members[k].x);
    EXPECT_EQ(written[k].r, f.members[k].r);
  }
  std::filesystem::remove_all(d);
}

// A triangulated sphere (1280 triangles, written as ASCII STL, exact): the printed values are the
// polyhedron's, checked against the independent tetrahedron quadrature about the sphere's centre
// (icosahedral symmetry: every principal moment is a third of the trace).
TEST(ClumpCommand, SpherePrintsThePolyhedronsExactValues) {
  const auto d = test::fresh_dir("clump_sphere");
  const Vec3 centre{0.02, -0.01, 0.005};
  const TriangleMesh m = test::icosphere(3, 0.01, centre);
  write_stl(d / "sphere.stl", soup(m), StlFormat::Ascii);
  const test::CommandResult r = test::run_mpdem("clump sphere.stl -n 1 -o sphere.csv", d);
  ASSERT_EQ(r.status, 0) << r.err;
  const test::QuadratureMass q = test::quadrature_mass(m, centre);
  const double moment = (q.inertia[0][0] + q.inertia[1][1] + q.inertia[2][2]) / 3;
  const Printed p = printed_solid(r.out);
  EXPECT_NEAR(p.volume, q.volume, 1e-9 * q.volume);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.centroid[k], q.centroid[k], 1e-9 * 0.01);
  for (const double i : p.moment) EXPECT_NEAR(i, moment, 1e-9 * moment);
  // The template column: one member, so the exact sphere volume and moment 2/5 r^2 of it; the
  // error column to its 4 printed digits.
  const std::vector<ClumpMember> members = read_template(d / "sphere.csv");
  ASSERT_EQ(members.size(), 1u);
  const double r3 = members[0].r * members[0].r * members[0].r, sphere = 4.0 / 3.0 * kPi * r3;
  const std::vector<double> volume = table_row(r.out, "volume (m^3)");
  ASSERT_EQ(volume.size(), 3u);
  EXPECT_NEAR(volume[1], sphere, 1e-9 * sphere);
  EXPECT_NEAR(volume[2], (sphere - q.volume) / q.volume, 1e-3 * std::abs(volume[2]));
  EXPECT_NEAR(table_row(r.out, "I1 (m^5)")[1], 0.4 * members[0].r * members[0].r * sphere, 1e-9 * moment);
  std::filesystem::remove_all(d);
}

// Bad input: one message naming the file (or the option) and exit status 2, nothing written.
TEST(ClumpCommand, BadInputExitsTwo) {
  const auto d = test::fresh_dir("clump_bad");
  ASSERT_EQ(test::run_mpdem("mesh box --size 0.01 0.01 0.01 -o open.stl", d).status, 0);  // no lid
  test::write_text(d / "junk.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n");
  test::write_text(d / "empty.stl", "");
  ASSERT_EQ(test::run_mpdem("mesh box --size 0.01 0.01 0.01 --closed -o cube.stl", d).status, 0);
  struct Case {
    std::string args, where, what;
  };
  const Case cases[] = {
      {"clump open.stl -n 4 -o t.csv", "open.stl", "not closed"},
      {"clump junk.stl -n 4 -o t.csv", "junk.stl:4", "vertex"},
      {"clump cube.stl -n 0 -o t.csv", "'-n'", "at least 1"},
      {"clump cube.stl -n 4 --resolution 1 -o t.csv", "'--resolution'", "2 to 128"},
      {"clump missing.stl -n 4 -o t.csv", "missing.stl", ""},
      {"clump empty.stl -n 4 -o t.csv", "empty.stl", ""},
  };
  for (const Case& c : cases) {
    const test::CommandResult r = test::run_mpdem(c.args, d);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.where), std::string::npos) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.what), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "one message only: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(d / "t.csv")) << c.args;
  }
  std::filesystem::remove_all(d);
}

}  // namespace
}  // namespace mpdem
