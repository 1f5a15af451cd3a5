// Sizes and counts the run derives from values each in range (issue 45 item 2, docs/scene.md
// "Derived limits"): coarse-grained point counts and names, region extents, squares and volumes,
// domain extents (periods), an inlet's insertion times, the particles due at one insertion and
// its radii against the material, radius distributions whose sampling overflows, and barrier
// motions whose displacement, velocity or angle overflows over the run. Each is refused when the
// scene is read, naming the file, the line and the key, instead of failing (or silently doing
// nothing) during the run.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/input_error.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::expect_contains;
using mpdem::test::TempDir;

namespace {

// Lines 1-5; a body starts at line 6.
const char* kHead = "[time]\nduration = 1.0\ndt = 1e-5\n[[material]]\nname = \"glass\"\n";

// Loads kHead + body (with a one-particle CSV beside it) and expects an InputError at `line` and
// `key` whose message holds `text`.
void expect_refused(const std::string& body, std::size_t line, const std::string& key, const std::string& text) {
  TempDir d("mpdem_derived_sizes");
  d.write("p.csv", "id,x,y,z,radius\n1,0.05,0.05,0.05,0.001\n");
  const fs::path scene = d.write("scene.toml", std::string(kHead) + body);
  try {
    load_scene(scene);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), scene.string()) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.key(), key) << e.what();
    expect_contains(e.what(), {text});
    return;
  }
  ADD_FAILURE() << "expected an InputError for:\n" << body;
}

const std::string kName300(300, 'a');

}  // namespace

// cells = [1e5, 1e5, 1e5] passed and the run died with std::bad_alloc at the first sample; a
// 300-character name died with a raw "filesystem error" when its folder was created.
TEST(DerivedSizes, CoarseGrainPointsAndNames) {
  const std::string cg = "[[coarse_grain]]\nwidth = 0.01\nevery = 0.1\n";  // lines 6-8
  expect_refused(cg + "grid = { min = [0, 0, 0], max = [1, 1, 1], cells = [1e5, 1e5, 1e5] }\n", 9,
                 "coarse_grain.grid.cells", "1e+15 points");
  // The limit holds for all entries together: two grids of 6e6 points.
  const std::string grid = "grid = { min = [0, 0, 0], max = [1, 1, 1], cells = [1000, 1000, 6] }\n";
  expect_refused(cg + "name = \"a\"\n" + grid + cg + "name = \"b\"\n" + grid, 15, "coarse_grain.grid.cells",
                 "1.2e+07 points");
  expect_refused(cg + "name = \"" + kName300 + "\"\ngrid = { min = [0, 0, 0], max = [1, 1, 1], cells = [2, 2, 2] }\n",
                 9, "coarse_grain.name", "at most 200 bytes");
  expect_refused(cg + "name = \"a\\tb\"\ngrid = { min = [0, 0, 0], max = [1, 1, 1], cells = [2, 2, 2] }\n", 9,
                 "coarse_grain.name", "control characters");
}

// A grid or profile whose extent overflows wrote inf coordinates and zero fields (exit 0); so did
// a kernel width whose normalisation 1 / width^d over- or underflows.
TEST(DerivedSizes, CoarseGrainExtentsAndWidth) {
  const std::string cg = "[[coarse_grain]]\nevery = 0.1\n";  // lines 6-7
  expect_refused(cg + "width = 0.01\ngrid = { min = [-1e308, 0, 0], max = [1e308, 1, 1], cells = [4, 4, 4] }\n", 9,
                 "coarse_grain.grid.max", "the point spacing (max - min) / cells along x overflows");
  expect_refused(cg + "width = 0.01\ngrid = { min = [0, 0, 0], max = [1e-320, 1, 1], cells = [4, 4, 4] }\n", 9,
                 "coarse_grain.grid.max", "along x underflows");
  expect_refused(cg + "width = 0.01\ngrid = { min = [-1e308, 0, 0], max = [1e308, 1, 1], cells = [4, 4, 4], "
                      "average_over = [\"x\"] }\n",
                 9, "coarse_grain.grid.max", "the averaged length along x overflows");
  expect_refused(cg + "width = 0.01\nprofile = { axis = \"z\", min = -1e308, max = 1e308, bins = 10, extent_min = "
                      "[0, 0, 0], extent_max = [1, 1, 1] }\n",
                 9, "coarse_grain.profile.max", "along z overflows");
  expect_refused(cg + "width = 0.01\nprofile = { axis = \"z\", min = 0, max = 1, bins = 10, extent_min = "
                      "[-1e308, 0, 0], extent_max = [1e308, 1, 1] }\n",
                 9, "coarse_grain.profile.extent_max", "the averaged length along x overflows");
  const std::string grid = "grid = { min = [0, 0, 0], max = [1, 1, 1], cells = [4, 4, 4] }\n";
  expect_refused(cg + "width = 1e-120\n" + grid, 8, "coarse_grain.width", "normalisation 1 / width^3");
  expect_refused(cg + "width = 1e200\n" + grid, 8, "coarse_grain.width", "normalisation 1 / width^3");
}

// A step the run cannot divide by, or more steps than are counted exactly: the run never ended.
TEST(DerivedSizes, StepCount) {
  TempDir d("mpdem_derived_sizes");
  const auto error = [&](const std::string& time) {
    const fs::path scene = d.write("scene.toml", "[time]\nduration = 1.0\n" + time + "[[material]]\nname = \"g\"\n");
    return test::error_of([&] { load_scene(scene); });
  };
  expect_contains(error("dt = 1e-300\n"), {"scene.toml:3: 'time.dt'", "1e+300 steps", "at most 2^53"});
  expect_contains(error("dt = 1e-320\ndt_min = 1e-320\nintegrator = \"trapezoidal\"\n"),
                  {"scene.toml:3: 'time.dt'", "dt underflows"});
  expect_contains(error("dt = 1e-5\nadaptive = true\ndt_min = 1e-320\nintegrator = \"trapezoidal\"\n"),
                  {"scene.toml:5: 'time.dt_min'", "dt_min underflows"});
  expect_contains(error("dt = 1e-5\nadaptive = true\ndt_min = 1e-17\nintegrator = \"trapezoidal\"\n"),
                  {"scene.toml:5: 'time.dt_min'", "1e+17 steps"});
}

// An [output] dir whose folder name exceeds a file system's 255 bytes.
TEST(DerivedSizes, OutputFolderNames) {
  expect_refused("[output]\ndir = \"out/" + kName300 + "\"\n", 7, "output.dir", "at most 255 bytes");
}

// A barrier group name with a comma or a quote (given, a CSV row's, or the file's name) passed
// and the run failed at its first barrier log ("bad column name", no file, line or key).
TEST(DerivedSizes, GroupNamesThatNameLogColumns) {
  TempDir d("mpdem_derived_sizes");
  const std::string tri = "0,0,0,1,0,0,0,1,0\n";
  d.write("w.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n" + tri);
  d.write("a,b.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n" + tri);
  d.write("g.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3,group\n" + tri.substr(0, tri.size() - 1) + ",x\"y\n");
  const auto refused = [&](const std::string& body, const std::string& where, const std::string& text) {
    const fs::path scene = d.write("scene.toml", std::string(kHead) + body);
    const std::string e = test::error_of([&] { load_scene(scene); });
    expect_contains(e, {where, text});
  };
  refused("[[barriers]]\nfile = \"w.csv\"\ngroup = \"x,\\\"y\"\n", "scene.toml:8: 'barriers.group'",
          "names log columns");
  refused("[[barriers]]\nfile = \"a,b.csv\"\n", "scene.toml:7: 'barriers.file'", "give `group`");
  refused("[[barriers]]\nfile = \"g.csv\"\n", "g.csv:2: 'group'", "names log columns");
}

// max_attempts beyond reason turned a jammed packing into a hang.
TEST(DerivedSizes, AttemptsBeyondReason) {
  expect_refused("[[particles]]\ngenerate = { region = \"box\", min = [0, 0, 0], max = [1, 1, 1], count = 2, "
                 "radius = 0.001, max_attempts = 1000000000 }\n",
                 7, "particles.generate.max_attempts", "[1, 100000000]");
  expect_refused("[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [0.1, 0.1, 0.1]\nradius = 0.001\n"
                 "count_rate = 10\nmax_attempts = 1000000000\n",
                 12, "inlet.max_attempts", "[1, 100000000]");
}

// A sink cylinder whose axis or radius squares overflow removed nothing; regions of generate,
// inlets and sinks share the checks (box extents, cylinder squares, volumes).
TEST(DerivedSizes, RegionExtentsSquaresAndVolumes) {
  const std::string sink = "[[sink]]\nregion = \"cylinder\"\nbase = [0, 0, 0]\n";  // lines 6-8
  expect_refused(sink + "axis = [0, 0, 1e200]\ncylinder_radius = 0.1\n", 9, "sink.axis",
                 "the squared axis length overflows");
  expect_refused(sink + "axis = [0, 0, 1]\ncylinder_radius = 1e200\n", 10, "sink.cylinder_radius",
                 "the squared radius overflows");
  expect_refused(sink + "axis = [0, 0, 1e-160]\ncylinder_radius = 0.1\n", 9, "sink.axis",
                 "the squared axis length underflows");
  expect_refused("[[sink]]\nregion = \"box\"\nmin = [-1e308, 0, 0]\nmax = [1e308, 1, 1]\n", 9, "sink.max",
                 "extent along x overflows");
  expect_refused("[[sink]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [1e-110, 1e-110, 1e-110]\n", 9, "sink.max",
                 "the region's volume underflows");
  expect_refused("[[particles]]\ngenerate = { region = \"box\", min = [-1e308, 0, 0], max = [1e308, 1, 1], count = 2, "
                 "radius = 0.001 }\n",
                 7, "particles.generate.max", "extent along x overflows");
  expect_refused("[[particles]]\ngenerate = { region = \"cylinder\", base = [0, 0, 0], axis = [0, 0, 1e200], "
                 "cylinder_radius = 0.1, count = 2, radius = 0.001 }\n",
                 7, "particles.generate.axis", "the squared axis length overflows");
  const std::string disc = "[[inlet]]\nregion = \"disc\"\ncentre = [0, 0, 0]\ndirection = [0, 0, -1]\n"
                           "radius = 0.001\ncount_rate = 10\n";  // lines 6-11
  expect_refused(disc + "disc_radius = 1e200\n", 12, "inlet.disc_radius", "the squared radius overflows");
  expect_refused(disc + "disc_radius = 0.1\ndepth = 1e200\n", 13, "inlet.depth", "the squared axis length overflows");
}

// A periodic period that overflowed gave NaN unwrapped positions and exit 0.
TEST(DerivedSizes, DomainExtentsAndPeriods) {
  expect_refused("[domain]\nmin = [-1e308, 0, 0]\nmax = [1e308, 1, 1]\nperiodic = [\"x\"]\n", 8, "domain.max",
                 "the extent max - min along x overflows");
  expect_refused("[domain]\nmin = [0, 0, 0]\nmax = [1, 1e-310, 1]\n", 8, "domain.max",
                 "the extent max - min along y underflows");
}

// interval = 1e-100 inserted nothing and reported no shortfall (the insertion count overflowed
// its integer); a rate beyond reason, and a radius the run cannot divide by, failed at run time.
TEST(DerivedSizes, InletCountsAndRadii) {
  const std::string inlet = "[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [0.1, 0.1, 0.1]\n";  // lines 6-9
  expect_refused(inlet + "radius = 0.001\ncount_rate = 100\ninterval = 1e-100\n", 12, "inlet.interval",
                 "insertion times");
  expect_refused(inlet + "radius = 0.001\ncount_rate = 1e300\n", 11, "inlet.count_rate",
                 "particles are due at one insertion");
  expect_refused(inlet + "radius = 0.001\nmass_rate = 1e10\n", 11, "inlet.mass_rate",
                 "particles are due at one insertion");
  expect_refused(inlet + "radius = 1e-100\ncount_rate = 100\n", 10, "inlet.radius", "material 'glass'");
  // An unbounded log-normal side is checked 8 standard deviations of ln r out.
  expect_refused(inlet + "radius = { distribution = \"lognormal\", mean = 0.001, std = 1e100 }\ncount_rate = 100\n", 10,
                 "inlet.radius", "underflows");
}

// A log-normal std = 1e300 failed at the first draw (exit 1, no file, line or key); the
// neighbouring parameters of every distribution kind whose derived values break sampling.
TEST(DerivedSizes, RadiusDistributionParameters) {
  const std::string inlet = "[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [0.1, 0.1, 0.1]\ncount_rate = 100\n"
                            "[inlet.radius]\n";  // lines 6-11
  expect_refused(inlet + "distribution = \"lognormal\"\nmean = 0.001\nstd = 1e300\n", 14, "inlet.radius.std",
                 "the log-normal's spread overflows");
  expect_refused(inlet + "distribution = \"lognormal\"\nmean = 0.001\nstd = 1e-200\n", 14, "inlet.radius.std",
                 "too small to sample");
  expect_refused(inlet + "distribution = \"normal\"\nmean = 0.001\nstd = 1e-310\nmin = 0.0005\nmax = 0.002\n", 14,
                 "inlet.radius.std", "too small to sample");
  expect_refused(inlet + "distribution = \"normal\"\nmean = 0.001\nstd = 1e-300\nmin = 0.002\nmax = 0.003\n", 15,
                 "inlet.radius.min", "standard deviations from the mean");
  expect_refused(inlet + "distribution = \"discrete\"\nradii = [0.001, 1e-200]\nfractions = [1, 1]\n"
                         "fractions_of = \"mass\"\n",
                 13, "inlet.radius.radii", "fraction / r^3");
  expect_refused("[[particles]]\ngenerate = { region = \"box\", min = [0, 0, 0], max = [1, 1, 1], count = 2, radius = "
                 "{ distribution = \"lognormal\", mean = 0.001, std = 1e300 } }\n",
                 7, "particles.generate.radius.std", "the log-normal's spread overflows");
}

// Barrier motions whose displacement, velocity or rotation angle overflows over the run (a
// [[barriers]] table's law and a barrier CSV row's motion columns).
TEST(DerivedSizes, BarrierMotionOverTheRun) {
  TempDir d("mpdem_derived_sizes");
  // Lines 1-7; the motion from line 8. A 10 s run: a finite rate over it can overflow.
  const std::string head = "[time]\nduration = 10.0\ndt = 1e-5\n[[material]]\nname = \"glass\"\n[[barriers]]\n"
                           "file = \"w.csv\"\n";
  const auto refused = [&](const std::string& row, const std::string& motion, const std::string& file, std::size_t line,
                           const std::string& key, const std::string& text) {
    d.write("w.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3" + row);
    const fs::path scene = d.write("scene.toml", head + motion);
    try {
      load_scene(scene);
      ADD_FAILURE() << "expected an InputError for:\n" << motion << row;
    } catch (const InputError& e) {
      EXPECT_EQ(fs::path(e.file()).filename(), file) << e.what();
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_EQ(e.key(), key) << e.what();
      expect_contains(e.what(), {text});
    }
  };
  const std::string row = "\n0,0,0,1,0,0,0,1,0\n";
  refused(row, "[barriers.motion]\nA = [0, 0, 1e300]\nw1 = 1e300\n", "scene.toml", 10, "barriers.motion.w1",
          "velocity bound");
  refused(row, "[barriers.motion]\na = [0, 0, 1e308]\n", "scene.toml", 9, "barriers.motion.a", "displacement bound");
  refused(row, "[barriers.motion]\nA = [1e308, 0, 0]\nB = [1e308, 0, 0]\n", "scene.toml", 9, "barriers.motion.A",
          "displacement bound");
  refused(row, "[barriers.motion.rotation]\naxis = [0, 0, 1]\nomega = 1e308\n", "scene.toml", 10,
          "barriers.motion.rotation.omega", "rotation angle bound");
  // A row's w1 column with the table's amplitude.
  refused(",w1\n0,0,0,1,0,0,0,1,0,1e300\n", "[barriers.motion]\nA = [0, 0, 1e10]\n", "w.csv", 2, "w1",
          "velocity bound");
}
