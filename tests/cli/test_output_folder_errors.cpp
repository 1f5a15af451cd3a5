// Output folders that cannot be created or written into (issue 45 item 5): a path under a
// regular file, an empty regular file, a folder name longer than the file system allows and a
// read-only file system each get one clean message naming the folder and exit 2 before step 1,
// like an output folder that is a file already did; never a raw "filesystem error" (which main
// printed with exit 1).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

// A one-particle scene in a fresh folder that also holds a regular file `afile` and an empty one.
fs::path scene_dir(const std::string& name) {
  const fs::path d = fresh_dir(name);
  write_text(d / "p.csv", "id,x,y,z,radius\n1,0.05,0.05,0.05,0.001\n");
  write_text(d / "scene.toml",
             "[time]\nduration = 2e-6\ndt = 1e-6\n[[material]]\nname = \"glass\"\n[[particles]]\nfile = \"p.csv\"\n");
  write_text(d / "afile", "x\n");
  write_text(d / "emptyfile", "");
  return d;
}

void expect_clean_refusal(const CommandResult& r, const std::string& folder, const std::string& why) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("error: " + folder + ": " + why), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "one message only: " << r.err;
  EXPECT_EQ(r.err.find("filesystem error"), std::string::npos) << r.err;
}

}  // namespace

TEST(OutputFolderErrors, PathUnderARegularFile) {
  const fs::path d = scene_dir("out_under_file");
  expect_clean_refusal(run_mpdem("run scene.toml --quiet --output afile/out", d), "afile/out",
                       "cannot create the output folder (a part of the path is a file, not a folder)");
  // The scene's own [output] dir and the validation report folder alike.
  write_text(d / "scene.toml", "[time]\nduration = 2e-6\ndt = 1e-6\n[[material]]\nname = \"glass\"\n[[particles]]\n"
                               "file = \"p.csv\"\n[output]\ndir = \"afile/out\"\n");
  expect_clean_refusal(run_mpdem("run scene.toml --quiet", d), (d / "afile/out").string(),
                       "cannot create the output folder");
  expect_clean_refusal(run_mpdem("validate --quick -o afile/v", d), (d / "afile/v").string(),
                       "cannot create the output folder");
  fs::remove_all(d);
}

TEST(OutputFolderErrors, EmptyRegularFile) {
  const fs::path d = scene_dir("out_empty_file");
  expect_clean_refusal(run_mpdem("run scene.toml --quiet --output emptyfile", d), "emptyfile",
                       "the output folder is a file");
  fs::remove_all(d);
}

TEST(OutputFolderErrors, NameTooLong) {
  const fs::path d = scene_dir("out_long_name");
  const std::string name(300, 'b');
  expect_clean_refusal(run_mpdem("run scene.toml --quiet --output " + name, d), name,
                       "cannot create the output folder (File name too long)");
  fs::remove_all(d);
}

// A read-only file system, mounted in a private mount namespace (unshare); skipped where the
// machine allows no such namespace.
TEST(OutputFolderErrors, ReadOnlyFileSystem) {
  const fs::path d = scene_dir("out_read_only");
  fs::create_directories(d / "ro");
  const std::string mount = "unshare -rm sh -c 'mount -t tmpfs -o ro tmpfs ro && ";
  if (std::system(("cd '" + d.string() + "' && " + mount + "true' >/dev/null 2>&1").c_str()) != 0) {
    fs::remove_all(d);
    GTEST_SKIP() << "no private mount namespace (unshare -rm) here";
  }
  const auto run = [&](const std::string& args) {
    const std::string cmd = "cd '" + d.string() + "' && " + mount + "\"" + MPDEM_BINARY + "\" " + args +
                            "' >out.txt 2>err.txt </dev/null";
    const int raw = std::system(cmd.c_str());
    CommandResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.err = slurp(d / "err.txt");
    return r;
  };
  expect_clean_refusal(run("run scene.toml --quiet --output ro/out"), "ro/out",
                       "cannot create the output folder (the file system is read-only)");
  expect_clean_refusal(run("run scene.toml --quiet --output ro"), "ro",
                       "cannot write into the output folder (the file system is read-only)");
  fs::remove_all(d);
}
