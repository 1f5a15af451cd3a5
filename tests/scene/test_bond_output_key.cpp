// [output] bonds_every (src/scene/scene_reader.cpp, docs/scene.md): read into its field, 0 by
// default, and a negative or non-numeric value an InputError naming the file, the line and the key.
#include <gtest/gtest.h>

#include <string>

#include "model/scene.hpp"
#include "scene/scene_reader.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using mpdem::test::TempDir;

namespace {
const char* kHead = "[time]\nduration = 1.0\ndt = 1e-5\n";
}  // namespace

TEST(BondOutputKey, ReadWithItsDefault) {
  TempDir d("mpdem_bond_key");
  EXPECT_EQ(parse_scene_file(d.write("a.toml", std::string(kHead) + "[output]\nbonds_every = 0.25\n"))
                .model.params.output.bonds_every,
            0.25);
  EXPECT_EQ(parse_scene_file(d.write("b.toml", kHead)).model.params.output.bonds_every, 0.0);
}

TEST(BondOutputKey, BadValuesNameFileLineAndKey) {
  TempDir d("mpdem_bond_key");
  for (const char* value : {"-1e-3", "\"often\"", "nan"}) {
    const auto file = d.write("s.toml", std::string(kHead) + "[output]\nlog_every = 10\nbonds_every = " + value + "\n");
    const std::string e = test::error_of([&] { parse_scene_file(file); });
    EXPECT_NE(e.find("s.toml:6"), std::string::npos) << e;
    EXPECT_NE(e.find("output.bonds_every"), std::string::npos) << e;
  }
}
