// `mpdem bench` physics beds (docs/benchmark.md "Physics beds"): --cohesion and --bonds on a
// 3 x 3 grid of 2 mm spheres on the floor, whose bonds, contacts and bridges are counted by hand;
// without the options (or with --cohesion none) the bed is the plain one; bad values exit 2 with
// one message.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

// A LAMMPS data file of a 3 x 3 grid of spheres of diameter 2 mm with centres `spacing` apart,
// at x in {2, 2 + s, 2 + 2s} mm, y in {8, 8 + s, 8 + 2s} mm and z = 1 mm - `sink` (overlapping
// the floor by `sink`), in a box of 14 x 14 x 10 mm: no sphere near a side wall, and every foot
// point at least 1.4 mm from the floor's diagonal edge (the floor is two triangles), so that each
// sphere touches the floor once.
std::string grid_bed(double spacing, double sink) {
  std::string t =
      "# 3 x 3 grid\n\n9 atoms\n1 atom types\n\n0 0.014 xlo xhi\n0 0.014 ylo yhi\n0 0.01 zlo zhi\n\nAtoms\n\n";
  int id = 1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      t += fmt::format("{} 1 0.002 2500 {:.9g} {:.9g} {:.9g}\n", id++, 0.002 + i * spacing, 0.008 + j * spacing,
                       0.001 - sink);
  return t;
}

// The value of key=... in the BENCH_RESULT line of `out` ("" when missing).
std::string result_field(const std::string& out, const std::string& key) {
  const std::size_t line = out.find("BENCH_RESULT");
  if (line == std::string::npos) return "";
  std::istringstream in(out.substr(line, out.find('\n', line) - line));
  for (std::string w; in >> w;)
    if (w.rfind(key + "=", 0) == 0) return w.substr(key.size() + 1);
  return "";
}

double number(const std::string& out, const std::string& key) { return std::stod(result_field(out, key)); }

CommandResult bench(const fs::path& d, const std::string& options) {
  return run_mpdem("bench bed.data --steps 10 --relax 0 " + options, d);
}

}  // namespace

// The gap rule bonds the grid's 12 nearest neighbours (gap 5 um < 10 um) and no diagonal (gap
// 0.84 mm); nothing breaks in 10 steps.
TEST(BenchBeds, BondsTheGridsNeighbours) {
  const fs::path d = fresh_dir("bench_bonds");
  write_text(d / "bed.data", grid_bed(0.002005, 0.0));
  const CommandResult r = bench(d, "--bonds");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(result_field(r.out, "bed"), "bonds");
  EXPECT_EQ(result_field(r.out, "bonds"), "12");
  EXPECT_EQ(result_field(r.out, "bonds_broken"), "0");
  EXPECT_NE(r.out.find("parallel bonds within a gap of 1e-05 m"), std::string::npos) << r.out;
  fs::remove_all(d);
}

// Overlapping neighbours (2 um) touching the floor (1 um): 12 sphere pairs, coordination
// 2 x 12 / 9, and with --cohesion bridges a bridge at every contact, 12 + 9 with the floor; no
// neck or bridge breaks in 10 steps. JKR and SJKR keep the same contacts.
TEST(BenchBeds, CohesionAtEveryContact) {
  const fs::path d = fresh_dir("bench_cohesion");
  write_text(d / "bed.data", grid_bed(0.001998, 1e-6));
  for (const char* kind : {"jkr", "sjkr", "bridges"}) {
    const CommandResult r = bench(d, std::string("--cohesion ") + kind);
    ASSERT_EQ(r.status, 0) << kind << ": " << r.err;
    EXPECT_EQ(result_field(r.out, "bed"), kind);
    EXPECT_NEAR(number(r.out, "coordination"), 24.0 / 9.0, 1e-5) << kind;  // printed to 5 decimals
    EXPECT_NEAR(number(r.out, "wall_contacts_per_particle"), 1.0, 1e-5) << kind;
    EXPECT_EQ(result_field(r.out, "bridges"), std::string(kind) == "bridges" ? "21" : "0") << kind;
    EXPECT_EQ(result_field(r.out, "cohesion_breaks"), "0") << kind;
    EXPECT_EQ(result_field(r.out, "ruptures"), "0") << kind;
  }
  const CommandResult jkr = bench(d, "--cohesion jkr");
  EXPECT_NE(jkr.out.find("JKR adhesion, surface energy 0.05 J/m^2"), std::string::npos) << jkr.out;
  fs::remove_all(d);
}

// No option and --cohesion none are the plain bed: the same state to the last printed digit,
// no bonds, no bridges; --clumps makes 4 members per sphere.
TEST(BenchBeds, WithoutOptionsThePlainBed) {
  const fs::path d = fresh_dir("bench_plain");
  write_text(d / "bed.data", grid_bed(0.001998, 1e-6));
  const CommandResult plain = bench(d, ""), none = bench(d, "--cohesion none"), clumps = bench(d, "--clumps");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(none.status, 0) << none.err;
  ASSERT_EQ(clumps.status, 0) << clumps.err;
  EXPECT_EQ(result_field(plain.out, "bed"), "plain");
  for (const char* key : {"bed", "ke", "zmax", "coordination", "wall_contacts_per_particle"})
    EXPECT_EQ(result_field(none.out, key), result_field(plain.out, key)) << key;
  for (const char* key : {"bodies", "bonds", "bridges"}) EXPECT_EQ(result_field(plain.out, key), "0") << key;
  EXPECT_EQ(result_field(clumps.out, "bed"), "clumps");
  EXPECT_EQ(result_field(clumps.out, "bodies"), "9");
  EXPECT_EQ(result_field(clumps.out, "particles"), "36");
  fs::remove_all(d);
}

TEST(BenchBeds, BadValuesExit2WithOneMessage) {
  const fs::path d = fresh_dir("bench_bad");
  write_text(d / "bed.data", grid_bed(0.002005, 0.0));
  for (const char* options : {"--cohesion glue", "--cohesion JKR", "--cohesion", "--bonds=maybe"}) {
    const CommandResult r = bench(d, options);
    EXPECT_EQ(r.status, 2) << options << "\n" << r.err;
    EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << options << ": one message only: " << r.err;
    const std::string option = std::string(options).substr(0, std::string(options).find_first_of(" ="));
    EXPECT_NE(r.err.find(option), std::string::npos) << options << ": names the option: " << r.err;
    EXPECT_EQ(r.out.find("BENCH_RESULT"), std::string::npos) << options;
  }
  fs::remove_all(d);
}
