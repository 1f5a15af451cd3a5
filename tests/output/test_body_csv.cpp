// Clump outputs of a run (docs/output.md): the body CSV series ([output] body_csv_every) numbered
// and resumed like the particle CSV series, never left behind by --overwrite; a body snapshot
// seeds a new scene as it is; the global log counts bodies and members; the contact snapshots name
// the members' bodies. Through the `mpdem` command, as a user runs it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "output/contact_writer.hpp"
#include "output/global_log.hpp"
#include "support/clump_scenes.hpp"
#include "support/run_command.hpp"

using namespace mpdem;
using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

constexpr double kDt = 2e-6;  // s

// Two L-shaped clumps of three separate spheres (template "ell") and a free sphere 100: body 7's
// member 1 runs into body 1's member 0 and the free sphere into body 1's member 1 (gaps 10 um,
// closing at 1 m/s: contacts from the fifth step on). Centres of mass: the template's centroid
// is (8.536e-4, 2.635e-4, 0) m from its origin as written.
const char* kBodies = "id,x,y,z,vx,vy,vz,wx,wy,wz\n1,0.01,0.01,0.01,0,0,0,0,0,0\n7,0.00599,0.01,0.01,0.5,0,0,0,0,3\n";
const char* kSpheres = "id,x,y,z,vx,radius\n100,0.0131564,0.0097365,0.01,-0.5,0.001\n";

// The scene running `steps` steps, with the given [output] keys and the bodies of `bodies`.
std::string scene(int steps, const std::string& output, const std::string& bodies = "bodies.csv") {
  char duration[64];
  std::snprintf(duration, sizeof duration, "%.17g", steps * kDt);
  const std::string contact = "restitution = 0.5\nmu_static = 0.5\nmu_dynamic = 0.4\n";
  return std::string("[time]\nduration = ") + duration +
         "\nintegrator = \"verlet\"\ndt = 2e-6\n[gravity]\nvector = [0.0, 0.0, 0.0]\n"
         "[contact.particle_particle]\n" +
         contact +
         "[[material]]\nname = \"glass\"\ndensity = 2500.0\nyoung = 1e7\npoisson = 0.3\n"
         "[[clump]]\nname = \"ell\"\nmembers = [[0.0, 0.0, 0.0, 0.001], [0.002, 0.0, 0.0, 0.001], "
         "[0.0, 0.0018, 0.0, 0.0007]]\n"
         "[[particles]]\nfile = \"" +
         bodies + "\"\nclump = \"ell\"\nmaterial = \"glass\"\n" +
         (bodies == "bodies.csv" ? "[[particles]]\nfile = \"spheres.csv\"\nmaterial = \"glass\"\n" : "") +
         "[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [0.03, 0.03, 0.03]\n[checks]\nmax_overlap = 0.3\n[output]\n" + output;
}

// Every output each 50 steps, the log each 25.
const char* kOutputs = "body_csv_every = 1e-4\nparticle_csv_every = 1e-4\ncontacts_every = 1e-4\nlog_every = 25\n";

int shell(const std::string& cmd) {
  const int raw = std::system(cmd.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// mpdem in folder d on one thread; a run that hangs is killed after 120 s.
int run_in(const fs::path& d, const std::string& args) {
  return shell("cd '" + d.string() + "' && timeout -s KILL 120 '" + MPDEM_BINARY + "' " + args +
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

using Table = std::vector<std::vector<std::string>>;  // a CSV's lines split at commas, header first
Table table(const fs::path& file) {
  Table t;
  std::istringstream in(slurp(file));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
    t.push_back(fields);
  }
  return t;
}
std::size_t column(const Table& t, const std::string& name) {
  for (std::size_t c = 0; c < t.at(0).size(); ++c)
    if (t[0][c] == name) return c;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

// d/u: the uninterrupted 300 steps (and inputs for the others).
fs::path uninterrupted(const std::string& name) {
  const fs::path d = fresh_dir(name);
  write_text(d / "bodies.csv", kBodies);
  write_text(d / "spheres.csv", kSpheres);
  write_text(d / "long.toml", scene(300, kOutputs));
  EXPECT_EQ(run_in(d, "run long.toml --output u"), 0) << slurp(d / "err.txt");
  return d;
}

}  // namespace

// The series: bodies_csv/bodies_000000.csv .. 000006.csv at t = 0, 1e-4, ..., 6e-4 s, as the
// particle CSV series; the header and one row per body in ascending id, the template's name.
TEST(BodyCsv, SeriesFollowsTheParticleCsvSeries) {
  const fs::path d = uninterrupted("body_csv_series");
  for (int k = 0; k <= 6; ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "bodies_%06d.csv", k);
    const Table b = table(d / "u" / "bodies_csv" / name);
    std::snprintf(name, sizeof name, "particles_%06d.csv", k);
    const Table p = table(d / "u" / "particles_csv" / name);
    ASSERT_EQ(b.size(), 3u) << name;
    EXPECT_EQ(b[0], (std::vector<std::string>{"time", "id", "clump", "x",  "y",  "z",  "q0",   "q1", "q2", "q3",
                                              "vx",   "vy", "vz",    "wx", "wy", "wz", "mass", "I1", "I2", "I3"}));
    EXPECT_EQ(b[1][0], p[1][0]) << name;  // the same time
    EXPECT_EQ(b[1][1], "1");
    EXPECT_EQ(b[2][1], "7");
    EXPECT_EQ(b[1][2], "ell");
  }
  EXPECT_FALSE(fs::exists(d / "u" / "bodies_csv" / "bodies_000007.csv"));
  fs::remove_all(d);
}

// 150 steps checkpointed at the end, resumed to 300: every file (the body CSV series, the log with
// its body columns, the contact snapshots with theirs) is the uninterrupted run's, byte for byte.
TEST(BodyCsv, ResumedRunWritesTheUninterruptedRunsFiles) {
  const fs::path d = uninterrupted("body_csv_resume");
  write_text(d / "short.toml", scene(150, std::string(kOutputs) + "checkpoint_every = 150\n"));
  ASSERT_EQ(run_in(d, "run short.toml --output r"), 0) << slurp(d / "err.txt");
  ASSERT_EQ(run_in(d, "run long.toml --output r --resume r/checkpoint.bin"), 0) << slurp(d / "err.txt");
  const auto whole = files(d / "u"), resumed = files(d / "r");
  ASSERT_TRUE(whole.count("bodies_csv/bodies_000006.csv"));
  for (const auto& [name, bytes] : whole) {
    const auto it = resumed.find(name);
    if (it == resumed.end()) ADD_FAILURE() << name << " is missing after the resume";
    else EXPECT_TRUE(it->second == bytes) << name << " differs from the uninterrupted run's";
  }
  for (const auto& [name, bytes] : resumed) EXPECT_TRUE(whole.count(name)) << name << ": not in the uninterrupted run";
  fs::remove_all(d);
}

// A run into a folder with an earlier run's outputs is refused (exit 2); with --overwrite the earlier
// body CSV snapshots go with the rest, so that no stale snapshot is left among the new ones.
TEST(BodyCsv, OverwriteRemovesTheEarlierBodySnapshots) {
  const fs::path d = uninterrupted("body_csv_overwrite");
  write_text(d / "u" / "bodies_csv" / "bodies_000099.csv", "stale\n");
  EXPECT_EQ(run_in(d, "run long.toml --output u"), 2);
  EXPECT_TRUE(fs::exists(d / "u" / "bodies_csv" / "bodies_000099.csv"));
  ASSERT_EQ(run_in(d, "run long.toml --output u --overwrite"), 0) << slurp(d / "err.txt");
  EXPECT_FALSE(fs::exists(d / "u" / "bodies_csv" / "bodies_000099.csv"));
  EXPECT_TRUE(fs::exists(d / "u" / "bodies_csv" / "bodies_000006.csv"));
  fs::remove_all(d);
}

// The last body snapshot (bodies turned and spinning after their contacts) seeds a new scene as it
// is ([[particles]] file = the snapshot, clump = "ell"): its first snapshot holds the same bodies,
// x, v, w, mass and moments printed the same, the orientation within round-off (1e-15).
TEST(BodyCsv, SnapshotSeedsANewScene) {
  const fs::path d = uninterrupted("body_csv_seed");
  const Table end = table(d / "u" / "bodies_csv" / "bodies_000006.csv");
  ASSERT_EQ(end.size(), 3u);
  EXPECT_NE(end[1][column(end, "wz")], "0");  // the contacts turned body 1
  write_text(d / "seed.toml", scene(10, "body_csv_every = 1e-4\n", "u/bodies_csv/bodies_000006.csv"));
  ASSERT_EQ(run_in(d, "run seed.toml --output s"), 0) << slurp(d / "err.txt");
  const Table start = table(d / "s" / "bodies_csv" / "bodies_000000.csv");
  ASSERT_EQ(start.size(), end.size());
  EXPECT_EQ(start[0], end[0]);
  for (std::size_t r = 1; r < end.size(); ++r) {
    EXPECT_EQ(start[r][0], "0");
    for (std::size_t c = 1; c < end[r].size(); ++c) {
      if (c >= 6 && c <= 9) EXPECT_NEAR(std::stod(start[r][c]), std::stod(end[r][c]), 1e-15) << end[0][c];
      else EXPECT_EQ(start[r][c], end[r][c]) << end[0][c] << " of body " << end[r][1];
    }
  }
  fs::remove_all(d);
}

// log.csv: bodies and members right after particles (2 bodies, 6 members of the 7 particles);
// contact snapshots: first_body, second_body after the sphere columns, each the body of the
// member it names in the particle snapshot of the same time (-1 for the free sphere), body-body
// and body-sphere contacts both present.
TEST(BodyCsv, LogAndContactsNameTheBodies) {
  const fs::path d = uninterrupted("body_csv_log_contacts");
  const Table log = table(d / "u" / "log.csv");
  const std::size_t particles = column(log, "particles");
  ASSERT_EQ(log[0].at(particles + 1), "bodies");
  ASSERT_EQ(log[0].at(particles + 2), "members");
  EXPECT_EQ(log[0].at(particles + 3), "removed");
  for (std::size_t r = 1; r < log.size(); ++r) {
    EXPECT_EQ(log[r][particles], "7");
    EXPECT_EQ(log[r][particles + 1], "2");
    EXPECT_EQ(log[r][particles + 2], "6");
  }
  std::map<std::string, std::map<std::string, std::string>> body_of;  // time -> particle id -> body id
  for (const auto& e : fs::directory_iterator(d / "u" / "particles_csv")) {
    const Table p = table(e.path());
    for (std::size_t r = 1; r < p.size(); ++r) body_of[p[r][0]][p[r][1]] = p[r].back();
  }
  int body_body = 0, body_sphere = 0;
  for (const auto& e : fs::directory_iterator(d / "u" / "contacts_csv")) {
    const Table c = table(e.path());
    EXPECT_EQ(c[0].at(c[0].size() - 3), "sliding");
    EXPECT_EQ(c[0].at(c[0].size() - 2), "first_body");
    EXPECT_EQ(c[0].back(), "second_body");
    for (std::size_t r = 1; r < c.size(); ++r) {
      ASSERT_TRUE(body_of.count(c[r][0])) << e.path() << ": no particle snapshot at t = " << c[r][0];
      const std::map<std::string, std::string>& at = body_of.at(c[r][0]);
      const std::string& first_body = c[r][c[r].size() - 2];
      EXPECT_EQ(first_body, at.at(c[r][1])) << e.path();
      EXPECT_EQ(c[r].back(), at.at(c[r][2])) << e.path();
      if (c[r].back() != "-1" && first_body != "-1") ++body_body;
      else ++body_sphere;
    }
  }
  EXPECT_GT(body_body, 0);
  EXPECT_GT(body_sphere, 0);
  fs::remove_all(d);
}

// A scene of spheres: no body columns in the log (its layout unchanged) and none in the contact CSV.
TEST(BodyCsv, SphereScenesKeepTheirColumns) {
  Scene s = make_scene(kDt, 1.0);
  add_particle(s, 1, 1e-3, {});
  const GlobalLogLayout spheres(s.model, s.barriers, {});
  for (const std::string& c : spheres.columns()) EXPECT_TRUE(c != "bodies" && c != "members") << c;
  add_template(s, "one", {{{0.0, 0.0, 0.0}, 1e-3}});
  const GlobalLogLayout clumps(s.model, s.barriers, {});
  EXPECT_EQ(clumps.columns().size(), spheres.columns().size() + 2);

  const fs::path d = fresh_dir("body_csv_sphere_contacts");
  ContactEntry e;
  e.first = 3;
  e.second = 4;
  write_contacts_csv(d / "c.csv", std::vector<ContactEntry>{e}, 0.5);
  EXPECT_EQ(table(d / "c.csv")[0].back(), "sliding");
  e.first_body = 11;
  write_contacts_csv(d / "b.csv", std::vector<ContactEntry>{e}, 0.5, true);
  EXPECT_EQ(table(d / "b.csv")[1].back(), "-1");
  EXPECT_EQ(table(d / "b.csv")[1].at(table(d / "b.csv")[1].size() - 2), "11");
  fs::remove_all(d);
}
