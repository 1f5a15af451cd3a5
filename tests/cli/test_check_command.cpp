// `mpdem check` reports every problem it finds before step 1, each with file and line or ids
// (exit 2 on errors, 0 with warnings only); `mpdem run` refuses a start that would stop at step 1
// and warns about the rest.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

const char* kFloor =
    "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n1,-0.1,-0.1,0,0.1,-0.1,0,0.1,0.1,0\n2,-0.1,-0.1,0,0.1,0.1,0,-0.1,0.1,0\n";

std::string scene(const std::string& young, const std::string& extra = "") {
  return "[time]\nduration = 0.002\ndt = 1e-6\nintegrator = \"verlet\"\n[[material]]\nname = \"glass\"\nyoung = " +
         young + "\n[[particles]]\nfile = \"p.csv\"\n[[barriers]]\nfile = \"floor.csv\"\n" + extra;
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

fs::path scene_dir(const std::string& name, const std::string& particles) {
  const fs::path d = fresh_dir(name);
  write_text(d / "p.csv", particles);
  write_text(d / "floor.csv", kFloor);
  return d;
}

}  // namespace

TEST(CheckCommand, ReportsEveryProblemWithIdsAndExits2) {
  // id 7 outside the domain, ids 1 and 2 overlapping by 40 %, id 3 in the floor, and a generate
  // region that a baffle (element 11) crosses.
  const fs::path d = scene_dir("check_all", "id,x,y,z,radius\n1,0.05,0.05,0.01,0.001\n2,0.0516,0.05,0.01,0.001\n"
                                            "3,-0.05,0.05,0.0008,0.001\n7,0.5,0,0.01,0.001\n");
  write_text(d / "baffle.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n11,-0.03,-0.05,0.03,-0.03,0,0.03,-0.03,0,0.07\n");
  write_text(d / "scene.toml",
             scene("1e9",
                   "[[barriers]]\nfile = \"baffle.csv\"\n"
                   "[[particles]]\ngenerate = { region = \"box\", min = [-0.05, -0.05, 0.04], max = [0.0, 0.0, 0.06], "
                   "count = 2, radius = 0.001 }\n"
                   "[domain]\nmin = [-0.1, -0.1, -0.01]\nmax = [0.1, 0.1, 0.2]\n"));
  const CommandResult r = run_mpdem("check scene.toml", d);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.out.find("particles: 6"), std::string::npos) << r.out;  // the summary still comes
  for (const char* part :
       {"p.csv: 1 particle of 'p.csv' lies outside the domain", "id 7 at (0.5, 0, 0.01)",
        "ids 1 and 2 by 0.0004 m (40%)", "scene.toml:10: 'barriers'", "particle id 3 and element id 2",
        "scene.toml:14: 'particles.generate.region'", "element id 11",
        "check: 4 errors, 1 warning before step 1"})  // and time.dt above the advice
    EXPECT_NE(r.err.find(part), std::string::npos) << "'" << part << "' not in:\n" << r.err;
  EXPECT_EQ(count(r.err, "error: "), 4u) << r.err;
  fs::remove_all(d);
}

TEST(CheckCommand, CleanSceneExits0AndNamesTheImpactSpeed) {
  const fs::path d = scene_dir("check_clean", "id,x,y,z,radius\n1,0,0,0.1,0.001\n2,0.01,0,0.0011,0.001\n");
  write_text(d / "scene.toml", scene("1e9"));
  const CommandResult r = run_mpdem("check scene.toml", d);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("error:"), std::string::npos) << r.err;
  // The closing count comes always (it did not without problems), and counts the time-step warning.
  EXPECT_NE(r.err.find("check: 0 errors, 1 warning before step 1"), std::string::npos) << r.err;
  // The time step's contact time is taken at the speed of a fall over the scene's height.
  EXPECT_NE(r.out.find("Hertz contact time at 1.4 m/s (expected impact speed: a fall of 0.1 m under gravity)"),
            std::string::npos)
      << r.out;
  fs::remove_all(d);
}

TEST(CheckCommand, SoftMaterialWarnsAboutTheImpactOverlapAndExits0) {
  const fs::path d = scene_dir("check_soft", "id,x,y,z,radius\n1,0,0,0.1,0.001\n2,0.01,0,0.0011,0.001\n");
  write_text(d / "scene.toml", scene("1e5"));
  const CommandResult r = run_mpdem("check scene.toml", d);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(count(r.err, "'checks.max_overlap': an impact at 1.4 m/s"), 2u) << r.err;
  EXPECT_NE(r.err.find("check: 0 errors, 2 warnings before step 1"), std::string::npos) << r.err;
  fs::remove_all(d);
}

TEST(CheckCommand, RunRefusesAStartThatWouldStopAtStepOne) {
  const fs::path d = scene_dir("run_refused", "id,x,y,z,radius\n1,0.05,0.05,0.01,0.001\n2,0.0516,0.05,0.01,0.001\n");
  write_text(d / "scene.toml", scene("1e9"));
  const CommandResult r = run_mpdem("run scene.toml --quiet", d);
  EXPECT_EQ(r.status, 2) << r.err;  // it stopped at step 1 with "reduce time.dt", exit 1
  EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ids 1 and 2 by 0.0004 m (40%)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the run would stop at its first step (1 problem above); nothing was run"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(d / "output"));
  fs::remove_all(d);
}

TEST(CheckCommand, RunWarnsAboutParticlesItWillRemoveAndStarts) {
  const fs::path d = scene_dir("run_removes", "id,x,y,z,radius\n1,0.05,0.05,0.01,0.001\n7,0.5,0,0.01,0.001\n");
  write_text(d / "scene.toml", scene("1e9", "[domain]\nmin = [-0.1, -0.1, -0.01]\nmax = [0.1, 0.1, 0.2]\n"
                                            "on_exit = \"remove\"\n"));
  const CommandResult r = run_mpdem("run scene.toml --quiet", d);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("id 7 at (0.5, 0, 0.01)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("they would be removed at the first step"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(d / "output" / "log.csv"));
  // `check` counts it as an error all the same: the particle never takes part.
  EXPECT_EQ(run_mpdem("check scene.toml", d).status, 2);
  fs::remove_all(d);
}

// A scene filled from empty by an inlet gets a time step recommendation from the inlet's
// particles (it printed "recommended dt <= 0 s" before).
TEST(CheckCommand, InletOnlySceneRecommendsAStepFromTheInletParticles) {
  const fs::path d = scene_dir("check_inlet", "x,y,z,radius\n");
  write_text(d / "scene.toml",
             "[time]\nduration = 0.1\ndt = 1e-5\n[[material]]\nname = \"beads\"\nyoung = 2e6\n"
             "[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [0.05, 0.05, 0.05]\ncount_rate = 1000\n"
             "radius = 0.0025\n");
  const CommandResult r = run_mpdem("check scene.toml", d);
  EXPECT_EQ(r.status, 0) << r.err;
  const auto at = r.out.find("recommended dt <= ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const double dt = std::stod(r.out.substr(at + 18));
  // 0.2 x the Rayleigh time of a 2.5 mm bead of E = 2e6 Pa (4.8e-4 s): 9.7e-5 s, or less.
  EXPECT_GT(dt, 1e-6) << r.out;
  EXPECT_LT(dt, 1e-4) << r.out;
}

// Under the linear law the recommended step is the linear contact time pi sqrt(m*/k_n) / 50, for
// two equal spheres (m* = m/2) and a sphere on the floor (m* = m), whatever the unused Young's
// modulus; the Rayleigh time (from E) is not used.
TEST(CheckCommand, LinearLawRecommendsFromTheLinearContactTime) {
  const fs::path d = scene_dir("check_linear", "x,y,z,radius\n0,0,0.002,0.001\n0.01,0,0.002,0.001\n");
  const std::string law = "[contact.particle_particle]\nlaw = \"linear\"\nstiffness_normal = 200.0\n"
                          "[contact.particle_barrier]\nlaw = \"linear\"\nstiffness_normal = 400.0\n";
  const double m = 2500.0 * 4.0 / 3.0 * M_PI * 1e-9;  // kg, default density 2500 kg/m^3
  const double pp = M_PI * std::sqrt(0.5 * m / 200.0), pb = M_PI * std::sqrt(m / 400.0);  // s
  for (const char* young : {"1e6", "1e9"}) {
    write_text(d / "scene.toml", scene(young, law));
    const CommandResult r = run_mpdem("check scene.toml", d);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("Rayleigh time not used"), std::string::npos) << r.out;
    const auto at = r.out.find("recommended dt <= ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const double dt = std::stod(r.out.substr(at + 18));
    EXPECT_NEAR(dt, std::min(pp, pb) / 50.0, 1e-3 * dt) << r.out;  // printed to 4 digits
    EXPECT_NE(r.out.find(fmt::format("particle-particle {:.4g} s, particle-barrier {:.4g} s", pp, pb)),
              std::string::npos)
        << r.out;
  }
}

// Issue 45 item 3: a scene whose only particles come from an inlet gets the inlet's impact
// speed in its time-step advice and its impact-overlap warning (before: "particles: 0 ... radius
// 0 .. 0 m", no warning, and the run stopped on an overlap at the first impacts); the summary
// lists inlets, sinks, coarse-grain entries and outputs; an inlet outside the domain is reported.
TEST(CheckCommand, InletOnlySceneGetsTheInletsImpactSpeedAndEntries) {
  const fs::path d = scene_dir("check_inlet_impact", "x,y,z,radius\n");
  const std::string head =
      "[time]\nduration = 0.2\ndt = 1e-5\n[[material]]\nname = \"beads\"\nyoung = 2e6\n"
      "[[barriers]]\nfile = \"floor.csv\"\n"
      "[[inlet]]\nname = \"feed\"\nregion = \"box\"\nmin = [-0.04, -0.04, 0.15]\nmax = [0.04, 0.04, 0.18]\n"
      "count_rate = 5000\nradius = { distribution = \"uniform\", min = 0.002, max = 0.003 }\n"
      "velocity = [0.0, 0.0, -1.0]\n"
      "[[sink]]\nname = \"out\"\nregion = \"box\"\nmin = [-0.2, -0.2, -0.3]\nmax = [0.2, 0.2, -0.05]\n"
      "[[coarse_grain]]\nname = \"bed\"\nprofile = { axis = \"z\", min = 0.0, max = 0.1, bins = 10 }\n"
      "width = 0.005\nevery = 0.05\n"
      "[output]\ndir = \"results\"\nparticle_csv_every = 0.05\n";
  write_text(d / "scene.toml", head + "[domain]\nmin = [-0.2, -0.2, -0.3]\nmax = [0.2, 0.2, 0.3]\n"
                                      "on_exit = \"remove\"\n");
  CommandResult r = run_mpdem("check scene.toml", d);
  EXPECT_EQ(r.status, 0) << r.err;
  // sqrt(1 + 2 g 0.178): the smallest particles' centres 0.178 m above the floor, inserted at 1 m/s.
  const std::string speed = "2.12 m/s (expected impact speed: inlet 'feed': inserted at 1 m/s, then a fall of 0.178 m";
  EXPECT_NE(r.out.find("Hertz contact time at " + speed), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("particles: 0 at t = 0 (the inlets below insert them)"), std::string::npos) << r.out;
  for (const char* part :
       {"inlets: 1\n  feed ", "5000 particles/s", "radius uniform [0.002, 0.003] m", "sinks: 1\n  out ",
        "coarse grain: 1\n  bed ", "profile along z in 10 bins", "results\n", "particle CSV every 0.05 s"})
    EXPECT_NE(r.out.find(part), std::string::npos) << "'" << part << "' not in:\n" << r.out;
  EXPECT_EQ(count(r.err, "'checks.max_overlap': an impact at 2.12 m/s (inlet 'feed'"), 2u) << r.err;
  EXPECT_NE(r.err.find("check: 0 errors, 2 warnings before step 1"), std::string::npos) << r.err;
  // The domain ends below the inlet: every particle it places would leave at once.
  write_text(d / "scene.toml", head + "[domain]\nmin = [-0.2, -0.2, -0.3]\nmax = [0.2, 0.2, 0.1]\n"
                                      "on_exit = \"remove\"\n");
  r = run_mpdem("check scene.toml", d);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("error: " + (d / "scene.toml").string() +
                       ":9: 'inlet': the particles of [[inlet]] 'feed' would be placed with centres in"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("entirely outside the domain"), std::string::npos) << r.err;
  fs::remove_all(d);
}
