// The compressed VTK layout (vtkZLibDataCompressor, UInt64 headers) of io/vtk_xml.hpp, decoded
// here with libdeflate's own zlib decompressor: every block is a zlib stream of at most 32 KiB,
// the header counts them and gives the partial last block's size.
#include <gtest/gtest.h>
#include <libdeflate.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <sstream>
#include <vector>

#include "io/vtk_xml.hpp"

using namespace mpdem;

namespace {

constexpr std::size_t kBlock = 32768;

std::uint64_t u64(const std::vector<std::byte>& b, std::size_t at) {
  std::uint64_t v;
  std::memcpy(&v, b.data() + at, sizeof v);
  return v;
}

// Decodes vtk_zlib_blocks' output and checks its header against the input size.
std::vector<std::byte> decode(const std::vector<std::byte>& packed, std::size_t expected_bytes) {
  const std::uint64_t blocks = u64(packed, 0);
  EXPECT_EQ(blocks, (expected_bytes + kBlock - 1) / kBlock);
  EXPECT_EQ(u64(packed, 8), kBlock);
  EXPECT_EQ(u64(packed, 16), expected_bytes % kBlock);
  std::size_t at = 8 * (3 + blocks);
  std::vector<std::byte> out;
  libdeflate_decompressor* d = libdeflate_alloc_decompressor();
  for (std::uint64_t k = 0; k < blocks; ++k) {
    const std::uint64_t size = u64(packed, 8 * (3 + k));
    std::vector<std::byte> block(kBlock);
    std::size_t got = 0;
    EXPECT_EQ(libdeflate_zlib_decompress(d, packed.data() + at, size, block.data(), block.size(), &got),
              LIBDEFLATE_SUCCESS);
    EXPECT_EQ(got, k + 1 < blocks ? kBlock : expected_bytes - k * kBlock);
    out.insert(out.end(), block.begin(), block.begin() + static_cast<std::ptrdiff_t>(got));
    at += size;
  }
  libdeflate_free_decompressor(d);
  EXPECT_EQ(at, packed.size());  // nothing after the last block
  return out;
}

std::vector<std::byte> bytes_of(const std::vector<double>& v) {
  std::vector<std::byte> b(v.size() * sizeof(double));
  std::memcpy(b.data(), v.data(), b.size());
  return b;
}

}  // namespace

TEST(VtkZlibBlocks, RandomDoublesRoundTripAcrossBlocks) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(20000);  // 160000 bytes: 5 blocks, the last partial
  for (double& x : v) x = u(rng);
  const auto raw = bytes_of(v);
  const auto packed = vtk_zlib_blocks(raw);
  EXPECT_EQ(decode(packed, raw.size()), raw);
}

TEST(VtkZlibBlocks, CompressibleDataShrinks) {
  std::vector<double> v(3 * kBlock / 8, 1.0);  // exactly 3 full blocks: partial size 0
  const auto raw = bytes_of(v);
  const auto packed = vtk_zlib_blocks(raw);
  EXPECT_EQ(decode(packed, raw.size()), raw);
  EXPECT_LT(packed.size(), raw.size() / 20);
}

TEST(VtkZlibBlocks, EmptyAndSmallArrays) {
  EXPECT_EQ(decode(vtk_zlib_blocks({}), 0).size(), 0u);
  const auto raw = bytes_of({1.5, -2.0, 3.25});
  EXPECT_EQ(decode(vtk_zlib_blocks(raw), raw.size()), raw);
}

TEST(VtkZlibBlocks, SameBytesForAnyThreadCount) {
  std::mt19937_64 rng(5);
  std::vector<double> v(100000);
  for (double& x : v) x = static_cast<double>(rng() % 1000) * 0.125;
  const auto raw = bytes_of(v);
  const auto one = vtk_zlib_blocks(raw);
#ifdef _OPENMP
  EXPECT_EQ(vtk_zlib_blocks(raw), one);  // the default team
#endif
  EXPECT_EQ(decode(one, raw.size()), raw);
}

// The appended layout: offsets in the tags point at UInt64 byte counts followed by the values.
TEST(VtkXmlDocument, BinaryOffsetsPointAtEachArray) {
  const std::vector<double> a{1.0, 2.0, 3.0};
  const std::vector<std::int32_t> b{7, 8};
  VtkXmlDocument d(VtkFormat::Binary, "UnstructuredGrid");
  d.array({"a", "Float64", 0}, std::span<const double>(a));
  d.array({"b", "Int32", 0}, std::span<const std::int32_t>(b));
  std::ostringstream os;
  d.write(os);
  const std::string f = os.str();
  const auto data = f.find('_', f.find("<AppendedData")) + 1;
  const auto offset_of = [&](const char* name) {
    const auto tag = f.find(std::string("Name=\"") + name + "\"");
    const auto at = f.find("offset=\"", tag) + 8;
    return std::stoull(f.substr(at, f.find('"', at) - at));
  };
  std::uint64_t count = 0;
  std::memcpy(&count, f.data() + data + offset_of("a"), 8);
  EXPECT_EQ(count, 24u);
  double second = 0.0;
  std::memcpy(&second, f.data() + data + offset_of("a") + 8 + 8, 8);
  EXPECT_EQ(second, 2.0);
  std::memcpy(&count, f.data() + data + offset_of("b"), 8);
  EXPECT_EQ(count, 8u);
  std::int32_t last = 0;
  std::memcpy(&last, f.data() + data + offset_of("b") + 8 + 4, 4);
  EXPECT_EQ(last, 8);
  EXPECT_EQ(f.substr(f.size() - 11), "</VTKFile>\n");
}

// The [output] format key's names map to the formats and back; any other name to none.
TEST(VtkXml, FormatNamesRoundTrip) {
  for (const VtkFormat f : {VtkFormat::Ascii, VtkFormat::Binary, VtkFormat::Compressed})
    EXPECT_EQ(vtk_format_from_name(vtk_format_name(f)), f);
  EXPECT_EQ(vtk_format_from_name("hdf5"), std::nullopt);
  EXPECT_EQ(vtk_format_from_name("Binary"), std::nullopt);
}
