// The analysis outputs of a run (output/analysis_outputs.hpp): contact snapshots (CSV and VTU) whose
// listed forces sum to each particle's contact force, read back by meshio and VTK; a
// [[coarse_grain]] profile of a bed whose mass balances; a resume that continues both series.
#include <gtest/gtest.h>
#include <fmt/core.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/csv_table.hpp"
#include "sim/simulation.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/shell_output.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

// Rows of a CSV file as numbers, by column name.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::size_t col(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return k;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};
Csv read_csv(const fs::path& f) {
  std::ifstream in(f);
  Csv c;
  std::string line, cell;
  std::getline(in, line);
  for (std::stringstream hs(line); std::getline(hs, cell, ',');) c.header.push_back(cell);
  while (std::getline(in, line)) {
    std::vector<double> r;
    for (std::stringstream ls(line); std::getline(ls, cell, ',');) r.push_back(std::stod(cell));
    c.rows.push_back(r);
  }
  return c;
}

constexpr double kDt = 1e-6;

Scene bed_scene(Integrator integ) {
  Scene s = dense_scene(4, 4, 3, 1e-3, 0.05, 2.09e-3, 0.15, 7, kDt);
  Params& prm = s.model.params;
  prm.time.integrator = integ;
  prm.time.duration = 300 * kDt;
  prm.output.contacts_every = 100 * kDt;
  prm.output.particle_csv_every = 100 * kDt;
  return s;
}

}  // namespace

TEST(AnalysisOutputs, ContactSnapshotsSumToEachParticlesContactForce) {
  omp_set_num_threads(1);
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    TempDir dir("analysis");
    Scene s = bed_scene(integ);
    const Vec3 g = s.model.params.fields.gravity;
    Simulation sim(std::move(s), RunOptions{dir.path, false, true});
    sim.run();
    // Snapshots at 100, 200, 300 steps; the last one against the particle CSV of the same time.
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(fs::exists(dir.path / fmt::format("contacts_csv/contacts_{:06d}.csv", k)));
    const Csv c = read_csv(dir.path / "contacts_csv/contacts_000002.csv");
    const Csv p = read_csv(dir.path / "particles_csv/particles_000003.csv");
    ASSERT_EQ(c.rows.front()[0], p.rows.front()[0]);  // the same time
    std::map<std::int64_t, Vec3> sum;
    std::size_t pairs = 0, walls = 0;
    for (const auto& r : c.rows) {
      const Vec3 f{r[c.col("fnx")] + r[c.col("ftx")], r[c.col("fny")] + r[c.col("fty")],
                   r[c.col("fnz")] + r[c.col("ftz")]};
      sum[static_cast<std::int64_t>(r[c.col("first")])] += f;
      const auto second = static_cast<std::int64_t>(r[c.col("second")]);
      if (second >= 0) sum[second] -= f;  // Newton's third law
      (second >= 0 ? pairs : walls) += 1;
    }
    ASSERT_GT(pairs, 10u);
    ASSERT_GT(walls, 10u);
    double scale = 0.0;
    std::vector<Vec3> contact_force;
    for (const auto& r : p.rows) {
      const double rad = r[p.col("radius")];
      const double mass = sim.particles().mass[0] * std::pow(rad / sim.particles().radius[0], 3);
      const Vec3 f = Vec3{r[p.col("fx")], r[p.col("fy")], r[p.col("fz")]} - mass * g;
      contact_force.push_back(f);
      scale = std::max({scale, std::abs(f.x), std::abs(f.y), std::abs(f.z)});
    }
    for (std::size_t k = 0; k < p.rows.size(); ++k) {
      const Vec3 listed = sum[static_cast<std::int64_t>(p.rows[k][p.col("id")])];
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(listed[a], contact_force[k][a], 1e-12 * scale) << k << " " << a;
    }
    // The VTU: meshio and VTK read it, one line cell per CSV row, with the CSV's ids and forces.
    const fs::path vtu = dir.path / "contacts/contacts_000002.vtu";
    const std::string reader = std::string("/usr/bin/python3 '") + MPDEM_SOURCE_DIR + "/tests/read_vtu.py' ";
    const std::string meshio = shell(reader + "'" + vtu.string() + "'");
    EXPECT_NE(meshio.find(fmt::format("cells line {} 2", c.rows.size())), std::string::npos) << meshio.substr(0, 300);
    EXPECT_NE(meshio.find(fmt::format("cell_data first {} 1\n{}\n", c.rows.size(),
                                      static_cast<std::int64_t>(c.rows[0][c.col("first")]))),
              std::string::npos);
    const std::string vtk = shell(reader + "--vtk '" + vtu.string() + "'");
    EXPECT_NE(vtk.find(fmt::format("cell_data normal_force {} 3", c.rows.size())), std::string::npos);
    EXPECT_NE(fs::file_size(dir.path / "contacts.pvd"), 0u);
  }
}

// A [[coarse_grain]] profile along z, averaged over x and y across the bed: its density
// integrates to the bed's mass (midpoint rule on bins 1/8 of the width: 1e-4), and a grid's
// .vti series is listed in its .pvd; outputs at every `every`, averaged over `samples`.
TEST(AnalysisOutputs, CoarseGrainedProfileHoldsTheBedsMass) {
  omp_set_num_threads(1);
  TempDir dir("analysis");
  Scene s = bed_scene(Integrator::Verlet);
  s.model.params.output.contacts_every = 0.0;
  double mass = 0.0;
  for (double m : s.particles.mass) mass += m;
  CoarseGrainSpec profile;
  profile.name = "z";
  profile.profile = true;
  profile.axis = 2;
  profile.width = 1e-3;
  profile.every = 100 * kDt;
  profile.average = 50 * kDt;
  profile.samples = 5;
  const double side = 4 * 2.09e-3;
  profile.grid.min = {-0.01, -0.01, -0.01};
  profile.grid.max = {side + 0.01, side + 0.01, 0.02};
  profile.grid.cells = {1, 1, 240};  // bins of 1.25e-4 m
  profile.grid.resolved = {false, false, true};
  CoarseGrainSpec grid = profile;
  grid.name = "box";
  grid.profile = false;
  grid.grid.cells = {4, 4, 6};
  grid.grid.resolved = {true, true, true};
  grid.average = 0.0;
  s.model.params.coarse_grain = {profile, grid};
  Simulation sim(std::move(s), RunOptions{dir.path, false, true});
  sim.run();
  const Csv c = read_csv(dir.path / "cg_z.csv");
  ASSERT_EQ(c.rows.size(), 3u * 240u);  // three outputs (100, 200, 300 steps) of 240 bins
  const double area = (side + 0.02) * (side + 0.02), bin = 0.03 / 240;
  for (int out = 0; out < 3; ++out) {
    double integral = 0.0;
    for (int k = 0; k < 240; ++k) integral += c.rows[static_cast<std::size_t>(out * 240 + k)][c.col("density")] * bin;
    EXPECT_NEAR(integral * area, mass, 1e-4 * mass) << "output " << out;
    EXPECT_NEAR(c.rows[static_cast<std::size_t>(out * 240)][0], (out + 1) * 100 * kDt, 1e-12);
  }
  const std::string pvd = [&] {
    std::ifstream in(dir.path / "cg_box.pvd");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  EXPECT_NE(pvd.find("cg_box/cg_box_000002.vti"), std::string::npos);
  const std::string reader = std::string("/usr/bin/python3 '") + MPDEM_SOURCE_DIR + "/tests/read_vtu.py' --vtk ";
  const std::string vtk = shell(reader + "'" + (dir.path / "cg_box/cg_box_000002.vti").string() + "'");
  EXPECT_NE(vtk.find("point_data density 96 1"), std::string::npos) << vtk.substr(0, 400);
  EXPECT_NE(vtk.find("point_data stress 96 9"), std::string::npos);
}
