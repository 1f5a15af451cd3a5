// Bonded agglomerates (`mpdem agglomerate`, generate/agglomerate.hpp): the dense packing lies in
// its container with overlaps below the tolerance at the requested solid fraction, is the same
// for a seed, and its bonds are exactly the gap rule's pairs, for a sphere and a closed surface.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "generate/agglomerate.hpp"
#include "geometry/mesh_solid.hpp"
#include "io/stl_writer.hpp"
#include "support/solid_meshes.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using mpdem::test::TempDir;

namespace {

double ball_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

AgglomerateSpec equal_spheres(std::size_t count, double fraction, std::uint64_t seed = 1) {
  AgglomerateSpec s;
  s.radius.law = RadiusLaw::Constant;
  s.radius.value = 0.5e-3;
  s.count = count;
  s.fraction = fraction;
  s.seed = seed;
  return s;
}

// Largest overlap over the smaller radius, by brute force over all pairs (no grid).
double largest_overlap(const Agglomerate& a) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.x.size(); ++i)
    for (std::size_t j = i + 1; j < a.x.size(); ++j)
      worst = std::max(worst, (a.radius[i] + a.radius[j] - norm(a.x[j] - a.x[i])) / std::min(a.radius[i], a.radius[j]));
  return worst;
}

// The gap rule's pairs by brute force: every pair i < j with |x_j - x_i| - r_i - r_j < gap.
std::vector<std::array<std::size_t, 2>> brute_gap_pairs(const Agglomerate& a, double gap) {
  std::vector<std::array<std::size_t, 2>> pairs;
  for (std::size_t i = 0; i < a.x.size(); ++i)
    for (std::size_t j = i + 1; j < a.x.size(); ++j)
      if (norm(a.x[j] - a.x[i]) - a.radius[i] - a.radius[j] < gap) pairs.push_back({i, j});
  return pairs;
}

double solid_volume(const Agglomerate& a) {
  double v = 0.0;
  for (const double r : a.radius) v += ball_volume(r);
  return v;
}

// The option an InputError names ("mpdem agglomerate: '--fraction': ...").
template <class F>
std::string option_of(F&& f) {
  const std::string what = test::error_of(f);
  const std::size_t a = what.find('\'') + 1, b = what.find('\'', a);
  return b == std::string::npos ? what : what.substr(a, b - a);
}

}  // namespace

// N equal spheres at solid fraction F: the sphere's radius is (N / F)^(1/3) r (to 1e-12), every
// sphere lies inside it (to rounding), no overlap exceeds the tolerance.
TEST(Agglomerate, EqualSpheresInASphereByCount) {
  AgglomerateSpec s = equal_spheres(600, 0.55, 4);
  s.centre = {0.01, -0.02, 0.03};
  const Agglomerate a = make_agglomerate(s);
  ASSERT_EQ(a.x.size(), 600u);
  EXPECT_NEAR(a.sphere_radius, std::cbrt(600 / 0.55) * 0.5e-3, 1e-12 * a.sphere_radius);
  EXPECT_NEAR(a.fraction, 0.55, 1e-12);
  EXPECT_NEAR(solid_volume(a) / ball_volume(a.sphere_radius), 0.55, 1e-12);
  for (std::size_t i = 0; i < a.x.size(); ++i)
    EXPECT_LE(norm(a.x[i] - s.centre) + a.radius[i], a.sphere_radius * (1 + 1e-12)) << "particle " << i;
  EXPECT_LE(largest_overlap(a), 1e-3);
  EXPECT_EQ(largest_overlap(a), a.largest_overlap);
  EXPECT_GT(a.largest_overlap, 0.0);  // dense: spheres are pressed together, up to the tolerance
}

// A given sphere: the count follows from the fraction; the fraction reached is within half the
// largest particle's volume of the target (the draw stops closest to it).
TEST(Agglomerate, PolydisperseInAGivenSphere) {
  AgglomerateSpec s;
  s.radius.law = RadiusLaw::Uniform;
  s.radius.min = 0.3e-3;
  s.radius.max = 0.6e-3;
  s.sphere_radius = 4e-3;
  s.fraction = 0.55;
  s.tolerance = 5e-4;
  const Agglomerate a = make_agglomerate(s);
  EXPECT_NEAR(a.fraction, 0.55, 0.5 * ball_volume(0.6e-3) / ball_volume(4e-3));
  EXPECT_NEAR(a.container_volume, ball_volume(4e-3), 1e-15);
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    EXPECT_LE(norm(a.x[i]) + a.radius[i], 4e-3 * (1 + 1e-12)) << "particle " << i;
    EXPECT_GE(a.radius[i], 0.3e-3);
    EXPECT_LE(a.radius[i], 0.6e-3);
  }
  EXPECT_LE(largest_overlap(a), 5e-4);
}

// The bonds are exactly the pairs whose surface gap is below the gap, by brute force, for the
// default gap (1 % of the mean radius) and for others; sorted, i < j.
TEST(Agglomerate, BondsAreTheGapRulesPairs) {
  for (const double gap : {-1.0, 0.0, 2e-5, 1e-4}) {
    AgglomerateSpec s = equal_spheres(400, 0.55, 2);
    s.radius.law = RadiusLaw::Discrete;
    s.radius.radii = {0.4e-3, 0.6e-3};
    s.radius.fractions = {1, 1};
    s.gap = gap;
    const Agglomerate a = make_agglomerate(s);
    const double used = gap < 0 ? 0.01 *
                                      [&] {
                                        double m = 0.0;
                                        for (const double r : a.radius) m += r;
                                        return m / static_cast<double>(a.radius.size());
                                      }()
                                : gap;
    EXPECT_DOUBLE_EQ(a.gap, used);
    EXPECT_EQ(a.bonds, brute_gap_pairs(a, used)) << "gap " << gap;
    if (gap != 0.0) {
      EXPECT_GT(a.bonds.size(), a.x.size()) << "a dense packing has several bonds per particle";
    }
  }
}

// The same spec gives the same agglomerate bit for bit; another seed another one.
TEST(Agglomerate, DeterministicForASeed) {
  const Agglomerate a = make_agglomerate(equal_spheres(300, 0.55, 7));
  const Agglomerate b = make_agglomerate(equal_spheres(300, 0.55, 7));
  const Agglomerate c = make_agglomerate(equal_spheres(300, 0.55, 8));
  ASSERT_EQ(a.x.size(), b.x.size());
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    EXPECT_EQ(a.x[i].x, b.x[i].x);
    EXPECT_EQ(a.x[i].y, b.x[i].y);
    EXPECT_EQ(a.x[i].z, b.x[i].z);
  }
  EXPECT_EQ(a.bonds, b.bonds);
  EXPECT_EQ(a.sweeps, b.sweeps);
  EXPECT_NE(a.x[0].x, c.x[0].x);
}

// A closed surface as the container: a cube (by count: scaled about the origin to the volume
// the fraction asks for; by scale: the count follows) and an icosphere. Every sphere lies inside
// the solid: its centre inside and at least (1 - tolerance) r from every triangle.
TEST(Agglomerate, ClosedSurfaceContainer) {
  TempDir dir("mpdem_agg");
  const auto cube = dir.path / "cube.stl";
  write_stl(cube, soup(test::solid_box(1, 1, 1)), StlFormat::Ascii);
  const auto ball = dir.path / "ball.stl";
  write_stl(ball, soup(test::icosphere(2, 1.0, {0.2, 0.1, 0.0})), StlFormat::Ascii);

  AgglomerateSpec by_count = equal_spheres(500, 0.55);
  by_count.surface = cube;
  AgglomerateSpec by_scale = equal_spheres(0, 0.5);
  by_scale.surface = ball;
  by_scale.scale = 5e-3;
  for (const AgglomerateSpec& s : {by_count, by_scale}) {
    const Agglomerate a = make_agglomerate(s);
    TriangleMesh m = s.surface == cube ? test::solid_box(1, 1, 1) : test::icosphere(2, 1.0, {0.2, 0.1, 0.0});
    for (Vec3& v : m.vertices) v = v * a.scale;
    const MeshSolid solid(m);
    EXPECT_NEAR(a.container_volume, solid.volume(), 1e-12 * solid.volume());
    EXPECT_NEAR(a.fraction, solid_volume(a) / solid.volume(), 1e-12);
    if (s.count > 0) {
      EXPECT_NEAR(a.scale, std::cbrt(500 * ball_volume(0.5e-3) / 0.55), 1e-12 * a.scale);
      EXPECT_NEAR(a.fraction, 0.55, 1e-9);
    } else {
      EXPECT_EQ(a.scale, 5e-3);
      EXPECT_NEAR(a.fraction, 0.5, 0.5 * ball_volume(0.5e-3) / solid.volume());
    }
    for (std::size_t i = 0; i < a.x.size(); ++i) {
      EXPECT_TRUE(solid.contains(a.x[i])) << "particle " << i;
      EXPECT_GE(solid.distance_to_surface(a.x[i]), a.radius[i] * (1 - 1e-3)) << "particle " << i;
    }
    EXPECT_LE(largest_overlap(a), 1e-3);
    EXPECT_EQ(a.bonds, brute_gap_pairs(a, a.gap));
  }
}

// A non-convex container: an 8 mm cube with a closed cubic cavity of 3.2 mm in its middle (the
// solid between them). Every sphere keeps out of the cavity: its centre is at least
// (1 - tolerance) r from the cavity's box, measured analytically, and inside the outer cube.
TEST(Agglomerate, ContainerWithACavity) {
  TempDir dir("mpdem_agg");
  TriangleMesh solid = test::solid_box(1, 1, 1);         // [0, 1]^3, normals out of the solid
  TriangleMesh cavity = test::solid_box(0.4, 0.4, 0.4);  // [0.3, 0.7]^3 once moved
  for (Vec3& v : cavity.vertices) v += Vec3{0.3, 0.3, 0.3};
  cavity.flip();  // normals into the cavity, out of the solid
  solid.append(cavity);
  const auto file = dir.path / "cavity.stl";
  write_stl(file, soup(solid), StlFormat::Ascii);

  AgglomerateSpec s = equal_spheres(0, 0.5);
  s.radius.value = 0.4e-3;
  s.surface = file;
  s.scale = 8e-3;
  const Agglomerate a = make_agglomerate(s);
  const double side = 8e-3, lo = 0.3 * side, hi = 0.7 * side;  // m
  EXPECT_NEAR(a.container_volume, side * side * side * (1 - 0.064), 1e-9 * a.container_volume);
  EXPECT_NEAR(a.fraction, 0.5, 0.5 * ball_volume(0.4e-3) / a.container_volume);
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    const double r = a.radius[i] * (1 - 1e-3);
    double d2 = 0.0;  // m^2, squared distance from the centre to the cavity's box
    for (int k = 0; k < 3; ++k) {
      const double c = a.x[i][k];
      EXPECT_GE(c, r) << "particle " << i;
      EXPECT_LE(c, side - r) << "particle " << i;
      const double out = std::max({lo - c, 0.0, c - hi});
      d2 += out * out;
    }
    EXPECT_GE(std::sqrt(d2), r) << "particle " << i;
  }
  EXPECT_LE(largest_overlap(a), 1e-3);
}

// Impossible or contradictory requests name the option at fault.
TEST(Agglomerate, BadRequestsNameTheOption) {
  AgglomerateSpec s = equal_spheres(100, 0.8);
  EXPECT_EQ(option_of([&] { make_agglomerate(s); }), "--fraction");
  s = equal_spheres(100, 0.55);
  s.sphere_radius = 5e-3;
  EXPECT_EQ(option_of([&] { make_agglomerate(s); }), "--count");
  s = equal_spheres(0, 0.55);
  EXPECT_EQ(option_of([&] { make_agglomerate(s); }), "--sphere");
  s.sphere_radius = 0.4e-3;  // smaller than a particle
  EXPECT_EQ(option_of([&] { make_agglomerate(s); }), "--sphere");
  s = equal_spheres(100, 0.55);
  s.tolerance = 0.0;
  EXPECT_EQ(option_of([&] { make_agglomerate(s); }), "--tolerance");
  // Denser than 100 equal spheres pack in a sphere: no convergence within the sweeps.
  s = equal_spheres(100, 0.7);
  s.max_sweeps = 2000;
  const std::string what = test::error_of([&] { make_agglomerate(s); });
  test::expect_contains(what, {"'--fraction'", "did not fall below the tolerance 0.001 within 2000 sweeps",
                               "solid fraction 0.7000", "lower --fraction"});
}

// largest_cluster_only keeps the largest bonded cluster: every particle bonded, all of them
// joined (a walk over the bonds reaches every one), the bonds the gap rule's pairs of the
// particles kept, and the particles kept those of the full packing, in its order.
TEST(Agglomerate, LargestClusterOnly) {
  AgglomerateSpec s = equal_spheres(1000, 0.55);
  const Agglomerate all = make_agglomerate(s);
  ASSERT_GT(all.unbonded, 0u) << "the test needs a packing with particles left out";
  s.largest_cluster_only = true;
  const Agglomerate a = make_agglomerate(s);
  EXPECT_EQ(a.x.size(), all.largest_cluster);
  EXPECT_EQ(a.dropped, all.x.size() - a.x.size());
  EXPECT_EQ(a.unbonded, 0u);
  EXPECT_EQ(a.largest_cluster, a.x.size());
  EXPECT_EQ(a.bonds, brute_gap_pairs(a, a.gap));
  EXPECT_NEAR(a.kept_fraction, solid_volume(a) / a.container_volume, 1e-12);
  EXPECT_EQ(a.fraction, all.fraction);
  // Connected: a breadth-first walk from particle 0.
  std::vector<std::vector<std::size_t>> next(a.x.size());
  for (const auto& [i, j] : a.bonds) {
    next[i].push_back(j);
    next[j].push_back(i);
  }
  std::vector<bool> seen(a.x.size(), false);
  std::vector<std::size_t> queue{0};
  seen[0] = true;
  for (std::size_t k = 0; k < queue.size(); ++k)
    for (const std::size_t j : next[queue[k]])
      if (!seen[j]) {
        seen[j] = true;
        queue.push_back(j);
      }
  EXPECT_EQ(queue.size(), a.x.size());
  // The kept particles are the packing's, in order.
  std::size_t k = 0;
  for (std::size_t i = 0; i < all.x.size() && k < a.x.size(); ++i)
    if (all.x[i].x == a.x[k].x && all.x[i].y == a.x[k].y && all.x[i].z == a.x[k].z) ++k;
  EXPECT_EQ(k, a.x.size());
}
