// CSV size limits (issue 16): a row of millions of fields took seconds and about 22 times the
// line's size in memory before it was refused. A line longer than CsvTable::kMaxLineLength is
// now refused without reading it whole, and splitting stops a few fields past the header's count
// (a header's past the columns the reader knows); the messages report the caps.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/csv_table.hpp"
#include "core/input_error.hpp"
#include "io/particle_csv_reader.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::error_of;
using mpdem::test::expect_contains;

namespace {

Model one_material() {
  Model m;
  m.materials.resize(1);
  m.materials[0].name = "glass";
  return m;
}

// "0,0,...,0" with n fields.
std::string zeros(std::size_t n) {
  std::string s;
  s.reserve(2 * n);
  for (std::size_t k = 0; k < n; ++k) s += k == 0 ? "0" : ",0";
  return s;
}

}  // namespace

// Two million fields (4 MB): refused at the line-length cap, which the message reports.
TEST(CsvLimits, RowOfMillionsOfFieldsIsRefusedAtTheLineCap) {
  TempDir d("mpdem_csvlim");
  const fs::path f = d.write("p.csv", "x,y,z,radius\n0,0,0,0.001\n" + zeros(2'000'000) + "\n0,0,1,0.001\n");
  Model m = one_material();
  Particles out;
  const std::string msg = error_of([&] { read_particle_csv(f, m, 0, out); });
  expect_contains(msg, {f.string() + ":3: line longer than the limit of 65536 characters"});
}

// Within the line cap, splitting stops at header + kFieldMargin fields: the message says "more
// than" that count, not the row's 30000.
TEST(CsvLimits, ManyFieldsStopAtTheFieldCap) {
  TempDir d("mpdem_csvlim");
  const fs::path f = d.write("p.csv", "x,y,z,radius\n" + zeros(30'000) + "\n");
  ASSERT_LT(zeros(30'000).size(), CsvTable::kMaxLineLength);
  const std::string msg = error_of([&] { CsvTable::read(f); });
  expect_contains(msg, {f.string() + ":2: expected 4 fields as in the header (line 1), got more than 12"});
  // A small miscount is still reported exactly.
  const fs::path g = d.write("q.csv", "x,y,z,radius\n0,0,0,0,0,0\n");
  expect_contains(error_of([&] { CsvTable::read(g); }), {"got 6"});
}

// A header cannot have more columns than the reader knows, plus the margin.
TEST(CsvLimits, HeaderIsCappedByTheKnownColumns) {
  TempDir d("mpdem_csvlim");
  std::string header;
  for (int c = 0; c < 1000; ++c) header += (c ? ",c" : "c") + std::to_string(c);
  const fs::path f = d.write("p.csv", header + "\n");
  Model m = one_material();
  Particles out;
  const std::string msg = error_of([&] { read_particle_csv(f, m, 0, out); });
  expect_contains(msg, {f.string() + ":1: more than 43 columns in the header; at most 35 columns are known"});
}

// The cap is on the line, inclusive: kMaxLineLength characters pass, one more does not; a long
// comment is skipped whatever its length; a last line without a newline is read.
TEST(CsvLimits, LineCapBoundaryAndLongComments) {
  TempDir d("mpdem_csvlim");
  const std::size_t cap = CsvTable::kMaxLineLength;
  const std::string row = "1" + std::string(cap - 1, ' ');  // trailing spaces are trimmed
  const CsvTable t = CsvTable::read(
      d.write("ok.csv", "# " + std::string(3 * cap, 'c') + "\na\n" + row + "\n" + std::string(cap, ' ') + "\n2"));
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.header_line(), 2u);
  EXPECT_EQ(t.rows()[0].line, 3u);
  EXPECT_EQ(t.number(t.rows()[0], 0), 1.0);
  EXPECT_EQ(t.number(t.rows()[1], 0), 2.0);
  EXPECT_EQ(t.rows()[1].line, 5u);

  const fs::path f = d.write("long.csv", "a\n1" + std::string(cap, ' ') + "\n");
  expect_contains(error_of([&] { CsvTable::read(f); }), {f.string() + ":2: line longer than the limit"});
}
