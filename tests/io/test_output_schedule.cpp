// When the periodic outputs are written: every series that promises a last snapshot at the end
// (particle and barrier VTU, particle CSV, barrier-group log) has it exactly once, at the final
// time - also when the step does not divide the interval and a periodic snapshot would fall
// within half a step of the end.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/pvd_index.hpp"
#include "sim/simulation.hpp"
#include "support/output_folder.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using test::output::OutputTest;
namespace fs = std::filesystem;

namespace {
constexpr double kEvery = 0.005;    // s, every periodic output
constexpr double kDuration = 0.25;  // s
constexpr int kSnapshots = 51;      // t = 0, 0.005, ..., 0.25

void run_scene(const fs::path& dir, double dt) {
  Scene s = test::make_scene(dt, kDuration);
  Params& prm = s.model.params;
  prm.time.integrator = Integrator::Verlet;
  prm.fields.gravity = {};
  OutputParams& o = prm.output;
  o.particles_every = o.barriers_every = o.particle_csv_every = o.barrier_log_every = kEvery;
  o.log_every = 1000;
  test::add_particle(s, 1, 0.001, {0, 0, 0.01}, {0.01, 0, 0});
  const int g = s.barriers.group_index("floor");
  s.barriers.add(77, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, g, 1e7, 0.3, {}, 0.0, NAN);
  Simulation sim(std::move(s), RunOptions{dir, false, true});
  const RunSummary sum = sim.run();
  EXPECT_EQ(sum.time, sim.time());
  EXPECT_NEAR(sum.time, kDuration, 1e-12);
}

void expect_series_ends_once_at_the_end(const std::vector<double>& times, const std::string& what) {
  ASSERT_EQ(times.size(), static_cast<std::size_t>(kSnapshots)) << what;
  EXPECT_NEAR(times.back(), kDuration, 1e-12) << what << ": the last snapshot is not at the end";
  for (std::size_t k = 1; k < times.size(); ++k)
    EXPECT_GT(times[k] - times[k - 1], 0.5 * kEvery) << what << ": snapshots " << k - 1 << " and " << k;
}

std::vector<double> pvd_times(const fs::path& file) {
  const PvdIndex pvd(file, 1e300);
  std::vector<double> t;
  for (const PvdIndex::Entry& e : pvd.entries()) t.push_back(e.time);
  return t;
}

// The `time` column (first) of a CSV's rows.
std::vector<double> csv_times(const fs::path& file) {
  std::vector<double> t;
  const auto lines = test::output::lines_of(test::output::slurp(file));
  for (std::size_t k = 1; k < lines.size(); ++k)
    if (!lines[k].empty()) t.push_back(std::stod(lines[k]));
  return t;
}

void expect_every_series_ends_at_the_end(const fs::path& dir) {
  expect_series_ends_once_at_the_end(pvd_times(dir / "particles.pvd"), "particles.pvd");
  expect_series_ends_once_at_the_end(pvd_times(dir / "barriers.pvd"), "barriers.pvd");
  expect_series_ends_once_at_the_end(csv_times(dir / "barrier_groups.csv"), "barrier_groups.csv");
  std::vector<double> csv;
  for (int k = 0; k < kSnapshots; ++k) {
    const fs::path f = dir / "particles_csv" /
                       ("particles_" + std::string(6 - std::to_string(k).size(), '0') + std::to_string(k) + ".csv");
    ASSERT_TRUE(fs::exists(f)) << f;
    csv.push_back(csv_times(f).at(0));
  }
  EXPECT_FALSE(fs::exists(dir / "particles_csv" / "particles_000051.csv")) << "a duplicate at the end";
  expect_series_ends_once_at_the_end(csv, "particles_csv");
}
}  // namespace

using OutputSchedule = OutputTest;

// 3e-5 s does not divide 0.005 s: the step before the end finishes at 0.24999 s, within half a
// step of the snapshot due at 0.25 s, which must still be written at 0.25 s.
TEST_F(OutputSchedule, LastSnapshotIsAtTheEndWhenTheStepDoesNotDivideTheInterval) {
  run_scene(dir, 3e-5);
  expect_every_series_ends_at_the_end(dir);
}

// 1e-4 s divides it: the last periodic snapshot is the end's, written once.
TEST_F(OutputSchedule, NoDuplicateAtTheEndWhenTheStepDividesTheInterval) {
  run_scene(dir, 1e-4);
  expect_every_series_ends_at_the_end(dir);
}
