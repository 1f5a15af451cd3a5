// A particle CSV snapshot seeds a new scene as it is (docs/output.md "Particle CSV snapshots"):
// the snapshot of a periodic run, with its time, force, image and unwrapped columns, is read by
// `mpdem check` and `mpdem run` as a [[particles]] file.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"

using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {
// Two spheres moving along the periodic x axis: the first crosses the face x = 0.02 m.
const char* kScene = R"([time]
duration = 0.02
dt = 1e-5
integrator = "verlet"

[[material]]
name = "glass"

[[particles]]
file = "%s"

[domain]
min = [0.0, 0.0, 0.0]
max = [0.02, 0.02, 0.02]
periodic = ["x"]

[output]
particle_csv_every = 0.01
)";

std::string scene_reading(const std::string& particles) {
  std::string s = kScene;
  return s.replace(s.find("%s"), 2, particles);
}

// The fields of the row of particle `id` in a particle CSV snapshot (empty if there is none).
std::vector<std::string> row_of(const fs::path& snapshot, const std::string& id) {
  std::istringstream in(slurp(snapshot));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
    if (fields.size() > 1 && fields[1] == id) return fields;
  }
  return {};
}
}  // namespace

TEST(SnapshotSeed, APeriodicRunsSnapshotSeedsANewScene) {
  const fs::path d = fresh_dir("snapshot_seed");
  write_text(d / "p.csv", "id,x,y,z,vx,radius\n4,0.015,0.005,0.01,1.0,0.001\n9,0.005,0.015,0.01,-0.1,0.001\n");
  write_text(d / "scene.toml", scene_reading("p.csv"));
  const CommandResult first = run_mpdem("run scene.toml --quiet", d);
  ASSERT_EQ(first.status, 0) << first.err;
  const fs::path snapshot = d / "output" / "particles_csv" / "particles_000002.csv";
  ASSERT_NE(slurp(snapshot).find(",ix,iy,iz,xu,yu,zu"), std::string::npos);
  // Columns: time,id,x,...,fixed (19), then ix,iy,iz,xu,yu,zu, then tx,ty,tz, body. Particle 4 crossed the face once:
  // x = 0.035 m less one period.
  const std::vector<std::string> end = row_of(snapshot, "4");
  ASSERT_EQ(end.size(), 29u);
  EXPECT_NEAR(std::stod(end[0]), 0.02, 1e-12);  // s, the end (time as a sum of steps: round-off)
  EXPECT_EQ(end[19], "1");
  EXPECT_NEAR(std::stod(end[22]), 0.035, 1e-12);
  EXPECT_NEAR(std::stod(end[2]), 0.015, 1e-12);

  write_text(d / "seed.toml", scene_reading("output/particles_csv/particles_000002.csv"));
  const CommandResult check = run_mpdem("check seed.toml", d);
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.out.find("particles: 2"), std::string::npos) << check.out;
  const CommandResult second = run_mpdem("run seed.toml --quiet --output again", d);
  EXPECT_EQ(second.status, 0) << second.err;
  // The seeded run starts where the first ended: its first snapshot holds particle 4's state
  // (x..radius, printed with round-trip digits) at t = 0, with image counts 0.
  const std::vector<std::string> start = row_of(d / "again" / "particles_csv" / "particles_000000.csv", "4");
  ASSERT_EQ(start.size(), 29u);
  EXPECT_EQ(start[0], "0");
  for (std::size_t c = 2; c <= 11; ++c) EXPECT_EQ(start[c], end[c]) << "column " << c;
  EXPECT_EQ(start[19], "0");
  EXPECT_EQ(start[22], start[2]);
  fs::remove_all(d);
}
