// Inlets and sinks over several ranks (docs/parallel.md "Inlets and sinks"), run under mpirun
// -np 1, 2, 3, 4: a square funnel fed from above by an inlet and discharging through its orifice
// into a sink. The bricks cut the funnel, so particles are inserted, pass and are removed on
// different ranks, with their contact history. Against the same run on one rank, the same
// particles are inserted (ids, count, mass), and removed.csv names the same ids at the same times:
//  - a trickle (one sphere every 10 ms, rarely two in contact), both integrators;
//  - a discharge (8 g/s, a stream of spheres that meet on the walls and in the orifice): the
//    same, over about 60 removals. (A dense flow run long enough separates from the one-rank run
//    at the first contact that the ranks' summation order decides differently: docs/parallel.md.)
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "parallel/communicator.hpp"
#include "sim/inlets.hpp"
#include "sim/simulation.hpp"
#include "sim/sinks.hpp"
#include "support/open_system_scenes.hpp"
#include "support/shared_temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

// Walls sloping at 45 degrees from a square orifice of half-width h (m) at z = 0 up to half-width
// H at z = H - h, normals inwards: four trapezoids, two triangles each.
void add_funnel(Barriers& b, double h, double H, double young, double poisson) {
  const int g = b.group_index("funnel");
  const double nan = std::numeric_limits<double>::quiet_NaN(), top = H - h;
  const auto turn = [](const Vec3& p, int k) {  // k quarter turns about z
    Vec3 q = p;
    for (int i = 0; i < k; ++i) q = {-q.y, q.x, q.z};
    return q;
  };
  for (int k = 0; k < 4; ++k) {
    const Vec3 b0 = turn({-h, -h, 0.0}, k), b1 = turn({h, -h, 0.0}, k);
    const Vec3 t0 = turn({-H, -H, top}, k), t1 = turn({H, -H, top}, k);
    const auto id = static_cast<std::int64_t>(b.size());
    b.add(id, b0, t1, b1, g, young, poisson, MotionLaw{}, 0.0, nan);
    b.add(id + 1, b0, t0, t1, g, young, poisson, MotionLaw{}, 0.0, nan);
  }
}

// The fed box's particles and contact law (open_system_scenes.hpp), with the funnel (orifice
// 6 mm, 3 diameters) instead of the box; the inlet above it runs for 0.1 s, inserting spheres of
// 1 mm at 8 g/s (about 80; discharge) or one every 10 ms (trickle); the sink takes everything 5 mm
// below the orifice.
enum class Feed { Trickle, Discharge };
Scene hopper(Integrator integ, Feed feed) {
  Scene s = fed_box_scene(0.25, 0.008);
  Params& prm = s.model.params;
  prm.time.integrator = integ;
  s.barriers = Barriers{};
  add_funnel(s.barriers, 0.003, 0.013, 1e6, 0.3);
  InletSpec& in = prm.inlets.front();
  in.volume.region.min = {-0.008, -0.008, 0.012};
  in.volume.region.max = {0.008, 0.008, 0.020};
  in.end = 0.1;
  if (feed == Feed::Trickle) {
    in.mass_rate = 0.0;
    in.count_rate = 100.0;  // 1/s
    in.interval = 0.01;     // s
  }
  SinkSpec sink;
  sink.name = "outlet";
  sink.region.min = {-0.02, -0.02, -0.03};
  sink.region.max = {0.02, 0.02, -0.005};
  prm.sinks.push_back(sink);
  prm.domain.bounded = true;
  prm.domain.min = {-0.02, -0.02, -0.03};
  prm.domain.max = {0.02, 0.02, 0.03};
  prm.output.log_every = 500;
  return s;
}

// (time, id) of every row of removed.csv.
std::vector<std::pair<double, long long>> removals(const std::filesystem::path& file) {
  std::vector<std::pair<double, long long>> rows;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string t, id;
    std::getline(ls, t, ',');
    std::getline(ls, id, ',');
    rows.emplace_back(std::stod(t), std::stoll(id));
  }
  return rows;
}

struct Totals {
  std::uint64_t inserted = 0, removed = 0;
  double inserted_mass = 0.0, removed_mass = 0.0;  // kg
};

Totals totals(const Simulation& sim) {
  return {sim.inlets()->states()[0].inserted, sim.sinks()->states()[0].removed, sim.inlets()->states()[0].inserted_mass,
          sim.sinks()->states()[0].removed_mass};
}

std::string integrator_name(const ::testing::TestParamInfo<Integrator>& p) {
  return p.param == Integrator::Verlet ? "Verlet" : "Trapezoidal";
}

struct Compared {
  Totals one, many;
  std::vector<std::pair<double, long long>> removed_one, removed_many;  // (s, id)
};

// Runs the scene on one rank (rank 0) and on all, with outputs (collective).
Compared run_both(Integrator integ, Feed feed) {
  const Communicator& world = Communicator::world();
  const SharedTempDir dir(world, "hopper");
  Compared c;
  if (world.rank() == 0) {
    Simulation one(hopper(integ, feed), RunOptions{dir.path / "one", false, true, &Communicator::single()});
    one.run();
    c.one = totals(one);
  }
  Simulation many(hopper(integ, feed), RunOptions{dir.path / "many", false, true, &world});
  many.run();
  c.many = totals(many);  // the same on every rank
  const std::uint64_t held = world.sum(static_cast<std::uint64_t>(many.particles().size()));
  EXPECT_EQ(held, c.many.inserted - c.many.removed);  // nobody lost or duplicated
  if (world.rank() == 0) {
    c.removed_one = removals(dir.path / "one" / "removed.csv");
    c.removed_many = removals(dir.path / "many" / "removed.csv");
    std::printf("[%d ranks, %s, %s] inserted %llu (%.6g kg) vs %llu (%.6g kg); removed %llu (%.6g kg) vs %llu "
                "(%.6g kg); first removal at %.6g s\n",
                world.size(), feed == Feed::Trickle ? "trickle" : "discharge",
                integ == Integrator::Verlet ? "verlet" : "trapezoidal", static_cast<unsigned long long>(c.one.inserted),
                c.one.inserted_mass, static_cast<unsigned long long>(c.many.inserted), c.many.inserted_mass,
                static_cast<unsigned long long>(c.one.removed), c.one.removed_mass,
                static_cast<unsigned long long>(c.many.removed), c.many.removed_mass,
                c.removed_one.empty() ? -1.0 : c.removed_one.front().first);
    EXPECT_EQ(c.many.inserted, c.one.inserted);
    EXPECT_EQ(c.many.inserted_mass, c.one.inserted_mass);  // the same particles, in the same order
  }
  return c;
}

}  // namespace

class DecomposedTrickle : public ::testing::TestWithParam<Integrator> {};

TEST_P(DecomposedTrickle, RemovesTheSameIdsAtTheSameTimes) {
  const Compared c = run_both(GetParam(), Feed::Trickle);
  if (Communicator::world().rank() != 0) return;
  EXPECT_EQ(c.one.inserted, 10u);
  EXPECT_GE(c.one.removed, 8u);  // the funnel drains
  EXPECT_EQ(c.many.removed, c.one.removed);
  EXPECT_NEAR(c.many.removed_mass, c.one.removed_mass, 1e-12 * c.one.removed_mass);
  EXPECT_EQ(c.removed_many, c.removed_one);  // ids and times
}

INSTANTIATE_TEST_SUITE_P(Integrators, DecomposedTrickle, ::testing::Values(Integrator::Verlet, Integrator::Trapezoidal),
                         integrator_name);

TEST(DecomposedDischarge, RemovesTheSameIdsAtTheSameTimes) {
  const Compared c = run_both(Integrator::Verlet, Feed::Discharge);
  if (Communicator::world().rank() != 0) return;
  EXPECT_GT(c.one.inserted, 50u);
  EXPECT_GT(c.one.removed, 40u);  // a discharge, not a trickle
  EXPECT_EQ(c.many.removed, c.one.removed);
  EXPECT_NEAR(c.many.removed_mass, c.one.removed_mass, 1e-12 * c.one.removed_mass);
  EXPECT_EQ(c.removed_many, c.removed_one);  // ids and times
}
