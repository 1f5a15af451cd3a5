// Tests of the clump readers (src/scene/clump_reader.cpp, the [[particles]] `clump` key of
// src/scene/scene_reader.cpp): [[clump]] templates inline and from a member CSV, the body CSV
// with and without an orientation, member ids, fixed bodies and overrides; and one InputError
// naming file:line and key (or the CSV's file:line and column) for each class of bad input.
// Inputs are written to a fresh temporary folder per test.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "model/scene.hpp"
#include "scene/scene_reader.hpp"
#include "support/clump_scenes.hpp"
#include "support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::error_of;
using mpdem::test::expect_contains;
using mpdem::test::member_of;
using mpdem::test::TempDir;

namespace {

constexpr double kR = 0.001;     // m, member radius of the dumbbell
constexpr double kRho = 2500.0;  // kg/m^3, density of material glass
// Tolerance of the dumbbell's mass properties: two touching spheres are summed in closed form
// (physics/clump_mass.hpp), so only round-off separates them from the formulas.
constexpr double kExact = 1e-12;

// Lines 1-7: [time] and the material; the [[clump]] block starts at line 8.
const std::string kHead =
    "[time]\nduration = 0.01\ndt = 1e-6\nintegrator = \"verlet\"\n[[material]]\nname = \"glass\"\ndensity = 2500\n";
// Lines 8-10.
const std::string kDumbbell =
    "[[clump]]\nname = \"dumbbell\"\nmembers = [[0.0, -0.001, 0.0, 0.001], [0.0, 0.001, 0.0, 0.001]]\n";
// Lines 11-13 after kDumbbell.
const std::string kBodies = "[[particles]]\nfile = \"bodies.csv\"\nclump = \"dumbbell\"\n";

std::string scene_text(const std::string& clump = kDumbbell, const std::string& particles = kBodies,
                       const std::string& extra = "") {
  return kHead + clump + particles + extra;
}

// Loads scene.toml of `d` after writing `text` to it (and bodies.csv unless given).
Scene load(const TempDir& d, const std::string& text, const std::string& bodies = "id,x,y,z\n1,0,0,0.01\n") {
  if (!fs::exists(d.path / "bodies.csv")) d.write("bodies.csv", bodies);
  return load_scene(d.write("scene.toml", text));
}

std::string load_error(const TempDir& d, const std::string& text,
                       const std::string& bodies = "id,x,y,z\n1,0,0,0.01\n") {
  return error_of([&] { load(d, text, bodies); });
}

double dumbbell_mass() { return 2.0 * (4.0 / 3.0) * std::numbers::pi * kR * kR * kR * kRho; }

void expect_rel(double got, double want, double tol) { EXPECT_NEAR(got, want, tol * std::abs(want)) << got; }

}  // namespace

TEST(ClumpReader, DumbbellInlineHasTheTouchingSpheresMassProperties) {
  TempDir d("mpdem_clump");
  const Scene s = load(d, scene_text());
  ASSERT_EQ(s.model.clumps.size(), 1u);
  const ClumpTemplate& t = s.model.clumps[0];
  EXPECT_EQ(t.name, "dumbbell");
  EXPECT_EQ(t.line, 8u);
  ASSERT_EQ(t.members().size(), 2u);
  const Bodies& B = s.particles.bodies;
  ASSERT_EQ(B.size(), 1u);
  const double M = dumbbell_mass();
  expect_rel(B.mass[0], M, kExact);
  // Principal moments ascending: the axial one 2 x 2/5 M/2 r^2, across 2 x (2/5 M/2 r^2 + M/2 r^2).
  expect_rel(B.inertia[0].x, 0.4 * M * kR * kR, kExact);
  expect_rel(B.inertia[0].y, 1.4 * M * kR * kR, kExact);
  expect_rel(B.inertia[0].z, 1.4 * M * kR * kR, kExact);
  EXPECT_EQ(t.shape.volume_error, 0.0);  // separate members: closed form
  EXPECT_EQ(s.particles.size(), 2u);
}

TEST(ClumpReader, MembersFromCsvEqualTheInlineTemplate) {
  TempDir d("mpdem_clump");
  d.write("shapes/dumbbell.csv", "# two touching spheres\nx, y, z, radius\n0, -0.001, 0, 0.001\n0, 0.001, 0, 0.001\n");
  const Scene csv = load(d, scene_text("[[clump]]\nname = \"dumbbell\"\nmembers = \"shapes/dumbbell.csv\"\n"));
  TempDir d2("mpdem_clump_inline");
  const Scene in = load(d2, scene_text());
  const Bodies &a = csv.particles.bodies, &b = in.particles.bodies;
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a.mass[0], b.mass[0]);
  EXPECT_EQ(a.inertia[0], b.inertia[0]);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(csv.particles.x[i], in.particles.x[i]);
}

TEST(ClumpReader, IdentityPlacesMembersAsWrittenAndQuaternionTurnsTheTemplate) {
  TempDir d("mpdem_clump");
  const Vec3 c{0.01, 0.02, 0.03};
  const std::string h = "0.70710678118654752";  // cos 45 deg = sin 45 deg: a 90-degree turn about z
  const Scene s = load(d, scene_text(),
                       "id,x,y,z,q0,q1,q2,q3\n1,0.01,0.02,0.03,1,0,0,0\n2,0.01,0.02,0.05," + h + ",0,0," + h + "\n");
  const Particles& p = s.particles;
  ASSERT_EQ(p.bodies.size(), 2u);
  const auto near = [](const Vec3& got, const Vec3& want) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-12 * kR) << "component " << k;  // round-off
  };
  // Body 1, identity: template (0, -r, 0) and (0, r, 0) about the centre.
  near(p.x[member_of(p, 1, 0)], c + Vec3{0, -kR, 0});
  near(p.x[member_of(p, 1, 1)], c + Vec3{0, kR, 0});
  // Body 2, 90 degrees about z: (0, r, 0) -> (-r, 0, 0).
  const Vec3 c2{0.01, 0.02, 0.05};
  near(p.x[member_of(p, 2, 1)], c2 + Vec3{-kR, 0, 0});
  near(p.x[member_of(p, 2, 0)], c2 + Vec3{kR, 0, 0});
  // Without q columns the body stands as its template is written.
  TempDir d2("mpdem_clump_noq");
  const Scene s2 = load(d2, scene_text(), "id,x,y,z\n1,0.01,0.02,0.03\n");
  near(s2.particles.x[member_of(s2.particles, 1, 1)], c + Vec3{0, kR, 0});
  near(s2.particles.x[member_of(s2.particles, 1, 0)], c + Vec3{0, -kR, 0});
}

TEST(ClumpReader, MemberIdsFollowTheLargestFreeSphereIdInBodyThenMemberOrder) {
  TempDir d("mpdem_clump");
  d.write("spheres.csv", "id,x,y,z,radius\n3,0.1,0,0,0.001\n17,0.2,0,0,0.001\n");
  const Scene s = load(d, scene_text(kDumbbell, kBodies + "[[particles]]\nfile = \"spheres.csv\"\n"),
                       "id,x,y,z\n9,0,0,0.01\n4,0,0,0.02\n");
  const Particles& p = s.particles;
  EXPECT_EQ(p.id[member_of(p, 9, 0)], 18);
  EXPECT_EQ(p.id[member_of(p, 9, 1)], 19);
  EXPECT_EQ(p.id[member_of(p, 4, 0)], 20);
  EXPECT_EQ(p.id[member_of(p, 4, 1)], 21);
}

// A sphere file after a clump entry may use any id, 0 included: the members read before it have
// no id yet (they are numbered after all free spheres at the end).
TEST(ClumpReader, SphereFileAfterClumpEntryKeepsItsIds) {
  TempDir d("mpdem_clump");
  d.write("spheres.csv", "id,x,y,z,radius\n0,0.1,0,0,0.001\n1,0.2,0,0,0.001\n");
  const Scene s = load(d, scene_text(kDumbbell, kBodies + "[[particles]]\nfile = \"spheres.csv\"\n"),
                       "id,x,y,z\n5,0,0,0.01\n");
  const Particles& p = s.particles;
  EXPECT_EQ(p.id[member_of(p, 5, 0)], 2);
  EXPECT_EQ(p.id[member_of(p, 5, 1)], 3);
  std::vector<std::int64_t> free_ids;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.body[i] == kNoBody) free_ids.push_back(p.id[i]);
  EXPECT_EQ(free_ids, (std::vector<std::int64_t>{0, 1}));
}

TEST(ClumpReader, FixedEntryFixesItsBodiesAndCsvColumnsApply) {
  TempDir d("mpdem_clump");
  const Scene s = load(
      d, scene_text(kDumbbell, "[[particles]]\nfile = \"bodies.csv\"\nclump = \"dumbbell\"\nfixed = true\n"),
      "id,x,y,z,vx,vy,vz,wx,wy,wz,fixed,temperature,charge,radius\n1,0,0,0.01,1,2,3,4,5,6,0,300,1e-9,\n");
  const Bodies& B = s.particles.bodies;
  ASSERT_EQ(B.size(), 1u);
  EXPECT_EQ(B.fixed[0], 1);
  EXPECT_EQ(B.v[0], (Vec3{1, 2, 3}));
  EXPECT_EQ(B.w[0], (Vec3{4, 5, 6}));
  EXPECT_EQ(B.T[0], 300.0);
  EXPECT_EQ(B.charge[0], 1e-9);
  // Without the entry's flag the column's 0 leaves the body free, and 1 fixes it.
  TempDir d2("mpdem_clump_free");
  EXPECT_EQ(load(d2, scene_text(), "id,x,y,z,fixed\n1,0,0,0.01,0\n").particles.bodies.fixed[0], 0);
  TempDir d3("mpdem_clump_col");
  EXPECT_EQ(load(d3, scene_text(), "id,x,y,z,fixed\n1,0,0,0.01,1\n").particles.bodies.fixed[0], 1);
}

TEST(ClumpReader, MassAndInertiaOverridesReplaceTheComputedValues) {
  TempDir d("mpdem_clump");
  const Scene s = load(d, scene_text(kDumbbell + "mass = 0.5\ninertia = [1e-7, 2e-7, 2.5e-7]\n"));
  EXPECT_EQ(s.particles.bodies.mass[0], 0.5);
  EXPECT_EQ(s.particles.bodies.inertia[0], (Vec3{1e-7, 2e-7, 2.5e-7}));
  // A mass alone scales the computed moments with it (the shape's distribution is kept).
  TempDir d2("mpdem_clump_mass");
  const Scene m = load(d2, scene_text(kDumbbell + "mass = 0.5\n"));
  expect_rel(m.particles.bodies.inertia[0].x, 0.4 * 0.5 * kR * kR, kExact);
  expect_rel(m.particles.bodies.inertia[0].z, 1.4 * 0.5 * kR * kR, kExact);
}

// One mistake per case: the message names the file, the line and the key (or CSV column).
struct BadTemplate {
  const char* what;
  std::string clump;  // the [[clump]] block from line 7
  std::string where;  // "scene.toml:LINE: 'KEY'"
  std::vector<std::string> expect;
};

TEST(ClumpReader, BadTemplatesNameLineAndKey) {
  const std::string head = "[[clump]]\nname = \"d\"\n";  // lines 8, 9
  const std::vector<BadTemplate> cases = {
      {"no members", head + "members = []\n", "scene.toml:10: 'clump.members'", {"got an empty array"}},
      {"members a number", head + "members = 3\n", "scene.toml:10: 'clump.members'", {"or the name of a CSV file"}},
      {"members missing", head, "scene.toml:8: 'clump.members'", {"missing required key"}},
      {"negative radius",
       head + "members = [\n  [0, 0, 0, 0.001],\n  [0, 0.001, 0, -0.001],\n]\n",
       "scene.toml:12: 'clump.members'",
       {"row 2 element 4 (radius) is -0.001, expected > 0"}},
      {"zero radius", head + "members = [[0, 0, 0, 0]]\n", "scene.toml:10: 'clump.members'", {"(radius) is 0"}},
      {"nan",
       head + "members = [[0, nan, 0, 0.001]]\n",
       "scene.toml:10: 'clump.members'",
       {"row 1 element 2 is not finite"}},
      {"inf", head + "members = [[0, 0, 0, inf]]\n", "scene.toml:10: 'clump.members'", {"element 4 is not finite"}},
      {"string",
       head + "members = [[0, 0, \"a\", 0.001]]\n",
       "scene.toml:10: 'clump.members'",
       {"element 3 is a string"}},
      {"three numbers",
       head + "members = [\n[0, 0, 0, 0.001],\n[0, 0, 0.001]]\n",
       "scene.toml:12: 'clump.members'",
       {"row 2 has 3 elements"}},
      {"row not an array",
       head + "members = [[0, 0, 0, 0.001], 5]\n",
       "scene.toml:10: 'clump.members'",
       {"row 2 is an integer"}},
      {"empty file name", head + "members = \"\"\n", "scene.toml:10: 'clump.members'", {"got an empty string"}},
      {"missing file",
       head + "members = \"nope.csv\"\n",
       "scene.toml:10: 'clump.members'",
       {"nope.csv' does not exist"}},
      {"no name", "[[clump]]\nmembers = [[0, 0, 0, 0.001]]\n", "scene.toml:8: 'clump.name'", {"missing required key"}},
      {"empty name",
       "[[clump]]\nname = \"\"\nmembers = [[0, 0, 0, 0.001]]\n",
       "scene.toml:9: 'clump.name'",
       {"empty string"}},
      {"duplicate name",
       head + "members = [[0, 0, 0, 0.001]]\n" + head + "members = [[0, 0, 0, 0.002]]\n",
       "scene.toml:12: 'clump.name'",
       {"clump 'd' is defined twice"}},
      {"unknown key",
       head + "members = [[0, 0, 0, 0.001]]\nradius = 1\n",
       "scene.toml:11: 'clump.radius'",
       {"unknown key"}},
      {"zero mass",
       head + "members = [[0, 0, 0, 0.001]]\nmass = 0\n",
       "scene.toml:11: 'clump.mass'",
       {"expected a number > 0, got 0"}},
      {"negative mass",
       head + "members = [[0, 0, 0, 0.001]]\nmass = -1.0\n",
       "scene.toml:11: 'clump.mass'",
       {"expected a number > 0"}},
      {"nan mass",
       head + "members = [[0, 0, 0, 0.001]]\nmass = nan\n",
       "scene.toml:11: 'clump.mass'",
       {"expected a finite number"}},
      {"triangle inequality",
       head + "members = [[0, 0, 0, 0.001]]\ninertia = [1.0, 1.0, 2.5]\n",
       "scene.toml:11: 'clump.inertia'",
       {"the largest exceeds the sum of the other two"}},
      {"zero moment",
       head + "members = [[0, 0, 0, 0.001]]\ninertia = [0.0, 1.0, 1.0]\n",
       "scene.toml:11: 'clump.inertia'",
       {"principal moments > 0"}},
      {"negative moment",
       head + "members = [[0, 0, 0, 0.001]]\ninertia = [1.0, -1.0, 1.0]\n",
       "scene.toml:11: 'clump.inertia'",
       {"principal moments > 0"}},
      {"two moments",
       head + "members = [[0, 0, 0, 0.001]]\ninertia = [1.0, 1.0]\n",
       "scene.toml:11: 'clump.inertia'",
       {"2 elements"}},
      {"huge member",
       head + "members = [[0, 0, 0, 1e200]]\n",
       "scene.toml:10: 'clump.members'",
       {"the volume of the union of the members overflows"}},
      {"tiny member",
       head + "members = [[0, 0, 0, 1e-200]]\n",
       "scene.toml:10: 'clump.members'",
       {"the volume of the union of the members underflows"}},
  };
  for (const BadTemplate& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_clump_bad");
    const std::string msg = load_error(d, scene_text(c.clump, ""));
    expect_contains(msg, {c.where});
    expect_contains(msg, c.expect);
  }
}

struct BadCsv {
  const char* what;
  std::string text;
  std::string where;  // "FILE:LINE: 'COLUMN'"
  std::vector<std::string> expect;
};

TEST(ClumpReader, BadMemberCsvNamesFileLineAndColumn) {
  const std::vector<BadCsv> cases = {
      {"missing column", "x,y,z\n0,0,0\n", "m.csv:1: 'radius'", {"missing required column"}},
      {"unknown column", "x,y,z,radius,mass\n0,0,0,0.001,1\n", "m.csv:1: 'mass'", {"unknown column"}},
      {"bad number", "x,y,z,radius\n0,0,0,0.001\n0,abc,0,0.001\n", "m.csv:3: 'y'", {"expected a number, got 'abc'"}},
      {"nan", "x,y,z,radius\n0,0,nan,0.001\n", "m.csv:2: 'z'", {"expected a finite number"}},
      {"negative radius", "x,y,z,radius\n0,0,0,-0.001\n", "m.csv:2: 'radius'", {"expected a radius > 0"}},
      {"three fields", "x,y,z,radius\n0,0,0\n", "m.csv:2", {"expected 4 fields"}},
      {"no rows", "x,y,z,radius\n", "m.csv:1", {"expected at least one member row"}},
  };
  for (const BadCsv& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_clump_csv");
    d.write("m.csv", c.text);
    const std::string msg = load_error(d, scene_text("[[clump]]\nname = \"d\"\nmembers = \"m.csv\"\n", ""));
    expect_contains(msg, {(d.path / c.where).string()});
    expect_contains(msg, c.expect);
  }
}

TEST(ClumpReader, BadBodyCsvNamesFileLineAndColumn) {
  const std::vector<BadCsv> cases = {
      {"missing x", "id,y,z\n1,0,0.01\n", "bodies.csv:1: 'x'", {"missing required column"}},
      {"missing id", "x,y,z\n0,0,0.01\n", "bodies.csv:1: 'id'", {"missing required column"}},
      {"unknown column", "id,x,y,z,material\n1,0,0,0.01,glass\n", "bodies.csv:1: 'material'", {"unknown column"}},
      {"non-unit quaternion",
       "id,x,y,z,q0,q1,q2,q3\n1,0,0,0.01,1,1,0,0\n",
       "bodies.csv:2: 'q0'",
       {"expected a unit quaternion", "norm^2 2"}},
      {"some of q", "id,x,y,z,q0,q3\n1,0,0,0.01,1,0\n", "bodies.csv:1: 'q1'", {"all of q0, q1, q2, q3", "or none"}},
      {"empty q field", "id,x,y,z,q0,q1,q2,q3\n1,0,0,0.01,1,,0,0\n", "bodies.csv:2: 'q1'", {"empty field"}},
      {"fixed 2", "id,x,y,z,fixed\n1,0,0,0.01,2\n", "bodies.csv:2: 'fixed'", {"expected 0 or 1"}},
      {"fixed yes", "id,x,y,z,fixed\n1,0,0,0.01,yes\n", "bodies.csv:2: 'fixed'", {"expected an integer"}},
      {"nan velocity", "id,x,y,z,vx\n1,0,0,0.01,nan\n", "bodies.csv:2: 'vx'", {"expected a finite number"}},
      {"duplicate id",
       "id,x,y,z\n1,0,0,0.01\n2,0,0,0.02\n1,0,0,0.03\n",
       "bodies.csv:4: 'id'",
       {"body id 1 is given twice (also at line 2)"}},
      {"id -1", "id,x,y,z\n-1,0,0,0.01\n", "bodies.csv:2: 'id'", {"expected a body id >= 0, got -1"}},
      {"no rows", "id,x,y,z\n", "bodies.csv:1", {"expected at least one body row"}},
  };
  for (const BadCsv& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_clump_body");
    const std::string msg = load_error(d, scene_text(), c.text);
    expect_contains(msg, {(d.path / c.where).string()});
    expect_contains(msg, c.expect);
  }
}

TEST(ClumpReader, DuplicateBodyIdAcrossEntriesNamesTheSecondRow) {
  TempDir d("mpdem_clump");
  d.write("more.csv", "id,x,y,z\n5,0,0,0.05\n1,0,0,0.03\n");
  const std::string msg = load_error(
      d, scene_text(kDumbbell, kBodies + "[[particles]]\nfile = \"more.csv\"\nclump = \"dumbbell\"\n"));
  expect_contains(
      msg, {(d.path / "more.csv").string() + ":3: 'id'", "body id 1 is given twice", "earlier [[particles]] entry"});
}

// Generated bodies (tests/generate/test_generated_bodies.cpp checks placement and orientations):
// the entry gives bodies of its template after the CSV's, with ids after the largest so far.
TEST(ClumpReader, GenerateGivesBodiesOfTheTemplate) {
  TempDir d("mpdem_clump");
  const Scene s = load(
      d, scene_text(kDumbbell, kBodies + "[[particles]]\nclump = \"dumbbell\"\ngenerate = { region = \"box\", "
                                         "min = [0, 0, 0], max = [0.1, 0.1, 0.1], count = 3 }\n"));
  const Bodies& B = s.particles.bodies;
  ASSERT_EQ(B.size(), 4u);
  ASSERT_EQ(s.particles.size(), 8u);
  EXPECT_EQ(B.id[0], 1);
  for (std::size_t b = 1; b < 4; ++b) {
    EXPECT_EQ(B.id[b], static_cast<std::int64_t>(b + 1));
    EXPECT_EQ(B.clump[b], 0);
    expect_rel(B.mass[b], dumbbell_mass(), kExact);
  }
}

TEST(ClumpReader, BadParticlesEntriesNameLineAndKey) {
  struct Case {
    const char* what;
    std::string particles;  // from line 11
    std::string extra;
    std::string where;
    std::vector<std::string> expect;
  };
  const std::string entry = "[[particles]]\nfile = \"bodies.csv\"\nclump = \"dumbbell\"\n";  // lines 11-13
  const std::vector<Case> cases = {
      {"unknown clump",
       "[[particles]]\nfile = \"bodies.csv\"\nclump = \"dumbell\"\n",
       "",
       "scene.toml:13: 'particles.clump'",
       {"unknown clump 'dumbell'", "(known: dumbbell)"}},
      {"clump not a string",
       "[[particles]]\nfile = \"bodies.csv\"\nclump = 3\n",
       "",
       "scene.toml:13: 'particles.clump'",
       {"expected a string"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_clump_entry");
    std::string text = scene_text(kDumbbell, c.particles, c.extra);
    const std::string msg = load_error(d, text);
    expect_contains(msg, {c.where});
    expect_contains(msg, c.expect);
  }
}

TEST(ClumpReader, UnusableBodyMassIsNamedAtTheBodyCsv) {
  // The template is fine per unit density; with the material's density (or an overridden mass)
  // the body's mass or moments are not numbers the run can divide by.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {kDumbbell + "mass = 1e308\n", "principal moment I1 overflows"},  // M / V * J
      {kDumbbell, "the body mass underflows"},                          // density 1e-300 below
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE(cases[k].second);
    TempDir d("mpdem_clump_size");
    std::string text = scene_text(cases[k].first);
    if (k == 1) text.replace(text.find("density = 2500"), 14, "density = 1e-300");
    const std::string msg = load_error(d, text);
    expect_contains(
        msg, {(d.path / "bodies.csv").string() + ":1: ", "clump 'dumbbell' of material 'glass'", cases[k].second});
  }
}

namespace {

// Lines 11-13: a generate entry whose `clump` (line 13) is `clump`.
std::string generated(const std::string& clump) {
  return "[[particles]]\ngenerate = { region = \"box\", min = [0, 0, 0], max = [0.1, 0.1, 0.1], count = 3 }\n"
         "clump = " +
         clump + "\n";
}

// Lines 14-19: an inlet box with count_rate, then `rest` from line 20.
std::string inlet(const std::string& rest) {
  return "[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0.05]\nmax = [0.01, 0.01, 0.06]\ncount_rate = 10\n"
         "velocity = [0, 0, -0.5]\n" +
         rest;
}

const std::string kStick = "[[clump]]\nname = \"stick\"\nmembers = [[0, 0, 0, 0.0005], [0, 0, 0.001, 0.0005]]\n";

}  // namespace

// A table of templates with number fractions: for generate and inlets, in the order written.
TEST(ClumpReader, FractionTableGivesTheMix) {
  TempDir d("mpdem_clump_mix");
  const Scene s = load(d, scene_text(kDumbbell, generated("{ stick = 0.25, dumbbell = 0.75 }"),
                                     kStick + inlet("clump = { stick = 0.4, dumbbell = 0.6 }\n")));
  const ClumpMix& g = s.particle_sources.front().clump;
  ASSERT_EQ(g.clumps.size(), 2u);
  EXPECT_EQ(g.clumps[0], 1);  // stick: written first
  EXPECT_EQ(g.fractions[0], 0.25);
  EXPECT_EQ(g.clumps[1], 0);
  EXPECT_EQ(s.particles.bodies.size(), 3u);
  const InletSpec& in = s.model.params.inlets.front();
  ASSERT_EQ(in.clump.clumps.size(), 2u);
  EXPECT_EQ(in.clump.fractions[1], 0.6);
  // The inlet's radii are its members' (the estimates that go by radius).
  EXPECT_EQ(in.radius.smallest(), 0.0005);
  EXPECT_EQ(in.radius.largest(), 0.001);
  // A string keeps working, and a table of one template is that template.
  const Scene one = load(d, scene_text(kDumbbell, generated("{ dumbbell = 1.0 }"), inlet("clump = \"dumbbell\"\n")));
  EXPECT_EQ(one.particle_sources.front().clump.clumps, std::vector<int>{0});
  EXPECT_EQ(one.model.params.inlets.front().clump.fractions, std::vector<double>{1.0});
}

TEST(ClumpReader, BadFractionTablesNameLineAndKey) {
  struct Case {
    const char* what;
    std::string particles;  // lines 11-13
    std::string extra;      // from line 14
    std::string where;
    std::vector<std::string> expect;
  };
  const std::vector<Case> cases = {
      {"negative",
       generated("{ dumbbell = -1.0 }"),
       "",
       "scene.toml:13: 'particles.clump.dumbbell'",
       {"expected a number > 0, got -1"}},
      {"zero",
       generated("{ dumbbell = 0 }"),
       "",
       "scene.toml:13: 'particles.clump.dumbbell'",
       {"expected a number > 0, got 0"}},
      {"sum below 1",
       generated("{ dumbbell = 0.5 }"),
       "",
       "scene.toml:13: 'particles.clump'",
       {"sum to 1 (within 1e-9)", "0.5"}},
      {"sum above 1",
       generated("{ dumbbell = 0.5, stick = 0.500001 }"),
       kStick,
       "scene.toml:13: 'particles.clump'",
       {"sum to 1 (within 1e-9)", "1.000001"}},
      {"unknown name",
       generated("{ dumbell = 1.0 }"),
       "",
       "scene.toml:13: 'particles.clump.dumbell'",
       {"unknown clump 'dumbell'", "(known: dumbbell)"}},
      {"not a number",
       generated("{ dumbbell = \"all\" }"),
       "",
       "scene.toml:13: 'particles.clump.dumbbell'",
       {"expected a number > 0, got a string"}},
      {"empty table", generated("{}"), "", "scene.toml:13: 'particles.clump'", {"at least one clump name"}},
      {"neither string nor table",
       generated("[\"dumbbell\"]"),
       "",
       "scene.toml:13: 'particles.clump'",
       {"expected a string (a clump name) or a table"}},
      {"table with a body CSV",
       "[[particles]]\nfile = \"bodies.csv\"\nclump = { dumbbell = 1.0 }\n",
       "",
       "scene.toml:13: 'particles.clump'",
       {"a body CSV takes one template"}},
      {"inlet: bad fraction",
       kBodies,
       inlet("clump = { dumbbell = 1.5 }\n"),
       "scene.toml:20: 'inlet.clump'",
       {"sum to 1"}},
      {"inlet: unknown name",
       kBodies,
       inlet("clump = \"dumbell\"\n"),
       "scene.toml:20: 'inlet.clump'",
       {"unknown clump 'dumbell'", "(known: dumbbell)"}},
      {"inlet: radius with clump",
       kBodies,
       inlet("clump = \"dumbbell\"\nradius = 0.001\n"),
       "scene.toml:21: 'inlet.radius'",
       {"does not apply with clump"}},
      {"inlet: radius table with clump",
       kBodies,
       inlet("clump = \"dumbbell\"\nradius = { distribution = \"uniform\", min = 0.001, max = 0.002 }\n"),
       "scene.toml:21: 'inlet.radius'",
       {"does not apply with clump"}},
      {"inlet: body larger than the region",
       kBodies,
       "[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0.05]\nmax = [0.01, 0.01, 0.053]\ncount_rate = 10\nclump = "
       "\"dumbbell\"\n",
       "scene.toml:19: 'inlet.clump'",
       {"bounding sphere (radius 0.002 m", "does not fit"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_clump_mix_bad");
    const std::string msg = load_error(d, scene_text(kDumbbell, c.particles, c.extra));
    expect_contains(msg, {c.where});
    expect_contains(msg, c.expect);
  }
}

// Clump bodies in the scene and an inlet of spheres run together (the refusal is lifted).
TEST(ClumpReader, ClumpEntryWithAnInletOfSpheresLoads) {
  TempDir d("mpdem_clump_inlet_spheres");
  const Scene s = load(d, scene_text(kDumbbell, kBodies, inlet("radius = 0.001\n")));
  EXPECT_EQ(s.particles.bodies.size(), 1u);
  EXPECT_TRUE(s.model.params.inlets.front().clump.empty());
}
