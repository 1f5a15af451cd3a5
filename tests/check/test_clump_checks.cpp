// The checks before the run on clump bodies (src/check/): the members of one body overlap by
// design and are never reported, members of different bodies (or a member and a free sphere) are,
// naming the bodies; a body with a member outside the domain is reported by its id; and what
// `mpdem check` prints about each template (check/clump_summary.hpp).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "check/clump_summary.hpp"
#include "check/initial_overlaps.hpp"
#include "check/scene_checks.hpp"
#include "scene/scene_reader.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using mpdem::test::expect_contains;
using mpdem::test::TempDir;

namespace {

constexpr double kR = 0.001;  // m, member radius
const std::string kHead = "[time]\nduration = 0.01\ndt = 1e-6\nintegrator = \"verlet\"\n"
                          "[[material]]\nname = \"glass\"\ndensity = 2500\nyoung = 1e9\n";
// Two members of radius r with centres r apart: they overlap by r (100 % of the radius).
const std::string kPeanut = "[[clump]]\nname = \"peanut\"\nmembers = [[0, -0.0005, 0, 0.001], [0, 0.0005, 0, 0.001]]\n";
const std::string kBodies = "[[particles]]\nfile = \"bodies.csv\"\nclump = \"peanut\"\n";

Scene load(const TempDir& d, const std::string& extra, const std::string& bodies) {
  d.write("bodies.csv", bodies);
  return load_scene(d.write("scene.toml", kHead + kPeanut + kBodies + extra));
}

std::string all_messages(const SceneProblems& problems) {
  std::string out;
  for (const SceneProblem& p : problems) out += located_text(p) + "\n";
  return out;
}

}  // namespace

TEST(ClumpChecks, MembersOfOneBodyAreNotOverlaps) {
  TempDir d("mpdem_clump_check");
  const Scene s = load(d, "", "id,x,y,z\n1,0,0,0.01\n2,0.01,0,0.01\n");
  ASSERT_EQ(s.particles.size(), 4u);
  EXPECT_TRUE(particle_overlaps(s.particles, 0.0).empty());
  EXPECT_TRUE(check_scene(s).empty()) << all_messages(check_scene(s));
}

TEST(ClumpChecks, MembersOfDifferentBodiesOverlapAndNameTheBodies) {
  TempDir d("mpdem_clump_check");
  // Bodies 1 and 2 side by side along x, 1.8 r apart: each member overlaps the member beside it
  // by 0.2 r (20 % of the radius) and not the other one (sqrt(1.8^2 + 1) r > 2 r away).
  const Scene s = load(d, "", "id,x,y,z\n1,0,0,0.01\n2,0.0018,0,0.01\n");
  const std::vector<PairOverlap> o = particle_overlaps(s.particles, 0.0);
  ASSERT_EQ(o.size(), 2u);
  for (const PairOverlap& pr : o) {
    EXPECT_NE(s.particles.body[pr.i], s.particles.body[pr.j]);
    EXPECT_NEAR(pr.overlap, 0.2 * kR, 1e-12 * kR);
  }
  const SceneProblems problems = check_scene(s);
  ASSERT_EQ(problems.size(), 1u) << all_messages(problems);
  EXPECT_EQ(problems[0].severity, Severity::Error);
  expect_contains(located_text(problems[0]),
                  {(d.path / "bodies.csv").string(), "2 pairs of particles of 'bodies.csv' overlap",
                   "(members of bodies 1 and 2) by 0.0002 m (20%)"});
}

TEST(ClumpChecks, MemberAndFreeSphereOverlapNameTheBody) {
  TempDir d("mpdem_clump_check");
  // 1.5 r beyond the member at y = +r/2, 2.5 r from the other one.
  d.write("spheres.csv", "id,x,y,z,radius\n1,0,0.002,0.01,0.001\n");
  const Scene s = load(d, "[[particles]]\nfile = \"spheres.csv\"\n", "id,x,y,z\n7,0,0,0.01\n");
  const SceneProblems problems = check_scene(s);
  ASSERT_EQ(problems.size(), 1u) << all_messages(problems);
  expect_contains(located_text(problems[0]), {"particles of 'bodies.csv' and of 'spheres.csv'",
                                              "(member of body 7 and a free sphere) by 0.0005 m (50%)"});
}

TEST(ClumpChecks, MemberInABarrierNamesItsBody) {
  TempDir d("mpdem_clump_check");
  // A floor at z = 0 (elements 1 and 2); body 6 at z = r/2: both members overlap it by r/2 (50 %).
  d.write("floor.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n1,-0.1,-0.1,0,0.1,-0.1,0,0.1,0.1,0\n"
                       "2,-0.1,-0.1,0,0.1,0.1,0,-0.1,0.1,0\n");
  const Scene s = load(d, "[[barriers]]\nfile = \"floor.csv\"\n", "id,x,y,z\n6,0.01,0.02,0.0005\n");
  const SceneProblems problems = check_scene(s);
  ASSERT_EQ(problems.size(), 1u) << all_messages(problems);
  expect_contains(located_text(problems[0]),
                  {"2 contacts of particles of 'bodies.csv' with barrier elements of 'floor.csv'",
                   "(member of body 6) and element id", "by 0.0005 m (50%)"});
}

TEST(ClumpChecks, BodyWithAMemberOutsideTheDomainIsNamedOnce) {
  TempDir d("mpdem_clump_check");
  // Body 3's centre is inside, its member at y = +0.0005 is not (the domain ends at y = 0.0002);
  // body 4 lies inside; body 5 lies wholly outside (both members, listed once). x of body 3's member
  // is 0 up to the round-off of the principal frame and back (1e-19 m), so only y and z are compared.
  const Scene s = load(d, "[domain]\nmin = [-0.1, -0.1, -0.1]\nmax = [0.1, 0.0002, 0.1]\non_exit = \"stop\"\n",
                       "id,x,y,z\n3,0,0,0.01\n4,0.01,-0.01,0.01\n5,0.5,-0.01,0.01\n");
  const SceneProblems problems = check_scene(s);
  ASSERT_EQ(problems.size(), 1u) << all_messages(problems);
  EXPECT_TRUE(problems[0].stops_run);
  const std::string msg = located_text(problems[0]);
  expect_contains(msg, {"2 clump bodies of 'bodies.csv' lie outside the domain", "body id 3 (its member id",
                        "0.0005, 0.01))", "body id 5 (its member id"});
  EXPECT_EQ(msg.find("body id 4"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("body id 5", msg.find("body id 5") + 1), std::string::npos) << "body 5 listed twice: " << msg;
}

TEST(ClumpChecks, SummaryGivesVolumeMassMomentsErrorsAndOverrides) {
  TempDir d("mpdem_clump_check");
  // A touching dumbbell (exact), used by glass; an unused copy with a mass override.
  d.write("bodies.csv", "id,x,y,z\n1,0,0,0.01\n");
  const Scene s = load_scene(
      d.write("scene.toml",
              kHead + "[[clump]]\nname = \"dumbbell\"\nmembers = [[0, -0.001, 0, 0.001], [0, 0.001, 0, 0.001]]\n" +
                  "[[clump]]\nname = \"heavy\"\nmembers = [[0, -0.001, 0, 0.001], [0, 0.001, 0, 0.001]]\n"
                  "mass = 0.5\n" +
                  kPeanut + "[[particles]]\nfile = \"bodies.csv\"\nclump = \"dumbbell\"\n"));
  const std::vector<std::string> lines = clump_summary_lines(s);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "clumps: 3 templates, 1 body, 2 member spheres");
  const double V = 2.0 * (4.0 / 3.0) * std::numbers::pi * kR * kR * kR, M = 2500.0 * V;
  expect_contains(lines[1],
                  {"dumbbell", "2 members", fmt::format("volume {:.6g} m^3", V), fmt::format("mass {:.6g} kg", M),
                   fmt::format("principal moments {:.6g}, {:.6g}, {:.6g} kg m^2", 0.4 * M * kR * kR, 1.4 * M * kR * kR,
                               1.4 * M * kR * kR),
                   "(material 'glass', 2500 kg/m^3)", "integration error: volume exact, moments exact",
                   "overrides: none"});
  expect_contains(lines[2], {"heavy", "per unit density: mass 0.5 kg", "no [[particles]] entry uses it",
                             "overrides: mass (computed from the members: mass " + fmt::format("{:.6g}", V) + " kg"});
  // Overlapping members are integrated: the estimate is stated, not "exact".
  EXPECT_EQ(lines[3].find("exact"), std::string::npos) << lines[3];
  expect_contains(lines[3], {"peanut", "integration error: volume "});
  EXPECT_GT(s.model.clumps[2].shape.volume_error, 0.0);
  EXPECT_LT(s.model.clumps[2].shape.volume_error, 1e-8);
}

TEST(ClumpChecks, CommandPrintsTemplatesAndBadSceneExitsTwoWithOneMessage) {
  TempDir d("mpdem_clump_cli");
  d.write("bodies.csv", "id,x,y,z\n1,0,0,0.01\n");
  d.write("scene.toml",
          kHead + "[[clump]]\nname = \"peanut\"\nmembers = [[0, -0.001, 0, 0.001], [0, 0.001, 0, 0.001]]\n" + kBodies);
  const test::CommandResult ok = test::run_mpdem("check scene.toml", d.path);
  EXPECT_EQ(ok.status, 0) << ok.err;
  // The total mass is the body's (each member carries it as its contacts' damping mass).
  const double M = 2500.0 * 2.0 * (4.0 / 3.0) * std::numbers::pi * kR * kR * kR;
  expect_contains(ok.out, {"particles: 2  total mass " + fmt::format("{:.6g}", M) + " kg",
                           "clumps: 1 template, 1 body, 2 member spheres", "peanut", "integration error"});
  // A bad member row: one line on stderr naming file:line:key, exit 2, for check and run alike.
  d.write("scene.toml", kHead + "[[clump]]\nname = \"peanut\"\nmembers = [[0, 0, 0, -0.001]]\n" + kBodies);
  for (const char* cmd : {"check scene.toml", "run scene.toml"}) {
    SCOPED_TRACE(cmd);
    const test::CommandResult bad = test::run_mpdem(cmd, d.path);
    EXPECT_EQ(bad.status, 2);
    expect_contains(bad.err, {"scene.toml:11: 'clump.members'", "(radius) is -0.001, expected > 0"});
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
  // The other classes of bad templates, through `mpdem check`.
  d.write("m.csv", "x,y,z\n0,0,0\n");
  const std::string clump = "[[clump]]\nname = \"peanut\"\n";  // lines 9, 10
  struct Case {
    std::string scene, where, what;
  };
  const std::vector<Case> cases = {
      {clump + "members = []\n" + kBodies, "scene.toml:11: 'clump.members'", "got an empty array"},
      {clump + "members = [[0, 0, nan, 0.001]]\n" + kBodies, "scene.toml:11: 'clump.members'", "is not finite"},
      {clump + "members = \"m.csv\"\n" + kBodies, "m.csv:1: 'radius'", "missing required column"},
      {clump + "members = [[0, 0, 0, 0.001]]\n[[particles]]\nfile = \"bodies.csv\"\nclump = \"peanuts\"\n",
       "scene.toml:14: 'particles.clump'", "unknown clump 'peanuts' (known: peanut)"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    d.write("scene.toml", kHead + c.scene);
    const test::CommandResult bad = test::run_mpdem("check scene.toml", d.path);
    EXPECT_EQ(bad.status, 2);
    expect_contains(bad.err, {c.where, c.what});
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
}
