// [[barriers]] active and motion_from (src/scene/scene_reader.cpp): both forms of the window and the
// law's time origin are read into every element's law, every bad value is an InputError naming
// file, line and key (exit 2 from the command line), and the scene fingerprint changes only when
// they differ from the defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "io/scene_fingerprint.hpp"
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

// A scene whose only barrier source ends with `keys` (line 10 and on).
std::string scene_with(const std::string& keys) {
  return "[time]\nduration = 0.01\ndt = 1e-5\n"  // 1-3
         "[[material]]\nname = \"steel\"\n"      // 4-5
         "[[particles]]\nfile = \"p.csv\"\n"     // 6-7
         "[[barriers]]\nfile = \"w.csv\"\n" +    // 8-9
         keys +
         "\n";
}

void write_sources(const TempDir& d) {
  d.write("p.csv", "x,y,z,radius\n0,0,0.5,0.01\n");
  d.write("w.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n1,0,0,2,0,0,1,1,0\n1,0,0,1,1,0,0,1,0\n");
}

std::vector<std::uint64_t> barrier_items(const Scene& s) {
  for (const FingerprintPart& p : fingerprint_scene(s).parts)
    if (p.name == "barriers") return p.items;
  return {};
}

}  // namespace

TEST(ActivityKeys, WindowAndOriginAreRead) {
  TempDir d("mpdem_activity");
  write_sources(d);
  {
    const Scene s = load_scene(d.write("a.toml", scene_with("active = [0, 0.5]")));
    ASSERT_EQ(s.barriers.size(), 2u);
    for (std::size_t e = 0; e < 2; ++e) {
      EXPECT_EQ(s.barriers.motion[e].active_from, 0.0);
      EXPECT_EQ(s.barriers.motion[e].active_until, 0.5);
      EXPECT_EQ(s.barriers.motion[e].since, 0.0);  // motion_from defaults to "zero"
      EXPECT_EQ(s.barriers.active[e], 1);          // on at t = 0
    }
    EXPECT_TRUE(s.barriers.timed());
  }
  {
    // One element: on from t_start for ever; "start" puts the law's (and the rotation's) origin there.
    const Scene s = load_scene(d.write("b.toml", scene_with("active = [0.25]\nmotion_from = \"start\"\n"
                                                            "motion = { a = [0, 0, 1], rotation = { axis = [0, "
                                                            "0, 1], omega = 2.0 } }")));
    const MotionLaw& m = s.barriers.motion[0];
    EXPECT_EQ(m.active_from, 0.25);
    EXPECT_EQ(m.active_until, HUGE_VAL);
    EXPECT_EQ(m.since, 0.25);
    ASSERT_TRUE(m.rotation.has_value());
    EXPECT_EQ(m.rotation->since, 0.25);
    EXPECT_EQ(s.barriers.active[0], 0);  // off at t = 0
  }
  {
    // "zero" is the default, a window from 0 for ever is none.
    const Scene s = load_scene(d.write("c.toml", scene_with("active = [0]\nmotion_from = \"zero\"")));
    EXPECT_FALSE(s.barriers.timed());
    EXPECT_EQ(s.barriers.motion[0].since, 0.0);
  }
}

// Existing checkpoints keep resuming: the defaults leave the barriers' fingerprint as it was; a
// window or an origin changes the motion law item.
TEST(ActivityKeys, FingerprintChangesOnlyOffTheDefaults) {
  TempDir d("mpdem_activity");
  write_sources(d);
  const auto items = [&](const std::string& keys) {
    return barrier_items(load_scene(d.write("f.toml", scene_with("motion = { a = [0, 0, 1] }\n" + keys))));
  };
  const std::vector<std::uint64_t> plain = items("");
  ASSERT_FALSE(plain.empty());
  EXPECT_EQ(items("active = [0]\nmotion_from = \"zero\""), plain);
  for (const std::string keys :
       {"active = [0, 0.5]", "active = [0.1]", "active = [0.1, 1e9]", "active = [0.1]\nmotion_from = \"start\""}) {
    SCOPED_TRACE(keys);
    const std::vector<std::uint64_t> changed = items(keys);
    ASSERT_EQ(changed.size(), plain.size());
    EXPECT_NE(changed, plain);
    EXPECT_EQ(changed[0], plain[0]);  // id or group
    EXPECT_EQ(changed[1], plain[1]);  // rest vertices
    EXPECT_NE(changed[2], plain[2]);  // the motion law item holds the window
  }
  EXPECT_NE(items("active = [0.1]"), items("active = [0.1]\nmotion_from = \"start\""));
}

TEST(ActivityKeys, BadValuesNameFileLineKey) {
  struct Case {
    const char* what;
    std::string keys;  // from line 10
    int line;
    std::string key;
    std::vector<std::string> expect;
  };
  const std::vector<Case> cases = {
      {"negative start", "active = [-0.1, 1]", 10, "barriers.active", {"t_start >= 0", "t_start = -0.1"}},
      {"empty window", "active = [0.5, 0.5]", 10, "barriers.active", {"t_start < t_end", "t_end = 0.5"}},
      {"reversed window", "active = [0.5, 0.2]", 10, "barriers.active", {"t_start < t_end"}},
      {"three numbers", "active = [0, 1, 2]", 10, "barriers.active", {"array of 1 or 2 numbers", "3 elements"}},
      {"no numbers", "active = []", 10, "barriers.active", {"array of 1 or 2 numbers", "0 elements"}},
      {"not an array", "active = 0.5", 10, "barriers.active", {"array of 1 or 2 numbers", "got a float"}},
      {"infinite end", "active = [0, inf]", 10, "barriers.active", {"element 2 is not finite"}},
      {"nan start", "active = [nan]", 10, "barriers.active", {"element 1 is not finite"}},
      {"string element", "active = [0, \"1\"]", 10, "barriers.active", {"element 2 is a string"}},
      {"unknown origin",
       "active = [0.1]\nmotion_from = \"begin\"",
       11,
       "barriers.motion_from",
       {"expected \"zero\"", "\"start\"", "got \"begin\""}},
      {"origin not a string", "motion_from = 1", 10, "barriers.motion_from", {"expected a string"}},
      {"misspelt key", "actve = [0, 1]", 10, "barriers.actve", {"unknown key", "did you mean"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_activity");
    write_sources(d);
    const fs::path scene = d.write("scene.toml", scene_with(c.keys));
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    const std::string where = scene.string() + ":" + std::to_string(c.line) + ": '" + c.key + "': ";
    EXPECT_EQ(msg.rfind(where, 0), 0u) << "expected prefix '" << where << "' in: " << msg;
    expect_contains(msg, c.expect);
  }
}

// The command line refuses such a scene with exit status 2, before writing anything.
TEST(ActivityKeys, CommandExitsTwo) {
  TempDir d("mpdem_activity");
  write_sources(d);
  d.write("scene.toml", scene_with("active = [1, 0.5]"));
  const mpdem::test::CommandResult r = mpdem::test::run_mpdem("run scene.toml", d.path);
  EXPECT_EQ(r.status, 2) << r.err;
  expect_contains(r.err, {"scene.toml:10: 'barriers.active'"});
  EXPECT_FALSE(fs::exists(d.path / "output"));
}
