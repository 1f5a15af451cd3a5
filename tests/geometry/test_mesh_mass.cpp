// Mass properties of closed triangle surfaces by the divergence theorem (geometry/mesh_mass.hpp):
// polyhedra against their closed forms (exact up to rounding: 1e-12 relative), an icosphere
// against an independent tetrahedron quadrature, and the convergence of finer icospheres to the
// sphere at the rate O(h^2) of an inscribed polyhedron.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/rotation.hpp"
#include "geometry/mesh_mass.hpp"
#include "geometry/mesh_transform.hpp"
#include "physics/principal_axes.hpp"
#include "support/solid_meshes.hpp"

namespace mpdem {
namespace {

constexpr double kPi = 3.14159265358979323846;

void expect_rel(double got, double want, double tol, const char* what) {
  EXPECT_NEAR(got, want, tol * std::abs(want)) << what;
}

// Every entry of the inertia tensor against `want`, relative to the tensor's largest entry.
void expect_tensor(const Mat3& got, const Mat3& want, double tol) {
  double scale = 0.0;
  for (const auto& row : want)
    for (double x : row) scale = std::max(scale, std::abs(x));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(got[i][j], want[i][j], tol * scale) << i << "," << j;
}

Mat3 diagonal(double a, double b, double c) { return {{{a, 0, 0}, {0, b, 0}, {0, 0, c}}}; }

TEST(MeshMass, UnitCube) {
  for (const bool flip : {false, true}) {
    TriangleMesh m = test::solid_box(1, 1, 1);
    if (flip) m.flip();
    const MeshMassProperties p = mesh_mass_properties(m);
    EXPECT_EQ(p.inward, flip);
    EXPECT_NEAR(p.volume, 1.0, 1e-12);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(p.centroid[a], 0.5, 1e-12);
    expect_tensor(p.inertia, diagonal(1.0 / 6, 1.0 / 6, 1.0 / 6), 1e-12);  // m (1 + 1) / 12
  }
}

// An a x b x c box centred at t and rotated: volume abc, centroid t, inertia R diag(m (b^2 + c^2)/12,
// m (a^2 + c^2)/12, m (a^2 + b^2)/12) R^T, principal axes the rotated box axes.
TEST(MeshMass, RotatedTranslatedBox) {
  const double a = 0.3, b = 0.2, c = 0.1;
  const Vec3 deg{30, -50, 70}, t{5, -3, 2};
  TriangleMesh m = test::solid_box(a, b, c);
  for (Vec3& v : m.vertices) v -= Vec3{a, b, c} * 0.5;
  transform_mesh(m, 1.0, deg, t);
  const MeshMassProperties p = mesh_mass_properties(m);
  const double vol = a * b * c;
  const double moment[3] = {vol * (b * b + c * c) / 12, vol * (a * a + c * c) / 12, vol * (a * a + b * b) / 12};
  EXPECT_FALSE(p.inward);
  expect_rel(p.volume, vol, 1e-12, "volume");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.centroid[k], t[k], 1e-12 * norm(t)) << k;
  const Vec3 axis[3] = {rotate_xyz_deg({1, 0, 0}, deg), rotate_xyz_deg({0, 1, 0}, deg), rotate_xyz_deg({0, 0, 1}, deg)};
  Mat3 want{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) want[i][j] += axis[k][i] * moment[k] * axis[k][j];
  expect_tensor(p.inertia, want, 1e-12);
  const PrincipalAxes principal = principal_axes(p.inertia);
  for (int k = 0; k < 3; ++k) {  // moments ascending: I_a < I_b < I_c here
    expect_rel(principal.moments[k], moment[k], 1e-12, "principal");
    const Vec3 e{principal.axes[0][k], principal.axes[1][k], principal.axes[2][k]};
    EXPECT_NEAR(std::abs(dot(e, axis[k])), 1.0, 1e-12) << k;
  }
}

// |x| + |y| + |z| <= a about (1, 2, 3): volume 4/3 a^3, isotropic moment a^2/5 of the volume.
TEST(MeshMass, Octahedron) {
  const double a = 0.7;
  const Vec3 centre{1, 2, 3};
  TriangleMesh m = test::solid_octahedron(a);
  for (Vec3& v : m.vertices) v += centre;
  const MeshMassProperties p = mesh_mass_properties(m);
  const double vol = 4.0 / 3.0 * a * a * a, moment = vol * a * a / 5;
  expect_rel(p.volume, vol, 1e-12, "volume");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.centroid[k], centre[k], 1e-12 * norm(centre));
  expect_tensor(p.inertia, diagonal(moment, moment, moment), 1e-12);
}

// The regular icosahedron of edge s: volume 5/12 (3 + sqrt 5) s^3, isotropic moment
// phi^2 s^2 / 10 of the volume (phi the golden ratio).
TEST(MeshMass, Icosahedron) {
  const TriangleMesh m = test::icosphere(0, 1.0);
  const double s = norm(m.corner(0, 1) - m.corner(0, 0)), phi = (1 + std::sqrt(5.0)) / 2;
  const double vol = 5.0 / 12.0 * (3 + std::sqrt(5.0)) * s * s * s, moment = phi * phi * s * s / 10 * vol;
  const MeshMassProperties p = mesh_mass_properties(m);
  expect_rel(p.volume, vol, 1e-12, "volume");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.centroid[k], 0.0, 1e-12);
  expect_tensor(p.inertia, diagonal(moment, moment, moment), 1e-12);
}

// An independent computation of the same polyhedron: tetrahedra from the sphere's centre (not the
// bounding box's centre) integrated by a quadrature rule (test::quadrature_mass).
TEST(MeshMass, IcosphereAgreesWithTetrahedronQuadrature) {
  const Vec3 centre{0.3, -0.2, 0.1};
  const TriangleMesh m = test::icosphere(3, 0.05, centre);
  const test::QuadratureMass q = test::quadrature_mass(m, centre);
  const MeshMassProperties p = mesh_mass_properties(m);
  expect_rel(p.volume, q.volume, 1e-12, "volume");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.centroid[k], q.centroid[k], 1e-12 * norm(centre));
  expect_tensor(p.inertia, q.inertia, 1e-12);
}

// Icospheres inscribed in the sphere of radius R converge to its volume 4/3 pi R^3 and moment
// 2/5 R^2 of it with the square of the edge length h: each flat triangle cuts off a cap of
// depth ~ h^2 / (8 R): the relative errors are about (h / R)^2 / 3 (volume) and (h / R)^2 / 2
// (moment), bounded here by 0.5 and 0.8 (h / R)^2 (h the longest edge), and fall by 4 per level.
TEST(MeshMass, IcosphereConvergesToSphere) {
  const double r = 0.02;
  const double vol = 4.0 / 3.0 * kPi * r * r * r, moment = 0.4 * r * r * vol;
  double previous_v = 0.0, previous_i = 0.0;
  for (int level = 1; level <= 5; ++level) {
    const TriangleMesh m = test::icosphere(level, r);
    double h = 0.0;  // m, longest edge
    for (std::size_t t = 0; t < m.size(); ++t)
      for (int k = 0; k < 3; ++k) h = std::max(h, norm(m.corner(t, k) - m.corner(t, (k + 1) % 3)));
    const MeshMassProperties p = mesh_mass_properties(m);
    const Vec3 moments = principal_axes(p.inertia).moments;
    const double ev = (vol - p.volume) / vol, ei = (moment - moments[0]) / moment;
    EXPECT_GT(ev, 0.0);  // inscribed: always less
    EXPECT_LT(ev, 0.5 * (h / r) * (h / r)) << "level " << level;
    EXPECT_LT(ei, 0.8 * (h / r) * (h / r)) << "level " << level;
    EXPECT_NEAR(moments[2], moments[0], 1e-12 * moment);  // icosahedral symmetry: isotropic
    if (level >= 3) {
      EXPECT_NEAR(previous_v / ev, 4.0, 0.3) << "level " << level;
      EXPECT_NEAR(previous_i / ei, 4.0, 0.3) << "level " << level;
    }
    previous_v = ev;
    previous_i = ei;
    std::printf("level %d: %zu triangles, h/R = %.4f, volume error %.3e, moment error %.3e\n", level, m.size(), h / r,
                ev, ei);
  }
}

TEST(MeshMass, EmptyOrFlatMeshThrows) {
  EXPECT_THROW(mesh_mass_properties(TriangleMesh{}), std::invalid_argument);
  TriangleMesh flat;  // two triangles back to back: closed, no volume
  for (const Vec3& v : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}) flat.add_vertex(v);
  flat.add_triangle(0, 1, 2);
  flat.add_triangle(0, 2, 1);
  EXPECT_THROW(mesh_mass_properties(flat), std::invalid_argument);
}

}  // namespace
}  // namespace mpdem
