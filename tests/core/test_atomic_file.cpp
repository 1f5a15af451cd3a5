// Atomic file writes (core/atomic_file.hpp): the data goes to a temporary beside the target; a throwing
// body or a failed stream leaves the previous file intact, and no temporary is left behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "support/output_folder.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using namespace mpdem::test::output;  // OutputTest, slurp, split, lines_of, files_in

// Both durabilities (power_loss syncs the temporary before the rename, kill does not): the data
// goes to the temporary, the final name appears only complete, nothing is left behind.
TEST_F(OutputTest, AtomicWriteUsesTemporaryBesideTargetAndLeavesNoneBehind) {
  for (const Durability durability : {Durability::power_loss, Durability::kill}) {
    const fs::path file = dir / "a.txt";
    fs::remove(file);
    const fs::path expected_tmp = dir / ("a.txt.tmp-" + std::to_string(::getpid()));
    EXPECT_EQ(temporary_path_for(file), expected_tmp);
    write_file_atomically(
        file,
        [&](std::ostream& os) {
          // While the body runs the final name does not exist yet; the data goes to the temporary.
          EXPECT_FALSE(fs::exists(file));
          EXPECT_TRUE(fs::exists(expected_tmp));
          os << "new content\n";
        },
        durability);
    EXPECT_EQ(slurp(file), "new content\n");
    EXPECT_EQ(files_in(dir), std::vector<fs::path>{"a.txt"});
  }
}

TEST_F(OutputTest, ThrowingBodyLeavesPreviousFileIntact) {
  const fs::path file = dir / "a.txt";
  write_file_atomically(file, [](std::ostream& os) { os << "old complete file\n"; });
  struct BodyError {};
  EXPECT_THROW(write_file_atomically(file,
                                     [](std::ostream& os) {
                                       os << std::string(100000, 'x');  // more than one buffer
                                       throw BodyError{};
                                     }),
               BodyError);
  EXPECT_EQ(slurp(file), "old complete file\n");
  EXPECT_EQ(files_in(dir), std::vector<fs::path>{"a.txt"});
}

TEST_F(OutputTest, FailedStreamThrowsNamingPathAndKeepsPreviousFile) {
  const fs::path file = dir / "a.txt";
  write_file_atomically(file, [](std::ostream& os) { os << "old\n"; });
  try {
    write_file_atomically(file, [](std::ostream& os) {
      os << "half";
      os.setstate(std::ios::badbit);  // what a full disk does to the stream
    });
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(file), "old\n");
  EXPECT_EQ(files_in(dir), std::vector<fs::path>{"a.txt"});

  const fs::path unreachable = dir / "no_such_folder" / "b.txt";
  try {
    write_file_atomically(unreachable, [](std::ostream& os) { os << "x"; });
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(unreachable.string()), std::string::npos) << e.what();
  }
}
