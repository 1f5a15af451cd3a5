// Pre-run scene checks (src/check/): every problem of a scene is found at once, each naming its
// file and line or the particle and barrier element ids; a clean scene has none.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "check/initial_overlaps.hpp"
#include "check/region_walls.hpp"
#include "check/scene_checks.hpp"
#include "support/temp_dir.hpp"
#include "tools/mesh_builder.hpp"
#include "tools/mesh_output.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
using mpdem::test::expect_contains;
using mpdem::test::TempDir;

namespace {

const std::string kHead = "[time]\nduration = 0.01\ndt = 1e-6\nintegrator = \"verlet\"\n"
                          "[[material]]\nname = \"glass\"\nyoung = 1e9\n";
const std::string kFloor =  // z = 0, ids 1 (y < x) and 2
    "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n1,-0.1,-0.1,0,0.1,-0.1,0,0.1,0.1,0\n2,-0.1,-0.1,0,0.1,0.1,0,-0.1,0.1,0\n";

// Line (1-based) of the first occurrence of `part` in `text`.
std::size_t line_of(const std::string& text, const std::string& part) {
  const std::size_t at = text.find(part);
  EXPECT_NE(at, std::string::npos) << part;
  return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

struct Files {
  TempDir dir{"mpdem_checks"};
  std::string toml;
  Scene load(const std::string& scene_text) {
    toml = scene_text;
    dir.write("scene.toml", toml);
    return load_scene(dir.path / "scene.toml");
  }
};

SceneProblems with_key(const SceneProblems& all, const std::string& key) {
  SceneProblems out;
  std::copy_if(all.begin(), all.end(), std::back_inserter(out), [&](const SceneProblem& p) { return p.key == key; });
  return out;
}

}  // namespace

TEST(SceneChecks, CleanSceneHasNoProblems) {
  Files f;
  f.dir.write("p.csv", "id,x,y,z,radius\n1,0.01,0,0.0011,0.001\n2,0.0121,0,0.0011,0.001\n3,0.05,0,0.02,0.001\n");
  f.dir.write("floor.csv", kFloor);
  const Scene s = f.load(
      kHead + "[[particles]]\nfile = \"p.csv\"\n"
              "[[particles]]\ngenerate = { region = \"box\", min = [-0.02, -0.02, 0.0], max = [0.0, 0.0, "
              "0.02], count = 10, radius = 0.001 }\n"
              "[[barriers]]\nfile = \"floor.csv\"\n[domain]\nmin = [-0.1, -0.1, -0.01]\nmax = [0.1, 0.1, 0.1]\n");
  const SceneProblems problems = check_scene(s);
  for (const SceneProblem& p : problems) ADD_FAILURE() << located_text(p);
  // Generated particles touch the floor at most (they keep their radius from the region's boundary).
  EXPECT_TRUE(particle_overlaps(s.particles, 1e-9).empty());
  EXPECT_TRUE(barrier_overlaps(s.particles, s.barriers, 1e-9).empty());
}

TEST(SceneChecks, ParticlesOutsideTheDomainAreNamedWithTheirFile) {
  Files f;
  const auto p = f.dir.write("p.csv", "id,x,y,z,radius\n1,0,0,0.01,0.001\n7,0.5,0,0.01,0.001\n8,0.5,0.5,0.01,0.001\n");
  const std::string domain = "[domain]\nmin = [-0.1, -0.1, -0.01]\nmax = [0.1, 0.1, 0.2]\n";
  SceneProblems r = check_scene(f.load(kHead + "[[particles]]\nfile = \"p.csv\"\n" + domain));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].severity, Severity::Error);
  EXPECT_TRUE(r[0].stops_run);  // on_exit = "stop" (the default)
  EXPECT_EQ(r[0].file, p.string());
  expect_contains(r[0].message,
                  {"2 particles of 'p.csv'", "id 7 at (0.5, 0, 0.01)", "id 8 at (0.5, 0.5, 0.01)", "stop"});
  EXPECT_EQ(r[0].message.find("id 1 "), std::string::npos) << r[0].message;
  // Removed at step 1 rather than stopping the run: still an error, but the run may start.
  r = check_scene(f.load(kHead + "[[particles]]\nfile = \"p.csv\"\n" + domain + "on_exit = \"remove\"\n"));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].severity, Severity::Error);
  EXPECT_FALSE(r[0].stops_run);
  expect_contains(r[0].message, {"removed", "id 7"});
}

TEST(SceneChecks, ManyParticlesOutsideAreCountedAndTheFirstListed) {
  Files f;
  std::string csv = "id,x,y,z,radius\n";
  for (int i = 0; i < 12; ++i) csv += std::to_string(100 + i) + ",0.5," + std::to_string(0.01 * i) + ",0,0.001\n";
  f.dir.write("p.csv", csv);
  const SceneProblems r = check_scene(
      f.load(kHead + "[[particles]]\nfile = \"p.csv\"\n[domain]\nmin = [-0.1, -0.1, -0.1]\nmax = [0.1, 0.2, 0.1]\n"));
  ASSERT_EQ(r.size(), 1u);
  expect_contains(r[0].message, {"12 particles", "id 100 at", "id 104 at", "and 7 more"});
  EXPECT_EQ(r[0].message.find("id 105"), std::string::npos) << r[0].message;
}

TEST(SceneChecks, ParticleOverlapsAreListedByIdsDeepestFirst) {
  Files f;
  // Pairs (1, 2) 40 %, (3, 4) 10 %, (5, 6) 2 % of the radius 1 mm; apart along x.
  f.dir.write("p.csv", "id,x,y,z,radius\n1,0,0,0,0.001\n2,0.0016,0,0,0.001\n3,0.01,0,0,0.001\n4,0.0119,0,0,0.001\n"
                       "5,0.02,0,0,0.001\n6,0.02198,0,0,0.001\n");
  const Scene s = f.load(kHead + "[gravity]\nvector = [0.0, 0.0, 0.0]\n[[particles]]\nfile = \"p.csv\"\n");
  const std::vector<PairOverlap> all = particle_overlaps(s.particles, 0.0);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_NEAR(all[0].ratio, 0.4, 1e-9);
  EXPECT_NEAR(all[1].ratio, 0.1, 1e-9);
  EXPECT_NEAR(all[2].ratio, 0.02, 1e-9);
  const SceneProblems r = check_scene(s);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].severity, Severity::Error);
  EXPECT_TRUE(r[0].stops_run);
  const std::string& m = r[0].message;
  expect_contains(m, {"2 pairs", "checks.max_overlap = 5%", "ids 1 and 2 by 0.0004 m (40%)", "ids 3 and 4"});
  EXPECT_LT(m.find("ids 1 and 2"), m.find("ids 3 and 4"));
  EXPECT_EQ(m.find("ids 5 and 6"), std::string::npos) << m;  // within checks.max_overlap
}

TEST(SceneChecks, InitialOverlapsWithinTheLimitOrWithTheCheckOff) {
  Files f;
  f.dir.write("p.csv", "id,x,y,z,radius\n1,0,0,0,0.001\n2,0.0016,0,0,0.001\n3,0.01,0,0,0.001\n4,0.01197,0,0,0.001\n");
  const std::string head = kHead + "[gravity]\nvector = [0.0, 0.0, 0.0]\n[[particles]]\nfile = \"p.csv\"\n";
  EXPECT_TRUE(check_scene(f.load(head + "[checks]\nmax_overlap = 0.5\n")).empty());
  // checks.max_overlap = 0: the run does not stop on them, but the 40 % pair still warns.
  const SceneProblems r = check_scene(f.load(head + "[checks]\nmax_overlap = 0.0\n"));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].severity, Severity::Warning);
  EXPECT_FALSE(r[0].stops_run);
  expect_contains(r[0].message, {"1 pair", "ids 1 and 2", "the check is off"});
  EXPECT_EQ(r[0].message.find("ids 3 and 4"), std::string::npos) << r[0].message;  // 1.5 %
}

TEST(SceneChecks, ParticleBarrierOverlapsNameParticleElementAndEntry) {
  Files f;
  // id 3: 0.2 mm into the floor (element 1); id 4: 0.1 mm into the floor's half thickness (0.2 mm);
  // id 5 is clear of it.
  f.dir.write("p.csv",
              "id,x,y,z,radius\n3,0.05,-0.05,0.0008,0.001\n4,-0.05,0.05,0.0011,0.001\n5,0,0.05,0.0013,0.001\n");
  f.dir.write("floor.csv", kFloor);
  const Scene s = f.load(kHead + "[[particles]]\nfile = \"p.csv\"\n[[barriers]]\nfile = \"floor.csv\"\n"
                                 "thickness = 0.0004\n");
  const std::vector<BarrierOverlap> all = barrier_overlaps(s.particles, s.barriers, 0.0);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_NEAR(all[0].ratio, 0.4, 1e-9);  // 0.2 mm + half the thickness
  EXPECT_NEAR(all[1].ratio, 0.1, 1e-9);
  const SceneProblems r = check_scene(s);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(r[0].stops_run);
  EXPECT_EQ(r[0].line, line_of(f.toml, "[[barriers]]"));
  EXPECT_EQ(r[0].key, "barriers");
  expect_contains(r[0].message, {"2 contacts", "'p.csv'", "'floor.csv'", "particle id 3 and element id 1 by 0.0004 m",
                                 "particle id 4 and element id 2 by 0.0001 m"});
  EXPECT_EQ(r[0].message.find("particle id 5"), std::string::npos);
}

TEST(SceneChecks, GenerateRegionCrossedByAWall) {
  Files f;
  f.dir.write("floor.csv", kFloor);
  // A vertical baffle at x = 0.01 through the region; the floor and the side wall at x = 0 lie on
  // its boundary.
  f.dir.write("baffle.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n11,0.01,-0.01,0.01,0.01,0.05,0.01,0.01,0.05,0.05\n");
  f.dir.write("side.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n21,0,-0.01,0,0,0.05,0,0,0.05,0.05\n");
  const Scene s = f.load(kHead +
                         "[[particles]]\ngenerate = { region = \"box\", min = [0.0, 0.0, 0.0], max = [0.02, 0.02, "
                         "0.02], count = 3, radius = 0.001, gap = 0.002 }\n"
                         "[[barriers]]\nfile = \"floor.csv\"\n[[barriers]]\nfile = \"baffle.csv\"\n"
                         "[[barriers]]\nfile = \"side.csv\"\n");
  const SceneProblems r = with_key(check_scene(s), "particles.generate.region");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].severity, Severity::Error);
  EXPECT_FALSE(r[0].stops_run);  // the overlaps it causes are reported (and stop the run) on their own
  EXPECT_EQ(r[0].line, line_of(f.toml, "[[particles]]"));
  expect_contains(r[0].message, {"[[particles]] entry 1", "box from (0, 0, 0) to (0.02, 0.02, 0.02)", "'baffle.csv'",
                                 "element id 11"});
}

TEST(RegionProbe, BoxFacesAreNotCrossingsButTheInsideIs) {
  GenerateSpec g;
  g.region.min = {0, 0, 0};
  g.region.max = {1, 1, 1};
  const RegionProbe box(g);
  EXPECT_FALSE(box.crossed_by({Vec3{-1, -1, 0}, Vec3{2, -1, 0}, Vec3{2, 2, 0}}, 0.0));  // on the floor
  EXPECT_TRUE(box.crossed_by({Vec3{-1, -1, 1e-3}, Vec3{2, -1, 1e-3}, Vec3{2, 2, 1e-3}}, 0.0));
  EXPECT_FALSE(box.crossed_by({Vec3{-1, -1, 1e-3}, Vec3{2, -1, 1e-3}, Vec3{2, 2, 1e-3}}, 2e-3));  // within the depth
  EXPECT_FALSE(box.crossed_by({Vec3{2, 0, 0}, Vec3{3, 0, 0}, Vec3{2, 1, 1}}, 0.0));               // outside
  EXPECT_TRUE(box.crossed_by({Vec3{0.4, 1.5, 0.5}, Vec3{1.5, 0.4, 0.5}, Vec3{1.5, 1.5, 0.5}}, 0.0));  // a corner
}

TEST(RegionProbe, CylinderSidesCapsAndAxis) {
  GenerateSpec g;
  g.region.shape = RegionShape::Cylinder;
  g.region.base = {0, 0, 0};
  g.region.axis = {0, 0, 1};
  g.region.radius = 0.1;
  const RegionProbe cyl(g);
  const auto wall = [](double x) {
    return std::array<Vec3, 3>{Vec3{x, -0.2, 0.2}, Vec3{x, 0.2, 0.2}, Vec3{x, 0.0, 0.8}};
  };
  EXPECT_TRUE(cyl.crossed_by(wall(0.09), 0.0));
  EXPECT_FALSE(cyl.crossed_by(wall(0.1), 0.0));  // tangent
  EXPECT_FALSE(cyl.crossed_by(wall(0.11), 0.0));
  EXPECT_FALSE(cyl.crossed_by({Vec3{-1, -1, 1}, Vec3{1, -1, 1}, Vec3{0, 1, 1}}, 0.0));  // on the top cap
  // A large horizontal triangle around the axis, its vertices all outside the radius.
  EXPECT_TRUE(cyl.crossed_by({Vec3{-1, -1, 0.5}, Vec3{1, -1, 0.5}, Vec3{0, 1, 0.5}}, 0.0));
}

TEST(RegionProbe, MeshRegionInsideAndOnItsSurface) {
  TempDir dir("mpdem_checks");
  const auto stl = dir.path / "box.stl";
  write_mesh(stl, make_box(0.1, 0.1, 0.1, true), MeshFileFormat::StlAscii, "");  // [-0.05, 0.05]^2 x [0, 0.1]
  GenerateSpec g;
  g.region.shape = RegionShape::Mesh;
  g.region.mesh = stl;
  const RegionProbe mesh(g);
  EXPECT_TRUE(mesh.crossed_by({Vec3{-0.2, -0.2, 0.05}, Vec3{0.2, -0.2, 0.05}, Vec3{0, 0.2, 0.05}}, 0.0));
  EXPECT_FALSE(mesh.crossed_by({Vec3{-0.2, -0.2, 0.0}, Vec3{0.2, -0.2, 0.0}, Vec3{0, 0.2, 0.0}}, 0.0));  // floor
  EXPECT_FALSE(mesh.crossed_by({Vec3{0.06, -0.2, 0.0}, Vec3{0.06, 0.2, 0.0}, Vec3{0.06, 0, 0.1}}, 0.0));
}

TEST(SceneChecks, EveryProblemIsReportedNotOnlyTheFirst) {
  Files f;
  f.dir.write("p.csv", "id,x,y,z,radius\n1,0.05,0.05,0.01,0.001\n2,0.0516,0.05,0.01,0.001\n7,0.5,0,0.01,0.001\n");
  const SceneProblems r = check_scene(
      f.load(kHead + "[[particles]]\nfile = \"p.csv\"\n[domain]\nmin = [-0.1, -0.1, -0.01]\nmax = [0.1, 0.1, 0.2]\n"));
  ASSERT_EQ(r.size(), 2u);
  expect_contains(r[0].message, {"outside the domain", "id 7"});
  expect_contains(r[1].message, {"ids 1 and 2", "40%"});
}
