// The parallel bonds' outputs (docs/output.md "bonds_broken.csv", "Bond VTU", log.csv): a bonded
// pair, one sphere fixed, pulled apart along the bond by a rising load breaks in tension once,
// with sigma_max >= tensile_strength, in bonds_broken.csv, the log's counts and the bond VTU
// series (read back by meshio, tests/read_vtu.py); the VTU's cells in each [output] format; the
// minimum image on a periodic domain; no bond output without [bonds].
#include <gtest/gtest.h>
#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/bond_vtu_writer.hpp"
#include "output/bond_cells.hpp"
#include "sim/simulation.hpp"
#include "support/bonded_scenes.hpp"
#include "support/shell_output.hpp"
#include "support/temp_dir.hpp"

#ifndef MPDEM_SOURCE_DIR
#error "MPDEM_SOURCE_DIR must name the repository root (tests/read_vtu.py lives there)"
#endif

using namespace mpdem;
using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

constexpr double kStrength = 1e6;  // Pa, the pair's tensile strength
constexpr double kDt = 2e-7;       // s
constexpr double kRamp = 1e4;      // N/s, the pull's rise: F = kRamp t reaches kStrength A at ~0.31 ms

// A CSV file's cells as text, by row; header first.
std::vector<std::vector<std::string>> read_csv(const fs::path& f) {
  std::ifstream in(f);
  std::vector<std::vector<std::string>> rows;
  std::string line, cell;
  while (std::getline(in, line)) {
    rows.emplace_back();
    for (std::stringstream ls(line); std::getline(ls, cell, ',');) rows.back().push_back(cell);
  }
  return rows;
}
std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t k = 0; k < header.size(); ++k)
    if (header[k] == name) return k;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

std::string meshio(const fs::path& vtu) {
  return shell(std::string("/usr/bin/python3 '") + MPDEM_SOURCE_DIR + "/tests/read_vtu.py' '" + vtu.string() + "'");
}

// Two touching spheres (ids 1, 2) bonded along x, the first fixed, the bonds damped.
Scene pair_scene(const fs::path& dir, bool bonds) {
  Scene s = bonded_scene(kDt, Integrator::Verlet, 0.5, 0.0);
  if (bonds) s.model.params.bonds.defaults->tensile_strength = kStrength;
  else s.model.params.bonds = {};
  add_chain(s, 2);
  s.model.params.time.duration = 4e-4;
  s.model.params.output.dir = dir.string();
  s.model.params.output.log_every = 50;
  s.model.params.output.bonds_every = 1e-4;
  return s;
}

// Runs the pair with particle 2 pulled along +x by kRamp t until `until` (s; default the scene's
// end, whose outputs finish() then writes).
void pull(Simulation& sim, double until = -1.0) {
  // The load of the time now, for the evaluation at the start (or the resume).
  sim.interactions().external_loads().set({2}, {Vec3{kRamp * sim.time(), 0.0, 0.0}}, {Vec3{}});
  sim.start();
  const double end = sim.model().params.time.duration;
  while (!sim.reached(until < 0.0 ? end : until)) {
    sim.interactions().external_loads().set({2}, {Vec3{kRamp * (sim.time() + kDt), 0.0, 0.0}}, {Vec3{}});
    sim.step(end);
  }
  if (until < 0.0) sim.finish();
}

std::string text_of(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(BondOutputs, PulledPairBreaksOnceInTension) {
  TempDir dir("bond_outputs");
  Simulation sim(pair_scene(dir.path, true), RunOptions{dir.path, false, true});
  pull(sim);
  // bonds_broken.csv: one row, in tension, at the stress that broke it.
  const auto breaks = read_csv(dir.path / "bonds_broken.csv");
  ASSERT_EQ(breaks.size(), 2u);
  EXPECT_EQ(breaks[0], (std::vector<std::string>{"time", "id_i", "id_j", "mode", "sigma_max", "tau_max"}));
  const double t_break = std::stod(breaks[1][0]);
  EXPECT_EQ(breaks[1][1], "1");
  EXPECT_EQ(breaks[1][2], "2");
  EXPECT_EQ(breaks[1][3], "tension");
  const double sigma = std::stod(breaks[1][4]);
  EXPECT_GE(sigma, kStrength);
  EXPECT_LT(sigma, 1.05 * kStrength);  // quasi-static: the pull F / A just past the strength
  EXPECT_LT(std::stod(breaks[1][5]), 1e-6 * kStrength);
  // The pull F(t) = kRamp t over the bond's area reaches the strength at t = kStrength A / kRamp.
  EXPECT_NEAR(t_break, kStrength * kBondArea / kRamp, 0.05 * kStrength * kBondArea / kRamp);

  // log.csv: the bonds' columns; the interval counts add up to the cumulative one.
  const auto log = read_csv(dir.path / "log.csv");
  const auto& h = log[0];
  for (const char* c :
       {"bonds", "bonds_broken", "bonds_broken_interval", "bond_energy", "bond_damping", "bond_break_energy"})
    column(h, c);
  EXPECT_EQ(column(h, "bonds_broken_interval"), column(h, "bonds_broken") + 1);
  const std::size_t cum = column(h, "bonds_broken"), inter = column(h, "bonds_broken_interval");
  const std::size_t intact = column(h, "bonds"), time = column(h, "time");
  double previous = 0.0, sum = 0.0;
  for (std::size_t r = 1; r < log.size(); ++r) {
    const double now = std::stod(log[r][cum]);
    EXPECT_EQ(std::stod(log[r][inter]), now - previous) << "row " << r;
    EXPECT_EQ(std::stod(log[r][intact]), std::stod(log[r][time]) < t_break ? 1.0 : 0.0) << "row " << r;
    sum += std::stod(log[r][inter]);
    previous = now;
  }
  EXPECT_EQ(previous, 1.0);
  EXPECT_EQ(sum, 1.0);

  // The bond VTU series: t = 0, 1e-4 .. 4e-4 s; the bond intact before the break, broken after.
  const std::string pvd = shell(std::string("/usr/bin/python3 '") + MPDEM_SOURCE_DIR + "/tests/read_vtu.py' '" +
                                (dir.path / "bonds.pvd").string() + "'");
  for (int k = 0; k <= 4; ++k) EXPECT_NE(pvd.find(fmt::format("bonds/bonds_{:06d}.vtu", k)), std::string::npos) << pvd;
  const std::string first = meshio(dir.path / "bonds/bonds_000000.vtu");
  EXPECT_NE(first.find("cells line 1 2\n0 1\n"), std::string::npos) << first;
  EXPECT_NE(first.find(fmt::format("points Points 2 3\n0.0 0.0 0.0\n{} 0.0 0.0\n", 2.0 * kBondR)), std::string::npos)
      << first;
  for (const char* a : {"cell_data id_i 1 1\n1\n", "cell_data id_j 1 1\n2\n", "cell_data intact 1 1\n1\n",
                        "cell_data length 1 1\n0.002\n", "cell_data normal_force 1 1\n", "cell_data shear_force 1 3\n",
                        "cell_data twisting_moment 1 1\n", "cell_data bending_moment 1 3\n",
                        "cell_data sigma_max 1 1\n", "cell_data tau_max 1 1\n"})
    EXPECT_NE(first.find(a), std::string::npos) << a << "\n" << first;
  const std::string before = meshio(dir.path / "bonds/bonds_000003.vtu");  // t = 3e-4 s < t_break
  EXPECT_NE(before.find("cell_data intact 1 1\n1\n"), std::string::npos) << before;
  // Stretched by the pull: the normal force is tension (< 0), sigma_max = -F_n / A.
  const auto value = [](const std::string& text, const std::string& name) {
    const std::string tag = "cell_data " + name + " 1 1\n";
    return std::stod(text.substr(text.find(tag) + tag.size()));
  };
  const double fn = value(before, "normal_force");
  EXPECT_LT(fn, 0.0);
  EXPECT_NEAR(value(before, "sigma_max"), -fn / kBondArea, 1e-9 * kStrength);
  EXPECT_NEAR(fn, -kRamp * 3e-4, 0.05 * kRamp * 3e-4);
  const std::string after = meshio(dir.path / "bonds/bonds_000004.vtu");
  EXPECT_NE(after.find("cell_data intact 1 1\n0\n"), std::string::npos) << after;
}

TEST(BondOutputs, NoneWithoutBonds) {
  TempDir dir("bond_outputs");
  Simulation sim(pair_scene(dir.path, false), RunOptions{dir.path, false, true});
  sim.start();
  sim.step(sim.model().params.time.duration);
  sim.finish();
  EXPECT_FALSE(fs::exists(dir.path / "bonds_broken.csv"));
  EXPECT_FALSE(fs::exists(dir.path / "bonds.pvd"));
  EXPECT_FALSE(fs::exists(dir.path / "bonds"));
  const auto log = read_csv(dir.path / "log.csv");
  for (const std::string& c : log[0]) EXPECT_EQ(c.find("bond"), std::string::npos) << c;
}

// Without breaks the table is there, its header alone.
TEST(BondOutputs, EmptyBreakTableHasItsHeader) {
  TempDir dir("bond_outputs");
  Scene s = pair_scene(dir.path, true);
  s.model.params.output.bonds_every = 0.0;
  Simulation sim(std::move(s), RunOptions{dir.path, false, true});
  sim.start();
  sim.step(sim.model().params.time.duration);
  sim.finish();
  EXPECT_EQ(read_csv(dir.path / "bonds_broken.csv").size(), 1u);
  EXPECT_FALSE(fs::exists(dir.path / "bonds.pvd"));
  EXPECT_TRUE(fs::exists(dir.path / "log.csv"));
}

// A bond across a periodic face: its line runs to the partner's nearest image, never across the box.
TEST(BondOutputs, PeriodicBondTakesTheMinimumImage) {
  Particles p;
  p.resize(2);
  p.id = {7, 9};
  p.x = {Vec3{0.0095, 0.0, 0.0}, Vec3{0.0005, 0.0, 0.0}};  // m, a 10 mm box along x: 1 mm apart
  BondRecord r;
  r.id_i = 7;
  r.id_j = 9;
  r.radius = 5e-4;
  r.length = 1e-3;
  r.fn = -2.0;
  r.ms = {0.0, 1e-4, 0.0};
  const BondCells c = bond_cells(std::span<const BondRecord>(&r, 1), p, Vec3{0.01, 0.0, 0.0});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c.from[0].x, 0.0095);
  EXPECT_NEAR(c.to[0].x, 0.0105, 1e-15);
  // sigma_max = -F_n / A + |M_s| R / I with A = pi R^2, I = pi R^4 / 4.
  const double a = std::numbers::pi * 25e-8, i = 0.25 * a * 25e-8;
  EXPECT_NEAR(c.sigma_max[0], 2.0 / a + 1e-4 * 5e-4 / i, 1e-12 * (2.0 / a + 1e-4 * 5e-4 / i));
  EXPECT_EQ(c.tau_max[0], 0.0);
}

// Every [output] format holds the same cells, exactly.
TEST(BondOutputs, EveryFormatReadsBackTheSame) {
  TempDir dir("bond_outputs");
  BondCells c;
  for (int b = 0; b < 3; ++b) {
    c.from.push_back({0.1 * b, 0.2, 0.3});
    c.to.push_back({0.1 * b + 1.0 / 3.0, 0.2, 0.3});
    c.id_i.push_back(b);
    c.id_j.push_back(b + 10);
    c.intact.push_back(b % 2 ? 0 : 1);
    c.normal_force.push_back(-1.0 / (b + 3.0));
    c.shear_force.push_back({1.0 / 7.0, static_cast<double>(b), 0.0});
    c.twisting_moment.push_back(1e-9 * b);
    c.bending_moment.push_back({0.0, 0.0, 2.0 / 3.0});
    c.sigma_max.push_back(1e6 / 3.0);
    c.tau_max.push_back(b);
    c.length.push_back(2e-3);
  }
  std::string reference;
  for (const VtkFormat f : {VtkFormat::Ascii, VtkFormat::Binary, VtkFormat::Compressed}) {
    const fs::path file = dir.path / fmt::format("bonds_{}.vtu", static_cast<int>(f));
    write_bonds_vtu(file, c, 0.25, f);
    const std::string got = meshio(file);
    if (reference.empty()) reference = got;
    EXPECT_EQ(got, reference) << static_cast<int>(f);
  }
  EXPECT_NE(reference.find("cells line 3 2\n0 1\n2 3\n4 5\n"), std::string::npos) << reference;
  EXPECT_NE(reference.find("cell_data intact 3 1\n1\n0\n1\n"), std::string::npos) << reference;
  EXPECT_NE(reference.find("cell_data shear_force 3 3\n0.14285714285714285 0.0 0.0\n"), std::string::npos) << reference;
  EXPECT_NE(reference.find("field_data TimeValue 1 1\n0.25\n"), std::string::npos) << reference;
}

// A run resumed from a checkpoint before the break, after an interrupted run wrote the break:
// bonds_broken.csv, log.csv and the bond VTU index are the uninterrupted run's, byte for byte (the
// rows after the checkpoint dropped, the break written once, the interval counts continued).
TEST(BondOutputs, ResumeContinuesTheFilesOnce) {
  TempDir whole("bond_outputs_whole"), parts("bond_outputs_parts");
  {
    Simulation sim(pair_scene(whole.path, true), RunOptions{whole.path, false, true});
    pull(sim);
  }
  {
    Simulation sim(pair_scene(parts.path, true), RunOptions{parts.path, false, true});
    pull(sim, 2e-4);
    sim.write_checkpoint(parts.path / "checkpoint.bin");
    pull(sim, 3.6e-4);  // past the break: its row and later log rows written, then the run stops
    sim.flush_outputs();
    ASSERT_EQ(read_csv(parts.path / "bonds_broken.csv").size(), 2u);
  }
  {
    Simulation sim(pair_scene(parts.path, true), RunOptions{parts.path, false, true});
    sim.resume_from(parts.path / "checkpoint.bin");
    pull(sim);
  }
  for (const char* f : {"bonds_broken.csv", "log.csv", "bonds.pvd"})
    EXPECT_EQ(text_of(parts.path / f), text_of(whole.path / f)) << f;
  EXPECT_EQ(text_of(parts.path / "bonds/bonds_000004.vtu"), text_of(whole.path / "bonds/bonds_000004.vtu"));
}
