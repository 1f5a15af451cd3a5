// What `mpdem run` tells its user: a resume command that works when pasted as printed, clear
// messages for a folder given as a file and for a thread count out of range, removed particles
// reported a few lines at a time, steps/s of the session only after --resume, and the end-of-run
// summary with its energy-drift warning.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {
const char* kPair = "id,x,y,z,vx,radius\n1,0,0,0,1,0.001\n2,0.0025,0,0,-1,0.001\n";   // they collide
const char* kApart = "id,x,y,z,vx,radius\n1,0,0,0,-1,0.001\n2,0.0025,0,0,1,0.001\n";  // they never touch

std::string pair_scene(const std::string& time, const std::string& extra = "") {
  return "[time]\n" + time + "\nintegrator = \"verlet\"\n[gravity]\nvector = [0.0, 0.0, 0.0]\n" +
         "[[material]]\nname = \"m\"\nyoung = 1e9\n[[particles]]\nfile = \"p.csv\"\n" + extra;
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

std::vector<std::string> last_csv_row(const fs::path& file) {
  std::string text = slurp(file), line;
  while (!text.empty() && text.back() == '\n') text.pop_back();
  std::vector<std::string> fields;
  std::stringstream row(text.substr(text.rfind('\n') + 1));
  while (std::getline(row, line, ',')) fields.push_back(line);
  return fields;
}
}  // namespace

TEST(RunReports, ResumeCommandAfterSigtermIsCompleteAndRuns) {
  const fs::path d = fresh_dir("resume_cmd");
  write_text(d / "p.csv", kApart);
  // Long enough that SIGTERM arrives in the middle; checkpoints show the run is under way.
  write_text(d / "scene.toml", pair_scene("duration = 1000.0\ndt = 2e-5", "[output]\ncheckpoint_every = 500\n"));
  const fs::path out = d / "int out";  // a space: the printed command must quote it
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (chdir(d.c_str()) != 0) _exit(99);
    if (freopen((d / "int_stderr.txt").c_str(), "w", stderr) == nullptr) _exit(97);
    execl(MPDEM_BINARY, MPDEM_BINARY, "run", "scene.toml", "--threads", "1", "--output", "int out", nullptr);
    _exit(98);
  }
  for (int k = 0; k < 1200 && !fs::exists(out / "checkpoint.bin"); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  const std::string err = slurp(d / "int_stderr.txt");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(err, m, std::regex("stopped by signal 15 at t = ([0-9.e+-]+) s"))) << err;
  const double stopped = std::stod(m[1]);
  ASSERT_TRUE(std::regex_search(err, m, std::regex("resume with: (.*)\n"))) << err;
  const std::string cmd = m[1];
  EXPECT_NE(cmd.find("--output 'int out'"), std::string::npos) << cmd;
  EXPECT_NE(cmd.find("--threads 1"), std::string::npos) << cmd;
  EXPECT_NE(cmd.find("--resume 'int out/checkpoint.bin'"), std::string::npos) << cmd;
  // The duration may change between the runs; 100 more steps keep the test short.
  char duration[64];
  std::snprintf(duration, sizeof duration, "duration = %.17g", stopped + 0.002);
  write_text(d / "scene.toml", pair_scene(std::string(duration) + "\ndt = 2e-5", "[output]\ncheckpoint_every = 500\n"));
  const std::string shell = "cd '" + d.string() + "' && " + cmd + " >/dev/null 2>resumed_stderr.txt";
  const int raw = std::system(shell.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 0) << slurp(d / "resumed_stderr.txt");
  EXPECT_FALSE(fs::exists(d / "output")) << "the resumed run went to the scene's default folder";
  EXPECT_NEAR(std::stod(last_csv_row(out / "log.csv").at(1)), stopped + 0.002, 1e-9);  // continued in "int out"
  fs::remove_all(d);
}

TEST(RunReports, FolderGivenAsAFileAndThreadsOutOfRange) {
  const fs::path d = fresh_dir("paths");
  write_text(d / "p.csv", kPair);
  write_text(d / "scene.toml", pair_scene("duration = 0.001\ndt = 1e-5"));
  fs::create_directories(d / "scenes.toml");
  fs::create_directories(d / "old");
  write_text(d / "old" / "checkpoint.bin", "x");
  for (const char* cmd : {"run scenes.toml", "check scenes.toml", "run scene.toml --resume old"}) {
    const CommandResult r = run_mpdem(cmd, d);
    EXPECT_EQ(r.status, 2) << cmd;
    EXPECT_NE(r.err.find("is a directory"), std::string::npos) << cmd << ": " << r.err;
    EXPECT_EQ(r.err.find("does not exist"), std::string::npos) << cmd << ": " << r.err;
  }
  EXPECT_NE(run_mpdem("run scene.toml --resume old", d).err.find("old/checkpoint.bin?"), std::string::npos);
  for (const char* n : {"0", "-3", "100000", "two", "99999999999999999999"}) {
    const CommandResult r = run_mpdem(std::string("run scene.toml --threads ") + n, d);
    EXPECT_EQ(r.status, 2) << n;
    EXPECT_NE(r.err.find("from 1 to 1024"), std::string::npos) << n << ": " << r.err;
    EXPECT_LT(r.err.size(), 200u) << n << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(d / "output")) << "nothing may be written for bad input";
  fs::remove_all(d);
}

TEST(RunReports, RemovedParticlesAreSummarised) {
  const fs::path d = fresh_dir("removed");
  // 20 particles flying out of the domain along +x, the faster ones ahead (no collisions); one stays.
  std::string csv = "id,x,y,z,vx,radius\n1,-0.005,0,0,0,0.0004\n";
  for (int i = 0; i < 20; ++i)
    csv += std::to_string(100 + i) + "," + std::to_string(0.001 * i) + ",0,0," + std::to_string(1.0 + 0.1 * i) +
           ",0.0004\n";
  write_text(d / "p.csv", csv);
  write_text(d / "scene.toml", pair_scene("duration = 0.03\ndt = 1e-5",
                                          "[domain]\nmin = [-0.01, -0.01, -0.01]\nmax = [0.02, 0.01, 0.01]\n"
                                          "on_exit = \"remove\"\n[output]\nprogress_every = 1000\n"));
  const CommandResult r = run_mpdem("run scene.toml", d);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(count(r.err, "removed particle id"), 3u) << r.err;
  EXPECT_EQ(count(r.err, "removed 17 more particles at t = "), 1u) << r.err;
  EXPECT_NE(r.err.find("(ids "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("20 removed so far"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("20 particles removed"), std::string::npos) << r.err;  // end-of-run summary
  EXPECT_EQ(count(slurp(d / "output" / "removed.csv"), "\n"), 21u);           // header + every particle
  fs::remove_all(d);
}

TEST(RunReports, StepsPerSecondAfterResumeCountTheSessionOnly) {
  const fs::path d = fresh_dir("resume_rate");
  write_text(d / "p.csv", kApart);
  write_text(d / "scene.toml", pair_scene("duration = 0.01\ndt = 1e-5", "[output]\ncheckpoint_every = 300\n"));
  ASSERT_EQ(run_mpdem("run scene.toml --quiet", d).status, 0);
  const long steps = std::stol(last_csv_row(d / "output" / "log.csv").at(0));
  const long session = steps - steps / 300 * 300;  // after the last checkpoint
  const CommandResult r = run_mpdem("run scene.toml --output output --resume output/checkpoint.bin", d);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("done: t = 0.01 s, " + std::to_string(session) + " steps in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("resumed at step " + std::to_string(steps - session)), std::string::npos) << r.err;
  fs::remove_all(d);
}

TEST(RunReports, SummaryReportsDriftAndOverlapAndWarnsOnADrift) {
  const fs::path d = fresh_dir("drift");
  write_text(d / "p.csv", kPair);
  // A resolved collision: small drift, the deepest contact between the two particles, no warning.
  write_text(d / "scene.toml", pair_scene("duration = 0.002\ndt = 2e-7"));
  const CommandResult ok = run_mpdem("run scene.toml", d);
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.err.find("energy balance drift "), std::string::npos) << ok.err;
  EXPECT_NE(ok.err.find("largest overlap "), std::string::npos) << ok.err;
  EXPECT_NE(ok.err.find("between particles id 1 and id 2 at t = "), std::string::npos) << ok.err;
  EXPECT_EQ(ok.err.find("energy_drift"), std::string::npos) << ok.err;
  EXPECT_FALSE(fs::exists(d / "output" / "warnings.txt"));
  // The same collision with a step far too large and the per-step checks too lenient to stop it.
  const std::string coarse = pair_scene("duration = 0.01\ndt = 1e-4",
                                        "[checks]\nmax_overlap = 0.5\nenergy_jump = 0.0\n");
  write_text(d / "scene.toml", coarse);
  const CommandResult bad = run_mpdem("run scene.toml --quiet --overwrite", d);
  EXPECT_EQ(bad.status, 0) << bad.err;  // complete outputs; the warning says they are suspect
  EXPECT_NE(bad.err.find("warning: the energy balance rose by "), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("more than checks.energy_drift = 5%"), std::string::npos) << bad.err;
  EXPECT_NE(slurp(d / "output" / "warnings.txt").find("checks.energy_drift"), std::string::npos);
  // energy_drift = 0 turns the warning off.
  write_text(d / "scene.toml", coarse + "energy_drift = 0.0\n");
  const CommandResult off = run_mpdem("run scene.toml --quiet --overwrite", d);
  EXPECT_EQ(off.status, 0) << off.err;
  EXPECT_EQ(off.err.find("energy_drift"), std::string::npos) << off.err;
  EXPECT_FALSE(fs::exists(d / "output" / "warnings.txt")) << "a stale warning is removed";
  fs::remove_all(d);
}
