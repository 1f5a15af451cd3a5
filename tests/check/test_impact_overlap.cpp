// Expected impact speed and the peak overlap estimate against checks.max_overlap
// (src/check/impact_overlap.hpp): the closed forms, the engine's own impact, and the warning.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "check/impact_overlap.hpp"
#include "check/scene_checks.hpp"
#include "sim/simulation.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
using mpdem::test::expect_contains;
using mpdem::test::TempDir;

namespace {

const std::string kFloor =  // z = 0
    "id,x1,y1,z1,x2,y2,z2,x3,y3,z3\n1,-0.1,-0.1,0,0.1,-0.1,0,0.1,0.1,0\n2,-0.1,-0.1,0,0.1,0.1,0,-0.1,0.1,0\n";

struct Files {
  TempDir dir{"mpdem_impact"};
  Scene load(const std::string& toml) {
    dir.write("scene.toml", toml);
    return load_scene(dir.path / "scene.toml");
  }
};

std::string scene_text(const std::string& material, const std::string& extra = "") {
  return "[time]\nduration = 0.01\ndt = 1e-6\nintegrator = \"verlet\"\n[[material]]\nname = \"glass\"\n" + material +
         "\n[[particles]]\nfile = \"p.csv\"\n[[barriers]]\nfile = \"floor.csv\"\nrigid = true\n" + extra;
}

const ImpactEstimate* find(const std::vector<ImpactEstimate>& all, bool barrier) {
  for (const ImpactEstimate& e : all)
    if (e.barrier == barrier) return &e;
  ADD_FAILURE() << "no " << (barrier ? "particle-barrier" : "particle-particle") << " estimate";
  return nullptr;
}

constexpr double kR = 0.002, kRho = 2500.0, kE = 1e7, kNu = 0.3;

}  // namespace

TEST(ImpactSpeed, FallOverTheSceneHeightOrTheFastestParticle) {
  Files f;
  f.dir.write("floor.csv", kFloor);
  f.dir.write("p.csv", "id,x,y,z,radius\n1,0,0,0.1,0.001\n2,0.01,0,0.05,0.001\n");
  ImpactSpeed s = expected_impact_speed(f.load(scene_text("")));
  EXPECT_DOUBLE_EQ(s.fall_height, 0.1);  // highest centre to the floor
  EXPECT_NEAR(s.speed, std::sqrt(2.0 * 9.81 * 0.1), 1e-12);
  EXPECT_EQ(s.origin(), "a fall of 0.1 m under gravity");
  // No farther than the domain's extent along gravity.
  s = expected_impact_speed(f.load(scene_text("", "[domain]\nmin = [-1, -1, 0.0]\nmax = [1, 1, 0.04]\n")));
  EXPECT_DOUBLE_EQ(s.fall_height, 0.04);
  f.dir.write("p.csv", "id,x,y,z,vz,radius\n1,0,0,0.1,-5,0.001\n");
  s = expected_impact_speed(f.load(scene_text("")));
  EXPECT_DOUBLE_EQ(s.speed, 5.0);
  EXPECT_EQ(s.origin(), "the fastest initial particle speed");
}

TEST(ImpactOverlap, PeakOverlapWithinOnePercentOfTheClosedForm) {
  Files f;
  f.dir.write("floor.csv", kFloor);
  f.dir.write("p.csv", "id,x,y,z,radius\n1,0,0,0.01,0.002\n2,0.05,0,0.01,0.002\n");
  const Scene s = f.load(scene_text("density = 2500.0\nyoung = 1e7\npoisson = 0.3"));
  const double v = 2.0;
  const std::vector<ImpactEstimate> all = impact_estimates(s, v);
  const double m = 4.0 / 3.0 * std::numbers::pi * kR * kR * kR * kRho;
  // On a rigid floor: m* = m, r* = R, E* = E / (1 - nu^2).
  const double Eb = kE / (1.0 - kNu * kNu);
  const double db = std::pow(15.0 * m * v * v / (16.0 * Eb * std::sqrt(kR)), 0.4);
  // Two equal spheres: m* = m/2, r* = R/2, E* = E / (2 (1 - nu^2)).
  const double dp = std::pow(15.0 * (m / 2) * v * v / (16.0 * (Eb / 2) * std::sqrt(kR / 2)), 0.4);
  const ImpactEstimate* b = find(all, true);
  const ImpactEstimate* p = find(all, false);
  ASSERT_TRUE(b && p);
  EXPECT_NEAR(b->overlap, db, 0.01 * db);
  EXPECT_NEAR(b->ratio, db / kR, 0.01 * db / kR);
  EXPECT_NEAR(p->overlap, dp, 0.01 * dp);
  EXPECT_NEAR(p->ratio, dp / kR, 0.01 * dp / kR);
}

TEST(ImpactOverlap, LinearLawPeakOverlapIsVSqrtMOverK) {
  Files f;
  f.dir.write("floor.csv", kFloor);
  f.dir.write("p.csv", "id,x,y,z,radius\n1,0,0,0.01,0.002\n");
  const Scene s = f.load(scene_text("density = 2500.0", "[contact.particle_barrier]\nlaw = \"linear\"\n"
                                                        "stiffness_normal = 1000.0\n"));
  const std::vector<ImpactEstimate> all = impact_estimates(s, 2.0);
  const ImpactEstimate* b = find(all, true);
  ASSERT_TRUE(b);
  const double m = 4.0 / 3.0 * std::numbers::pi * kR * kR * kR * kRho;
  EXPECT_NEAR(b->overlap, 2.0 * std::sqrt(m / 1000.0), 1e-12);
}

TEST(ImpactOverlap, EstimateMatchesTheEnginesUndampedImpact) {
  Files f;
  f.dir.write("floor.csv", kFloor);
  f.dir.write("p.csv", "id,x,y,z,vz,radius\n1,0,0,0.00201,-2,0.002\n");
  Scene s = f.load(scene_text("density = 2500.0\nyoung = 1e7\npoisson = 0.3",
                              "[gravity]\nvector = [0.0, 0.0, 0.0]\n[contact.particle_barrier]\ndamping_ratio = 0.0\n"
                              "[checks]\nmax_overlap = 0.5\n"));
  const std::vector<ImpactEstimate> all = impact_estimates(s, expected_impact_speed(s).speed);
  const ImpactEstimate* b = find(all, true);
  ASSERT_TRUE(b);
  const double estimate = b->ratio;
  // t_c = 2.94 delta_max / v: the run covers the whole contact at t_c / 1000 a step.
  const double tc = 2.943 * b->overlap / 2.0;
  s.model.params.time.dt = tc / 1000.0;
  s.model.params.time.duration = 1.2 * tc;
  RunOptions opt;
  opt.write_output = false;
  opt.progress = false;
  Simulation sim(std::move(s), opt);
  const RunSummary sum = sim.run();
  EXPECT_EQ(sum.record.deepest.particle, 1);
  EXPECT_NEAR(sum.record.deepest.ratio, estimate, 0.01 * estimate);
}

TEST(ImpactOverlap, SoftMaterialsWarnWithTheSpeedAndWhatToDo) {
  Files f;
  f.dir.write("floor.csv", kFloor);
  f.dir.write("p.csv", "id,x,y,z,radius\n1,0,0,0.1,0.001\n2,0.05,0,0.05,0.001\n");
  SceneProblems r;
  check_impact_overlaps(f.load(scene_text("young = 1e5")), r);
  ASSERT_EQ(r.size(), 2u);  // on the floor, and two particles
  for (const SceneProblem& p : r) {
    EXPECT_EQ(p.severity, Severity::Warning);
    EXPECT_FALSE(p.stops_run);
    EXPECT_EQ(p.key, "checks.max_overlap");
    expect_contains(p.message, {"1.4 m/s (a fall of 0.1 m under gravity)", "'glass'", "checks.max_overlap = 5%",
                                "young x", "raise checks.max_overlap"});
  }
  // Two equal spheres overlap deeper than one on a rigid floor (m*/(E* sqrt(r*)) is sqrt(2) larger).
  expect_contains(r[0].message, {"two particles of material 'glass'"});
  expect_contains(r[1].message, {"on a barrier of material", "(rigid)"});
  // A limit the impact stays within, or the check off: nothing to report.
  r.clear();
  check_impact_overlaps(f.load(scene_text("young = 1e5", "[checks]\nmax_overlap = 0.9\n")), r);
  EXPECT_TRUE(r.empty());
  check_impact_overlaps(f.load(scene_text("young = 1e5", "[checks]\nmax_overlap = 0.0\n")), r);
  EXPECT_TRUE(r.empty());
  check_impact_overlaps(f.load(scene_text("young = 1e9")), r);
  EXPECT_TRUE(r.empty());
}
