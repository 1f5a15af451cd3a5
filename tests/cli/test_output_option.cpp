// Which folder the outputs go to (docs/output.md): `--output DIR` relative to the working folder
// mpdem is started in, `[output] dir` relative to the scene file's folder.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

TEST(OutputOption, RelativeToTheWorkingFolderAndTheSceneFolder) {
  const fs::path d = fresh_dir("output_option");
  fs::create_directories(d / "case");
  fs::create_directories(d / "work");
  write_text(d / "case" / "p.csv", "id,x,y,z,radius\n1,0,0,0.01,0.001\n");
  write_text(d / "case" / "scene.toml", "[time]\nduration = 1e-4\ndt = 1e-5\nintegrator = "
                                        "\"trapezoidal\"\n\n[[material]]\nname = \"glass\"\n\n[[particles]]\nfile = "
                                        "\"p.csv\"\n\n[output]\ndir = \"from_scene\"\n");
  const CommandResult option = run_mpdem("run ../case/scene.toml --quiet --output from_option", d / "work");
  EXPECT_EQ(option.status, 0) << option.err;
  EXPECT_TRUE(fs::exists(d / "work" / "from_option" / "log.csv"));
  EXPECT_FALSE(fs::exists(d / "case" / "from_option"));
  const CommandResult key = run_mpdem("run ../case/scene.toml --quiet", d / "work");
  EXPECT_EQ(key.status, 0) << key.err;
  EXPECT_TRUE(fs::exists(d / "case" / "from_scene" / "log.csv"));
  EXPECT_FALSE(fs::exists(d / "work" / "from_scene"));
  fs::remove_all(d);
}
