// Tests of reading scenes from disk (src/scene/scene_reader.cpp): each class of bad input gives an InputError
// naming file, line, dotted key and the expectation; load_scene reads the sources and the documented example.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::error_of;
using mpdem::test::expect_contains;

namespace {

const char* kTime = "\n[time]\nduration = 1.0\ndt = 1e-5\n";

}  // namespace

// One bad scene per error class: line number, dotted key and expectation text.
TEST(SceneReader, ErrorsNameFileLineKeyAndExpectation) {
  struct Case {
    const char* what;
    std::string toml;
    int line;
    std::string key;  // "" = no key in the message
    std::vector<std::string> expect;
  };
  const std::string mat = "[[material]]\nname = \"glass\"\n";  // 2 lines
  const std::vector<Case> cases = {
      {"unknown key, suggestion",
       "[time]\nduration = 1\ndt = 1e-5\ndurration = 2\n",
       4,
       "time.durration",
       {"unknown key", "did you mean 'time.duration'"}},
      {"unknown key, no suggestion",
       "[output]\nfrobnicate = 1\n" + std::string(kTime),
       2,
       "output.frobnicate",
       {"unknown key"}},
      {"unknown table", "[tme]\nduration = 1\n" + std::string(kTime), 1, "tme", {"unknown key", "did you mean 'time'"}},
      {"unknown motion key",
       std::string(kTime) + "[[barriers]]\nfile = \"w.csv\"\nmotion = { a = [0,0,0], w3 = 1 }\n",
       7,
       "barriers.motion.w3",
       {"unknown key", "did you mean 'barriers.motion.w1'"}},
      {"not a number",
       "[time]\nduration = 1\ndt = 1e-5\nphi = \"half\"\nintegrator = \"trapezoidal\"\n",
       4,
       "time.phi",
       {"expected a number in [0, 1], got a string"}},
      {"not a vector",
       "[gravity]\nvector = [0, 0]\n" + std::string(kTime),
       2,
       "gravity.vector",
       {"expected an array of 3 numbers", "2 elements"}},
      {"vector element",
       "[fields]\n\nelectric = [0, \"x\", 0]\n" + std::string(kTime),
       3,
       "fields.electric",
       {"expected an array of 3 numbers", "element 2 is a string"}},
      {"not a boolean",
       "[analysis]\nthermal = 1\n" + std::string(kTime),
       2,
       "analysis.thermal",
       {"expected a boolean"}},
      {"not an integer",
       "[time]\nduration = 1\ndt = 1e-5\nmax_iterations = 2.5\nintegrator = \"trapezoidal\"\n",
       4,
       "time.max_iterations",
       {"expected an integer >= 1, got a float"}},
      {"not a table", "time = 3\n", 1, "time", {"expected a table"}},
      {"single [material]",
       std::string(kTime) + "[material]\nname = \"x\"\n",
       5,
       "material",
       {"expected an array of tables [[material]]"}},
      {"zero duration", "[time]\nduration = 0\ndt = 1e-5\n", 2, "time.duration", {"expected a number > 0, got 0"}},
      {"negative dt", "[time]\nduration = 1\ndt = -1e-5\n", 3, "time.dt", {"expected a number > 0, got -1e-05"}},
      {"phi above 1",
       "[time]\nduration = 1\ndt = 1e-5\nphi = 1.5\nintegrator = \"trapezoidal\"\n",
       4,
       "time.phi",
       {"in [0, 1], got 1.5"}},
      {"dt_min > dt_max",
       "[time]\nduration = 1\ndt = 1e-5\ndt_min = 1e-4\ndt_max = 1e-5\nintegrator = \"trapezoidal\"\n",
       4,
       "time.dt_min",
       {"expected dt_min <= dt_max"}},
      {"dt outside bounds",
       "[time]\nduration = 1\ndt = 1e-3\ndt_max = 1e-4\nintegrator = \"trapezoidal\"\n",
       3,
       "time.dt",
       {"expected dt within [dt_min, dt_max]"}},
      {"unknown integrator",
       "[time]\nduration = 1\ndt = 1e-5\nintegrator = \"rk4\"\n",
       4,
       "time.integrator",
       {"expected \"trapezoidal\" or \"verlet\", got \"rk4\""}},
      {"missing duration", "\n[time]\ndt = 1e-5\n", 2, "time.duration", {"missing required key"}},
      {"missing dt", "[time]\nduration = 1\n", 1, "time.dt", {"missing required key"}},
      {"missing [time]", "[analysis]\nthermal = true\n", 0, "time.duration", {"missing required key"}},
      {"negative density",
       std::string(kTime) + mat + "density = -2500\n",
       7,
       "material.density",
       {"expected a number > 0, got -2500"}},
      {"zero young", std::string(kTime) + mat + "young = 0\n", 7, "material.young", {"expected a number > 0, got 0"}},
      {"poisson 0.5",
       std::string(kTime) + mat + "poisson = 0.5\n",
       7,
       "material.poisson",
       {"expected a number in [0, 0.5), got 0.5"}},
      {"material without name",
       std::string(kTime) + "[[material]]\ndensity = 1000\n",
       5,
       "material.name",
       {"missing required key"}},
      {"duplicate material", std::string(kTime) + mat + mat, 8, "material.name", {"duplicate material name 'glass'"}},
      {"restitution zero",
       "[contact.particle_particle]\nrestitution = 0\n" + std::string(kTime),
       2,
       "contact.particle_particle.restitution",
       {"expected a number in [0.001, 1], got 0", "give damping_ratio instead"}},
      {"restitution above 1",
       "[contact.particle_barrier]\nrestitution = 1.2\n" + std::string(kTime),
       2,
       "contact.particle_barrier.restitution",
       {"in [0.001, 1], got 1.2"}},
      {"restitution and damping",
       "[contact.particle_particle]\nrestitution = 0.5\ndamping_ratio = 0.2\n" + std::string(kTime),
       3,
       "contact.particle_particle.damping_ratio",
       {"either restitution or damping_ratio"}},
      {"mu_dynamic > mu_static",
       "[contact.particle_particle]\nmu_static = 0.3\nmu_dynamic = 0.35\n" + std::string(kTime),
       3,
       "contact.particle_particle.mu_dynamic",
       {"expected mu_dynamic <= mu_static"}},
      {"default mu_dynamic > mu_static",
       "[contact.particle_barrier]\nmu_static = 0.2\n" + std::string(kTime),
       2,
       "contact.particle_barrier.mu_static",
       {"mu_dynamic = 0.4 (default) > mu_static = 0.2"}},
      {"negative friction",
       "[contact.particle_particle]\nmu_rolling = -0.1\n" + std::string(kTime),
       2,
       "contact.particle_particle.mu_rolling",
       {"expected a number >= 0, got -0.1"}},
      {"unknown particle material",
       std::string(kTime) + mat + "[[particles]]\nfile = \"p.csv\"\nmaterial = \"wood\"\n",
       9,
       "particles.material",
       {"unknown material 'wood'", "known: glass"}},
      {"unknown barrier material",
       std::string(kTime) + "[[barriers]]\nfile = \"w.csv\"\nmaterial = \"wood\"\n",
       7,
       "barriers.material",
       {"unknown material 'wood'"}},
      {"unknown pair material",
       std::string(kTime) + mat +
           "[near_field]\ncutoff = 1\n[[near_field.pair]]\n"
           "material_a = \"glass\"\nmaterial_b = \"tin\"\n",
       11,
       "near_field.pair.material_b",
       {"unknown material 'tin'"}},
      {"near field without cutoff",
       std::string(kTime) + "[near_field]\ncoulomb = true\n",
       5,
       "near_field.cutoff",
       {"expected a cutoff > 0"}},
      {"particles without material",
       std::string(kTime) + "\n[[particles]]\nfile = \"p.csv\"\n",
       6,
       "material",
       {"at least one [[material]] is required"}},
      {"missing particle file",
       std::string(kTime) + mat + "[[particles]]\nfile = \"nope.csv\"\n",
       8,
       "particles.file",
       {"nope.csv", "does not exist"}},
      {"missing barrier file",
       std::string(kTime) + "[[barriers]]\nfile = \"gone/walls.csv\"\n",
       6,
       "barriers.file",
       {"gone/walls.csv", "does not exist"}},
      {"barrier without file",
       std::string(kTime) + "[[barriers]]\ngroup = \"g\"\n",
       5,
       "barriers.file",
       {"missing required key (give file or stl)"}},
      {"STL transform on CSV",
       std::string(kTime) + "[[barriers]]\nfile = \"w.csv\"\nscale = 2\n",
       7,
       "barriers.scale",
       {"applies to stl barriers only"}},
      {"unknown on_exit",
       std::string(kTime) + "[domain]\nmin = [0,0,0]\nmax = [1,1,1]\non_exit = \"reflect\"\n",
       8,
       "domain.on_exit",
       {"expected \"remove\" or \"stop\", got \"reflect\""}},
      {"domain min >= max",
       std::string(kTime) + "[domain]\nmin = [0,0,0]\nmax = [1,0,1]\n",
       7,
       "domain.max",
       {"expected max > min in every component", "y: min 0 >= max 0"}},
      {"domain without max",
       std::string(kTime) + "[domain]\nmin = [0,0,0]\n",
       5,
       "domain.max",
       {"missing required key"}},
      {"log_every zero",
       std::string(kTime) + "[output]\nlog_every = 0\n",
       6,
       "output.log_every",
       {"expected an integer >= 1, got 0"}},
      {"negative skin", std::string(kTime) + "[neighbor]\nskin = -1\n", 6, "neighbor.skin", {"expected a number >= 0"}},
      {"syntax error", "[time]\nduration = = 1\n", 2, "", {"TOML syntax error", "column"}},
      {"duplicate key", "[time]\nduration = 1\nduration = 2\n", 3, "", {"TOML syntax error"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_scene");
    d.write("p.csv", "x,y,z,radius\n0,0,0,1\n");
    d.write("w.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n0,0,0,1,0,0,0,1,0\n");
    const fs::path scene = d.write("scene.toml", c.toml);
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    // "file:line: 'key': message"; line 0 is left out.
    const std::string where = scene.string() + (c.line > 0 ? ":" + std::to_string(c.line) : "") + ": ";
    EXPECT_EQ(msg.rfind(where, 0), 0u) << "expected prefix '" << where << "' in: " << msg;
    if (!c.key.empty()) expect_contains(msg, {where + "'" + c.key + "': "});
    expect_contains(msg, c.expect);
  }
}

TEST(SceneReader, InputErrorCarriesFieldsSeparately) {
  TempDir d("mpdem_scene");
  const fs::path scene = d.write("scene.toml", "[time]\nduration = 1\ndt = 0\n");
  try {
    parse_scene_file(scene);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), scene.string());
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.key(), "time.dt");
  }
}

TEST(SceneReader, MissingSceneFile) {
  TempDir d("mpdem_scene");
  const std::string msg = error_of([&] { parse_scene_file(d.path / "absent.toml"); });
  expect_contains(msg, {"absent.toml", "does not exist"});
}

TEST(SceneReader, LoadSceneReadsSources) {
  TempDir d("mpdem_scene");
  d.write("beads.csv", "x,y,z,radius\n0,0,0.1,0.002\n0,0,0.2,0.003\n");
  d.write("more/beads2.csv", "id,x,y,z,radius,material\n7,1,0,0,0.001,glass\n");
  d.write("walls/floor.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n0,0,0,1,0,0,0,1,0\n0,0,0,0,1,0,-1,0,0\n");
  const fs::path scene = d.write("scene.toml", std::string(kTime) + R"(
[[material]]
name = "glass"
density = 2500
young = 5e9
[[material]]
name = "steel"
density = 7800
young = 2e11
poisson = 0.29
[[particles]]
file = "beads.csv"
material = "steel"
[[particles]]
file = "more/beads2.csv"
[[barriers]]
file = "walls/floor.csv"
material = "steel"
temperature = 500
motion = { B = [0, 0, 0.01], w2 = 2.0 }
)");
  const Scene s = load_scene(scene);
  ASSERT_EQ(s.particles.size(), 3u);
  EXPECT_EQ(s.particles.material[0], 1);  // the source's material
  EXPECT_EQ(s.model.materials[s.particles.material[1]].density, 7800.0);
  EXPECT_EQ(s.particles.id[0], 0);
  EXPECT_EQ(s.particles.id[1], 1);
  EXPECT_EQ(s.particles.id[2], 7);
  EXPECT_EQ(s.particles.material[2], 0);
  EXPECT_EQ(s.model.materials[s.particles.material[2]].young, 5e9);
  const double r = 0.003;
  EXPECT_DOUBLE_EQ(s.particles.mass[1], 4.0 / 3.0 * std::numbers::pi * r * r * r * 7800.0);

  ASSERT_EQ(s.barriers.size(), 2u);
  ASSERT_EQ(s.barriers.group_names.size(), 1u);
  EXPECT_EQ(s.barriers.group_names[0], "floor");  // the file stem
  EXPECT_EQ(s.barriers.young[0], 2e11);
  EXPECT_EQ(s.barriers.poisson[1], 0.29);
  EXPECT_EQ(s.barriers.temperature[0], 500.0);
  // Literal motion law: B cos(w2 t) shifts the barrier by B at t = 0.
  EXPECT_EQ(s.barriers.offset[0], (Vec3{0.0, 0.0, 0.01}));
  EXPECT_EQ(s.model.params.neighbor.skin, 0.0);  // no [neighbor]: the engine derives it
}

TEST(SceneReader, StlSourceErrorsNameTheStlFile) {
  TempDir d("mpdem_scene");
  d.write("chute.stl", "solid x\nendsolid x\n");
  const fs::path scene = d.write("scene.toml",
                                 std::string(kTime) + "[[barriers]]\nstl = \"chute.stl\"\nscale = 0.001\n");
  const Scene parsed = parse_scene_file(scene);  // parsing accepts the source...
  ASSERT_EQ(parsed.barrier_sources.size(), 1u);
  EXPECT_EQ(parsed.barrier_sources[0].scale, 0.001);
  const std::string msg = error_of([&] { load_scene(scene); });  // ...loading finds no triangles
  expect_contains(msg, {"chute.stl", "no facets"});
}

TEST(SceneReader, ErrorsInSourcesNameTheCsvFile) {
  TempDir d("mpdem_scene");
  d.write("beads.csv", "x,y,z,radius\n0,0,0,0.1\n0,0,0,-0.1\n");
  const fs::path scene = d.write("scene.toml", std::string(kTime) +
                                                   "[[material]]\nname = \"m\"\n[[particles]]\nfile = \"beads.csv\"\n");
  const std::string msg = error_of([&] { load_scene(scene); });
  expect_contains(msg, {"beads.csv:3: 'radius': expected a radius > 0"});
}

// The annotated example of docs/scene.md, shipped as tests/data/example_scene: it loads, and the
// documentation shows exactly the shipped scene file.
TEST(SceneReader, DocumentedExampleLoads) {
#ifdef MPDEM_SOURCE_DIR
  const fs::path root(MPDEM_SOURCE_DIR);
  const fs::path scene = root / "tests" / "data" / "example_scene" / "scene.toml";
  const Scene s = load_scene(scene);
  EXPECT_EQ(s.model.materials.size(), 2u);
  ASSERT_EQ(s.particles.size(), 4u);
  EXPECT_EQ(s.particles.id, (std::vector<std::int64_t>{1, 2, 3, 4}));
  EXPECT_EQ(s.particles.charge[1], -1e-10);
  EXPECT_EQ(s.model.materials[s.particles.material[0]].young, 6.3e10);  // material "glass"
  ASSERT_EQ(s.barriers.size(), 2u);
  EXPECT_NEAR(s.barriers.area[0], 0.005, 1e-15);  // half the 0.1 m square; 1e-15 m^2 allows rounding of 0.05
  EXPECT_EQ(s.barriers.normal[1], (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(s.barriers.young[1], 2.1e11);  // from material "steel"
  EXPECT_EQ(s.barriers.motion[0].w1, 314.16);

  const auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  const std::string doc = slurp(root / "docs" / "scene.md");
  const std::size_t a = doc.find("```toml\n");
  ASSERT_NE(a, std::string::npos);
  const std::size_t b = doc.find("```", a + 8);
  EXPECT_EQ(doc.substr(a + 8, b - (a + 8)), slurp(scene)) << "docs/scene.md example differs from the shipped scene";
#else
  GTEST_SKIP() << "MPDEM_SOURCE_DIR not defined";
#endif
}
