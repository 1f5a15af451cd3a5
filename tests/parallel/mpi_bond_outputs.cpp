// The parallel bonds' outputs over several ranks (docs/output.md "bonds_broken.csv", "Bond VTU"),
// run under mpirun -np 1, 2, 3, 4: a bonded slab of 16 x 3 spheres, its left column held, its
// right column drawn away at a prescribed velocity until bonds break in tension and shear, cut
// across by the bricks so that bonds join particles of two ranks and break there. Rank 0's
// bonds_broken.csv, bond VTU series and log columns are the one-rank run's: the same breaks (ids,
// modes, times) with their stresses within 1e-8, the same cells with every array within 1e-8 of
// its largest magnitude, the same bond counts in the log.
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
#include "support/bonded_scenes.hpp"
#include "support/shared_temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

constexpr double kDt = 2e-7;  // s
constexpr int kNx = 16, kNy = 3;

Scene slab() {
  Scene s = bonded_scene(kDt, Integrator::Verlet, 0.3, 0.0);
  BondKeys& k = *s.model.params.bonds.defaults;
  k.tensile_strength = 3e5;
  k.shear_strength = 4.5e4;
  std::int64_t id = 0;
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i) {
      const std::size_t n = add_particle(s, ++id, kBondR, {2.0 * kBondR * i, 2.0 * kBondR * j, 0.0});
      if (i == 0) s.particles.fixed[n] = 1;
      if (i == kNx - 1) {
        s.particles.fixed[n] = 1;
        s.particles.v[n] = {0.03, 0.08, 0.0};  // m/s
      }
    }
  DomainParams& d = s.model.params.domain;
  d.bounded = true;
  d.min = {-3e-3, -3e-3, -3e-3};
  d.max = {35e-3, 9e-3, 3e-3};
  s.model.params.time.duration = 2000 * kDt;
  OutputParams& o = s.model.params.output;
  o.format = VtkFormat::Ascii;
  o.bonds_every = 500 * kDt;
  o.log_every = 100;
  return s;
}

std::vector<std::vector<std::string>> csv_rows(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    rows.push_back(std::move(f));
  }
  return rows;
}

// The numbers of each DataArray of an ASCII VTU file, in file order.
std::vector<std::vector<double>> vtu_arrays(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  std::vector<std::vector<double>> arrays;
  for (std::size_t at = text.find("<DataArray"); at != std::string::npos; at = text.find("<DataArray", at + 1)) {
    const std::size_t from = text.find('>', at) + 1, to = text.find("</DataArray>", from);
    std::stringstream values(text.substr(from, to - from));
    arrays.emplace_back();
    for (double v; values >> v;) arrays.back().push_back(v);
  }
  return arrays;
}

}  // namespace

TEST(BondOutputsAcrossRanks, AreTheOneRankRuns) {
  const Communicator& world = Communicator::world();
  const SharedTempDir dir(world, "bond_outputs");
  {
    Simulation many(slab(), RunOptions{dir.path / "many", false, true, &world, false});
    many.run();
  }
  if (world.rank() != 0) return;
  Simulation one(slab(), RunOptions{dir.path / "one", false, true, &Communicator::single(), false});
  one.run();
  // bonds_broken.csv: the same breaks in the same order.
  const auto ref = csv_rows(dir.path / "one" / "bonds_broken.csv"),
             got = csv_rows(dir.path / "many" / "bonds_broken.csv");
  ASSERT_GT(ref.size(), 3u);  // the header and some breaks
  ASSERT_EQ(got.size(), ref.size());
  std::size_t shear = 0;
  double worst = 0.0;
  for (std::size_t r = 0; r < ref.size(); ++r) {
    ASSERT_EQ(got[r].size(), 6u);
    for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(got[r][c], ref[r][c]) << "row " << r;
    if (r == 0) continue;
    shear += ref[r][3] == "shear" ? 1 : 0;
    for (std::size_t c = 4; c < 6; ++c)
      worst = std::max(worst, std::abs(std::stod(got[r][c]) - std::stod(ref[r][c])) / std::stod(ref[r][4]));
  }
  EXPECT_GT(shear, 0u);
  EXPECT_LT(shear, ref.size() - 1);  // both modes
  EXPECT_LT(worst, 1e-8);
  // The bond VTU series: the same cells, each array within 1e-8 of its largest magnitude.
  double vtu_worst = 0.0;
  for (int k = 0; k <= 4; ++k) {
    const std::string name = "bonds/bonds_00000" + std::to_string(k) + ".vtu";
    const auto a = vtu_arrays(dir.path / "one" / name), b = vtu_arrays(dir.path / "many" / name);
    ASSERT_EQ(a.size(), b.size()) << name;
    ASSERT_GT(a.size(), 10u) << name;
    for (std::size_t m = 0; m < a.size(); ++m) {
      ASSERT_EQ(a[m].size(), b[m].size()) << name << " array " << m;
      double scale = 0.0;
      for (const double v : a[m]) scale = std::max(scale, std::abs(v));
      for (std::size_t q = 0; q < a[m].size(); ++q)
        if (scale > 0.0) vtu_worst = std::max(vtu_worst, std::abs(a[m][q] - b[m][q]) / scale);
    }
  }
  EXPECT_LT(vtu_worst, 1e-8);
  // log.csv: the bond counts row by row.
  const auto la = csv_rows(dir.path / "one" / "log.csv"), lb = csv_rows(dir.path / "many" / "log.csv");
  ASSERT_EQ(la.size(), lb.size());
  ASSERT_FALSE(la.empty());
  for (const char* name : {"bonds", "bonds_broken", "bonds_broken_interval"}) {
    const auto c = static_cast<std::size_t>(std::find(la[0].begin(), la[0].end(), name) - la[0].begin());
    ASSERT_LT(c, la[0].size()) << name;
    EXPECT_EQ(lb[0][c], name);
    for (std::size_t r = 1; r < la.size(); ++r) EXPECT_EQ(lb[r][c], la[r][c]) << name << " row " << r;
  }
  std::printf("[%d ranks] %zu breaks (%zu in shear), stresses within %.2e, bond VTU within %.2e\n", world.size(),
              ref.size() - 1, shear, worst, vtu_worst);
}
