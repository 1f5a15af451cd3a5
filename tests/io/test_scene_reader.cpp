// Tests of the TOML scene reader (src/io/scene_reader.cpp): every key lands in the right field,
// documented defaults apply, and each class of bad input gives an InputError naming file, line,
// dotted key and the expectation. Inputs are written to a fresh temporary folder per test.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::error_of;
using mpdem::test::expect_contains;

namespace {

// A fresh folder under the system temp dir, removed at the end of the test.

// what() of the InputError `f` throws ("" and a test failure when it throws none).


const char* kTime = "\n[time]\nduration = 1.0\ndt = 1e-5\n";

}  // namespace

TEST(SceneReader, FullSceneMapsEveryKey) {
  TempDir d("mpdem_scene");
  d.write("data/beads.csv", "x,y,z,radius\n0,0,0,0.001\n");
  d.write("walls.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n0,0,0,1,0,0,0,1,0\n");
  const fs::path scene = d.write("scene.toml", R"(
[time]
duration = 2          # an integer where a float is expected
integrator = "verlet"
phi = 0.75
dt = 1e-4
dt_min = 1e-6
dt_max = 2e-4
adaptive = true
desired_iterations = 8
p = 3.0
max_iterations = 40

[tolerance]
position = 1e-6
velocity = 2e-6
rotation = 3e-6
angular_velocity = 4e-6
temperature = 5e-6

[analysis]
rotation = false
thermal = true

[gravity]
vector = [0.5, -1, -9.0]

[fields]
electric = [1.0, 2.0, 3.0]
magnetic = [0.0, 0.0, 0.5]

[near_field]
a1 = 1e-9
b1 = 2.0
a2 = 3e-9
b2 = 4.0
coulomb = true
permittivity = 2.5
cutoff = 0.01

[[near_field.pair]]
material_a = "glass"
material_b = "steel"
a1 = 7e-9

[contact.particle_particle]
restitution = 0.8
mu_static = 0.6
mu_dynamic = 0.5
mu_rolling = 0.02
tangential_damping = 0.1

[contact.particle_barrier]
damping_ratio = 0.3
mu_static = 0.4
mu_dynamic = 0.3
mu_rolling = 0.01
tangential_damping = 0.2

[thermal]
air_temperature = 300.0
air_velocity = [1.0, 0.0, 0.0]
environment_temperature = 310.0
conduction = false
convection = true
radiation = true

[[material]]
name = "glass"
density = 2600.0
young = 6e10
poisson = 0.22
conductivity = 1.1
heat_capacity = 840.0
emissivity = 0.85
charge = 1e-12
temperature = 350.0

[[material]]
name = "steel"
density = 7800

[[particles]]
file = "data/beads.csv"
material = "steel"

[[barriers]]
file = "walls.csv"
group = "floor"
material = "steel"
thickness = 0.002
temperature = 400.0
motion = { a = [0.1, 0, 0], A = [0, 0.2, 0], w1 = 3.0, B = [0, 0, 0.3], w2 = 4.0 }

[domain]
min = [-1, -2, -3]
max = [1, 2, 3]
on_exit = "remove"

[neighbor]
skin = 0.0005

[output]
dir = "out"
particles_every = 0.01
barriers_every = 0.02
particle_csv_every = 0.03
barrier_log_every = 0.04
log_every = 50
checkpoint_every = 1000
progress_every = 5.0
)");
  const Scene s = parse_scene_file(scene);
  const Params& p = s.model.params;
  EXPECT_EQ(s.dir, d.path.lexically_normal());
  EXPECT_EQ(p.time.duration, 2.0);
  EXPECT_EQ(p.time.integrator, Integrator::Verlet);
  EXPECT_EQ(p.time.phi, 0.75);
  EXPECT_EQ(p.time.dt, 1e-4);
  EXPECT_EQ(p.time.dt_min, 1e-6);
  EXPECT_EQ(p.time.dt_max, 2e-4);
  EXPECT_TRUE(p.time.adaptive);
  EXPECT_EQ(p.time.desired_iterations, 8);
  EXPECT_EQ(p.time.p, 3.0);
  EXPECT_EQ(p.time.max_iterations, 40);

  EXPECT_EQ(p.tolerance.position, 1e-6);
  EXPECT_EQ(p.tolerance.velocity, 2e-6);
  EXPECT_EQ(p.tolerance.rotation, 3e-6);
  EXPECT_EQ(p.tolerance.angular_velocity, 4e-6);
  EXPECT_EQ(p.tolerance.temperature, 5e-6);
  EXPECT_FALSE(p.analysis.rotation);
  EXPECT_TRUE(p.analysis.thermal);
  EXPECT_EQ(p.fields.gravity, (Vec3{0.5, -1.0, -9.0}));
  EXPECT_EQ(p.fields.electric, (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(p.fields.magnetic, (Vec3{0.0, 0.0, 0.5}));

  const NearFieldParams& nf = p.near_field;
  EXPECT_TRUE(nf.empirical);  // switched on by giving coefficients
  EXPECT_EQ(nf.a1, 1e-9);
  EXPECT_EQ(nf.b1, 2.0);
  EXPECT_EQ(nf.a2, 3e-9);
  EXPECT_EQ(nf.b2, 4.0);
  EXPECT_TRUE(nf.coulomb);
  EXPECT_EQ(nf.permittivity, 2.5);
  EXPECT_EQ(nf.cutoff, 0.01);
  ASSERT_EQ(nf.pairs.size(), 1u);
  EXPECT_EQ(nf.pairs[0].material_a, "glass");
  EXPECT_EQ(nf.pairs[0].material_b, "steel");
  EXPECT_EQ(nf.pairs[0].a1, 7e-9);
  EXPECT_EQ(nf.pairs[0].b1, 2.0);  // not given: the global value
  EXPECT_EQ(nf.pairs[0].a2, 3e-9);
  EXPECT_EQ(nf.pairs[0].b2, 4.0);

  const ContactLawParams& pp = p.contact.particle_particle;
  ASSERT_TRUE(pp.restitution.has_value());
  EXPECT_EQ(*pp.restitution, 0.8);
  EXPECT_FALSE(pp.damping_ratio.has_value());
  EXPECT_EQ(pp.mu_static, 0.6);
  EXPECT_EQ(pp.mu_dynamic, 0.5);
  EXPECT_EQ(pp.mu_rolling, 0.02);
  EXPECT_EQ(pp.tangential_damping, 0.1);
  const ContactLawParams& pb = p.contact.particle_barrier;
  EXPECT_FALSE(pb.restitution.has_value());
  ASSERT_TRUE(pb.damping_ratio.has_value());
  EXPECT_EQ(*pb.damping_ratio, 0.3);
  EXPECT_EQ(pb.mu_static, 0.4);
  EXPECT_EQ(pb.mu_dynamic, 0.3);
  EXPECT_EQ(pb.mu_rolling, 0.01);
  EXPECT_EQ(pb.tangential_damping, 0.2);

  EXPECT_EQ(p.thermal.air_temperature, 300.0);
  EXPECT_EQ(p.thermal.air_velocity, (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(p.thermal.environment_temperature, 310.0);
  EXPECT_FALSE(p.thermal.conduction);
  EXPECT_TRUE(p.thermal.convection);
  EXPECT_TRUE(p.thermal.radiation);

  ASSERT_EQ(s.model.materials.size(), 2u);
  const Material& g = s.model.materials[0];
  EXPECT_EQ(g.name, "glass");
  EXPECT_EQ(g.density, 2600.0);
  EXPECT_EQ(g.young, 6e10);
  EXPECT_EQ(g.poisson, 0.22);
  EXPECT_EQ(g.conductivity, 1.1);
  EXPECT_EQ(g.heat_capacity, 840.0);
  EXPECT_EQ(g.emissivity, 0.85);
  EXPECT_EQ(g.charge, 1e-12);
  EXPECT_EQ(g.temperature, 350.0);
  EXPECT_EQ(s.model.materials[1].density, 7800.0);
  EXPECT_EQ(s.model.materials[1].young, Material{}.young);  // not given: Material's default
  EXPECT_EQ(s.model.material_index("steel"), 1);
  EXPECT_EQ(s.model.material_index("wood"), -1);

  ASSERT_EQ(s.particle_sources.size(), 1u);
  EXPECT_EQ(s.particle_sources[0].file, (d.path / "data" / "beads.csv").lexically_normal());
  EXPECT_EQ(s.particle_sources[0].material, "steel");
  EXPECT_EQ(s.particle_sources[0].line, 83u);

  ASSERT_EQ(s.barrier_sources.size(), 1u);
  const BarrierSource& b = s.barrier_sources[0];
  EXPECT_EQ(b.file, (d.path / "walls.csv").lexically_normal());
  EXPECT_TRUE(b.stl.empty());
  EXPECT_EQ(b.group, "floor");
  EXPECT_EQ(b.material, "steel");
  EXPECT_EQ(b.thickness, 0.002);
  ASSERT_TRUE(b.temperature.has_value());
  EXPECT_EQ(*b.temperature, 400.0);
  EXPECT_EQ(b.motion.a, (Vec3{0.1, 0.0, 0.0}));
  EXPECT_EQ(b.motion.A, (Vec3{0.0, 0.2, 0.0}));
  EXPECT_EQ(b.motion.w1, 3.0);
  EXPECT_EQ(b.motion.B, (Vec3{0.0, 0.0, 0.3}));
  EXPECT_EQ(b.motion.w2, 4.0);

  EXPECT_TRUE(p.domain.bounded);
  EXPECT_EQ(p.domain.min, (Vec3{-1.0, -2.0, -3.0}));
  EXPECT_EQ(p.domain.max, (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(p.domain.on_exit, ExitPolicy::Remove);
  EXPECT_EQ(p.neighbor.skin, 0.0005);
  EXPECT_EQ(p.output.dir, "out");
  EXPECT_EQ(p.output.particles_every, 0.01);
  EXPECT_EQ(p.output.barriers_every, 0.02);
  EXPECT_EQ(p.output.particle_csv_every, 0.03);
  EXPECT_EQ(p.output.barrier_log_every, 0.04);
  EXPECT_EQ(p.output.log_every, 50);
  EXPECT_EQ(p.output.checkpoint_every, 1000);
  EXPECT_EQ(p.output.progress_every, 5.0);
}

// The defaults documented in docs/scene.md.
TEST(SceneReader, DocumentedDefaults) {
  TempDir d("mpdem_scene");
  const Scene s = parse_scene_file(d.write("scene.toml", "[time]\nduration = 0.5\ndt = 2e-5\n"));
  const Params& p = s.model.params;
  EXPECT_EQ(p.time.duration, 0.5);
  EXPECT_EQ(p.time.dt, 2e-5);
  EXPECT_EQ(p.time.dt_min, 2e-5 / 1000.0);
  EXPECT_EQ(p.time.dt_max, 2e-5);
  EXPECT_EQ(p.time.integrator, Integrator::Trapezoidal);
  EXPECT_EQ(p.time.phi, 0.5);
  EXPECT_FALSE(p.time.adaptive);
  EXPECT_EQ(p.time.desired_iterations, 10);
  EXPECT_EQ(p.time.p, 2.0);
  EXPECT_EQ(p.time.max_iterations, 50);
  EXPECT_EQ(p.tolerance.position, 1e-8);
  EXPECT_EQ(p.tolerance.temperature, 1e-8);
  EXPECT_TRUE(p.analysis.rotation);
  EXPECT_FALSE(p.analysis.thermal);
  EXPECT_EQ(p.fields.gravity, (Vec3{0.0, 0.0, -9.81}));
  EXPECT_EQ(p.fields.electric, (Vec3{}));
  EXPECT_EQ(p.fields.magnetic, (Vec3{}));
  EXPECT_FALSE(p.near_field.empirical);
  EXPECT_FALSE(p.near_field.coulomb);
  EXPECT_EQ(p.near_field.cutoff, 0.0);
  EXPECT_FALSE(p.contact.particle_particle.restitution.has_value());
  EXPECT_FALSE(p.contact.particle_particle.damping_ratio.has_value());
  EXPECT_EQ(p.contact.particle_particle.mu_static, 0.5);
  EXPECT_EQ(p.contact.particle_particle.mu_dynamic, 0.4);
  EXPECT_EQ(p.contact.particle_barrier.mu_rolling, 0.0);
  EXPECT_EQ(p.thermal.air_temperature, 293.15);
  EXPECT_TRUE(p.thermal.conduction);
  EXPECT_FALSE(p.thermal.convection);
  EXPECT_FALSE(p.domain.bounded);
  EXPECT_EQ(p.neighbor.skin, 0.0);
  EXPECT_EQ(p.output.dir, "output");
  EXPECT_EQ(p.output.log_every, 100);
  EXPECT_EQ(p.output.checkpoint_every, 0);
  EXPECT_TRUE(s.model.materials.empty());
  EXPECT_TRUE(s.particle_sources.empty());
  EXPECT_TRUE(s.barrier_sources.empty());
}

TEST(SceneReader, DtBoundsDefaultAroundAGivenDt) {
  TempDir d("mpdem_scene");
  // Only dt_max given: dt_min still defaults to dt / 1000.
  const Scene s = parse_scene_file(d.write("scene.toml", "[time]\nduration = 1\ndt = 1e-3\ndt_max = 1e-2\n"));
  EXPECT_EQ(s.model.params.time.dt_min, 1e-6);
  EXPECT_EQ(s.model.params.time.dt_max, 1e-2);
}

TEST(SceneReader, DomainTableMeansBounded) {
  TempDir d("mpdem_scene");
  const Scene s = parse_scene_file(d.write("scene.toml", std::string(kTime) + "[domain]\nmin = [0,0,0]\nmax = [1,1,1]\n"));
  EXPECT_TRUE(s.model.params.domain.bounded);
  EXPECT_EQ(s.model.params.domain.on_exit, ExitPolicy::Stop);
}

TEST(SceneReader, ExplicitEmpiricalFalseWins) {
  TempDir d("mpdem_scene");
  const Scene s = parse_scene_file(
      d.write("scene.toml", std::string(kTime) + "[near_field]\na1 = 1.0\nempirical = false\n"));
  EXPECT_FALSE(s.model.params.near_field.empirical);
  EXPECT_EQ(s.model.params.near_field.a1, 1.0);
}

// One bad scene per error class: line number, dotted key and expectation text.
TEST(SceneReader, ErrorsNameFileLineKeyAndExpectation) {
  struct Case {
    const char* what;
    std::string toml;
    int line;
    std::string key;              // "" = no key in the message
    std::vector<std::string> expect;
  };
  const std::string mat = "[[material]]\nname = \"glass\"\n";   // 2 lines
  const std::vector<Case> cases = {
      {"unknown key, suggestion", "[time]\nduration = 1\ndt = 1e-5\ndurration = 2\n", 4, "time.durration",
       {"unknown key", "did you mean 'time.duration'"}},
      {"unknown key, no suggestion", "[output]\nfrobnicate = 1\n" + std::string(kTime), 2, "output.frobnicate",
       {"unknown key"}},
      {"unknown table", "[tme]\nduration = 1\n" + std::string(kTime), 1, "tme", {"unknown key", "did you mean 'time'"}},
      {"unknown motion key", std::string(kTime) + "[[barriers]]\nfile = \"w.csv\"\nmotion = { a = [0,0,0], w3 = 1 }\n", 7,
       "barriers.motion.w3", {"unknown key", "did you mean 'barriers.motion.w1'"}},
      {"not a number", "[time]\nduration = 1\ndt = 1e-5\nphi = \"half\"\n", 4, "time.phi",
       {"expected a number in [0, 1], got a string"}},
      {"not a vector", "[gravity]\nvector = [0, 0]\n" + std::string(kTime), 2, "gravity.vector",
       {"expected an array of 3 numbers", "2 elements"}},
      {"vector element", "[fields]\n\nelectric = [0, \"x\", 0]\n" + std::string(kTime), 3, "fields.electric",
       {"expected an array of 3 numbers", "element 2 is a string"}},
      {"not a boolean", "[analysis]\nthermal = 1\n" + std::string(kTime), 2, "analysis.thermal", {"expected a boolean"}},
      {"not an integer", "[time]\nduration = 1\ndt = 1e-5\nmax_iterations = 2.5\n", 4, "time.max_iterations",
       {"expected an integer >= 1, got a float"}},
      {"not a table", "time = 3\n", 1, "time", {"expected a table"}},
      {"single [material]", std::string(kTime) + "[material]\nname = \"x\"\n", 5, "material",
       {"expected an array of tables [[material]]"}},
      {"zero duration", "[time]\nduration = 0\ndt = 1e-5\n", 2, "time.duration", {"expected a number > 0, got 0"}},
      {"negative dt", "[time]\nduration = 1\ndt = -1e-5\n", 3, "time.dt", {"expected a number > 0, got -1e-05"}},
      {"phi above 1", "[time]\nduration = 1\ndt = 1e-5\nphi = 1.5\n", 4, "time.phi", {"in [0, 1], got 1.5"}},
      {"dt_min > dt_max", "[time]\nduration = 1\ndt = 1e-5\ndt_min = 1e-4\ndt_max = 1e-5\n", 4, "time.dt_min",
       {"expected dt_min <= dt_max"}},
      {"dt outside bounds", "[time]\nduration = 1\ndt = 1e-3\ndt_max = 1e-4\n", 3, "time.dt",
       {"expected dt within [dt_min, dt_max]"}},
      {"unknown integrator", "[time]\nduration = 1\ndt = 1e-5\nintegrator = \"rk4\"\n", 4, "time.integrator",
       {"expected \"trapezoidal\" or \"verlet\", got \"rk4\""}},
      {"missing duration", "\n[time]\ndt = 1e-5\n", 2, "time.duration", {"missing required key"}},
      {"missing dt", "[time]\nduration = 1\n", 1, "time.dt", {"missing required key"}},
      {"missing [time]", "[analysis]\nthermal = true\n", 0, "time.duration", {"missing required key"}},
      {"negative density", std::string(kTime) + mat + "density = -2500\n", 7, "material.density",
       {"expected a number > 0, got -2500"}},
      {"zero young", std::string(kTime) + mat + "young = 0\n", 7, "material.young", {"expected a number > 0, got 0"}},
      {"poisson 0.5", std::string(kTime) + mat + "poisson = 0.5\n", 7, "material.poisson",
       {"expected a number in [0, 0.5), got 0.5"}},
      {"material without name", std::string(kTime) + "[[material]]\ndensity = 1000\n", 5, "material.name",
       {"missing required key"}},
      {"duplicate material", std::string(kTime) + mat + mat, 8, "material.name", {"duplicate material name 'glass'"}},
      {"restitution zero", "[contact.particle_particle]\nrestitution = 0\n" + std::string(kTime), 2,
       "contact.particle_particle.restitution", {"expected a number in (0, 1], got 0"}},
      {"restitution above 1", "[contact.particle_barrier]\nrestitution = 1.2\n" + std::string(kTime), 2,
       "contact.particle_barrier.restitution", {"in (0, 1], got 1.2"}},
      {"restitution and damping", "[contact.particle_particle]\nrestitution = 0.5\ndamping_ratio = 0.2\n" +
           std::string(kTime), 3, "contact.particle_particle.damping_ratio", {"either restitution or damping_ratio"}},
      {"mu_dynamic > mu_static", "[contact.particle_particle]\nmu_static = 0.3\nmu_dynamic = 0.35\n" +
           std::string(kTime), 3, "contact.particle_particle.mu_dynamic", {"expected mu_dynamic <= mu_static"}},
      {"default mu_dynamic > mu_static", "[contact.particle_barrier]\nmu_static = 0.2\n" + std::string(kTime), 2,
       "contact.particle_barrier.mu_static", {"mu_dynamic = 0.4 (default) > mu_static = 0.2"}},
      {"negative friction", "[contact.particle_particle]\nmu_rolling = -0.1\n" + std::string(kTime), 2,
       "contact.particle_particle.mu_rolling", {"expected a number >= 0, got -0.1"}},
      {"unknown particle material", std::string(kTime) + mat + "[[particles]]\nfile = \"p.csv\"\nmaterial = \"wood\"\n",
       9, "particles.material", {"unknown material 'wood'", "known: glass"}},
      {"unknown barrier material", std::string(kTime) + "[[barriers]]\nfile = \"w.csv\"\nmaterial = \"wood\"\n", 7,
       "barriers.material", {"unknown material 'wood'"}},
      {"unknown pair material", std::string(kTime) + mat + "[near_field]\ncutoff = 1\n[[near_field.pair]]\n"
           "material_a = \"glass\"\nmaterial_b = \"tin\"\n", 11, "near_field.pair.material_b", {"unknown material 'tin'"}},
      {"near field without cutoff", std::string(kTime) + "[near_field]\ncoulomb = true\n", 5, "near_field.cutoff",
       {"expected a cutoff > 0"}},
      {"particles without material", std::string(kTime) + "\n[[particles]]\nfile = \"p.csv\"\n", 6, "material",
       {"at least one [[material]] is required"}},
      {"missing particle file", std::string(kTime) + mat + "[[particles]]\nfile = \"nope.csv\"\n", 8, "particles.file",
       {"nope.csv", "does not exist"}},
      {"missing barrier file", std::string(kTime) + "[[barriers]]\nfile = \"gone/walls.csv\"\n", 6, "barriers.file",
       {"gone/walls.csv", "does not exist"}},
      {"barrier without file", std::string(kTime) + "[[barriers]]\ngroup = \"g\"\n", 5, "barriers.file",
       {"missing required key (give file or stl)"}},
      {"STL transform on CSV", std::string(kTime) + "[[barriers]]\nfile = \"w.csv\"\nscale = 2\n", 7, "barriers.scale",
       {"applies to stl barriers only"}},
      {"unknown on_exit", std::string(kTime) + "[domain]\nmin = [0,0,0]\nmax = [1,1,1]\non_exit = \"reflect\"\n", 8,
       "domain.on_exit", {"expected \"remove\" or \"stop\", got \"reflect\""}},
      {"domain min >= max", std::string(kTime) + "[domain]\nmin = [0,0,0]\nmax = [1,0,1]\n", 7, "domain.max",
       {"expected max > min in every component", "y: min 0 >= max 0"}},
      {"domain without max", std::string(kTime) + "[domain]\nmin = [0,0,0]\n", 5, "domain.max", {"missing required key"}},
      {"log_every zero", std::string(kTime) + "[output]\nlog_every = 0\n", 6, "output.log_every",
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
  const fs::path scene = d.write("scene.toml", std::string(kTime) + "[[barriers]]\nstl = \"chute.stl\"\nscale = 0.001\n");
  const Scene parsed = parse_scene_file(scene);  // parsing accepts the source...
  ASSERT_EQ(parsed.barrier_sources.size(), 1u);
  EXPECT_EQ(parsed.barrier_sources[0].scale, 0.001);
  const std::string msg = error_of([&] { load_scene(scene); });  // ...loading finds no triangles
  expect_contains(msg, {"chute.stl", "no facets"});
}

TEST(SceneReader, ErrorsInSourcesNameTheCsvFile) {
  TempDir d("mpdem_scene");
  d.write("beads.csv", "x,y,z,radius\n0,0,0,0.1\n0,0,0,-0.1\n");
  const fs::path scene = d.write("scene.toml", std::string(kTime) + "[[material]]\nname = \"m\"\n[[particles]]\nfile = \"beads.csv\"\n");
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
  EXPECT_EQ(s.barriers.young[1], 2.1e11);   // from material "steel"
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
