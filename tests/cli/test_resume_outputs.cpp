// A run resumed from its end checkpoint with a longer duration (docs/output.md "Checkpoints and
// restart") is the uninterrupted run: every output file bitwise equal, each .pvd listing each
// file once in time order, no file of the earlier run rewritten, also when the checkpoint was
// written on 2 ranks. Output intervals below the step give one snapshot per step (like
// particles_every), and a SIGTERM stops such a run after its step.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

constexpr double kDt = 3e-6;  // s

// 48 beads of radius 1 mm on a 4 x 4 x 3 lattice (gaps 0.1 mm), the bottom layer on the floor,
// neighbours moving towards each other at 0.4 m/s: contacts from the first steps on.
void write_inputs(const fs::path& d) {
  std::ostringstream p;
  p << "id,x,y,z,vx,vy,vz,radius\n";
  int id = 1;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i, ++id)
        p << id << "," << 1.5e-3 + 2.1e-3 * i << "," << 1.5e-3 + 2.1e-3 * j << "," << 1e-3 + 2.1e-3 * k << ","
          << (i % 2 ? -0.2 : 0.2) << "," << (j % 2 ? -0.2 : 0.2) << ",0,0.001\n";
  write_text(d / "p.csv", p.str());
  write_text(d / "floor.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3,group\n1,0,0,0,0.012,0,0,0.012,0.012,0,floor\n"
                              "2,0,0,0,0.012,0.012,0,0,0.012,0,floor\n");
}

// The scene, running `steps` steps of kDt, with the given [output] keys and [[coarse_grain]] entries.
void write_scene(const fs::path& file, int steps, const std::string& output, const std::string& extra = "") {
  char duration[64];
  std::snprintf(duration, sizeof duration, "%.17g", steps * kDt);
  const std::string contact = "restitution = 0.5\nmu_static = 0.5\nmu_dynamic = 0.4\nmu_rolling = 0.01\n";
  write_text(file, std::string("[time]\nduration = ") + duration +
                       "\nintegrator = \"verlet\"\ndt = 3e-6\n[gravity]\nvector = [0.0, 0.0, -9.81]\n"
                       "[contact.particle_particle]\n" +
                       contact + "[contact.particle_barrier]\n" + contact +
                       "[[material]]\nname = \"glass\"\ndensity = 2500.0\nyoung = 1e7\npoisson = 0.3\n"
                       "[[particles]]\nfile = \"p.csv\"\nmaterial = \"glass\"\n"
                       "[[barriers]]\nfile = \"floor.csv\"\nmaterial = \"glass\"\n"
                       "[domain]\nmin = [-0.01, -0.01, -0.01]\nmax = [0.02, 0.02, 0.03]\n"
                       "[checks]\nmax_overlap = 0.2\n[output]\n" +
                       output + extra);
}

// Every output an interval drives, each every 15 steps (4.5e-5 s), coarse-grained fields averaged
// over 3 samples; the log every 10 steps.
const char* kEveryOutput =
    "particles_every = 4.5e-5\nbarriers_every = 4.5e-5\nparticle_csv_every = 4.5e-5\nbarrier_log_every = 4.5e-5\n"
    "contacts_every = 4.5e-5\nlog_every = 10\n";
const char* kFields =
    "[[coarse_grain]]\nname = \"g\"\ngrid = { min = [0.0, 0.0, 0.0], max = [0.009, 0.009, 0.006], cells = [2, 2, 2] }\n"
    "width = 0.002\nevery = 4.5e-5\naverage = 2e-5\nsamples = 3\n"
    "[[coarse_grain]]\nname = \"p\"\nprofile = { axis = \"z\", min = 0.0, max = 0.006, bins = 4 }\n"
    "width = 0.002\nevery = 4.5e-5\n";

// Exit status of a shell command (-1: it did not exit, e.g. killed).
int shell(const std::string& cmd) {
  const int raw = std::system(cmd.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// mpdem in folder d on one thread; a run that hangs is killed after 120 s (status -1 or 137).
int run_in(const fs::path& d, const std::string& args, const std::string& launcher = "") {
  return shell("cd '" + d.string() + "' && timeout -s KILL 120 " + launcher + " '" + MPDEM_BINARY + "' " + args +
               " --threads 1 --quiet >>out.txt 2>>err.txt </dev/null");
}

// Every file under dir (relative paths) but the checkpoint, with its bytes.
std::map<std::string, std::string> files(const fs::path& dir) {
  std::map<std::string, std::string> all;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != "checkpoint.bin")
      all[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return all;
}

// The (timestep, file) entries of a .pvd, in file order.
std::vector<std::pair<std::string, std::string>> pvd_entries(const fs::path& pvd) {
  const std::string text = slurp(pvd);
  const std::regex entry("timestep=\"([^\"]*)\"[^>]*file=\"([^\"]*)\"");
  std::vector<std::pair<std::string, std::string>> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it)
    out.emplace_back((*it)[1], (*it)[2]);
  return out;
}

// Every .pvd of dir lists each file once, in ascending time.
void expect_pvds_list_each_file_once(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".pvd") continue;
    std::set<std::string> seen;
    double last = -1.0;
    for (const auto& [time, file] : pvd_entries(e.path())) {
      EXPECT_TRUE(seen.insert(file).second) << e.path() << " lists " << file << " twice";
      EXPECT_GT(std::stod(time), last) << e.path() << ": " << file << " at t = " << time;
      last = std::stod(time);
    }
  }
}

// The files of an earlier run that a resumed run must leave as they are: every snapshot file
// (the .pvd indexes and the row logs are continued, not kept).
void expect_kept(const std::map<std::string, std::string>& before, const std::map<std::string, std::string>& after) {
  for (const auto& [name, bytes] : before) {
    if (name.ends_with(".pvd") || name.find('/') == std::string::npos) continue;
    const auto it = after.find(name);
    ASSERT_NE(it, after.end()) << name << " was removed";
    EXPECT_TRUE(it->second == bytes) << name << " was rewritten by the resumed run";
  }
}

// Column `col` (0-based) of every row of a CSV text.
std::vector<std::string> column(const std::string& csv, std::size_t col) {
  std::vector<std::string> out;
  std::stringstream in(csv);
  for (std::string line; std::getline(in, line);) {
    std::stringstream row(line);
    std::string cell;
    for (std::size_t c = 0; c <= col && std::getline(row, cell, ','); ++c) {}
    out.push_back(cell);
  }
  return out;
}

// In d/u the uninterrupted run of 300 steps; in d/r a run of `steps` (started by `launcher`),
// checkpointed every `checkpoint_every` steps, resumed from its end checkpoint to 300 steps, each
// .pvd then listing each file once and no snapshot file of the first run rewritten. Returns
// whether all three runs exited with 0.
bool run_and_resume(const fs::path& d, int steps, int checkpoint_every, const std::string& launcher = "") {
  write_inputs(d);
  const std::string output = std::string(kEveryOutput) + "checkpoint_every = " + std::to_string(checkpoint_every) +
                             "\n";
  write_scene(d / "long.toml", 300, output, kFields);
  write_scene(d / "short.toml", steps, output, kFields);
  if (run_in(d, "run long.toml --output u") != 0 || run_in(d, "run short.toml --output r", launcher) != 0) return false;
  const auto first = files(d / "r");
  if (run_in(d, "run long.toml --output r --resume r/checkpoint.bin") != 0) return false;
  expect_pvds_list_each_file_once(d / "r");
  expect_kept(first, files(d / "r"));
  return true;
}

}  // namespace

// 150 steps, then resumed from the checkpoint of step 150 (the run's end) to 300: every file, the
// logs and .pvd indexes included, is the uninterrupted 300-step run's, byte for byte.
TEST(ResumeOutputs, EndCheckpointResumedLongerIsTheUninterruptedRun) {
  const fs::path d = fresh_dir("resume_end");
  ASSERT_TRUE(run_and_resume(d, 150, 150)) << slurp(d / "err.txt");
  const auto whole = files(d / "u"), resumed = files(d / "r");
  ASSERT_GT(whole.size(), 100u);
  for (const auto& [name, bytes] : whole) {
    const auto it = resumed.find(name);
    if (it == resumed.end()) ADD_FAILURE() << name << " is missing after the resume";
    else EXPECT_TRUE(it->second == bytes) << name << " differs from the uninterrupted run's";
  }
  for (const auto& [name, bytes] : resumed) EXPECT_TRUE(whole.count(name)) << name << ": not in the uninterrupted run";
  fs::remove_all(d);
}

// A run whose end (155 steps) is no multiple of the intervals (15 steps) writes an extra snapshot
// at its end; resumed to 300 steps, every series goes on with the next number at the next
// regular time: no file listed twice or rewritten, no regular snapshot of the uninterrupted run
// missing, its times (functions of the step count) the same.
TEST(ResumeOutputs, UnalignedEndKeepsItsSnapshotAndEveryRegularOne) {
  const fs::path d = fresh_dir("resume_unaligned");
  ASSERT_TRUE(run_and_resume(d, 155, 5)) << slurp(d / "err.txt");
  char end[64];
  std::snprintf(end, sizeof end, "%.17g", 155 * kDt);
  for (const char* pvd : {"particles.pvd", "barriers.pvd", "contacts.pvd"}) {
    std::set<std::string> times;
    for (const auto& [time, file] : pvd_entries(d / "r" / pvd)) times.insert(time);
    for (const auto& [time, file] : pvd_entries(d / "u" / pvd))
      EXPECT_TRUE(times.count(time)) << pvd << ": the regular snapshot at t = " << time << " is missing";
    EXPECT_TRUE(times.count(end)) << pvd << ": the short run's end snapshot is not listed";
    EXPECT_EQ(times.size(), pvd_entries(d / "u" / pvd).size() + 1) << pvd;
  }
  fs::remove_all(d);
}

// The end checkpoint of a run on 2 ranks, resumed on 1 with a longer duration: no file of the
// 2-rank run rewritten, each file listed once, and the times of every series and log row those of
// the uninterrupted one-rank run (the states agree within round-off, docs/parallel.md).
TEST(ResumeOutputs, TwoRankEndCheckpointResumedOnOneRank) {
  if (std::string(MPDEM_MPIEXEC).empty()) GTEST_SKIP() << "built without MPDEM_MPI";
  const fs::path d = fresh_dir("resume_2to1");
  const std::string mpirun =
      std::string("env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 '") +
      MPDEM_MPIEXEC + "' -np 2 --oversubscribe";
  ASSERT_TRUE(run_and_resume(d, 150, 150, mpirun)) << slurp(d / "err.txt");
  ASSERT_TRUE(fs::exists(d / "r" / "particles/particles_000010.pvtu"));  // written on 2 ranks
  for (const char* pvd : {"particles.pvd", "barriers.pvd", "contacts.pvd", "cg_g.pvd"}) {
    const auto a = pvd_entries(d / "u" / pvd), b = pvd_entries(d / "r" / pvd);
    ASSERT_EQ(a.size(), b.size()) << pvd;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].first, b[k].first) << pvd << " entry " << k;
      // The 2-rank snapshots are .pvtu indexes, the 1-rank ones .vtu files: the same number.
      EXPECT_EQ(fs::path(a[k].second).stem(), fs::path(b[k].second).stem()) << pvd << " entry " << k;
    }
  }
  // log.csv: step, time, dt; the others: time.
  for (const auto& [csv, columns] : {std::pair{"log.csv", 3}, {"barrier_groups.csv", 1}, {"cg_p.csv", 1}}) {
    for (int col = 0; col < columns; ++col)
      EXPECT_EQ(column(slurp(d / "u" / csv), col), column(slurp(d / "r" / csv), col)) << csv << " column " << col;
  }
  fs::remove_all(d);
}

// contacts_every and [[coarse_grain]] every far below the step (1e-7, 1e-12, 1e-20 s against
// dt = 3e-6 s): one snapshot or output per step, as particles_every gives, the contact snapshots
// those of contacts_every = dt. A run that hangs is killed after 120 s and fails.
TEST(OutputIntervals, ContactsEveryBelowTheStepGivesOneSnapshotPerStep) {
  const fs::path d = fresh_dir("contacts_below_dt");
  write_inputs(d);
  write_scene(d / "tiny.toml", 40, "contacts_every = 1e-7\n");
  write_scene(d / "dt.toml", 40, "contacts_every = 3e-6\n");
  ASSERT_EQ(run_in(d, "run tiny.toml --output tiny"), 0) << slurp(d / "err.txt");
  ASSERT_EQ(run_in(d, "run dt.toml --output dt"), 0) << slurp(d / "err.txt");
  const auto tiny = files(d / "tiny"), per_step = files(d / "dt");
  for (int k = 0; k < 40; ++k)
    for (const std::string& name :
         {fmt::format("contacts_csv/contacts_{:06d}.csv", k), fmt::format("contacts/contacts_{:06d}.vtu", k)}) {
      ASSERT_TRUE(tiny.count(name)) << name;
      EXPECT_TRUE(tiny.at(name) == per_step.at(name)) << name;
    }
  EXPECT_FALSE(tiny.count("contacts_csv/contacts_000040.csv"));
  EXPECT_EQ(pvd_entries(d / "tiny" / "contacts.pvd").size(), 40u);
  expect_pvds_list_each_file_once(d / "tiny");
  fs::remove_all(d);
}

TEST(OutputIntervals, CoarseGrainEveryBelowTheStepGivesOneOutputPerStep) {
  const fs::path d = fresh_dir("cg_below_dt");
  write_inputs(d);
  const std::string fields =
      "[[coarse_grain]]\nname = \"g\"\ngrid = { min = [0.0, 0.0, 0.0], max = [0.009, 0.009, 0.006], cells = [2, 2, "
      "2] }\nwidth = 0.002\nevery = 1e-20\naverage = 1e-20\nsamples = 5\n"
      "[[coarse_grain]]\nname = \"p\"\nprofile = { axis = \"z\", min = 0.0, max = 0.006, bins = 4 }\n"
      "width = 0.002\nevery = 1e-12\n";
  write_scene(d / "tiny.toml", 40, "", fields);
  ASSERT_EQ(run_in(d, "run tiny.toml --output tiny"), 0) << slurp(d / "err.txt");
  EXPECT_EQ(pvd_entries(d / "tiny" / "cg_g.pvd").size(), 40u);
  EXPECT_TRUE(fs::exists(d / "tiny" / "cg_g" / "cg_g_000039.vti"));
  EXPECT_EQ(column(slurp(d / "tiny" / "cg_p.csv"), 0).size(), 1u + 40u * 4u);  // header + 4 bins a step
  expect_pvds_list_each_file_once(d / "tiny");
  fs::remove_all(d);
}

// SIGTERM to a run with contacts_every below the step stops it after its step (exit 143, with a
// checkpoint), however far its snapshots are behind the intervals.
TEST(OutputIntervals, SigtermStopsARunWithIntervalsBelowTheStep) {
  const fs::path d = fresh_dir("every_sigterm");
  write_inputs(d);
  write_scene(d / "scene.toml", 100000000, "contacts_every = 1e-7\n");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (chdir(d.c_str()) != 0) _exit(99);
    if (freopen((d / "err.txt").c_str(), "w", stderr) == nullptr) _exit(97);
    execl(MPDEM_BINARY, MPDEM_BINARY, "run", "scene.toml", "--threads", "1", "--quiet", "--output", "out", nullptr);
    _exit(98);
  }
  for (int k = 0; k < 1200 && !fs::exists(d / "out" / "contacts_csv" / "contacts_000000.csv"); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  kill(child, SIGTERM);
  int status = 0;
  pid_t done = 0;
  for (int k = 0; k < 1200 && (done = waitpid(child, &status, WNOHANG)) == 0; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  if (done == 0) {
    kill(child, SIGKILL);
    waitpid(child, &status, 0);
    FAIL() << "the run did not stop on SIGTERM within 60 s";
  }
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << slurp(d / "err.txt");
  EXPECT_TRUE(fs::exists(d / "out" / "checkpoint.bin"));
  fs::remove_all(d);
}
