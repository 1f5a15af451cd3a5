// A checkpoint carries the fingerprint of the scene its run started from: a resume with a scene
// whose materials, barriers, particle sources, domain, contact laws, physics or time integration
// differ is refused naming the part and its first differing item; the editable keys (duration,
// outputs, checks, step controls) stay editable, and such a resume continues bitwise identically.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/checkpoint_format.hpp"
#include "io/scene_fingerprint.hpp"
#include "core/input_error.hpp"
#include "sim/simulation.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
namespace fs = std::filesystem;

namespace {

// Four glass spheres above a steel floor (an STL square) and a wall (a barrier CSV), in a domain.
const std::string kParticles = "id,x,y,z,vx,vy,vz,radius\n"
                               "1,0.002,0.002,0.0011,0,0,-0.5,0.001\n"
                               "2,0.0045,0.002,0.0011,0.01,0,-0.5,0.001\n"
                               "3,0.002,0.0045,0.0011,0,0.01,-0.5,0.001\n"
                               "4,0.0045,0.0045,0.0011,0,0,-0.5,0.001\n";
const std::string kWall = "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n"
                          "1,0,0,0,0,0.01,0,0,0.01,0.01\n"
                          "2,0,0,0,0,0.01,0.01,0,0,0.01\n";
const std::string kFloor =
    "solid floor\n"
    "facet normal 0 0 1\n outer loop\n  vertex -0.01 -0.01 0\n  vertex 0.02 -0.01 0\n  vertex 0.02 0.02 0\n"
    " endloop\nendfacet\n"
    "facet normal 0 0 1\n outer loop\n  vertex -0.01 -0.01 0\n  vertex 0.02 0.02 0\n  vertex -0.01 0.02 0\n"
    " endloop\nendfacet\nendsolid floor\n";
const std::string kScene = "[time]\nduration = 0.01\ndt = 1e-6\nintegrator = \"verlet\"\n"
                           "[contact.particle_particle]\nrestitution = 0.5\n"
                           "[contact.particle_barrier]\nrestitution = 0.5\n"
                           "[[material]]\nname = \"glass\"\ndensity = 2500\nyoung = 1e7\npoisson = 0.3\n"
                           "[[material]]\nname = \"steel\"\ndensity = 7800\nyoung = 2e8\npoisson = 0.29\n"
                           "[[particles]]\nfile = \"p.csv\"\nmaterial = \"glass\"\n"
                           "[[barriers]]\nfile = \"wall.csv\"\nmaterial = \"steel\"\n"
                           "[[barriers]]\nstl = \"floor.stl\"\ngroup = \"floor\"\nmaterial = \"steel\"\n"
                           "[domain]\nmin = [-0.02, -0.02, -0.02]\nmax = [0.03, 0.03, 0.03]\non_exit = \"remove\"\n"
                           "[checks]\nmax_overlap = 0.2\n"
                           "[output]\nparticle_csv_every = 0.001\nlog_every = 100\n";

// Replaces the one occurrence of `from` in `text` (a test failure when there is none).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

struct Files {
  std::string scene = kScene, particles = kParticles, wall = kWall, floor = kFloor;
};

void write(const test::TempDir& d, const Files& f) {
  d.write("scene.toml", f.scene);
  d.write("p.csv", f.particles);
  d.write("wall.csv", f.wall);
  d.write("floor.stl", f.floor);
}

Simulation loaded(const test::TempDir& d) {
  return Simulation(load_scene(d.path / "scene.toml"), RunOptions{{}, false, false});
}

void advance(Simulation& sim, int steps) {
  for (int k = 0; k < steps; ++k) sim.advance(sim.model().params.time.dt);
}

// Writes the original scene, runs it 50 steps to a checkpoint, then writes `edited` and resumes
// it: the refusal's message ("" when the resume is accepted).
std::string resume_message(const test::TempDir& d, const Files& edited) {
  write(d, Files{});
  {
    Simulation first = loaded(d);
    advance(first, 50);
    first.write_checkpoint(d.path / "ck.bin");
  }
  write(d, edited);
  Simulation resumed = loaded(d);
  try {
    resumed.resume_from(d.path / "ck.bin");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_refused(const Files& edited, const std::vector<std::string>& parts) {
  test::TempDir d("fingerprint");
  const std::string msg = resume_message(d, edited);
  ASSERT_FALSE(msg.empty()) << "the edited scene was resumed";
  test::expect_contains(msg, {(d.path / "scene.toml").string(), "ck.bin", "written for another scene",
                              "editable on resume: time.duration"});
  test::expect_contains(msg, parts);
}

}  // namespace

TEST(CheckpointFingerprint, MovedStlVertexIsRefusedNamingTheElement) {
  Files f;
  f.floor = replaced(f.floor, "vertex 0.02 -0.01 0", "vertex 0.02 -0.01 0.0001");
  expect_refused(f, {"in its barriers (element id 3 of group 'floor': rest vertices)"});
}

TEST(CheckpointFingerprint, MovedCsvBarrierVertexIsRefusedNamingTheElement) {
  Files f;
  f.wall = replaced(f.wall, "2,0,0,0,0,0.01,0.01,0,0,0.01", "2,0,0,0,0,0.01,0.01,0,0,0.011");
  expect_refused(f, {"in its barriers (element id 2 of group 'wall': rest vertices)"});
}

TEST(CheckpointFingerprint, ChangedMaterialValuesAreRefusedNamingMaterialAndKey) {
  Files density;
  density.scene = replaced(kScene, "density = 2500", "density = 2501");
  expect_refused(density, {"in its materials (material 'glass': density)"});
  Files young;
  young.scene = replaced(kScene, "young = 1e7", "young = 1.1e7");
  expect_refused(young, {"materials (material 'glass': young)"});
  Files poisson;
  poisson.scene = replaced(kScene, "poisson = 0.29", "poisson = 0.28");
  // The barrier elements take the steel's poisson too.
  expect_refused(poisson, {"materials (material 'steel': poisson)", "barriers (element id 1 of group 'wall': young, "
                                                                    "poisson, thickness or temperature)"});
}

TEST(CheckpointFingerprint, RenamedMaterialIsRefused) {
  Files f;
  f.scene = replaced(kScene, "name = \"glass\"", "name = \"sodaglass\"");
  f.scene = replaced(f.scene, "material = \"glass\"", "material = \"sodaglass\"");
  expect_refused(f, {"materials (the name of material 1, 'sodaglass')"});
}

TEST(CheckpointFingerprint, ChangedParticleCsvIsRefusedNamingTheParticle) {
  Files moved;
  moved.particles = replaced(kParticles, "3,0.002,0.0045,0.0011", "3,0.002,0.0046,0.0011");
  expect_refused(moved, {"in its particle sources (particle id 3)"});
  Files fewer;
  fewer.particles = replaced(kParticles, "4,0.0045,0.0045,0.0011,0,0,-0.5,0.001\n", "");
  expect_refused(fewer, {"particle sources (3 particles, the checkpoint's scene had 4)"});
}

TEST(CheckpointFingerprint, ChangedGenerateSpecIsRefused) {
  const std::string generated = replaced(
      kScene, "[[particles]]\nfile = \"p.csv\"\n",
      "[[particles]]\ngenerate = { region = \"box\", min = [0.001, 0.001, 0.001], max = [0.008, 0.008, 0.004], "
      "count = 6, radius = 0.0008, seed = 1 }\n");
  Files f;
  f.scene = generated;
  test::TempDir d("fingerprint");
  write(d, f);
  Simulation first = loaded(d);
  advance(first, 20);
  first.write_checkpoint(d.path / "ck.bin");
  EXPECT_NO_THROW(loaded(d).resume_from(d.path / "ck.bin"));  // the same spec generates the same particles
  d.write("scene.toml", replaced(generated, "seed = 1", "seed = 2"));
  const std::string msg = test::error_of([&] { loaded(d).resume_from(d.path / "ck.bin"); });
  test::expect_contains(msg, {"in its particle sources (particle id 0)"});
}

TEST(CheckpointFingerprint, ShrunkDomainIsRefused) {
  Files f;
  f.scene = replaced(kScene, "max = [0.03, 0.03, 0.03]", "max = [0.03, 0.03, 0.02]");
  expect_refused(f, {"in its domain (domain.max)"});
  Files none;
  none.scene = replaced(kScene,
                        "[domain]\nmin = [-0.02, -0.02, -0.02]\nmax = [0.03, 0.03, 0.03]\non_exit = \"remove\"\n", "");
  expect_refused(none, {"domain ([domain] given or not)"});
}

TEST(CheckpointFingerprint, ChangedContactLawOrIntegratorIsRefused) {
  Files contact;
  contact.scene = replaced(kScene, "[contact.particle_barrier]\nrestitution = 0.5",
                           "[contact.particle_barrier]\nrestitution = 0.6");
  expect_refused(contact, {"contact laws (contact.particle_barrier.restitution)"});
  Files integrator;
  integrator.scene = replaced(kScene, "integrator = \"verlet\"", "integrator = \"trapezoidal\"");
  expect_refused(integrator, {"time integration (time.integrator)"});
  Files gravity;
  gravity.scene = kScene + "[gravity]\nvector = [0, 0, -9.8]\n";
  expect_refused(gravity, {"physics (gravity.vector)"});
}

// A checkpoint of a scene that ran the trapezoidal rule by default (before velocity Verlet became
// the default), resumed with that scene unchanged: refused, saying what the scene now runs.
TEST(CheckpointFingerprint, ResumeAcrossTheNewDefaultIntegratorSaysWhy) {
  test::TempDir d("fingerprint");
  Files old_default;
  old_default.scene = replaced(kScene, "integrator = \"verlet\"", "integrator = \"trapezoidal\"");
  write(d, old_default);
  {
    Simulation first = loaded(d);
    advance(first, 20);
    first.write_checkpoint(d.path / "ck.bin");
  }
  Files unnamed;
  unnamed.scene = replaced(kScene, "integrator = \"verlet\"\n", "");
  write(d, unnamed);
  const std::string msg = test::error_of([&] { loaded(d).resume_from(d.path / "ck.bin"); });
  test::expect_contains(msg, {"time integration (time.integrator)", "without [time] integrator runs velocity Verlet",
                              "needs integrator = \"trapezoidal\""});
}

// Liquid bridges belong to the contact laws: a changed [liquid_bridge] key or an entry's
// liquid_bridge table is refused naming it; scenes without bridges keep their items.
TEST(CheckpointFingerprint, ChangedLiquidBridgeIsRefused) {
  const auto difference = [](const std::string& a, const std::string& b) {
    test::TempDir d("fingerprint");
    Files f;
    f.scene = a;
    write(d, f);
    const SceneFingerprint first = fingerprint_scene(load_scene(d.path / "scene.toml"));
    f.scene = b;
    write(d, f);
    return fingerprint_difference(first, fingerprint_scene(load_scene(d.path / "scene.toml")));
  };
  const std::string bridge = kScene + "[liquid_bridge]\nsurface_tension = 0.07\nvolume = 1e-12\n";
  EXPECT_EQ(difference(bridge, bridge), "");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"volume = 1e-12", "volume = 2e-12"},
                                 {"volume = 1e-12", "liquid_fraction = 0.01"},
                                 {"volume = 1e-12", "volume = 1e-12\nbarriers = false"},
                                 {"volume = 1e-12", "volume = 1e-12\nmodel = \"rabinovich\""}})
    EXPECT_EQ(difference(bridge, replaced(bridge, from, to)), "contact laws ([liquid_bridge])") << to;
  EXPECT_EQ(difference(kScene, bridge), "contact laws (its layout)");
  const std::string pair = kScene + "[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\nmu_static = 0.5\n";
  EXPECT_EQ(difference(pair, pair + "liquid_bridge = { surface_tension = 0.07, volume = 1e-12 }\n"),
            "contact laws ([[contact.pair]] 'glass'-'steel')");
}

// The editable keys stay editable: the checkpoint carries the fingerprint, a longer duration,
// other output intervals and checks resume, and the run continues bitwise identically to an
// uninterrupted run of the edited scene.
TEST(CheckpointFingerprint, EditableKeysResumeBitwiseIdentically) {
  Files edited;
  edited.scene = replaced(kScene, "duration = 0.01", "duration = 0.02");
  edited.scene = replaced(edited.scene, "particle_csv_every = 0.001\nlog_every = 100",
                          "particle_csv_every = 0.002\nlog_every = 7");
  edited.scene = replaced(edited.scene, "max_overlap = 0.2", "max_overlap = 0.3\nenergy_jump = 0");
  test::TempDir d("fingerprint");
  ASSERT_EQ(resume_message(d, edited), "");
  const std::string bytes = test::slurp(d.path / "ck.bin");
  EXPECT_TRUE(CheckpointReader(bytes.data(), bytes.size()).has("scene_fingerprint"));

  Simulation resumed = loaded(d);  // the edited scene
  resumed.resume_from(d.path / "ck.bin");
  advance(resumed, 450);
  Simulation full = loaded(d);
  advance(full, 500);
  ASSERT_EQ(full.steps(), resumed.steps());
  EXPECT_GT(full.record().deepest.ratio, 0.0);  // the particles have reached the floor
  const Particles& a = full.particles();
  const Particles& b = resumed.particles();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.id[i], b.id[i]);
    EXPECT_EQ(a.x[i], b.x[i]) << "id " << a.id[i];
    EXPECT_EQ(a.v[i], b.v[i]) << "id " << a.id[i];
    EXPECT_EQ(a.w[i], b.w[i]) << "id " << a.id[i];
  }
  // The numerical controls are editable too (another trajectory, by the user's choice).
  for (const auto& [from, to] :
       std::vector<std::pair<std::string, std::string>>{{"dt = 1e-6", "dt = 5e-7"},
                                                        {"on_exit = \"remove\"", "on_exit = \"stop\""},
                                                        {"[checks]", "[neighbor]\nskin = 0.0002\n[checks]"}}) {
    Files f;
    f.scene = replaced(kScene, from, to);
    test::TempDir e("fingerprint_edit");
    EXPECT_EQ(resume_message(e, f), "") << to;
  }
}

// Through the command line: exit 2 and the message on stderr.
TEST(CheckpointFingerprint, CommandLineRefusesAMovedVertexWithExit2) {
  test::TempDir d("fingerprint_cli");
  Files f;
  f.scene = replaced(kScene, "log_every = 100", "log_every = 100\ncheckpoint_every = 200");
  f.scene = replaced(f.scene, "duration = 0.01", "duration = 0.0005");
  write(d, f);
  ASSERT_EQ(test::run_mpdem("run scene.toml --quiet", d.path).status, 0);
  ASSERT_TRUE(fs::exists(d.path / "output" / "checkpoint.bin"));
  d.write("floor.stl", replaced(kFloor, "vertex -0.01 0.02 0", "vertex -0.01 0.021 0"));
  d.write("scene.toml", replaced(f.scene, "duration = 0.0005", "duration = 0.001"));
  const test::CommandResult r = test::run_mpdem("run scene.toml --quiet --resume output/checkpoint.bin", d.path);
  EXPECT_EQ(r.status, 2) << r.err;
  test::expect_contains(r.err,
                        {"scene.toml", "checkpoint.bin", "barriers (element id 4 of group 'floor': rest vertices)"});
}

TEST(CheckpointFingerprint, AddedOrChangedRotationIsRefused) {
  const std::string wall = "file = \"wall.csv\"\nmaterial = \"steel\"\n";
  Files added;
  added.scene = replaced(kScene, wall,
                         wall + "motion = { rotation = { axis = [0, 0, 1], origin = [0, 0, 0], omega = 0.5 } }\n");
  expect_refused(added, {"in its barriers (element id 1 of group 'wall': motion law)"});
  // A rotating original and another rate: the rotation's own values are fingerprinted.
  test::TempDir d("fingerprint_rotation");
  Files turning = added;
  write(d, turning);
  {
    Simulation first = loaded(d);
    advance(first, 20);
    first.write_checkpoint(d.path / "ck.bin");
  }
  Files faster = turning;
  faster.scene = replaced(turning.scene, "omega = 0.5", "omega = 0.6");
  write(d, faster);
  Simulation resumed = loaded(d);
  try {
    resumed.resume_from(d.path / "ck.bin");
    ADD_FAILURE() << "a changed rotation rate was resumed";
  } catch (const InputError& e) {
    test::expect_contains(e.what(), {"element id 1 of group 'wall': motion law"});
  }
}
