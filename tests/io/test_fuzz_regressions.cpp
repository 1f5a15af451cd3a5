// Regression tests for the findings of the libFuzzer campaign (docs/fuzzing.md, fuzz/). Each
// finding's input is embedded byte for byte; the reader must reject it with an InputError (the
// contract for bad input) - not crash, hang, or throw anything else - and the message must name
// the file, so the CLI can report it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "io/barrier_csv.hpp"
#include "core/binary_stream.hpp"
#include "core/crc32.hpp"
#include "core/input_error.hpp"
#include "io/particle_csv_reader.hpp"
#include "io/stl_reader.hpp"
#include "model/scene.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::error_of;
using mpdem::test::expect_contains;

namespace {


// Runs f; passes when it throws an InputError whose message names `file`.
template <class F>
void expect_input_error(F&& f, const fs::path& file, const std::string& what) {
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos) << what << ": " << e.what();
    return;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": expected an InputError, got another exception: " << e.what();
    return;
  }
  ADD_FAILURE() << what << ": expected an InputError, nothing was thrown";
}

// UTF-8 encoding of a code point below U+10000.
std::string utf8(char32_t c) {
  std::string s;
  if (c < 0x80) {
    s += static_cast<char>(c);
  } else if (c < 0x800) {
    s += static_cast<char>(0xC0 | (c >> 6));
    s += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    s += static_cast<char>(0xE0 | (c >> 12));
    s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (c & 0x3F));
  }
  return s;
}

}  // namespace

// Finding 1 (fuzz_scene): a non-ASCII letter inside a bare key ("dura\u024Fion") drove toml++
// 3.3's is_non_ascii_horizontal_whitespace() into TOML_UNREACHABLE (a UBSan report in the
// header-only build; upstream marzer/tomlplusplus #190/#295). The shipped build links the
// system's compiled toml++; there it must come out as a TOML syntax error.
TEST(FuzzRegressions, SceneNonAsciiInBareKeyIsASyntaxError) {
  TempDir d("mpdem_fuzzreg");
  const std::string input = "[time]\ndura\xC9\x8Fion = 0\n dt =\n";
  ASSERT_EQ(input.size(), 27u);  // no NUL inside: every byte of the input is in the string
  const fs::path f = d.write("scene.toml", input);
  expect_input_error([&] { (void)parse_scene_file(f); }, f, "U+024F in a bare key");
}

// The same finding, swept over every code point whose lookup reaches the faulty switch
// default: U+00A1..U+0499 (child index 0) and U+F9F6..U+FEFE (index 63), each placed right after a
// bare key, where toml++ asks whether it is whitespace. None is valid TOML there.
TEST(FuzzRegressions, SceneNonAsciiAfterBareKeySweep) {
  TempDir d("mpdem_fuzzreg");
  int checked = 0;
  for (char32_t c = 0xA1; c <= 0xFEFE; ++c) {
    if (c > 0x499 && c < 0xF9F6) c = 0xF9F6;
    const fs::path f = d.write("scene.toml", "[time]\nduration" + utf8(c) + " = 1\ndt = 0.1\n");
    try {
      (void)parse_scene_file(f);
      ADD_FAILURE() << "U+" << std::hex << static_cast<std::uint32_t>(c) << " after a bare key was accepted";
    } catch (const InputError&) {
      ++checked;
    }
  }
  EXPECT_EQ(checked, (0x499 - 0xA1 + 1) + (0xFEFE - 0xF9F6 + 1));
}

namespace {

Model one_material() {
  Model m;
  m.materials.resize(1);
  m.materials[0].name = "glass";
  return m;
}

}  // namespace

// Finding 2 (code review while fuzzing, confirmed by fuzz_particle_csv's UBSan build): the id
// INT64_MAX made "next free id = id + 1" a signed overflow. Such an id is now rejected, naming the
// line and the `id` column; the largest accepted id is INT64_MAX - 1.
TEST(FuzzRegressions, ParticleIdAtInt64MaxIsRejected) {
  TempDir d("mpdem_fuzzreg");
  Model model = one_material();
  const fs::path f = d.write("p.csv", "id,x,y,z,radius\n9223372036854775807,0,0,0,0.01\n");
  Particles out;
  expect_input_error([&] { read_particle_csv(f, model, 0, out); }, f, "particle id INT64_MAX");
  try {
    read_particle_csv(f, model, 0, out);
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.key(), "id");
  }
}

// A row without id after id INT64_MAX - 1 would be given INT64_MAX: rejected the same way.
TEST(FuzzRegressions, ParticleNextFreeIdPastInt64MaxIsRejected) {
  TempDir d("mpdem_fuzzreg");
  Model model = one_material();
  const fs::path f = d.write("p.csv", "id,x,y,z,radius\n9223372036854775806,0,0,0,0.01\n,1,0,0,0.01\n");
  Particles out;
  expect_input_error([&] { read_particle_csv(f, model, 0, out); }, f, "implicit id INT64_MAX");
  ASSERT_EQ(out.size(), 1u);  // the first row (id INT64_MAX - 1) is valid and was read
  EXPECT_EQ(out.id[0], 9223372036854775806);
}

// Finding 2, barrier side: same overflow in read_barrier_csv.
TEST(FuzzRegressions, BarrierIdAtInt64MaxIsRejected) {
  TempDir d("mpdem_fuzzreg");
  Model model = one_material();
  BarrierSource src;
  const fs::path f = d.write("b.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n9223372036854775807,0,0,0,1,0,0,0,1,0\n");
  Barriers out;
  expect_input_error([&] { read_barrier_csv(f, src, model, out); }, f, "barrier id INT64_MAX");
  const fs::path g = d.write(
      "b2.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n9223372036854775806,0,0,0,1,0,0,0,1,0\n,0,0,0,1,0,0,0,1,0\n");
  Barriers out2;
  expect_input_error([&] { read_barrier_csv(g, src, model, out2); }, g, "implicit barrier id INT64_MAX");
}

// Finding 3 (code review while fuzzing): finite but huge vertices made the barrier's area
// overflow to infinity; Barriers::add accepted it with a NaN normal. The reader now rejects the
// row (|edge| ~ 1e200 m: cross product ~ 1e400 > DBL_MAX ~ 1.8e308).
TEST(FuzzRegressions, BarrierWithOverflowingAreaIsRejected) {
  TempDir d("mpdem_fuzzreg");
  Model model = one_material();
  BarrierSource src;
  const fs::path f = d.write("b.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n0,0,0,1e200,0,0,0,1e200,0\n");
  Barriers out;
  expect_input_error([&] { read_barrier_csv(f, src, model, out); }, f, "overflowing area");
  EXPECT_EQ(out.size(), 0u);
}

// Finding 5 (fuzz_checkpoint, UBSan "load of value 81, which is not a valid value for type
// 'bool'" at core/binary_stream.hpp): BinaryReader::value<bool>() copied any byte into a bool. The
// "run" section ends with the flag energy_checked and "run_record" with started; a checkpoint
// with another byte there (its checksum recomputed) was undefined behaviour. A flag is now read
// as a byte and anything but 0 or 1 refused.
namespace {

// Two spheres at rest on nothing, a few steps: a real checkpoint of the running format.
std::string checkpoint_bytes(const fs::path& file) {
  Scene s = test::make_scene(1e-5, 1.0);
  test::add_particle(s, 1, 0.01, {0, 0, 0});
  test::add_particle(s, 2, 0.01, {0.0199, 0, 0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 3; ++k) sim.advance(1e-5);
  sim.write_checkpoint(file);
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Sets the payload byte `from_end` bytes before the last of `section` to `byte` and recomputes its CRC-32 (the framing
// of io/checkpoint_format.hpp: u16 name length, name, u64 payload length, payload, u32 CRC).
bool set_last_byte(std::string& b, const std::string& section, char byte, std::size_t from_end = 0) {
  std::size_t at = 12;  // magic and version
  while (at + 2 <= b.size()) {
    std::uint16_t name_size = 0;
    std::uint64_t payload_size = 0;
    std::memcpy(&name_size, b.data() + at, 2);
    const std::string name = b.substr(at + 2, name_size);
    std::memcpy(&payload_size, b.data() + at + 2 + name_size, 8);
    const std::size_t payload = at + 2 + name_size + 8;
    if (name == section && payload_size > from_end) {
      b[payload + payload_size - 1 - from_end] = byte;
      const std::uint32_t crc = crc32(b.data() + payload, payload_size, crc32(name.data(), name.size()));
      std::memcpy(b.data() + payload + payload_size, &crc, 4);
      return true;
    }
    at = payload + payload_size + 4;
  }
  return false;
}

}  // namespace

TEST(FuzzRegressions, BinaryReaderRefusesAFlagThatIsNeitherZeroNorOne) {
  for (const char c : {'\0', '\1', 'Q', '\xff'}) {
    BinaryReader r(&c, 1);
    if (c == '\0' || c == '\1') {
      EXPECT_EQ(r.value<bool>(), c == '\1');
      EXPECT_TRUE(r.at_end());
    } else {
      EXPECT_THROW(r.value<bool>(), std::runtime_error) << int(static_cast<unsigned char>(c));
    }
  }
}

TEST(FuzzRegressions, CheckpointWithAFlagByteOf81IsRejected) {
  TempDir d("mpdem_fuzzreg");
  const std::string good = checkpoint_bytes(d.path / "good.bin");
  for (const std::string section : {"run", "run_record"}) {
    std::string bad = good;
    ASSERT_TRUE(set_last_byte(bad, section, 81)) << section;
    const fs::path f = d.write(section + ".bin", bad);
    Scene s = test::make_scene(1e-5, 1.0);
    test::add_particle(s, 1, 0.01, {0, 0, 0});
    test::add_particle(s, 2, 0.01, {0.0199, 0, 0});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    expect_input_error([&] { sim.resume_from(f); }, f, "flag byte 81 in section " + section);
  }
  // The same bytes with the flag 1 resume (the patch itself is sound).
  std::string one = good;
  ASSERT_TRUE(set_last_byte(one, "run_record", 1));
  const fs::path f = d.write("one.bin", one);
  Scene s = test::make_scene(1e-5, 1.0);
  test::add_particle(s, 1, 0.01, {0, 0, 0});
  test::add_particle(s, 2, 0.01, {0.0199, 0, 0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  EXPECT_NO_THROW(sim.resume_from(f));
}

// Finding 4 (fuzz_checkpoint): resume_from took the restored particle values as they came; a
// material index out of range was then read out of bounds at the first step (ASan
// heap-buffer-overflow), a negative radius or a non-finite position left as an internal
// std::logic_error (exit 1). Each is now refused as bad input naming the array and the particle.
TEST(FuzzRegressions, CheckpointWithImpossibleParticleValuesIsRejected) {
  TempDir d("mpdem_fuzzreg");
  const std::string good = checkpoint_bytes(d.path / "good.bin");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::string nan_bytes(8, '\0');
  std::memcpy(nan_bytes.data(), &nan, 8);
  struct Case {
    std::string section, last_bytes, expected;
  };
  // The last bytes of a section are its last particle's value (the most significant byte of an
  // int32 material index, the sign and exponent of a double radius; a whole NaN z coordinate).
  const std::vector<Case> cases = {{"particles/material", "\x7f", "'particles/material' is not an index"},
                                   {"particles/radius", "\xbf", "'particles/radius' is not finite and > 0"},
                                   {"particles/x", nan_bytes, "'particles/x' is not finite"},
                                   {"particles/force", nan_bytes, "'particles/force' is not finite"}};
  for (const Case& c : cases) {
    std::string bad = good;
    for (std::size_t k = 0; k < c.last_bytes.size(); ++k) {
      ASSERT_TRUE(set_last_byte(bad, c.section, c.last_bytes[c.last_bytes.size() - 1 - k], k)) << c.section;
    }
    const fs::path f = d.write("bad.bin", bad);
    Scene s = test::make_scene(1e-5, 1.0);
    test::add_particle(s, 1, 0.01, {0, 0, 0});
    test::add_particle(s, 2, 0.01, {0.0199, 0, 0});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    expect_input_error([&] { sim.resume_from(f); }, f, c.section);
    try {
      sim.resume_from(f);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("particle id "), std::string::npos) << e.what();
    }
  }
}
