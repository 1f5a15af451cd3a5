// The checks before the run see what acts after t = 0 (issue 45 item 3): the particles an inlet
// will insert (impact speed, radii), an inlet's volume outside the domain or its start after
// the run's end, and a barrier that its motion carries across a periodic face.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "check/impact_overlap.hpp"
#include "check/scene_checks.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
using mpdem::test::TempDir;

namespace {

// A scene without particles: an inlet box [-0.04, 0.04]^2 x [0.15, 0.18] m of beads (radius 2 ..
// 3 mm) moving down at 1 m/s, over a floor at z = 0; `extra` is appended.
std::string inlet_scene(const std::string& young, const std::string& extra = "", const std::string& inlet = "") {
  return "[time]\nduration = 0.2\ndt = 1e-6\nintegrator = \"verlet\"\n[[material]]\nname = \"beads\"\nyoung = " +
         young +
         "\n[[barriers]]\nfile = \"floor.csv\"\n"
         "[[inlet]]\nname = \"feed\"\nregion = \"box\"\nmin = [-0.04, -0.04, 0.15]\nmax = [0.04, 0.04, 0.18]\n"
         "count_rate = 1000\nradius = { distribution = \"uniform\", min = 0.002, max = 0.003 }\n"
         "velocity = [0.0, 0.0, -1.0]\n" +
         inlet + extra;
}

const char* kFloor =  // z = 0
    "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n1,-0.1,-0.1,0,0.1,-0.1,0,0.1,0.1,0\n2,-0.1,-0.1,0,0.1,0.1,0,-0.1,0.1,0\n";

struct Files {
  TempDir dir{"mpdem_open_checks"};
  Files() { dir.write("floor.csv", kFloor); }
  Scene load(const std::string& toml) { return load_scene(dir.write("scene.toml", toml)); }
};

std::size_t count(const SceneProblems& all, Severity severity, const std::string& part) {
  std::size_t n = 0;
  for (const SceneProblem& p : all) n += p.severity == severity && located_text(p).find(part) != std::string::npos;
  return n;
}

std::string all_text(const SceneProblems& all) {
  std::string s;
  for (const SceneProblem& p : all) s += located_text(p) + "\n";
  return s;
}

}  // namespace

// Today's main: speed 0 (no particles at t = 0), no estimate, no warning.
TEST(OpenSceneChecks, InletParticlesSetTheImpactSpeedAndTheOverlapEstimate) {
  Files f;
  const Scene s = f.load(inlet_scene("2e6"));
  const ImpactSpeed v = expected_impact_speed(s);
  // The smallest particles' centres start 2 mm below the top, 0.178 m above the floor.
  EXPECT_EQ(v.inlet, "feed");
  EXPECT_NEAR(v.inlet_fall, 0.178, 1e-12);
  EXPECT_DOUBLE_EQ(v.insertion_speed, 1.0);
  EXPECT_NEAR(v.speed, std::sqrt(1.0 + 2.0 * 9.81 * 0.178), 1e-12);
  EXPECT_EQ(v.origin(), "inlet 'feed': inserted at 1 m/s, then a fall of 0.178 m under gravity");
  // Particle-particle (the inlet inserts many) and particle-floor, both of the radii range.
  const std::vector<ImpactEstimate> est = impact_estimates(s, v.speed);
  ASSERT_EQ(est.size(), 2u);
  for (const ImpactEstimate& e : est) EXPECT_GT(e.ratio, 0.05);
  const SceneProblems problems = check_scene(s);
  EXPECT_EQ(count(problems, Severity::Warning, "an impact at 2.12 m/s (inlet 'feed'"), 2u) << all_text(problems);
  // The velocity spread adds sqrt(3) x spread at most.
  const ImpactSpeed spread = expected_impact_speed(f.load(inlet_scene("2e6", "velocity_spread = 0.1\n")));
  EXPECT_NEAR(spread.insertion_speed, 1.0 + std::sqrt(3.0) * 0.1, 1e-12);
  // A stiff material: no warning.
  EXPECT_TRUE(check_scene(f.load(inlet_scene("1e12"))).empty()) << all_text(check_scene(f.load(inlet_scene("1e12"))));
}

TEST(OpenSceneChecks, InletVolumeOutsideTheDomain) {
  Files f;
  const std::string domain = "[domain]\nmin = [-0.1, -0.1, -0.01]\nmax = [0.1, 0.1, {}]\non_exit = \"{}\"\n";
  const auto scene = [&](const char* top, const char* on_exit) {
    std::string d = domain;
    d.replace(d.find("{}"), 2, top);
    d.replace(d.find("{}"), 2, on_exit);
    return f.load(inlet_scene("1e12", d));
  };
  // Inside: the centres of the smallest particles reach z = 0.178 at most.
  EXPECT_TRUE(check_scene(scene("0.2", "stop")).empty()) << all_text(check_scene(scene("0.2", "stop")));
  // The volume ends on the domain's face: centres keep a radius inside, no problem.
  EXPECT_TRUE(check_scene(scene("0.18", "stop")).empty()) << all_text(check_scene(scene("0.18", "stop")));
  // Partly outside: a warning when the particles placed outside are removed, an error when they stop the run.
  SceneProblems p = check_scene(scene("0.16", "remove"));
  EXPECT_EQ(count(p, Severity::Warning, "scene.toml:10: 'inlet': the particles of [[inlet]] 'feed'"), 1u)
      << all_text(p);
  EXPECT_EQ(count(p, Severity::Warning, "partly outside the domain"), 1u) << all_text(p);
  p = check_scene(scene("0.16", "stop"));
  ASSERT_EQ(count(p, Severity::Error, "partly outside the domain"), 1u) << all_text(p);
  EXPECT_FALSE(p[0].stops_run);
  // Entirely outside: an error; with on_exit = "stop" it refuses the run.
  p = check_scene(scene("0.1", "remove"));
  ASSERT_EQ(count(p, Severity::Error, "entirely outside the domain"), 1u) << all_text(p);
  EXPECT_FALSE(p[0].stops_run);
  p = check_scene(scene("0.1", "stop"));
  ASSERT_EQ(count(p, Severity::Error, "entirely outside the domain"), 1u) << all_text(p);
  EXPECT_TRUE(p[0].stops_run);
  // A cylinder inlet reaching past the side wall x = 0.1.
  p = check_scene(
      f.load("[time]\nduration = 0.2\ndt = 1e-6\n[[material]]\nname = \"beads\"\nyoung = 1e12\n"
             "[[inlet]]\nregion = \"cylinder\"\nbase = [0.09, 0, 0.05]\naxis = [0, 0, 0.02]\ncylinder_radius = 0.02\n"
             "count_rate = 100\nradius = 0.002\n[domain]\nmin = [-0.1, -0.1, -0.01]\nmax = [0.1, 0.1, 0.2]\n"
             "on_exit = \"remove\"\n"));
  EXPECT_EQ(count(p, Severity::Warning, "partly outside the domain [(-0.1, -0.1, -0.01), (0.1, 0.1, 0.2)] (along x)"),
            1u)
      << all_text(p);
}

TEST(OpenSceneChecks, InletStartingAfterTheRunsEndWarns) {
  Files f;
  SceneProblems p = check_scene(f.load(inlet_scene("1e12", "", "start = 0.2\n")));
  EXPECT_EQ(count(p, Severity::Warning, "scene.toml:10: 'inlet.start': [[inlet]] 'feed' starts at t = 0.2 s"), 1u)
      << all_text(p);
  EXPECT_TRUE(check_scene(f.load(inlet_scene("1e12", "", "start = 0.19\n"))).empty());
}

// A wall along the periodic x axis: sliding along x carries it across the face (an error),
// moving along z does not; a turning paddle whose tip reaches past the face half a turn later.
TEST(OpenSceneChecks, BarrierMotionAcrossAPeriodicFace) {
  Files f;
  f.dir.write("plate.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n5,-0.1,-0.05,0.1,0.1,-0.05,0.1,0.1,0.05,0.1\n");
  const auto scene = [&](const std::string& motion, const std::string& duration) {
    return check_scene(f.load("[time]\nduration = " + duration +
                              "\ndt = 1e-6\n[[material]]\nname = \"beads\"\nyoung = 1e12\n"
                              "[[barriers]]\nfile = \"plate.csv\"\nmotion = " +
                              motion +
                              "\n[domain]\nmin = [-0.1, -0.1, -0.01]\nmax = [0.1, 0.1, 0.2]\nperiodic = [\"x\"]\n"));
  };
  SceneProblems p = scene("{ a = [0.01, 0, 0] }", "1.0");
  ASSERT_EQ(count(p, Severity::Error, "the motion of 1 barrier element of 'plate.csv'"), 1u) << all_text(p);
  EXPECT_FALSE(p[0].stops_run);
  EXPECT_NE(all_text(p).find("(element ids 5) carries it across a periodic face"), std::string::npos) << all_text(p);
  EXPECT_NE(all_text(p).find("along x before the run's end t = 1 s, up to 0.01 m beyond it"), std::string::npos)
      << all_text(p);
  EXPECT_TRUE(scene("{ a = [0, 0, 0.01] }", "1.0").empty()) << all_text(scene("{ a = [0, 0, 0.01] }", "1.0"));
  // A vibration along x that moves the plate's ends past the faces, and one of zero amplitude there.
  EXPECT_EQ(count(scene("{ A = [0.001, 0, 0], w1 = 100.0 }", "1.0"), Severity::Error, "up to 0.001 m beyond"), 1u);
  EXPECT_TRUE(scene("{ A = [0, 0, 0.01], w1 = 100.0 }", "1.0").empty());
  // Paddles turning about y through (ox, 0, 0.1) at 2 rad/s: a vertex at x0 (on the axis' z)
  // sweeps x in [ox - |x0 - ox|, ox + |x0 - ox|] in a full turn (4 s: 8 rad).
  f.dir.write("plate.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n5,0,-0.05,0.1,0.08,-0.05,0.1,0.08,0.05,0.1\n");
  const auto turn = [](const char* ox) {
    return std::string("{ rotation = { axis = [0, 1, 0], origin = [") + ox + ", 0, 0.1], omega = 2.0 } }";
  };
  EXPECT_TRUE(scene(turn("0"), "4.0").empty()) << all_text(scene(turn("0"), "4.0"));        // [-0.08, 0.08]
  EXPECT_TRUE(scene(turn("0.03"), "4.0").empty()) << all_text(scene(turn("0.03"), "4.0"));  // [-0.02, 0.08]
  f.dir.write("plate.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n5,-0.09,-0.05,0.1,0.0,-0.05,0.1,0.0,0.05,0.1\n");
  EXPECT_TRUE(scene(turn("-0.02"), "4.0").empty()) << all_text(scene(turn("-0.02"), "4.0"));  // [-0.09, 0.05]
  p = scene(turn("0.04"), "4.0");  // x0 = -0.09 sweeps [-0.09, 0.17]
  EXPECT_EQ(count(p, Severity::Error, "up to 0.07 m beyond"), 1u) << all_text(p);
  // The same arm within 0.1 s turns by 0.2 rad only: x = 0.04 - 0.13 cos(theta) <= -0.087.
  p = scene(turn("0.04"), "0.1");
  EXPECT_TRUE(p.empty()) << all_text(p);
}
