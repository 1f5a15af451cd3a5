// [domain] periodic (src/scene/scene_reader.cpp) and the checks of a periodic scene
// (src/check/periodic_domain.cpp): the axes are read, bad values are an InputError naming file,
// line and key, a barrier crossing a periodic face and a period too short for the neighbour
// search are errors located at their entries, and the fingerprint holds the axes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "check/scene_checks.hpp"
#include "core/input_error.hpp"
#include "io/scene_fingerprint.hpp"
#include "model/scene.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::error_of;
using mpdem::test::TempDir;

namespace {

// Lines 1-9: time, material, particles, one barrier source; the [domain] table from line 10.
std::string scene_with(const std::string& domain) {
  return "[time]\nduration = 0.01\ndt = 1e-5\n"  // 1-3
         "[[material]]\nname = \"steel\"\n"      // 4-5
         "[[particles]]\nfile = \"p.csv\"\n"     // 6-7
         "[[barriers]]\nfile = \"w.csv\"\n" +    // 8-9
         domain +
         "\n";
}

// One sphere of radius 1 mm; a floor triangle pair over x, y in [0, 0.02].
void write_sources(const TempDir& d, double floor_max = 0.02) {
  d.write("p.csv", "x,y,z,radius\n0.01,0.01,0.002,0.001\n");
  const std::string m = std::to_string(floor_max);
  d.write("w.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n0,0,0," + m + ",0,0," + m + "," + m + ",0\n0,0,0," + m + "," + m +
                       ",0,0," + m + ",0\n");
}

const std::string kBox = "[domain]\nmin = [0, 0, -0.01]\nmax = [0.02, 0.02, 0.02]\n";  // lines 10-12

}  // namespace

TEST(PeriodicKeys, AxesAreRead) {
  TempDir d("mpdem_periodic");
  write_sources(d);
  const Scene s = load_scene(d.write("a.toml", scene_with(kBox + "periodic = [\"x\", \"y\"]")));
  EXPECT_TRUE(s.model.params.domain.periodic[0]);
  EXPECT_TRUE(s.model.params.domain.periodic[1]);
  EXPECT_FALSE(s.model.params.domain.periodic[2]);
  EXPECT_EQ(s.model.params.domain.periodic_line, 13u);
  const Scene none = load_scene(d.write("b.toml", scene_with(kBox + "periodic = []")));
  EXPECT_FALSE(none.model.params.domain.any_periodic());
  // A floor ending on the faces is allowed: nothing to report.
  EXPECT_TRUE(check_scene(s).empty());
  // The axes are part of the scene's fingerprint (a checkpoint of the walled scene is refused).
  EXPECT_NE(fingerprint_difference(fingerprint_scene(s), fingerprint_scene(none)), "");
}

TEST(PeriodicKeys, BadValuesNameFileLineKey) {
  struct Case {
    const char* what;
    std::string keys;
    std::vector<std::string> expect;
  };
  const std::vector<Case> cases = {
      {"unknown axis", "periodic = [\"x\", \"w\"]", {"expected axis names \"x\", \"y\" or \"z\"", "got \"w\""}},
      {"twice", "periodic = [\"z\", \"z\"]", {"axis \"z\" is listed twice"}},
      {"four axes", "periodic = [\"x\", \"y\", \"z\", \"x\"]", {"array of 0 to 3 strings", "4 elements"}},
      {"not an array", "periodic = \"x\"", {"array of 0 to 3 strings", "got a string"}},
      {"a number", "periodic = [1]", {"element 1 is"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_periodic");
    write_sources(d);
    const fs::path scene = d.write("scene.toml", scene_with(kBox + c.keys));
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    const std::string where = scene.string() + ":13: 'domain.periodic': ";
    EXPECT_EQ(msg.rfind(where, 0), 0u) << "expected prefix '" << where << "' in: " << msg;
    for (const std::string& e : c.expect) EXPECT_NE(msg.find(e), std::string::npos) << e << " in: " << msg;
  }
}

TEST(PeriodicKeys, BarrierCrossingAFaceIsAnError) {
  TempDir d("mpdem_periodic");
  write_sources(d, 0.03);  // the floor reaches 10 mm past x = 0.02 and y = 0.02
  const Scene s = load_scene(d.write("a.toml", scene_with(kBox + "periodic = [\"x\"]")));
  const SceneProblems r = check_scene(s);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].severity, Severity::Error);
  EXPECT_TRUE(r[0].stops_run);
  EXPECT_EQ(r[0].line, 8u);  // the [[barriers]] entry
  EXPECT_NE(r[0].message.find("2 barrier elements"), std::string::npos) << r[0].message;
  EXPECT_NE(r[0].message.find("cross a periodic face"), std::string::npos) << r[0].message;
  // Along a bounded, non-periodic axis the same floor is fine (particles just stay inside).
  const Scene z = load_scene(d.write("b.toml", scene_with(kBox + "periodic = [\"z\"]")));
  EXPECT_TRUE(check_scene(z).empty());
}

TEST(PeriodicKeys, PeriodShorterThanTheNeighbourReachIsAnError) {
  TempDir d("mpdem_periodic");
  write_sources(d);
  // 4 mm along x: less than twice 2 x 1 mm + 2 skins (0.2 mm each, the default).
  const Scene s = load_scene(d.write(
      "a.toml", scene_with("[domain]\nmin = [0.008, 0, -0.01]\nmax = [0.012, 0.02, 0.02]\nperiodic = [\"x\"]")));
  const SceneProblems r = check_scene(s);
  bool found = false;
  for (const SceneProblem& p : r)
    if (p.key == "domain.periodic") {
      found = true;
      EXPECT_EQ(p.line, 13u);
      EXPECT_NE(p.message.find("shorter than twice the neighbour search's reach"), std::string::npos) << p.message;
    }
  EXPECT_TRUE(found);
}
