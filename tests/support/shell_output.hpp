#pragma once
// The output (stdout and stderr) of a shell command that must succeed (a test failure otherwise):
// the independent readers of the output files (tests/read_vtu.py) are run through it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace mpdem::test {

inline std::string shell(const std::string& cmd) {
  FILE* pipe = ::popen((cmd + " 2>&1").c_str(), "r");
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  EXPECT_EQ(::pclose(pipe), 0) << cmd << "\n" << out;
  return out;
}

}  // namespace mpdem::test
