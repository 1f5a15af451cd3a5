// The LAMMPS/LIGGGHTS data-file reader behind `mpdem bench` (io/lammps_data.hpp): header counts
// and box bounds, Atoms rows with and without image flags, and one clear InputError (file, line,
// key) for each kind of bad input.
#include <gtest/gtest.h>

#include <string>

#include "io/lammps_data.hpp"
#include "support/temp_dir.hpp"

namespace mpdem {
namespace {

using test::error_of;
using test::expect_contains;
using test::TempDir;

const std::string kHeader =
    "# a comment line\n\n3 atoms\n1 atom types\n\n-0.5 0.08 xlo xhi\n0 0.08 ylo yhi\n0 0.05 zlo zhi\n\nAtoms\n\n";

TEST(LammpsData, ReadsHeaderAndAtomsInFileOrder) {
  TempDir dir("lammps");
  const auto file = dir.write("bed.data", kHeader + "7 1 0.002 2500 0.001 0.002 0.003\n"
                                                    "3 1 0.004 2600 1e-3 2e-3 3e-3 0 0 1\n"  // image flags ignored
                                                    "5 1 0.002 2500 -0.1 0.02 0.01\n");
  const LammpsData d = read_lammps_data(file);
  EXPECT_EQ(d.atom_types, 1u);
  EXPECT_EQ(d.lo.x, -0.5);
  EXPECT_EQ(d.hi.x, 0.08);
  EXPECT_EQ(d.hi.y, 0.08);
  EXPECT_EQ(d.hi.z, 0.05);
  ASSERT_EQ(d.atoms.size(), 3u);
  EXPECT_EQ(d.atoms[0].id, 7);
  EXPECT_EQ(d.atoms[1].id, 3);
  EXPECT_EQ(d.atoms[1].diameter, 0.004);
  EXPECT_EQ(d.atoms[1].density, 2600.0);
  EXPECT_EQ(d.atoms[1].x.z, 3e-3);
  EXPECT_EQ(d.atoms[2].x.x, -0.1);
}

TEST(LammpsData, BadInputNamesFileLineAndKey) {
  TempDir dir("lammps");
  auto err = [&](const std::string& name, const std::string& text) {
    const auto file = dir.write(name, text);
    return error_of([&] { read_lammps_data(file); });
  };
  // Atom rows start at line 12 of kHeader + rows (the first line of a data file is its title).
  expect_contains(err("nocount.data", "title\n1 atom types\n0 1 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n"),
                  {"nocount.data", "N atoms"});
  expect_contains(err("count.data", kHeader + "1 1 0.002 2500 0 0 0\n"), {"count.data", "atoms"});
  expect_contains(err("dup.data", kHeader + "1 1 0.002 2500 0 0 0\n1 1 0.002 2500 0 0 0\n2 1 0.002 2500 0 0 0\n"),
                  {"dup.data", ":13", "duplicate atom id 1"});
  expect_contains(err("diam.data", kHeader + "1 1 -0.002 2500 0 0 0\n"), {"diam.data", ":12", "diameter"});
  expect_contains(err("rho.data", kHeader + "1 1 0.002 0 0 0 0\n"), {"rho.data", ":12", "density"});
  expect_contains(err("nan.data", kHeader + "1 1 0.002 2500 nan 0 0\n"), {"nan.data", ":12", "x y z"});
  expect_contains(err("cols.data", kHeader + "1 1 0.002 2500 0 0\n"), {"cols.data", ":12", "7 columns"});
  expect_contains(err("box.data", "title\n2 atoms\n1 atom types\n0.1 0.0 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n"),
                  {"box.data", ":4", "xlo"});
  expect_contains(err("noatoms.data", "title\n2 atoms\n1 atom types\n0 1 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n"),
                  {"noatoms.data", "Atoms"});
  expect_contains(error_of([&] { read_lammps_data(dir.path / "missing.data"); }), {"missing.data", "cannot open"});
}

}  // namespace
}  // namespace mpdem
