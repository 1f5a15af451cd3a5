// Particle generator (`mpdem generate`, scene `generate = {...}`): no overlaps, every sphere inside its region,
// reproducible from the seed, solid fraction targets met, velocities, clear errors for impossible requests.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "io/particle_csv_reader.hpp"
#include "io/stl_writer.hpp"
#include "model/scene.hpp"
#include "generate/generator.hpp"
#include "tools/mesh_builder.hpp"
#include "geometry/mesh_solid.hpp"
#include "support/generate_box_spec.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::box_spec;
using mpdem::test::TempDir;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Smallest surface-to-surface distance over all pairs, by brute force (no grid: independent of
// the generator's cell logic). Sorting by x prunes pairs that are far apart in x only.
double min_surface_gap(const std::vector<GeneratedParticle>& ps) {
  std::vector<GeneratedParticle> s = ps;
  std::sort(s.begin(), s.end(), [](const auto& a, const auto& b) { return a.x.x < b.x.x; });
  double r_max = 0.0;
  for (const auto& p : s) r_max = std::max(r_max, p.radius);
  double best = INFINITY;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size() && s[j].x.x - s[i].x.x < 2 * r_max + best; ++j)
      best = std::min(best, norm(s[j].x - s[i].x) - s[i].radius - s[j].radius);
  return best;
}

double volume_fraction(const std::vector<GeneratedParticle>& ps, double region_volume) {
  double v = 0.0;
  for (const auto& p : ps) v += 4.0 / 3.0 * kPi * p.radius * p.radius * p.radius;
  return v / region_volume;
}

}  // namespace

TEST(Generator, BoxNoOverlapAllInsideWithGap) {
  // 4000 spheres with radii uniform in [1, 2] mm and a 0.1 mm gap; tolerance 1e-12 m (rounding).
  GenerateSpec s = box_spec(0.1, 4000, 0.0);
  s.radius.law = RadiusLaw::Uniform;
  s.radius.min = 0.001;
  s.radius.max = 0.002;
  s.gap = 1e-4;
  const GenerateResult r = generate_particles(s);
  ASSERT_EQ(r.particles.size(), 4000u);
  EXPECT_GE(min_surface_gap(r.particles), 1e-4 - 1e-12);
  for (const auto& p : r.particles)
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p.x[a] - p.radius, 1e-4 - 1e-12);
      EXPECT_LE(p.x[a] + p.radius, 0.1 - 1e-4 + 1e-12);
    }
}

TEST(Generator, TiltedCylinderNoOverlapAllInside) {
  GenerateSpec s = box_spec(1, 3000, 0.002);
  s.region.shape = RegionShape::Cylinder;
  s.region.base = {0.1, -0.2, 0.3};
  s.region.axis = {0.03, 0.04, 0.12};  // length 0.13 m
  s.region.radius = 0.04;
  const GenerateResult r = generate_particles(s);
  ASSERT_EQ(r.particles.size(), 3000u);
  EXPECT_NEAR(r.region_volume, kPi * 0.04 * 0.04 * 0.13, 1e-15);
  EXPECT_GE(min_surface_gap(r.particles), -1e-12);
  const Vec3 w = s.region.axis / 0.13;
  for (const auto& p : r.particles) {
    const Vec3 d = p.x - s.region.base;
    const double t = dot(d, w);
    const double radial = norm(d - w * t);
    EXPECT_GE(t, 0.002 - 1e-12);
    EXPECT_LE(t, 0.13 - 0.002 + 1e-12);
    EXPECT_LE(radial, 0.04 - 0.002 + 1e-12);
  }
}

TEST(Generator, MeshRegionWithCavity) {
  // A unit box with a closed cubic cavity [0.3, 0.7]^3: a non-convex region of volume 1 - 0.064.
  TempDir dir("mpdem_gen");
  TriangleMesh outer = make_box(1, 1, 1, true);
  outer.flip();                                        // normals out of the solid
  TriangleMesh inner = make_box(0.4, 0.4, 0.4, true);  // normals into the cavity = out of the solid
  transform_mesh(inner, 1.0, {}, {0, 0, 0.3});
  outer.append(inner);
  transform_mesh(outer, 1.0, {}, {0.5, 0.5, 0});  // [0, 1]^3
  const fs::path stl = dir.path / "solid.stl";
  write_stl(stl, soup(outer), StlFormat::Ascii);

  // Membership against the analytic answer for points on a grid offset from every face.
  const MeshSolid solid(outer);
  EXPECT_NEAR(solid.volume(), 1.0 - 0.064, 1e-12);
  int wrong = 0;
  for (int i = 0; i < 23; ++i)
    for (int j = 0; j < 23; ++j)
      for (int k = 0; k < 23; ++k) {
        const Vec3 p{-0.05 + 0.05 * i + 0.0123, -0.05 + 0.05 * j + 0.0071, -0.05 + 0.05 * k + 0.0037};
        const auto in_box = [&](double lo, double hi) {
          return p.x > lo && p.x < hi && p.y > lo && p.y < hi && p.z > lo && p.z < hi;
        };
        wrong += solid.contains(p) != (in_box(0, 1) && !in_box(0.3, 0.7));
      }
  EXPECT_EQ(wrong, 0);
  // Points exactly in line with edges and vertices of the mesh (ray through shared features).
  EXPECT_TRUE(solid.contains({0.2, 0.5, 0.5}));  // ray along +x through the cavity's faces
  EXPECT_TRUE(solid.contains({0.2, 0.3, 0.3}));  // ray grazing the cavity's edge
  EXPECT_TRUE(solid.contains({0.1, 0.5, 0.5}));
  EXPECT_FALSE(solid.contains({0.5, 0.5, 0.5}));  // in the cavity
  EXPECT_TRUE(solid.contains({0.5, 0.5, 0.15}));  // below it, on the diagonals' plane x = y

  GenerateSpec s = box_spec(1, 2000, 0.02);
  s.region.shape = RegionShape::Mesh;
  s.region.mesh = stl;
  const GenerateResult r = generate_particles(s);
  ASSERT_EQ(r.particles.size(), 2000u);
  EXPECT_NEAR(r.region_volume, 0.936, 1e-12);
  EXPECT_GE(min_surface_gap(r.particles), -1e-12);
  for (const auto& p : r.particles) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p.x[a], 0.02 - 1e-12);
      EXPECT_LE(p.x[a], 1 - 0.02 + 1e-12);
    }
    // Distance from the centre to the cavity box must be at least the radius.
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double e = std::max({0.3 - p.x[a], 0.0, p.x[a] - 0.7});
      d2 += e * e;
    }
    EXPECT_GE(std::sqrt(d2), 0.02 - 1e-12);
  }
}

TEST(Generator, SameSeedSameFileOtherSeedDifferent) {
  TempDir dir("mpdem_gen");
  GenerateSpec s = box_spec(0.05, 1500, 0.0);
  s.radius.law = RadiusLaw::Normal;
  s.radius.mean = 0.001;
  s.radius.std = 0.0002;
  s.radius.min = 0.0006;
  s.radius.max = 0.0014;
  s.seed = 42;
  s.speed = 0.5;
  s.material = "glass";
  write_generated_csv(dir.path / "a.csv", s, generate_particles(s).particles);
  write_generated_csv(dir.path / "b.csv", s, generate_particles(s).particles);
  const std::string a = slurp(dir.path / "a.csv");
  EXPECT_GT(a.size(), 1500u * 30);
  EXPECT_EQ(a, slurp(dir.path / "b.csv"));
  s.seed = 43;
  write_generated_csv(dir.path / "c.csv", s, generate_particles(s).particles);
  EXPECT_NE(a, slurp(dir.path / "c.csv"));

  // The file is a valid particle CSV with the material column and exact numbers.
  Model model;
  Material glass;
  glass.name = "glass";
  model.materials.push_back(glass);
  Particles p;
  read_particle_csv(dir.path / "a.csv", model, 0, p);
  s.seed = 42;
  const auto g = generate_particles(s).particles;
  ASSERT_EQ(p.size(), g.size());
  for (std::size_t i = 0; i < g.size(); i += 97) {
    EXPECT_EQ(p.x[i], g[i].x);
    EXPECT_EQ(p.radius[i], g[i].radius);
    EXPECT_EQ(p.v[i], g[i].v);
  }
}

TEST(Generator, SolidFractionTargetMetWithinOnePercent) {
  {
    GenerateSpec s = box_spec(0.04, 0, 0.001);  // ~6100 equal spheres
    s.solid_fraction = 0.3;
    const GenerateResult r = generate_particles(s);
    std::printf("  monodisperse: solid fraction %.5f (%zu particles)\n",
                volume_fraction(r.particles, 0.04 * 0.04 * 0.04), r.particles.size());
    EXPECT_NEAR(volume_fraction(r.particles, 0.04 * 0.04 * 0.04) / 0.3, 1.0, 0.01);
    EXPECT_NEAR(r.solid_fraction / 0.3, 1.0, 0.01);
  }
  {
    GenerateSpec s = box_spec(0.05, 0, 0.0);  // radii uniform in [0.8, 1.6] mm
    s.radius.law = RadiusLaw::Uniform;
    s.radius.min = 0.0008;
    s.radius.max = 0.0016;
    s.solid_fraction = 0.3;
    const GenerateResult r = generate_particles(s);
    std::printf("  polydisperse: solid fraction %.5f (%zu particles)\n",
                volume_fraction(r.particles, 0.05 * 0.05 * 0.05), r.particles.size());
    EXPECT_NEAR(volume_fraction(r.particles, 0.05 * 0.05 * 0.05) / 0.3, 1.0, 0.01);
    EXPECT_GE(min_surface_gap(r.particles), -1e-12);
  }
}

TEST(Generator, ImpossibleRequestsAreClearErrors) {
  GenerateSpec s = box_spec(0.02, 0, 0.001);
  s.solid_fraction = 0.6;  // beyond random sequential addition's jamming limit (~0.38)
  s.max_attempts = 2000;
  try {
    generate_particles(s);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("could not place particle"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("of the requested 0.6"), std::string::npos) << e.what();
  }
  GenerateSpec big = box_spec(0.01, 1, 0.006);  // diameter larger than the box
  EXPECT_THROW(generate_particles(big), InputError);
}

TEST(Generator, Velocities) {
  GenerateSpec s = box_spec(0.05, 3000, 0.001);
  s.velocity = Vec3{0.1, -0.2, 0.3};
  for (const auto& p : generate_particles(s).particles) EXPECT_EQ(p.v, (Vec3{0.1, -0.2, 0.3}));
  s.velocity.reset();
  s.speed = 2.0;
  Vec3 sum{};
  const auto ps = generate_particles(s).particles;
  for (const auto& p : ps) {
    EXPECT_NEAR(norm(p.v), 2.0, 1e-12);
    sum += p.v / 2.0;
  }
  // Mean of 3000 unit vectors uniform on the sphere: each component has sd 1/sqrt(3 * 3000) = 0.0105.
  EXPECT_LT(norm(sum / 3000.0), 0.05);
}

TEST(Generator, SceneInlineTable) {
  TempDir dir("mpdem_gen");
  const fs::path scene = dir.write("scene.toml", R"(
[time]
duration = 1.0
dt = 1e-5

[[material]]
name = "glass"
density = 2500.0

[[material]]
name = "steel"
density = 7850.0
young = 2e11

[[particles]]
generate = { region = "box", min = [0, 0, 0], max = [0.05, 0.05, 0.05], count = 500, radius = { distribution = "uniform", min = 0.001, max = 0.0015 }, seed = 3, gap = 0.0001, material = "steel", velocity = [0, 0, -1] }

[[particles]]
generate = { region = "cylinder", base = [1, 0, 0], axis = [0, 0, 0.1], cylinder_radius = 0.02, solid_fraction = 0.1, radius = 0.002 }
)");
  const Scene sc = load_scene(scene);
  ASSERT_GT(sc.particles.size(), 500u);
  for (std::size_t i = 0; i < 500; ++i) {
    EXPECT_EQ(sc.particles.material[i], 1);
    EXPECT_EQ(sc.model.materials[sc.particles.material[i]].young, 2e11);
    EXPECT_EQ(sc.particles.v[i], (Vec3{0, 0, -1}));
    EXPECT_GE(sc.particles.radius[i], 0.001);
    EXPECT_LE(sc.particles.radius[i], 0.0015);
  }
  // Second source: ids continue, first material, solid fraction 0.1 of the cylinder within 1 %.
  const std::size_t n2 = sc.particles.size() - 500;
  EXPECT_EQ(sc.particles.id[500], 500);
  EXPECT_EQ(sc.particles.material[500], 0);
  const double v_cyl = kPi * 0.02 * 0.02 * 0.1, v_p = 4.0 / 3.0 * kPi * 0.002 * 0.002 * 0.002;
  EXPECT_NEAR(static_cast<double>(n2) * v_p / v_cyl / 0.1, 1.0, 0.01);

  // Errors name file, line and key.
  const auto error_of = [&](const std::string& gen) -> std::string {
    const fs::path p = dir.write("bad.toml", "[time]\nduration = 1.0\ndt = 1e-5\n[[material]]\nname = \"glass\"\n"
                                             "[[particles]]\ngenerate = " +
                                                 gen + "\n");
    try {
      load_scene(p);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  std::string e = error_of(R"({ region = "box", min = [0,0,0], max = [1,1,1], count = 5, radius = 0.1, colour = 1 })");
  EXPECT_NE(e.find("bad.toml:7: 'particles.generate.colour': unknown key"), std::string::npos) << e;
  e = error_of(R"({ region = "box", min = [0,0,0], max = [1,1,1], count = 5, solid_fraction = 0.1, radius = 0.1 })");
  EXPECT_NE(e.find("'particles.generate.solid_fraction': give exactly one of count and solid_fraction"),
            std::string::npos)
      << e;
  e = error_of(R"({ region = "sphere", count = 5, radius = 0.1 })");
  EXPECT_NE(e.find("'particles.generate.region': expected \"box\", \"cylinder\" or \"mesh\""), std::string::npos) << e;
  e = error_of(
      R"({ region = "box", min = [0,0,0], max = [1,1,1], count = 5, radius = { distribution = "uniform", min = 0.2, max = 0.1 } })");
  EXPECT_NE(e.find("'particles.generate.radius"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 0 < min <= max"), std::string::npos) << e;
  e = error_of(
      R"({ region = "box", min = [0,0,0], max = [1,1,1], count = 5, radius = { distribution = "uniform", value = 0.1 } })");
  EXPECT_NE(e.find("'particles.generate.radius.value': does not apply to distribution \"uniform\""), std::string::npos)
      << e;
  e = error_of(R"({ region = "box", min = [0,0,0], max = [1,1,1], count = 5, radius = 0.1, material = "gold" })");
  EXPECT_NE(e.find("unknown material 'gold'"), std::string::npos) << e;
}

TEST(Generator, CommandLine) {
  TempDir dir("mpdem_gen");
  const auto run = [&](const std::string& args) {
    const std::string cmd = std::string("\"") + MPDEM_BINARY + "\" generate " + args + " > /dev/null 2> \"" +
                            (dir.path / "err.txt").string() + "\"";
    const int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  };
  const std::string common = " --min 0 0 0 --max 0.02 0.02 0.02 --distribution discrete --radii 0.001 0.0015 "
                             "--fractions 1 1 --fractions-of mass -f 0.2 --seed 9 --material glass";
  ASSERT_EQ(run("-o \"" + (dir.path / "a.csv").string() + "\"" + common), 0);
  ASSERT_EQ(run("-o \"" + (dir.path / "b.csv").string() + "\"" + common), 0);
  EXPECT_EQ(slurp(dir.path / "a.csv"), slurp(dir.path / "b.csv"));
  EXPECT_NE(slurp(dir.path / "a.csv").find(",glass\n"), std::string::npos);
  // An unreachable target: exit status 2 and a message saying why.
  EXPECT_EQ(run("-o \"" + (dir.path / "c.csv").string() +
                "\" --min 0 0 0 --max 0.01 0.01 0.01 -r 0.001 -f 0.7 "
                "--max-attempts 500"),
            2);
  EXPECT_NE(slurp(dir.path / "err.txt").find("could not place particle"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir.path / "c.csv"));
}
