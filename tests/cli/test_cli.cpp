// The mpdem command line: bad input gives one message naming file, line and key, exit status 2,
// and writes nothing; --help and --version; a small run writes its outputs.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {
const char* kParticles = "id,x,y,z,radius\n1,0,0,0.01,0.001\n2,0.005,0,0.01,0.001\n";

std::string scene_text(const std::string& time_table) {
  return time_table +
         "\n[[material]]\nname = \"glass\"\n\n[[particles]]\nfile = \"p.csv\"\n\n[output]\nparticles_every = 0.001\n";
}

void expect_bad_input(const std::string& name, const std::string& scene, const std::string& particles,
                      const std::string& expected_location, const std::string& expected_text) {
  const fs::path d = fresh_dir(name);
  write_text(d / "scene.toml", scene);
  write_text(d / "p.csv", particles);
  for (const char* cmd : {"run scene.toml --quiet", "check scene.toml"}) {
    const CommandResult r = run_mpdem(cmd, d);
    EXPECT_EQ(r.status, 2) << name << ": " << cmd << "\n" << r.err;
    EXPECT_NE(r.err.find(expected_location), std::string::npos) << name << ": " << r.err;
    EXPECT_NE(r.err.find(expected_text), std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "one message only: " << r.err;
  }
  EXPECT_FALSE(fs::exists(d / "output")) << name << ": nothing may be written for bad input";
  fs::remove_all(d);
}
}  // namespace

TEST(Cli, UnknownKey) {
  expect_bad_input("unknown", scene_text("[time]\nduration = 0.01\ndt = 1e-5\nphii = 0.5\n"), kParticles,
                   "scene.toml:4: 'time.phii'", "unknown key");
}

TEST(Cli, WrongType) {
  expect_bad_input("type", scene_text("[time]\nduration = \"long\"\ndt = 1e-5\n"), kParticles,
                   "scene.toml:2: 'time.duration'", "expected a number");
}

TEST(Cli, OutOfRange) {
  expect_bad_input("phi", scene_text("[time]\nduration = 0.01\ndt = 1e-5\nphi = 1.5\nintegrator = \"trapezoidal\"\n"),
                   kParticles, "scene.toml:4: 'time.phi'", "[0, 1]");
  expect_bad_input(
      "dtbounds",
      scene_text("[time]\nduration = 0.01\ndt = 1e-5\ndt_min = 1e-4\ndt_max = 1e-6\nintegrator = \"trapezoidal\"\n"),
      kParticles, "scene.toml", "dt_min");
  expect_bad_input("poisson",
                   "[time]\nduration = 0.01\ndt = 1e-5\n[[material]]\nname = \"m\"\npoisson = 0.5\n"
                   "[[particles]]\nfile = \"p.csv\"\n",
                   kParticles, "scene.toml:6: 'material.poisson'", "0.5");
  expect_bad_input("radius", scene_text("[time]\nduration = 0.01\ndt = 1e-5\n"), "id,x,y,z,radius\n1,0,0,0,-0.001\n",
                   "p.csv:2", "radius");
}

TEST(Cli, MissingFile) {
  const fs::path d = fresh_dir("missing2");
  write_text(d / "scene.toml", "[time]\nduration = 0.01\ndt = 1e-5\n[[particles]]\nfile = \"nope.csv\"\n"
                               "[[material]]\nname = \"m\"\n");
  const CommandResult r = run_mpdem("run scene.toml", d);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("nope.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  const CommandResult r2 = run_mpdem("run no_such_scene.toml", d);
  EXPECT_EQ(r2.status, 2);
  EXPECT_NE(r2.err.find("no_such_scene.toml"), std::string::npos) << r2.err;
  fs::remove_all(d);
}

TEST(Cli, MalformedCsvRow) {
  expect_bad_input("row", scene_text("[time]\nduration = 0.01\ndt = 1e-5\n"),
                   "id,x,y,z,radius\n1,0,0,0.01,0.001\n2,0,zero,0,0.001\n", "p.csv:3", "'y'");
  expect_bad_input("fields", scene_text("[time]\nduration = 0.01\ndt = 1e-5\n"), "id,x,y,z,radius\n1,0,0,0.01\n",
                   "p.csv:2", "");
}

TEST(Cli, HelpAndVersion) {
  const fs::path d = fresh_dir("help");
  const CommandResult v = run_mpdem("--version", d);
  EXPECT_EQ(v.status, 0);
  EXPECT_NE(v.out.find("mpdem "), std::string::npos);
  const CommandResult h = run_mpdem("--help", d);
  EXPECT_EQ(h.status, 0);
  for (const char* word : {"run", "check"}) EXPECT_NE(h.out.find(word), std::string::npos) << h.out;
  const CommandResult bad = run_mpdem("frobnicate", d);
  EXPECT_EQ(bad.status, 2);
  fs::remove_all(d);
}

TEST(Cli, SmallRunWritesOutputsAndCheckRecommendsAStep) {
  const fs::path d = fresh_dir("run");
  write_text(d / "scene.toml", scene_text("[time]\nduration = 0.005\ndt = 1e-5\nintegrator = \"verlet\"\n"));
  write_text(d / "p.csv", kParticles);
  const CommandResult c = run_mpdem("check scene.toml", d);
  EXPECT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("particles: 2"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("recommended dt"), std::string::npos) << c.out;
  const CommandResult r = run_mpdem("run scene.toml", d);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(d / "output" / "particles.pvd"));
  EXPECT_TRUE(fs::exists(d / "output" / "log.csv"));
  // Snapshots every 1 ms over 5 ms: t = 0, 1, ..., 5 ms.
  int vtus = 0;
  for (const auto& e : fs::directory_iterator(d / "output" / "particles")) vtus += e.path().extension() == ".vtu";
  EXPECT_EQ(vtus, 6);
  EXPECT_NE(r.err.find("done: t = 0.005 s"), std::string::npos) << r.err;  // progress summary
  fs::remove_all(d);
}

TEST(Cli, NonEmptyOutputFolderNeedsOverwrite) {
  const fs::path d = fresh_dir("overwrite");
  write_text(d / "scene.toml", scene_text("[time]\nduration = 0.002\ndt = 1e-5\nintegrator = \"verlet\"\n"));
  write_text(d / "p.csv", kParticles);
  ASSERT_EQ(run_mpdem("run scene.toml --quiet", d).status, 0);
  write_text(d / "output" / "notes.txt", "mine");
  const std::string first_log = slurp(d / "output" / "log.csv");
  const CommandResult again = run_mpdem("run scene.toml --quiet", d);
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("not empty"), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
  EXPECT_EQ(slurp(d / "output" / "log.csv"), first_log);  // untouched
  const CommandResult over = run_mpdem("run scene.toml --quiet --overwrite", d);
  EXPECT_EQ(over.status, 0) << over.err;
  EXPECT_EQ(slurp(d / "output" / "notes.txt"), "mine");  // only mpdem's own outputs are replaced
  fs::remove_all(d);
}
