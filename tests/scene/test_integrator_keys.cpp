// [time] integrator (src/scene/scene_reader.cpp, scene/trapezoidal_keys.cpp): velocity Verlet is
// the default, and the keys only the trapezoidal rule reads ([time] phi, adaptive, dt_min, dt_max,
// desired_iterations, p, max_iterations, every [tolerance] key) are refused under Verlet with a
// message naming file, line and key (exit 2 from the command line), so that a scene written for
// the trapezoidal rule without naming it never runs Verlet silently.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "scene/scene_reader.hpp"
#include "sim/simulation.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::error_of;
using mpdem::test::expect_contains;
using mpdem::test::TempDir;

namespace {

// One sphere coasting against viscous drag: the two integrators give different velocities.
// `time` is the [time] table's extra lines (from line 4), `extra` more tables after the rest.
std::string scene_with(const std::string& time, const std::string& extra = "") {
  return "[time]\nduration = 0.01\ndt = 1e-4\n" + time +
         "\n[gravity]\nvector = [0, 0, 0]\n"
         "[fields]\ndrag = 1e-3\n"
         "[[material]]\nname = \"glass\"\n"
         "[[particles]]\nfile = \"p.csv\"\n" +
         extra + "\n";
}

void write_sources(const TempDir& d) { d.write("p.csv", "x,y,z,vx,vy,vz,radius\n0,0,0,1,0.5,0,0.01\n"); }

struct RunResult {
  Vec3 x, v;
  std::uint64_t evaluations = 0;
  int iterations = 0;  // summed over the steps
};

RunResult run_steps(const fs::path& scene, int steps) {
  Simulation sim(load_scene(scene), RunOptions{{}, false, false});
  sim.initialize();
  RunResult r;
  for (int k = 0; k < steps; ++k) r.iterations += sim.advance(sim.model().params.time.dt).iterations;
  r.x = sim.particles().x[0];
  r.v = sim.particles().v[0];
  r.evaluations = sim.evaluations();
  return r;
}

// The keys only the trapezoidal rule reads: (table, key, value).
struct TrapezoidalKey {
  std::string table, key, value;
};
const std::vector<TrapezoidalKey> kTrapezoidalKeys = {
    {"time", "phi", "0.5"},
    {"time", "adaptive", "true"},
    {"time", "dt_min", "1e-6"},
    {"time", "dt_max", "1e-3"},
    {"time", "desired_iterations", "4"},
    {"time", "p", "2.0"},
    {"time", "max_iterations", "20"},
    {"tolerance", "position", "1e-6"},
    {"tolerance", "velocity", "1e-6"},
    {"tolerance", "rotation", "1e-6"},
    {"tolerance", "angular_velocity", "1e-6"},
    {"tolerance", "temperature", "1e-6"},
    {"tolerance", "position_floor", "1e-12"},
    {"tolerance", "velocity_floor", "1e-10"},
    {"tolerance", "rotation_floor", "1e-12"},
    {"tolerance", "angular_velocity_floor", "1e-8"},
    {"tolerance", "temperature_floor", "1e-9"},
};

// The scene with the key set (line 4 in [time]; line 14 in [tolerance], after the integrator line
// `integrator` at line 4 or nothing).
std::string scene_with_key(const TrapezoidalKey& k, const std::string& integrator) {
  const std::string head = integrator.empty() ? "" : "integrator = \"" + integrator + "\"\n";
  if (k.table == "time") return scene_with(head + k.key + " = " + k.value);
  return scene_with(head, "[tolerance]\n" + k.key + " = " + k.value);
}

}  // namespace

TEST(IntegratorKeys, DefaultIsVerlet) {
  TempDir d("mpdem_integrator");
  write_sources(d);
  EXPECT_EQ(load_scene(d.write("default.toml", scene_with(""))).model.params.time.integrator, Integrator::Verlet);
  EXPECT_EQ(TimeParams{}.integrator, Integrator::Verlet);
  EXPECT_EQ(load_scene(d.write("v.toml", scene_with("integrator = \"verlet\""))).model.params.time.integrator,
            Integrator::Verlet);
  EXPECT_EQ(load_scene(d.write("t.toml", scene_with("integrator = \"trapezoidal\""))).model.params.time.integrator,
            Integrator::Trapezoidal);
}

// A scene without the key runs velocity Verlet: bitwise the run of the same scene that names it,
// one evaluation a step and no iterations; the trapezoidal rule's run differs.
TEST(IntegratorKeys, SceneWithoutTheKeyRunsVerlet) {
  TempDir d("mpdem_integrator");
  write_sources(d);
  constexpr int kSteps = 20;
  const RunResult unnamed = run_steps(d.write("default.toml", scene_with("")), kSteps);
  const RunResult verlet = run_steps(d.write("verlet.toml", scene_with("integrator = \"verlet\"")), kSteps);
  const RunResult trapezoidal = run_steps(d.write("t.toml", scene_with("integrator = \"trapezoidal\"")), kSteps);
  EXPECT_EQ(unnamed.x, verlet.x);
  EXPECT_EQ(unnamed.v, verlet.v);
  EXPECT_EQ(unnamed.evaluations, verlet.evaluations);
  EXPECT_EQ(unnamed.evaluations, kSteps + 1u);  // the first evaluation at t = 0, then one a step
  EXPECT_EQ(unnamed.iterations, 0);
  EXPECT_GT(trapezoidal.iterations, 0);
  EXPECT_NE(unnamed.v, trapezoidal.v);
}

// Every key of the class, without an integrator and with integrator = "verlet": refused at its
// line; with integrator = "trapezoidal" it is read.
TEST(IntegratorKeys, TrapezoidalKeysAreRefusedUnderVerlet) {
  for (const TrapezoidalKey& k : kTrapezoidalKeys) {
    for (const std::string integrator : {"", "verlet"}) {
      SCOPED_TRACE(k.table + "." + k.key + " with integrator '" + integrator + "'");
      TempDir d("mpdem_integrator");
      write_sources(d);
      const fs::path scene = d.write("scene.toml", scene_with_key(k, integrator));
      const std::string msg = error_of([&] { parse_scene_file(scene); });
      const int line = k.table == "time" ? (integrator.empty() ? 4 : 5) : (integrator.empty() ? 14 : 15);
      const std::string where = scene.string() + ":" + std::to_string(line) + ": '" + k.table + "." + k.key + "': ";
      EXPECT_EQ(msg.rfind(where, 0), 0u) << "expected prefix '" << where << "' in: " << msg;
      expect_contains(msg, {"only the trapezoidal rule reads this key", "set [time] integrator = \"trapezoidal\""});
      expect_contains(msg, {integrator.empty() ? "the default integrator is \"verlet\"" : "integrator = \"verlet\""});
    }
    SCOPED_TRACE(k.table + "." + k.key + " with integrator = \"trapezoidal\"");
    TempDir d("mpdem_integrator");
    write_sources(d);
    const Scene s = parse_scene_file(d.write("scene.toml", scene_with_key(k, "trapezoidal")));
    EXPECT_EQ(s.model.params.time.integrator, Integrator::Trapezoidal);
  }
}

// The first such key by line is the one named.
TEST(IntegratorKeys, FirstKeyByLineIsNamed) {
  TempDir d("mpdem_integrator");
  write_sources(d);
  const fs::path scene = d.write("scene.toml", scene_with("max_iterations = 20\nadaptive = false\nphi = 1.0"));
  const std::string msg = error_of([&] { parse_scene_file(scene); });
  EXPECT_EQ(msg.rfind(scene.string() + ":4: 'time.max_iterations': ", 0), 0u) << msg;
}

// The command line refuses such a scene with exit status 2, before writing anything.
TEST(IntegratorKeys, CommandExitsTwo) {
  TempDir d("mpdem_integrator");
  write_sources(d);
  d.write("scene.toml", scene_with("adaptive = true"));
  const mpdem::test::CommandResult r = mpdem::test::run_mpdem("run scene.toml", d.path);
  EXPECT_EQ(r.status, 2) << r.err;
  expect_contains(r.err, {"scene.toml:4: 'time.adaptive'", "the default integrator is \"verlet\""});
  EXPECT_FALSE(fs::exists(d.path / "output"));
}
