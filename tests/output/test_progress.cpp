// The progress line (output/progress.hpp): the liquid bridges and the bonds after the contacts only when given
// (a scene with cohesion, with [bonds]); a plain scene's line unchanged. Printed at every update here
// (plain_every 0, stderr not a terminal under ctest).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "output/progress.hpp"

using namespace mpdem;

TEST(Progress, BridgesOnlyWithCohesion) {
  if (isatty(fileno(stderr)) != 0) GTEST_SKIP() << "stderr is a terminal: the line is drawn in place";
  Progress p(1.0, 0.0, true);
  testing::internal::CaptureStderr();
  p.update(0.5, 10, 7, 20);
  p.update(0.6, 12, 7, 20, 0.0, 3);
  const std::string out = testing::internal::GetCapturedStderr();
  const std::size_t first = out.find('\n');
  ASSERT_NE(first, std::string::npos) << out;
  const std::string plain = out.substr(0, first), cohesive = out.substr(first + 1);
  EXPECT_NE(plain.find("  contacts 7  particles 20"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("bridges"), std::string::npos) << plain;
  EXPECT_NE(cohesive.find("  contacts 7  bridges 3  particles 20\n"), std::string::npos) << cohesive;
}

TEST(Progress, BondsOnlyWithBonds) {
  if (isatty(fileno(stderr)) != 0) GTEST_SKIP() << "stderr is a terminal: the line is drawn in place";
  Progress p(1.0, 0.0, true);
  testing::internal::CaptureStderr();
  p.update(0.5, 10, 7, 20);
  p.update(0.6, 12, 7, 20, 0.0, std::nullopt, std::array<std::uint64_t, 2>{40, 3});
  const std::string out = testing::internal::GetCapturedStderr();
  const std::size_t first = out.find('\n');
  ASSERT_NE(first, std::string::npos) << out;
  EXPECT_EQ(out.substr(0, first).find("bonds"), std::string::npos) << out;
  EXPECT_NE(out.substr(first + 1).find("  contacts 7  bonds 40 (3 broken)  particles 20\n"), std::string::npos) << out;
}
