// `mpdem agglomerate` (also `mpdem generate agglomerate`) end to end: the particle CSV a scene reads and the bond CSV
// of the gap rule's pairs (checked by brute force on the numbers read back), the same files for a seed, earlier files
// kept unless --overwrite, a closed STL as the container, and bad options refused with one message naming the option
// (exit status 2, nothing written).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

struct Sphere {
  double x, y, z, r;  // m
};

// The spheres of a particle CSV written by the command: a '#' line, the header, then
// id,x,y,z,radius[,...] rows with ids 0, 1, 2, ...
std::vector<Sphere> read_spheres(const fs::path& file, std::string& header) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# mpdem agglomerate, seed ", 0), 0u) << line;
  std::getline(in, header);
  std::vector<Sphere> s;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::string cell;
    std::vector<std::string> c;
    while (std::getline(ls, cell, ',')) c.push_back(cell);
    EXPECT_EQ(std::stoul(c.at(0)), s.size());
    s.push_back({std::stod(c.at(1)), std::stod(c.at(2)), std::stod(c.at(3)), std::stod(c.at(4))});
  }
  return s;
}

std::vector<std::array<std::size_t, 2>> read_bonds(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "id_i,id_j");
  std::vector<std::array<std::size_t, 2>> b;
  while (std::getline(in, line)) {
    const std::size_t comma = line.find(',');
    b.push_back({std::stoul(line.substr(0, comma)), std::stoul(line.substr(comma + 1))});
  }
  return b;
}

double distance(const Sphere& a, const Sphere& b) {
  return std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y) + (b.z - a.z) * (b.z - a.z));
}

}  // namespace

TEST(AgglomerateCommand, WritesParticlesAndTheGapRulesBonds) {
  const fs::path d = fresh_dir("agg_files");
  const CommandResult r = run_mpdem(
      "agglomerate -o agg -n 400 -r 0.5e-3 --material glass --density 2500 --gap 1e-5 --seed 3", d);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("packed 400 particles in a sphere of radius"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("solid fraction 0.5500, largest overlap"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bonds (surface gap < 1e-05 m)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("-> agg_particles.csv, agg_bonds.csv"), std::string::npos) << r.out;

  std::string header;
  const std::vector<Sphere> s = read_spheres(d / "agg_particles.csv", header);
  EXPECT_EQ(header, "id,x,y,z,radius,material,density");
  ASSERT_EQ(s.size(), 400u);
  // Numbers are written exactly, so the file's bonds are the gap rule's pairs of the file's spheres.
  std::vector<std::array<std::size_t, 2>> expected;
  double worst = 0.0;  // largest overlap over the radius
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      if (distance(s[i], s[j]) - s[i].r - s[j].r < 1e-5) expected.push_back({i, j});
      worst = std::max(worst, (s[i].r + s[j].r - distance(s[i], s[j])) / s[i].r);
    }
  EXPECT_EQ(read_bonds(d / "agg_bonds.csv"), expected);
  EXPECT_GT(expected.size(), 400u);
  EXPECT_LE(worst, 1e-3);

  // A scene reads the particle file as it is.
  write_text(d / "scene.toml",
             "[time]\nduration = 0.001\ndt = 1e-7\n[[material]]\nname = \"glass\"\n[[particles]]\nfile = "
             "\"agg_particles.csv\"\n");
  const CommandResult c = run_mpdem("check scene.toml", d);
  EXPECT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("particles: 400"), std::string::npos) << c.out;
  fs::remove_all(d);
}

TEST(AgglomerateCommand, SameSeedSameFilesAndEarlierFilesKept) {
  const fs::path d = fresh_dir("agg_seed");
  const std::string common = " -n 300 -r 0.5e-3 --seed 5 -q";
  ASSERT_EQ(run_mpdem("agglomerate -o a" + common, d).status, 0);
  ASSERT_EQ(run_mpdem("agglomerate -o b" + common, d).status, 0);
  EXPECT_EQ(slurp(d / "a_particles.csv"), slurp(d / "b_particles.csv"));
  EXPECT_EQ(slurp(d / "a_bonds.csv"), slurp(d / "b_bonds.csv"));
  ASSERT_EQ(run_mpdem("agglomerate -o c -n 300 -r 0.5e-3 --seed 6 -q", d).status, 0);
  EXPECT_NE(slurp(d / "a_particles.csv"), slurp(d / "c_particles.csv"));

  // An existing output is kept: exit 2 and the files untouched; --overwrite replaces them.
  const std::string before = slurp(d / "c_particles.csv");
  const CommandResult r = run_mpdem("agglomerate -o c" + common, d);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("'--output': 'c_particles.csv' exists; pass --overwrite"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(d / "c_particles.csv"), before);
  ASSERT_EQ(run_mpdem("agglomerate -o c --overwrite" + common, d).status, 0);
  EXPECT_EQ(slurp(d / "c_particles.csv"), slurp(d / "a_particles.csv"));
  EXPECT_EQ(slurp(d / "c_bonds.csv"), slurp(d / "a_bonds.csv"));
  fs::remove_all(d);
}

// `mpdem generate agglomerate` is the same command (the spelling); `mpdem generate`
// without it still needs its --output.
TEST(AgglomerateCommand, AlsoUnderGenerate) {
  const fs::path d = fresh_dir("agg_generate");
  const std::string common = " -n 200 -r 0.5e-3 --seed 3 -q";
  ASSERT_EQ(run_mpdem("agglomerate -o a" + common, d).status, 0);
  ASSERT_EQ(run_mpdem("generate agglomerate -o g" + common, d).status, 0);
  EXPECT_EQ(slurp(d / "a_particles.csv"), slurp(d / "g_particles.csv"));
  EXPECT_EQ(slurp(d / "a_bonds.csv"), slurp(d / "g_bonds.csv"));
  const CommandResult r = run_mpdem("generate --count 10", d);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--output"), std::string::npos) << r.err;
  fs::remove_all(d);
}

// A cube from `mpdem mesh` ([-5, 5] mm x [-5, 5] mm x [0, 10] mm, normals inward) holds every
// sphere of an agglomerate filling it at the default fraction.
TEST(AgglomerateCommand, ClosedStlContainer) {
  const fs::path d = fresh_dir("agg_stl");
  ASSERT_EQ(run_mpdem("mesh box --size 0.01 0.01 0.01 --closed -o cube.stl --format stl-ascii", d).status, 0);
  const CommandResult r = run_mpdem("agglomerate --stl cube.stl -r 0.5e-3 -o cube", d);
  ASSERT_EQ(r.status, 0) << r.err;
  // 0.55 x 1e-6 m^3 / (4/3 pi 0.5^3 mm^3) = 1050.4 spheres: the draw stops closest to it, 1050,
  // whose solid fraction is 1050 x 5.236e-10 m^3 / 1e-6 m^3 = 0.54978.
  EXPECT_NE(r.out.find("packed 1050 particles in cube.stl scaled by 1 (1e-06 m^3): solid fraction 0.5498"),
            std::string::npos)
      << r.out;
  std::string header;
  const std::vector<Sphere> s = read_spheres(d / "cube_particles.csv", header);
  EXPECT_EQ(header, "id,x,y,z,radius");
  EXPECT_EQ(s.size(), 1050u);
  for (const Sphere& p : s) {
    EXPECT_GE(p.x - p.r, -0.005 - 1e-6 * p.r);
    EXPECT_LE(p.x + p.r, 0.005 + 1e-6 * p.r);
    EXPECT_GE(p.y - p.r, -0.005 - 1e-6 * p.r);
    EXPECT_LE(p.y + p.r, 0.005 + 1e-6 * p.r);
    EXPECT_GE(p.z - p.r, 0.0 - 1e-6 * p.r);
    EXPECT_LE(p.z + p.r, 0.01 + 1e-6 * p.r);
  }
  fs::remove_all(d);
}

TEST(AgglomerateCommand, BadOptionsExit2NamingTheOption) {
  const fs::path d = fresh_dir("agg_bad");
  write_text(d / "open.stl",
             "solid f\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
             "endsolid f\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"-n 100 -r 0.5e-3 --fraction 0.8", "'--fraction': expected a solid fraction in (0, 0.74]"},
      {"-n 100 -r 0.5e-3 --fraction 0", "'--fraction'"},
      {"-n 100 -r 0.5e-3 --sphere 0.01", "'--count': give --count or the container's size (--sphere)"},
      {"-r 0.5e-3", "'--sphere': give the sphere's radius"},
      {"-r 0.5e-3 --sphere -1", "'--sphere': expected a finite radius > 0"},
      {"-r 0.5e-3 --sphere 0", "'--sphere': expected a finite radius > 0"},
      {"-r 0.5e-3 --stl open.stl --scale 0", "'--scale': expected a finite scale > 0"},
      {"-r 0.5e-3 --sphere 0.4e-3", "'--sphere': the container holds less than one particle"},
      {"-r 1e-5 --sphere 1", "'--sphere': the container holds more than 1e7 particles"},
      {"-n 100", "'--radius': give --radius R > 0 or a --distribution"},
      {"-n 100 -r -1", "'--radius'"},
      {"-n 100 --distribution cubic", "'--distribution': expected constant, uniform"},
      {"-n 100 -r 0.5e-3 --gap -1", "'--gap': expected a gap >= 0"},
      {"-n 100 -r 0.5e-3 --density 0", "'--density': expected a finite density > 0"},
      {"-n 100 -r 0.5e-3 --tolerance 0", "'--tolerance': expected an overlap tolerance in (0, 1)"},
      {"-n 100 -r 0.5e-3 --material a,b", "'--material'"},
      {"-n 100 -r 0.5e-3 --stl open.stl --scale 2", "'--count': give --count or the container's size (--scale)"},
      {"-r 0.5e-3 --stl open.stl", "open.stl: the surface is not closed"},
      {"-n 100 -r 0.5e-3 --scale 2", "'--scale'"},
      {"-n 100 -r 0.5e-3 --stl open.stl --centre 0 0 1", "'--centre'"},
      {"-n 100 -r 0.5e-3 -o nodir/bad", "'--output': the folder 'nodir' does not exist"},
      {"-n 100 -r 0.5e-3 --fraction 0.7 --max-sweeps 500", "'--fraction': the overlaps did not fall below"},
  };
  for (const auto& [args, message] : cases) {
    const bool output = args.find("-o ") != std::string::npos;  // the case names its own output
    const CommandResult r = run_mpdem(std::string("agglomerate ") + (output ? "" : "-o bad ") + args, d);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "one message only: " << r.err;
    EXPECT_FALSE(fs::exists(d / "bad_particles.csv")) << args;
    EXPECT_FALSE(fs::exists(d / "bad_bonds.csv")) << args;
  }
  fs::remove_all(d);
}
