// `mpdem plot OUTPUT_DIR` (docs/output.md, "Plots"): a short run with barriers, then its plots -
// every expected PNG written (a real PNG of some size) and listed on stdout; a folder without
// log.csv, a missing folder and an interpreter that cannot be run give exit status 2 and one
// message. Needs /usr/bin/python3 with numpy and matplotlib (else skipped).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

bool python_has_matplotlib() {
  static const bool ok = std::system("/usr/bin/python3 -c 'import numpy, matplotlib' >/dev/null 2>&1 </dev/null") == 0;
  return ok;
}

// The open box of examples/demo: a floor (group "floor", 2 triangles) and four walls ("walls").
const char* kBox = "id,x1,y1,z1,x2,y2,z2,x3,y3,z3,group\n"
                   "1,0,0,0,0.04,0,0,0.04,0.04,0,floor\n"
                   "2,0,0,0,0.04,0.04,0,0,0.04,0,floor\n"
                   "3,0,0,0,0,0.04,0,0,0.04,0.05,walls\n"
                   "4,0,0,0,0,0.04,0.05,0,0,0.05,walls\n"
                   "5,0.04,0,0,0.04,0,0.05,0.04,0.04,0.05,walls\n"
                   "6,0.04,0,0,0.04,0.04,0.05,0.04,0.04,0,walls\n"
                   "7,0,0,0,0,0,0.05,0.04,0,0.05,walls\n"
                   "8,0,0,0,0.04,0,0.05,0.04,0,0,walls\n"
                   "9,0,0.04,0,0.04,0.04,0,0.04,0.04,0.05,walls\n"
                   "10,0,0.04,0,0.04,0.04,0.05,0,0.04,0.05,walls\n";

// 60 beads dropped into the box, whose barriers turn slowly about the vertical axis (so
// barrier_groups.csv has the torque and power columns too); trapezoidal (iterations > 0).
// About 1 s on one thread.
const char* kScene = R"(
[time]
duration = 0.04
integrator = "trapezoidal"
dt = 4e-6

[gravity]
vector = [0.0, 0.0, -9.81]

[contact.particle_particle]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.4

[contact.particle_barrier]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.4

[[material]]
name = "glass"
density = 2500.0
young = 1e7
poisson = 0.3

[[particles]]
[particles.generate]
region = "box"
min = [0.005, 0.005, 0.001]
max = [0.035, 0.035, 0.008]
count = 60
radius = 0.001
seed = 1
gap = 0.0002
material = "glass"

[[barriers]]
file = "box.csv"
material = "glass"
motion = { rotation = { axis = [0, 0, 1], origin = [0.02, 0.02, 0], omega = 2.0 } }

[checks]
max_overlap = 0.15

[output]
dir = "output"
particles_every = 0
barriers_every = 0
barrier_log_every = 0.001
log_every = 100
)";

std::string read_bytes(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expect_png(const fs::path& f) {
  ASSERT_TRUE(fs::is_regular_file(f)) << f;
  const std::string bytes = read_bytes(f);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << f;
  EXPECT_GT(bytes.size(), 10000u) << f << ": too small for a plot with axes and curves";
}

}  // namespace

TEST(PlotCommand, PlotsARunWithBarriers) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 cannot import numpy and matplotlib";
  const fs::path d = fresh_dir("plot_run");
  write_text(d / "scene.toml", kScene);
  write_text(d / "box.csv", kBox);
  const CommandResult run = run_mpdem("run scene.toml --quiet --threads 1", d);
  ASSERT_EQ(run.status, 0) << run.err;
  ASSERT_TRUE(fs::exists(d / "output" / "log.csv"));
  ASSERT_TRUE(fs::exists(d / "output" / "barrier_groups.csv"));
  // A coarse-grained profile (position first; two times: the last one is drawn) and an empty one.
  write_text(d / "output" / "profile_z.csv",
             "time,z,solid_fraction,vx\n0.01,0,0.5,0\n0.01,0.001,0.4,0.1\n0.01,0.002,0.2,0.3\n"
             "0.02,0,0.55,0\n0.02,0.001,0.45,0.2\n0.02,0.002,0.25,0.4\n");
  write_text(d / "output" / "profile_empty.csv", "");

  const CommandResult r = run_mpdem("plot output", d);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const std::vector<std::string> expected = {"log_energy.png", "log_contacts.png", "log_step.png", "barrier_groups.png",
                                             "profile_z.png"};
  for (const std::string& png : expected) {
    expect_png(d / "output" / "plots" / png);
    EXPECT_NE(r.out.find("output/plots/" + png + "\n"), std::string::npos) << png << " not listed:\n" << r.out;
  }
  // One stdout line per PNG, nothing else; no thermal or inlet/sink plots for this scene.
  std::size_t lines = 0;
  for (const char ch : r.out) lines += ch == '\n' ? 1 : 0;
  EXPECT_EQ(lines, expected.size()) << r.out;
  std::size_t pngs = 0;
  for (const auto& e : fs::directory_iterator(d / "output" / "plots")) pngs += e.path().extension() == ".png";
  EXPECT_EQ(pngs, expected.size());
  EXPECT_NE(r.err.find("profile_empty.csv: empty, skipped"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;

  // Again over the old plots (replaced), with an explicit interpreter and an absolute folder.
  const CommandResult again = run_mpdem("plot '" + (d / "output").string() + "' --python /usr/bin/python3", d);
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find((d / "output" / "plots" / "barrier_groups.png").string()), std::string::npos) << again.out;
  fs::remove_all(d);
}

TEST(PlotCommand, FolderWithoutLogIsRefused) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 cannot import numpy and matplotlib";
  const fs::path d = fresh_dir("plot_empty");
  fs::create_directories(d / "empty");
  const CommandResult r = run_mpdem("plot empty", d);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("error: empty: no log.csv (not an mpdem output folder?)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "one message only: " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(d / "empty" / "plots")) << "nothing may be written";
  fs::remove_all(d);
}

TEST(PlotCommand, MissingFolderIsRefused) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 cannot import numpy and matplotlib";
  const fs::path d = fresh_dir("plot_missing");
  const CommandResult r = run_mpdem("plot no_such_folder", d);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no_such_folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "no_such_folder"));
  fs::remove_all(d);
}

TEST(PlotCommand, InterpreterThatCannotRun) {
  const fs::path d = fresh_dir("plot_nopython");
  fs::create_directories(d / "out");
  write_text(d / "out" / "log.csv", "step,time\n0,0\n");
  const CommandResult r = run_mpdem("plot out --python /no/such/python3", d);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cannot run the Python interpreter '/no/such/python3'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "one message only: " << r.err;
  EXPECT_FALSE(fs::exists(d / "out" / "plots"));
  fs::remove_all(d);
}
