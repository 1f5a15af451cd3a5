// A folder given where a file is expected (issue 16) was reported as "does not exist": every
// reader now says "is a directory", with the scene's line and key where a scene names the path.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/csv_table.hpp"
#include "core/input_error.hpp"
#include "io/stl_reader.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::error_of;
using mpdem::test::expect_contains;

TEST(DirectoryInputs, SceneKeysNamingAFolderSayItIsADirectory) {
  struct Case {
    std::string entry;  // from line 6 on
    std::size_t line;
    std::string key;
  };
  const std::vector<Case> cases = {
      {"[[particles]]\nfile = \"beads\"\n", 7, "particles.file"},
      {"[[barriers]]\nfile = \"beads\"\n", 7, "barriers.file"},
      {"[[barriers]]\nstl = \"beads\"\n", 7, "barriers.stl"},
      {"[[particles]]\ngenerate = { region = \"mesh\", mesh = \"beads\", count = 1, radius = 0.01 }\n", 7,
       "particles.generate.mesh"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.key);
    TempDir d("mpdem_dirs");
    fs::create_directories(d.path / "beads");
    const fs::path scene = d.write("scene.toml",
                                   "[time]\nduration = 1.0\ndt = 1e-5\n[[material]]\nname = \"m\"\n" + c.entry);
    try {
      parse_scene_file(scene);
      ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), scene.string());
      EXPECT_EQ(e.line(), c.line);
      EXPECT_EQ(e.key(), c.key);
      expect_contains(e.what(), {"file '" + (d.path / "beads").string() + "' is a directory, expected a file"});
      EXPECT_EQ(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
  }
}

TEST(DirectoryInputs, ReadersCalledOnAFolderSayItIsADirectory) {
  TempDir d("mpdem_dirs");
  fs::create_directories(d.path / "sub");
  expect_contains(error_of([&] { parse_scene_file(d.path / "sub"); }), {"is a directory, expected a file"});
  expect_contains(error_of([&] { CsvTable::read(d.path / "sub"); }), {"is a directory, expected a file"});
  expect_contains(error_of([&] { read_stl(d.path / "sub"); }), {"STL file is a directory, expected a file"});
  // A missing file is still told so.
  expect_contains(error_of([&] { CsvTable::read(d.path / "none.csv"); }), {"none.csv' does not exist"});
}
