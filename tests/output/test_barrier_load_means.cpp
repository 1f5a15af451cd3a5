// Barrier loads averaged over each output interval (output/barrier_load_means.hpp, [output]
// barrier_loads): a sphere resting on a plate loads it with exactly its weight; an oscillating
// load sampled evenly over whole periods averages to its mean; "sample" keeps the last
// evaluation's loads; the means continue across a checkpoint.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "output/barrier_load_means.hpp"
#include "model/scene.hpp"
#include "sim/simulation.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
using mpdem::test::TempDir;

namespace {

Barriers two_elements() {
  Barriers b;
  EXPECT_TRUE(b.add(1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1e9, 0.3, MotionLaw{}, 0.0, 300.0));
  EXPECT_TRUE(b.add(2, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, 0, 1e9, 0.3, MotionLaw{}, 0.0, 300.0));
  return b;
}

// The last row of a CSV file, by column name.
double last_value(const std::filesystem::path& f, const std::string& column) {
  std::ifstream in(f);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::stringstream hs(header), ls(last);
  std::string name, value;
  while (std::getline(hs, name, ',')) {
    std::getline(ls, value, ',');
    if (name == column) return std::stod(value);
  }
  ADD_FAILURE() << "no column " << column << " in " << f;
  return 0.0;
}

// A glass sphere of radius 5 mm at height z over a 0.1 m square plate (group "plate"), run for
// `duration` s with barrier_groups.csv rows every `log_every` s and the given barrier_loads.
std::filesystem::path plate_scene(const TempDir& d, double z, double restitution, double duration, double log_every,
                                  const std::string& kind) {
  d.write("plate.csv", "id,x1,y1,z1,x2,y2,z2,x3,y3,z3,group\n1,-0.05,-0.05,0,0.05,-0.05,0,0.05,0.05,0,plate\n"
                       "2,-0.05,-0.05,0,0.05,0.05,0,-0.05,0.05,0,plate\n");
  d.write("ball.csv", "id,x,y,z,radius\n1,0.001,0.002," + std::to_string(z) + ",0.005\n");
  return d.write("scene.toml", "[time]\nduration = " + std::to_string(duration) +
                                   "\nintegrator = \"verlet\"\ndt = 1e-5\n[gravity]\nvector = [0.0, 0.0, -9.81]\n"
                                   "[contact.particle_barrier]\nrestitution = " +
                                   std::to_string(restitution) +
                                   "\nmu_static = 0.5\nmu_dynamic = 0.5\n[[material]]\nname = \"glass\"\n"
                                   "density = 2500.0\nyoung = 1e7\npoisson = 0.3\n[[particles]]\nfile = \"ball.csv\"\n"
                                   "material = \"glass\"\n[[barriers]]\nfile = \"plate.csv\"\nmaterial = \"glass\"\n"
                                   "[output]\nbarrier_log_every = " +
                                   std::to_string(log_every) +
                                   "\nlog_every = 1000\nprogress_every = 0\nbarrier_loads = \"" + kind + "\"\n");
}

}  // namespace

TEST(BarrierLoadMeans, OscillatingLoadOverWholePeriodsIsItsMean) {
  Barriers b = two_elements();
  BarrierLoadMeans means;
  const double period = 0.01, f0 = 2.5, amp = 7.0;  // s, N, N
  const int steps = 1000;                           // 4 periods of 250 steps
  const double h = 4 * period / steps;
  double peak = 0.0;  // Pa, largest distance of a sample of the pressure from its mean
  for (int k = 1; k <= steps; ++k) {
    const double t = k * h;
    const double s = std::sin(2.0 * std::numbers::pi * t / period);
    b.force[0] = {f0 + amp * s, -f0, 0.0};
    b.force[1] = {0.0, 0.0, -amp * s};
    b.moment[0] = {0.0, 0.1 * amp * s, 0.0};
    b.pressure[0] = 1e3 * (1.0 + s);
    means.add(b, h);
    peak = std::max(peak, std::abs(b.pressure[0] - 1e3));
  }
  EXPECT_NEAR(means.span(), 4 * period, 1e-15);
  const BarrierLoads m = means.mean(b);
  EXPECT_NEAR(m.force[0].x, f0, 1e-9 * f0);
  EXPECT_NEAR(m.force[0].y, -f0, 1e-9 * f0);
  EXPECT_NEAR(m.force[1].z, 0.0, 1e-9 * amp);
  EXPECT_NEAR(m.moment[0].y, 0.0, 1e-9 * amp);
  EXPECT_NEAR(m.pressure[0], 1e3, 1e-9 * 1e3);
  // The samples were far from the mean: the test tells the mean from any one of them.
  EXPECT_GT(peak, 999.0);
  means.clear();
  EXPECT_EQ(means.span(), 0.0);
  EXPECT_EQ(means.mean(b).pressure[0], b.pressure[0]);  // nothing added: the current sample
}

TEST(BarrierLoadMeans, MeansSurviveSaveAndRestore) {
  Barriers b = two_elements();
  BarrierLoadMeans a;
  b.force[1] = {1.0, 2.0, 3.0};
  a.add(b, 0.5);
  b.force[1] = {3.0, 2.0, 1.0};
  a.add(b, 0.25);
  BinaryWriter w;
  a.save(w);
  BinaryReader r(w.bytes().data(), w.bytes().size());
  BarrierLoadMeans c;
  c.restore(r);
  EXPECT_TRUE(r.at_end());
  EXPECT_EQ(c.span(), 0.75);
  EXPECT_EQ(c.mean(b).force[1], a.mean(b).force[1]);
  EXPECT_NEAR(c.mean(b).force[1].x, (0.5 + 0.75) / 0.75, 1e-15);
}

// A sphere dropped onto a plate comes to rest; the plate's mean load over the last logging
// interval is the sphere's weight (round-off: 1e-9 relative), with either kind of load output.
TEST(BarrierLoadMeans, SphereRestingOnAPlateLoadsItWithItsWeight) {
  for (const char* kind : {"mean", "sample"}) {
    TempDir d("mpdem_load_means");
    const auto scene = plate_scene(d, 0.0052, 0.1, 0.3, 0.01, kind);
    Simulation sim(load_scene(scene), RunOptions{d.path / "out", false, true});
    sim.run();
    const double weight = sim.particles().mass[0] * 9.81;
    EXPECT_NEAR(last_value(d.path / "out" / "barrier_groups.csv", "plate.fz"), -weight, 1e-9 * weight) << kind;
    EXPECT_NEAR(last_value(d.path / "out" / "barrier_groups.csv", "plate.fx"), 0.0, 1e-9 * weight) << kind;
  }
}

// While the sphere bounces, the mean over an interval differs from the sample at its end; the
// time integral of the plate's load over the first 0.1 s equals the momentum it took (weight x
// time less the sphere's momentum change), which only the mean reproduces.
TEST(BarrierLoadMeans, MeanDiffersFromTheSampleWhileTheSphereBounces) {
  std::vector<double> rows[2];
  int k = 0;
  for (const char* kind : {"mean", "sample"}) {
    TempDir d("mpdem_load_means");
    const auto scene = plate_scene(d, 0.02, 0.5, 0.1, 0.1, kind);
    Simulation sim(load_scene(scene), RunOptions{d.path / "out", false, true});
    sim.run();
    const double m = sim.particles().mass[0];
    // Momentum balance over [0, 0.1 s]: the plate's impulse on the sphere = m (v_end - 0) + m g t.
    const double impulse_on_plate = -(m * sim.particles().v[0].z + m * 9.81 * 0.1);
    rows[k++].push_back(last_value(d.path / "out" / "barrier_groups.csv", "plate.fz") * 0.1 - impulse_on_plate);
    rows[k - 1].push_back(impulse_on_plate);
  }
  // mean x 0.1 s is the impulse (rectangle rule with end-of-step loads over 10^4 steps: 1e-3)
  EXPECT_NEAR(rows[0][0], 0.0, 1e-3 * std::abs(rows[0][1]));
  EXPECT_GT(std::abs(rows[1][0]), 1e-2 * std::abs(rows[1][1]));  // the sample is not
}
