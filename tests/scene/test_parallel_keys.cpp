// [parallel] (src/scene/scene_reader.cpp, docs/scene.md): the load-balance keys of a run on several
// ranks are read, default as documented, and bad values are an InputError naming file, line and key.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::error_of;
using mpdem::test::TempDir;

namespace {
const std::string kTime = "[time]\nduration = 0.01\ndt = 1e-5\n";  // lines 1-3; [parallel] on line 4
}

TEST(ParallelKeys, DefaultsAndValues) {
  TempDir d("mpdem_parallel");
  const ParallelParams def = parse_scene_file(d.write("a.toml", kTime)).model.params.parallel;
  EXPECT_EQ(def.balance_every, 1000);
  EXPECT_EQ(def.balance_threshold, 1.1);
  EXPECT_EQ(def.balance_cost, BalanceCost::Work);
  const ParallelParams set =
      parse_scene_file(
          d.write("b.toml",
                  kTime + "[parallel]\nbalance_every = 50\nbalance_threshold = 1.25\nbalance_cost = \"time\"\n"))
          .model.params.parallel;
  EXPECT_EQ(set.balance_every, 50);
  EXPECT_EQ(set.balance_threshold, 1.25);
  EXPECT_EQ(set.balance_cost, BalanceCost::Time);
  const ParallelParams off =
      parse_scene_file(d.write("c.toml", kTime + "[parallel]\nbalance_every = 0\n")).model.params.parallel;
  EXPECT_EQ(off.balance_every, 0);
}

TEST(ParallelKeys, BadValuesNameTheKey) {
  struct Case {
    std::string keys, key, expect;
  };
  const std::vector<Case> cases = {
      {"balance_every = -1", "balance_every", ">= 0"},
      {"balance_threshold = 0.9", "balance_threshold", "expected >= 1"},
      {"balance_cost = \"pairs\"", "balance_cost", "expected \"work\" or \"time\", got \"pairs\""},
      {"balance_evrey = 10", "balance_evrey", "unknown key"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.keys);
    TempDir d("mpdem_parallel");
    const fs::path scene = d.write("scene.toml", kTime + "[parallel]\n" + c.keys + "\n");
    const std::string msg = error_of([&] { parse_scene_file(scene); });
    const std::string where = scene.string() + ":5: 'parallel." + c.key + "': ";
    EXPECT_EQ(msg.rfind(where, 0), 0u) << "expected prefix '" << where << "' in: " << msg;
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.expect << " in: " << msg;
  }
}
