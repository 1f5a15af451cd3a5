// What `mpdem check` prints about parallel bonds (check/bond_summary.hpp): the bonds made at t = 0
// by the gap rule, from the bond CSV and their union, the isolated and the unbondable particles,
// the bond lengths, and the bonds' time step 2 / omega (the faster of the normal mode
// sqrt(k_n A / m*) and the rotational one sqrt((k_s A a^2 + k_n I) / I*), physics.md 22) against
// its closed form (1e-12 in the summary, 1e-3 printed to 4 digits), which the time-step advice
// takes with the contacts' factor 1/50.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "check/bond_summary.hpp"
#include "support/run_command.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 1e-3;  // m

// The number printed after `label` in the line, or NaN.
double number_after(const std::string& line, const std::string& label) {
  const auto at = line.find(label);
  return at == std::string::npos ? std::nan("") : std::strtod(line.c_str() + at + label.size(), nullptr);
}

// The line of `lines` that contains `part` ("" if none).
std::string line_with(const std::vector<std::string>& lines, const std::string& part) {
  for (const std::string& l : lines)
    if (l.find(part) != std::string::npos) return l;
  ADD_FAILURE() << "no line with '" << part << "'";
  return "";
}

// s, 2 / omega of a bond (written out, not from the header): the faster of the normal mode
// sqrt(k_n A / m*) and the rotational one sqrt((k_s A a^2 + k_n I) / I*), with m* and I* the
// reduced mass (kg) and moment of inertia (kg m^2), a the longer lever from a centre to the bond's
// centre (m), k_n = E_b / L, k_s = k_n / 2.5, A = pi R_b^2, I = A R_b^2 / 4.
double bond_step(double m_star, double i_star, double young, double r_b, double length, double lever) {
  const double kn = young / length, area = kPi * r_b * r_b, inertia = 0.25 * area * r_b * r_b;
  const double normal = kn * area / m_star, turning = (kn / 2.5 * area * lever * lever + kn * inertia) / i_star;
  return 2.0 / std::sqrt(std::max(normal, turning));
}
// kg m^2, a sphere's moment of inertia.
double solid_ball_inertia(double m, double r) { return 0.4 * m * r * r; }

Scene bonded_scene() {
  Scene s = test::make_scene(1e-7, 1e-3);
  BondKeys k;
  k.young = 1e9;
  k.radius_ratio = 0.5;
  k.gap = 0.2 * kR;
  s.model.params.bonds.defaults = k;
  return s;
}

}  // namespace

TEST(BondSummary, ChainWithAnIsolatedSphere) {
  // Five spheres 0.1 mm apart along x (four bonds), a sixth far away; then a smaller pair whose
  // bond sets the time step.
  Scene s = bonded_scene();
  for (std::int64_t id = 1; id <= 5; ++id)
    test::add_particle(s, id, kR, {static_cast<double>(id - 1) * 2.1 * kR, 0.0, 0.0});
  test::add_particle(s, 6, kR, {0.0, 0.01, 0.0});
  const double rho = s.model.materials.front().density, m = 4.0 / 3.0 * kPi * kR * kR * kR * rho;
  BondSummary b = bond_summary(s);
  EXPECT_EQ(b.by_gap, 4u);
  EXPECT_EQ(b.listed, 0u);
  EXPECT_EQ(b.made, 4u);
  EXPECT_EQ(b.isolated, 1u);
  EXPECT_EQ(b.isolated_ids, std::vector<std::int64_t>{6});
  EXPECT_EQ(b.unbondable, 0u);
  EXPECT_NEAR(b.length_min, 2.1 * kR, 1e-15);
  EXPECT_NEAR(b.length_max, 2.1 * kR, 1e-15);
  const double dt = bond_step(0.5 * m, 0.5 * solid_ball_inertia(m, kR), 1e9, 0.5 * kR, 2.1 * kR, 1.05 * kR);
  EXPECT_NEAR(b.time_step / dt, 1.0, 1e-12);
  const std::vector<std::string> lines = bond_summary_lines(s);
  for (const std::string& l : lines) std::printf("%s\n", l.c_str());
  EXPECT_EQ(lines.at(0), "bonds: 4 made at t = 0 (4 by the gap rule)");
  EXPECT_NEAR(number_after(line_with(lines, "time step"), "physics.md 22): ") / dt, 1.0, 1e-3);
  EXPECT_NEAR(number_after(line_with(lines, "lengths"), "lengths ") / (2.1 * kR), 1.0, 1e-3);
  EXPECT_NE(line_with(lines, "isolated").find("isolated particles (no bond): 1, ids 6"), std::string::npos);
  // A pair of spheres of radius r = R/2 next to the first one: m* = m_r m / (m_r + m), R_b = r/2.
  const double r = 0.5 * kR, m_r = m / 8.0, L = kR + r + 0.1 * kR;
  test::add_particle(s, 7, r, {-L, 0.0, 0.0});
  b = bond_summary(s);
  EXPECT_EQ(b.made, 5u);
  EXPECT_NEAR(b.length_min / L, 1.0, 1e-12);
  const double i = solid_ball_inertia(m, kR), i_r = solid_ball_inertia(m_r, r);
  EXPECT_NEAR(b.time_step / bond_step(m_r * m / (m_r + m), i_r * i / (i_r + i), 1e9, 0.5 * r, L, kR + 0.05 * kR), 1.0,
              1e-12);
}

TEST(BondSummary, FixedParticleCountsAsInfinitelyHeavy) {
  Scene s = bonded_scene();
  test::add_particle(s, 1, kR, {0.0, 0.0, 0.0});
  test::add_particle(s, 2, kR, {2.1 * kR, 0.0, 0.0});
  s.particles.fixed[0] = 1;
  const double m = s.particles.mass[1];
  EXPECT_NEAR(bond_summary(s).time_step / bond_step(m, solid_ball_inertia(m, kR), 1e9, 0.5 * kR, 2.1 * kR, 1.05 * kR),
              1.0, 1e-12);
}

TEST(BondSummary, ListedUnionAndUnbondableMaterials) {
  Scene s = bonded_scene();
  Material steel = s.model.materials.front();
  steel.name = "steel";
  s.model.materials.push_back(steel);
  // Ids 1-4 along x (gap bonds 1-2, 2-3, 3-4), 5 and 6 of steel next to them.
  for (std::int64_t id = 1; id <= 4; ++id)
    test::add_particle(s, id, kR, {static_cast<double>(id - 1) * 2.1 * kR, 0.0, 0.0});
  for (std::int64_t id = 5; id <= 6; ++id) {
    const std::size_t i = test::add_particle(s, id, kR, {static_cast<double>(id - 5) * 2.1 * kR, 2.1 * kR, 0.0});
    s.particles.material[i] = 1;
  }
  s.model.params.bonds.file = "/somewhere/b.csv";
  s.model.params.bonds.listed = {{2, 1, 2}, {4, 1, 3}};
  // Steel is bonded to nothing.
  for (const char* other : {"default", "steel"}) {
    BondPairParams e{"steel", other, {}, 0};
    e.keys.bonded = false;
    s.model.params.bonds.pairs.push_back(e);
  }
  const BondSummary b = bond_summary(s);
  EXPECT_EQ(b.by_gap, 3u);
  EXPECT_EQ(b.listed, 2u);
  EXPECT_EQ(b.made, 4u);
  EXPECT_EQ(b.isolated, 2u);
  EXPECT_EQ(b.isolated_ids, (std::vector<std::int64_t>{5, 6}));
  EXPECT_EQ(b.unbondable, 2u);
  EXPECT_EQ(b.unbondable_materials, std::vector<std::string>{"steel"});
  EXPECT_NEAR(b.length_max, 3 * 2.1 * kR, 1e-15);
  const std::vector<std::string> lines = bond_summary_lines(s);
  for (const std::string& l : lines) std::printf("%s\n", l.c_str());
  EXPECT_EQ(lines.at(0), "bonds: 4 made at t = 0 (3 by the gap rule, 2 listed in b.csv (1 in both))");
  EXPECT_NE(line_with(lines, "unbondable").find("2, of 'steel'"), std::string::npos);
}

TEST(BondSummary, NothingWithoutBonds) {
  Scene s = test::make_scene(1e-7, 1e-3);
  test::add_particle(s, 1, kR, {0.0, 0.0, 0.0});
  EXPECT_TRUE(bond_summary_lines(s).empty());
  EXPECT_EQ(bond_summary(s).made, 0u);
}

// `mpdem check` prints the summary, and the recommended step is the bonds' time step / 50 when the
// bonds are stiffer than the contacts (E = 1e5 Pa particles held by E_b = 1 GPa bonds).
TEST(BondSummary, CheckCommandAdvisesTheBondsStep) {
  test::TempDir d("mpdem_bond_summary");
  d.write("p.csv", "id,x,y,z,radius\n1,0,0,0,0.001\n2,0.0021,0,0,0.001\n3,0.0042,0,0,0.001\n");
  d.write("scene.toml",
          "[time]\nduration = 1e-3\ndt = 1e-7\n[[material]]\nname = \"soft\"\ndensity = 2500\nyoung = 1e5\n"
          "[[particles]]\nfile = \"p.csv\"\n[bonds]\nyoung = 1e9\ngap = 2e-4\n");
  const test::CommandResult r = test::run_mpdem("check scene.toml", d.path);
  EXPECT_EQ(r.status, 0) << r.err;
  std::printf("%s", r.out.c_str());
  const double m = 4.0 / 3.0 * kPi * kR * kR * kR * 2500.0;
  const double dt = bond_step(0.5 * m, 0.5 * solid_ball_inertia(m, kR), 1e9, kR, 2.1 * kR, 1.05 * kR);
  test::expect_contains(r.out, {"bonds: 2 made at t = 0 (2 by the gap rule)", "and the bonds' time step / 50"});
  EXPECT_NEAR(number_after(r.out, "bonds 2/omega ") / dt, 1.0, 1e-3);
  EXPECT_NEAR(number_after(r.out, "recommended dt <= ") / (dt / 50.0), 1.0, 1e-3);
  // time.dt above it: `mpdem check` warns, naming the bonds.
  test::expect_contains(r.err, {"warning: time.dt = 1e-07 s exceeds the recommended", "bonds' time step"});
}
