// Contact snapshots and coarse-grained fields on several ranks (docs/output.md "Contact
// snapshots", "Coarse-grained fields"; ctest runs this under mpirun -np 1, 2, 3, 4) against the
// one-rank run of the same scene: a frictional cluster settling in an open box (pairs across the
// brick cuts, barrier contacts on every rank) runs 600 steps with a contact snapshot every 200
// steps, a time-averaged coarse-grained profile along z and an instantaneous profile along x (the
// axis the bricks cut), then on rank 0 alone. Rank 0's files:
//  - contacts.pvd lists the one-rank run's snapshot times; each contact CSV has the one-rank
//    run's rows: the same (first, second, element) keys in the same (sorted) order, each
//    cross-rank pair once, every number equal to 1e-10 of its column's largest magnitude (the
//    rank-count round-off of docs/parallel.md), ids and the sliding flag exactly;
//  - each profile CSV has the one-rank run's rows and times, every column equal to 1e-10 of its
//    largest magnitude.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "parallel/communicator.hpp"
#include "sim/simulation.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/shared_temp_dir.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kDt = 2e-6;  // s
constexpr int kSteps = 600;

CoarseGrainSpec profile(const std::string& name, int axis, double lo, double hi, int bins, double average) {
  CoarseGrainSpec c;
  c.name = name;
  c.profile = true;
  c.axis = axis;
  double min[3] = {0.0, 0.0, 0.0}, max[3] = {0.0128, 0.0128, 0.012};  // m, the box
  min[axis] = lo;
  max[axis] = hi;
  c.grid.min = {min[0], min[1], min[2]};
  c.grid.max = {max[0], max[1], max[2]};
  c.grid.cells = {1, 1, 1};
  c.grid.resolved = {false, false, false};
  c.grid.cells[static_cast<std::size_t>(axis)] = bins;
  c.grid.resolved[static_cast<std::size_t>(axis)] = true;
  c.kernel = CgKernel::gaussian;
  c.width = 1e-3;
  c.every = 300 * kDt;
  c.average = average;
  c.samples = 10;
  return c;
}

// 6 x 6 x 5 spheres (r = 1-1.05 mm) settling in an open box of 12.8 mm, with friction.
Scene cluster() {
  Scene s = dense_scene(6, 6, 5, 1e-3, 0.05, 2.12e-3, 0.15, 5, kDt);
  Params& prm = s.model.params;
  prm.time.duration = kSteps * kDt;
  prm.output.contacts_every = 200 * kDt;
  prm.coarse_grain.push_back(profile("z", 2, 0.0, 0.012, 24, 100 * kDt));
  prm.coarse_grain.push_back(profile("x", 0, 0.0, 0.0128, 16, 0.0));
  return s;
}

// A CSV file: header names and rows of numbers.
struct Csv {
  std::vector<std::string> head;
  std::vector<std::vector<double>> rows;
};
Csv read_csv(const fs::path& f) {
  Csv c;
  std::ifstream in(f);
  std::string line;
  std::getline(in, line);
  std::stringstream h(line);
  for (std::string name; std::getline(h, name, ',');) c.head.push_back(name);
  while (std::getline(in, line)) {
    std::stringstream r(line);
    std::vector<double> row;
    for (std::string v; std::getline(r, v, ',');) row.push_back(std::stod(v));
    c.rows.push_back(std::move(row));
  }
  return c;
}

// Largest |a - b| over a column divided by the column's largest |b|, worst over the columns;
// `exact` columns (by index) must agree bitwise. Rows and columns must match in number.
double compare(const Csv& a, const Csv& b, const std::vector<std::size_t>& exact, const std::string& what) {
  EXPECT_EQ(a.head, b.head) << what;
  EXPECT_EQ(a.rows.size(), b.rows.size()) << what;
  if (a.head != b.head || a.rows.size() != b.rows.size()) return 1.0;
  double worst = 0.0;
  for (std::size_t c = 0; c < b.head.size(); ++c) {
    double scale = 0.0, diff = 0.0;
    for (std::size_t r = 0; r < b.rows.size(); ++r) {
      scale = std::max(scale, std::abs(b.rows[r].at(c)));
      diff = std::max(diff, std::abs(a.rows[r].at(c) - b.rows[r].at(c)));
    }
    const bool is_exact = std::find(exact.begin(), exact.end(), c) != exact.end();
    if (is_exact) EXPECT_EQ(diff, 0.0) << what << " column " << b.head[c];
    else if (scale > 0.0) worst = std::max(worst, diff / scale);
  }
  return worst;
}

// Rank 0: compares the analysis outputs of `many` (run on `ranks` ranks) with the one-rank run's.
void compare_runs(const fs::path& many_dir, const fs::path& one_dir, int ranks, const char* label) {
  // Contact snapshots: t = 200, 400, 600 steps.
  std::size_t snapshots = 0, contacts = 0, pairs = 0, walls = 0;
  double worst = 0.0;
  for (const auto& e : fs::directory_iterator(one_dir / "contacts_csv")) {
    const Csv b = read_csv(e.path()), a = read_csv(many_dir / "contacts_csv" / e.path().filename());
    worst = std::max(worst, compare(a, b, {0, 1, 2, 3, 17}, e.path().filename().string()));
    for (const auto& r : b.rows) (r.at(3) >= 0 ? walls : pairs) += 1;
    contacts += b.rows.size();
    ++snapshots;
  }
  EXPECT_EQ(snapshots, 3u);
  EXPECT_GT(pairs, 100u);
  EXPECT_GT(walls, 20u);
  std::ifstream pa(many_dir / "contacts.pvd"), pb(one_dir / "contacts.pvd");
  std::stringstream sa, sb;
  sa << pa.rdbuf();
  sb << pb.rdbuf();
  EXPECT_EQ(sa.str(), sb.str());
  // Coarse-grained profiles: t = 300 and 600 steps.
  double worst_cg = 0.0;
  for (const auto& [name, bins] : {std::pair{"cg_z.csv", 24u}, std::pair{"cg_x.csv", 16u}}) {
    const Csv b = read_csv(one_dir / name), a = read_csv(many_dir / name);
    EXPECT_EQ(b.rows.size(), 2 * bins) << name;
    worst_cg = std::max(worst_cg, compare(a, b, {0, 1}, name));
  }
  std::printf("[%d ranks%s] %zu contact snapshots (%zu pair and %zu barrier rows): largest relative deviation from "
              "the one-rank run %.2e; coarse-grained profiles %.2e\n",
              ranks, label, snapshots, pairs, walls, worst, worst_cg);
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worst_cg, 1e-10);
  EXPECT_EQ(contacts, pairs + walls);
}

}  // namespace

TEST(AnalysisOutputsOnRanks, EqualTheOneRankRun) {
  const Communicator& world = Communicator::world();
  const SharedTempDir root(world, "analysis");
  const fs::path many_dir = root.path / "ranks", one_dir = root.path / "one";
  Simulation many(cluster(), RunOptions{many_dir, false, true, &world});
  many.run();
  world.barrier();
  if (world.rank() == 0) {
    Simulation one(cluster(), RunOptions{one_dir, false, true, &Communicator::single()});
    one.run();
    compare_runs(many_dir, one_dir, world.size(), "");
  }
}

// Checkpointed on all ranks at step 250, in the middle of the z profile's averaging window
// (samples at steps 210, 220, ..., 300) and between contact snapshots, and resumed on all ranks
// into the same folder: the series continue as if never interrupted.
TEST(AnalysisOutputsOnRanks, ResumedMidWindowContinueTheSeries) {
  const Communicator& world = Communicator::world();
  const SharedTempDir root(world, "analysis_resumed");
  const fs::path dir = root.path / "resumed", one_dir = root.path / "one";
  {
    Simulation first(cluster(), RunOptions{dir, false, true, &world});
    for (int k = 0; k < 250; ++k) first.step(kSteps * kDt);
    first.write_checkpoint(dir / "checkpoint.bin");  // collective
  }
  world.barrier();
  {
    Simulation second(cluster(), RunOptions{dir, false, true, &world});
    second.resume_from(dir / "checkpoint.bin");
    second.run();
  }
  world.barrier();
  if (world.rank() == 0) {
    Simulation one(cluster(), RunOptions{one_dir, false, true, &Communicator::single()});
    one.run();
    compare_runs(dir, one_dir, world.size(), ", resumed at step 250");
  }
}
