// [[barriers]] motion.rotation (src/scene/scene_reader.cpp): both forms of the rate are read into
// the elements' law, and every bad value is an InputError naming file, line and key (exit 2 from
// the command line).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::error_of;
using mpdem::test::expect_contains;
using mpdem::test::TempDir;

namespace {

// A scene whose only barrier source ends with `motion` (line 10 and on).
std::string scene_with(const std::string& motion) {
  return "[time]\nduration = 0.01\ndt = 1e-5\n"  // 1-3
         "[[material]]\nname = \"steel\"\n"      // 4-5
         "[[particles]]\nfile = \"p.csv\"\n"     // 6-7
         "[[barriers]]\nfile = \"w.csv\"\n" +    // 8-9
         motion +
         "\n";
}

void write_sources(const TempDir& d) {
  d.write("p.csv", "x,y,z,radius\n0,0,0.5,0.01\n");
  d.write("w.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n1,0,0,2,0,0,1,1,0\n");
}

}  // namespace

TEST(RotationKeys, BothRateFormsAreRead) {
  TempDir d("mpdem_rotation");
  write_sources(d);
  {
    const fs::path f = d.write("a.toml", scene_with("motion = { a = [0, 0, 1], rotation = { axis = [0, 2, 0], origin = "
                                                    "[1, 2, 3], omega = 2.0 } }"));
    const Scene s = load_scene(f);
    ASSERT_TRUE(s.barrier_sources[0].motion.rotation.has_value());
    const RotationLaw& r = *s.barrier_sources[0].motion.rotation;
    EXPECT_EQ(r.axis, (Vec3{0, 1, 0}));  // normalised
    EXPECT_EQ(r.origin, (Vec3{1, 2, 3}));
    EXPECT_EQ(r.omega, 2.0);
    EXPECT_TRUE(r.omega_table.empty());
    ASSERT_TRUE(s.barriers.rotating());
    EXPECT_EQ(s.barriers.rotation_of[0], 0);
    EXPECT_EQ(s.barriers.motion[0].a, (Vec3{0, 0, 1}));
  }
  {
    const fs::path f = d.write("b.toml", scene_with("[barriers.motion.rotation]\naxis = [0, 0, 1]\n"
                                                    "omega_table = [[0.0, 0.0], [0.5, 6.0]]"));
    const Scene s = load_scene(f);
    const RotationLaw& r = *s.barrier_sources[0].motion.rotation;
    EXPECT_EQ(r.origin, (Vec3{}));
    ASSERT_EQ(r.omega_table.size(), 2u);
    EXPECT_EQ(r.omega_table[1][0], 0.5);
    EXPECT_EQ(r.omega_table[1][1], 6.0);
    EXPECT_NEAR(r.angle(1.0), 1.5 + 6.0 * 0.5, 1e-15);
  }
}

TEST(RotationKeys, BadValuesNameFileLineKey) {
  struct Case {
    const char* what;
    std::string motion;  // from line 10
    int line;
    std::string key;
    std::vector<std::string> expect;
  };
  const std::string pre = "motion = { rotation = { ";
  const std::vector<Case> cases = {
      {"zero axis",
       pre + "axis = [0, 0, 0], omega = 1 } }",
       10,
       "barriers.motion.rotation.axis",
       {"expected a non-zero axis"}},
      {"missing axis", pre + "omega = 1 } }", 10, "barriers.motion.rotation.axis", {"missing required key"}},
      {"non-finite omega",
       pre + "axis = [0, 0, 1], omega = inf } }",
       10,
       "barriers.motion.rotation.omega",
       {"expected a finite number"}},
      {"non-finite axis",
       pre + "axis = [0, nan, 1], omega = 1 } }",
       10,
       "barriers.motion.rotation.axis",
       {"element 2 is not finite"}},
      {"both rates",
       pre + "axis = [0, 0, 1], omega = 1, omega_table = [[0, 1]] } }",
       10,
       "barriers.motion.rotation.omega_table",
       {"give either omega or omega_table, not both"}},
      {"no rate",
       pre + "axis = [0, 0, 1] } }",
       10,
       "barriers.motion.rotation.omega",
       {"missing required key (give omega or omega_table)"}},
      {"unsorted table",
       "[barriers.motion.rotation]\naxis = [0, 0, 1]\nomega_table = [[0, 0], [0.5, 1], [0.5, 2]]",
       12,
       "barriers.motion.rotation.omega_table",
       {"strictly ascending times", "row 3"}},
      {"row of three",
       "[barriers.motion.rotation]\naxis = [0, 0, 1]\nomega_table = [\n  [0, 0],\n  [0.5, 1, 2],\n]",
       14,
       "barriers.motion.rotation.omega_table",
       {"row 2 has 3 elements"}},
      {"non-finite row",
       "[barriers.motion.rotation]\naxis = [0, 0, 1]\nomega_table = [[0, 0], [1, -inf]]",
       12,
       "barriers.motion.rotation.omega_table",
       {"row 2 element 2 is not finite"}},
      {"empty table",
       pre + "axis = [0, 0, 1], omega_table = [] } }",
       10,
       "barriers.motion.rotation.omega_table",
       {"got an empty array"}},
      {"not a table", "motion = { rotation = 2.0 }", 10, "barriers.motion.rotation", {"expected a table"}},
      {"unknown key",
       pre + "axis = [0, 0, 1], omega = 1, omgea = 2 } }",
       10,
       "barriers.motion.rotation.omgea",
       {"unknown key", "did you mean"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_rotation");
    write_sources(d);
    const fs::path scene = d.write("scene.toml", scene_with(c.motion));
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    const std::string where = scene.string() + ":" + std::to_string(c.line) + ": '" + c.key + "': ";
    EXPECT_EQ(msg.rfind(where, 0), 0u) << "expected prefix '" << where << "' in: " << msg;
    expect_contains(msg, c.expect);
  }
}

// The command line refuses such a scene with exit status 2, before writing anything.
TEST(RotationKeys, CommandExitsTwo) {
  TempDir d("mpdem_rotation");
  write_sources(d);
  d.write("scene.toml", scene_with("motion = { rotation = { axis = [0, 0, 0], omega = 1 } }"));
  const mpdem::test::CommandResult r = mpdem::test::run_mpdem("run scene.toml", d.path);
  EXPECT_EQ(r.status, 2) << r.err;
  expect_contains(r.err, {"scene.toml:10: 'barriers.motion.rotation.axis'"});
  EXPECT_FALSE(fs::exists(d.path / "output"));
}
