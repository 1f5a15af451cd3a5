// The command line on inputs whose derived values overflow (issue 16): `mpdem check` accepted an
// STL scaled to an infinite area and a young of 1e308, and `mpdem run` failed at step 1 (exit 1)
// on a radius of 1e308. Each is now bad input: one message naming file, line and key, exit
// status 2, nothing written. So is a folder named as a particle file.
#include <gtest/gtest.h>

#include <string>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

const char* kHead = "[time]\nduration = 0.001\ndt = 1e-6\n[[material]]\nname = \"glass\"\n";  // lines 1-5

// Runs `check` and `run` on the scene in `d`; both must refuse it with `location` and `text`.
void expect_refused(const fs::path& d, const std::string& location, const std::string& text) {
  for (const char* cmd : {"check scene.toml", "run scene.toml --quiet"}) {
    const CommandResult r = run_mpdem(cmd, d);
    EXPECT_EQ(r.status, 2) << cmd << "\n" << r.err;
    EXPECT_NE(r.err.find(location), std::string::npos) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find(text), std::string::npos) << cmd << ": " << r.err;
    EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "one message only: " << r.err;
  }
  EXPECT_FALSE(fs::exists(d / "output")) << "nothing may be written for bad input";
}

}  // namespace

TEST(CliInputLimits, StlScaledToAnInfiniteArea) {
  const fs::path d = fresh_dir("lim_stl");
  write_text(d / "floor.stl",
             "solid f\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
             "endsolid f\n");
  write_text(d / "scene.toml", std::string(kHead) + "[[barriers]]\nstl = \"floor.stl\"\nscale = 1e160\n");
  expect_refused(d, "scene.toml:6: 'barriers.scale'", "its area overflows");
  fs::remove_all(d);
}

TEST(CliInputLimits, RadiusWithAnInfiniteMass) {
  const fs::path d = fresh_dir("lim_radius");
  write_text(d / "p.csv", "id,x,y,z,radius\n1,0,0,0,0.001\n2,0,0,1,1e308\n");
  write_text(d / "scene.toml", std::string(kHead) + "[[particles]]\nfile = \"p.csv\"\n");
  expect_refused(d, "p.csv:3: 'radius'", "particle id 2: the mass 4/3 pi r^3 rho overflows");
  fs::remove_all(d);
}

TEST(CliInputLimits, YoungWithAnInfiniteContactModulus) {
  const fs::path d = fresh_dir("lim_young");
  write_text(d / "p.csv", "id,x,y,z,radius\n1,0,0,0,0.001\n");
  write_text(d / "scene.toml", "[time]\nduration = 0.001\ndt = 1e-6\n[[material]]\nname = \"glass\"\nyoung = 1e308\n"
                               "[[particles]]\nfile = \"p.csv\"\n");
  expect_refused(d, "scene.toml:6: 'material.young'", "the contact modulus E*");
  fs::remove_all(d);
}

TEST(CliInputLimits, FolderAsParticleFile) {
  const fs::path d = fresh_dir("lim_dir");
  fs::create_directories(d / "p.csv");
  write_text(d / "scene.toml", std::string(kHead) + "[[particles]]\nfile = \"p.csv\"\n");
  expect_refused(d, "scene.toml:7: 'particles.file'", "is a directory");
  fs::remove_all(d);
}

// Issue 45 item 2: values each in range whose derived sizes are beyond reason. On main they ran:
// the grid died with std::bad_alloc at its first sample, the sink removed nothing, the periodic
// run wrote NaN unwrapped positions (exit 0), the inlet inserted nothing, the log-normal failed
// at its first draw without file, line or key (exit 1), the long name with a raw "filesystem
// error". Now `check` and `run` refuse each before step 1: exit 2, file:line:key, nothing written.
TEST(CliInputLimits, DerivedSizesBeyondReason) {
  const std::string particles = "[[particles]]\nfile = \"p.csv\"\n";  // lines 6-7
  const std::string inlet = "[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [0.1, 0.1, 0.1]\ncount_rate = 100\n";
  const struct {
    std::string body, location, text;
  } cases[] = {
      {"[[coarse_grain]]\nwidth = 0.01\nevery = 0.0005\n"
       "grid = { min = [0, 0, 0], max = [1, 1, 1], cells = [1e5, 1e5, 1e5] }\n",
       "scene.toml:11: 'coarse_grain.grid.cells'", "1e+15 points"},
      {"[[sink]]\nregion = \"cylinder\"\nbase = [0, 0, 0]\naxis = [0, 0, 1e200]\ncylinder_radius = 0.1\n",
       "scene.toml:11: 'sink.axis'", "the squared axis length overflows"},
      {"[domain]\nmin = [-1e308, 0, 0]\nmax = [1e308, 1, 1]\nperiodic = [\"x\"]\n", "scene.toml:10: 'domain.max'",
       "the extent max - min along x overflows"},
      {inlet + "radius = 0.001\ninterval = 1e-100\n", "scene.toml:14: 'inlet.interval'", "insertion times"},
      {inlet + "radius = { distribution = \"lognormal\", mean = 0.001, std = 1e300 }\n",
       "scene.toml:13: 'inlet.radius.std'", "the log-normal's spread overflows"},
      {"[[coarse_grain]]\nwidth = 0.01\nevery = 0.0005\nname = \"" + std::string(300, 'a') +
           "\"\ngrid = { min = [0, 0, 0], max = [1, 1, 1], cells = [2, 2, 2] }\n",
       "scene.toml:11: 'coarse_grain.name'", "at most 200 bytes"},
  };
  for (const auto& c : cases) {
    const fs::path d = fresh_dir("lim_derived");
    write_text(d / "p.csv", "id,x,y,z,radius\n1,0.05,0.05,0.05,0.001\n");
    write_text(d / "scene.toml", std::string(kHead) + particles + c.body);
    expect_refused(d, c.location, c.text);
    fs::remove_all(d);
  }
}

// `mpdem generate` wrote particles at x = inf for a box whose extent overflows, and at NaN for a
// cylinder whose squared axis does: now exit 2 naming the option, nothing written.
TEST(CliInputLimits, GenerateRegionSizes) {
  const fs::path d = fresh_dir("lim_generate");
  for (const char* args : {"--min -1e308 0 0 --max 1e308 0.01 0.01", "--region cylinder --base 0 0 0 --axis 0 0 1e200 "
                                                                     "--cylinder-radius 0.01"}) {
    const CommandResult r = run_mpdem(std::string("generate -o g.csv -n 3 -r 0.001 ") + args, d);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("overflows"), std::string::npos) << r.err;
    EXPECT_TRUE(r.err.find("'--max'") != std::string::npos || r.err.find("'--axis'") != std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d / "g.csv")) << args;
  }
  fs::remove_all(d);
}
