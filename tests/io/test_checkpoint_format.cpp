// The checkpoint container (io/checkpoint_format.hpp) and its CRC-32 (core/crc32.hpp): sections
// read back as written; every kind of damage is refused with a message that names it.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "io/checkpoint_format.hpp"
#include "core/crc32.hpp"

using namespace mpdem;

namespace {

// The standard check value of CRC-32 (IEEE): "123456789" -> 0xCBF43926; and continuation.
TEST(Crc32, StandardCheckValueAndContinuation) {
  const std::string s = "123456789";
  EXPECT_EQ(crc32(s.data(), s.size()), 0xCBF43926u);
  EXPECT_EQ(crc32(s.data() + 4, 5, crc32(s.data(), 4)), 0xCBF43926u);
  EXPECT_EQ(crc32(nullptr, 0), 0u);
}

std::vector<char> sample() {
  CheckpointWriter w;
  w.section("run", [](BinaryWriter& b) {
    b.value(1.5);
    b.value<std::uint64_t>(7);
  });
  w.section("particles/x", [](BinaryWriter& b) { b.vector(std::vector<double>{1.0, 2.0, 3.0}); });
  return w.bytes();
}

std::string refusal(const std::vector<char>& bytes) {
  try {
    CheckpointReader r(bytes.data(), bytes.size());
    r.open("run");
    r.open("particles/x");
    r.finish();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointFormat, SectionsReadBackAsWritten) {
  const std::vector<char> bytes = sample();
  CheckpointReader r(bytes.data(), bytes.size());
  BinaryReader run = r.open("run");
  EXPECT_EQ(run.value<double>(), 1.5);
  EXPECT_EQ(run.value<std::uint64_t>(), 7u);
  r.done("run", run);
  BinaryReader x = r.open("particles/x");
  EXPECT_EQ(x.vector<double>(), (std::vector<double>{1.0, 2.0, 3.0}));
  r.done("particles/x", x);
  r.finish();
  EXPECT_THROW(r.open("particles/v"), std::runtime_error);
}

// One flipped bit anywhere, a file cut short by one byte or more, or a byte appended: refused.
TEST(CheckpointFormat, EveryFlippedBitTruncationAndTrailingByteIsRefused) {
  const std::vector<char> good = sample();
  ASSERT_EQ(refusal(good), "");
  for (std::size_t i = 0; i < good.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::vector<char> bad = good;
      bad[i] = static_cast<char>(bad[i] ^ (1 << bit));
      EXPECT_NE(refusal(bad), "") << "byte " << i << " bit " << bit;
    }
  for (std::size_t n = 0; n < good.size(); ++n)
    EXPECT_NE(refusal(std::vector<char>(good.begin(), good.begin() + static_cast<long>(n))), "") << n;
  std::vector<char> longer = good;
  longer.push_back('\0');
  EXPECT_NE(refusal(longer), "");
}

TEST(CheckpointFormat, MessagesNameTheProblem) {
  std::vector<char> bad = sample();
  bad[bad.size() - 8] ^= 1;  // inside the particles/x payload
  EXPECT_NE(refusal(bad).find("section 'particles/x' is damaged"), std::string::npos) << refusal(bad);
  std::vector<char> old = {'M', 'P', 'D', 'E', 'M', 'C', 'K', '2', 0, 0, 0, 0};
  const std::string reads = "this mpdem reads format " + std::to_string(kCheckpointFormat);
  EXPECT_NE(refusal(old).find("it has checkpoint format 2, " + reads), std::string::npos);
  std::vector<char> newer = sample();
  newer[8] = static_cast<char>(kCheckpointFormat + 1);
  EXPECT_NE(refusal(newer).find("it has checkpoint format " + std::to_string(kCheckpointFormat + 1) + ", " + reads),
            std::string::npos);
  CheckpointWriter w;
  w.section("run", [](BinaryWriter& b) { b.value(1.0); });
  w.section("future", [](BinaryWriter& b) { b.value(1.0); });
  const std::vector<char> extra = w.bytes();
  CheckpointReader r(extra.data(), extra.size());
  r.open("run");
  try {
    r.finish();
    ADD_FAILURE() << "an unknown section was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("section 'future' is not known"), std::string::npos);
  }
}

}  // namespace
