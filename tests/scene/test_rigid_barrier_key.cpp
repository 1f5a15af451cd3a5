// The [[barriers]] key `rigid` (src/scene/scene_reader.cpp, docs/scene.md): read from TOML for CSV
// and STL sources, the elements get a rigid variant of their material (E = +inf, the material's
// other constants kept), a non-boolean value and per-row young/poisson columns are refused, and
// `mpdem check` prints the rigid barrier without NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "model/scene.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::error_of;
using mpdem::test::expect_contains;
using mpdem::test::TempDir;

namespace {

const std::string kHead =
    "[time]\nduration = 1e-3\ndt = 1e-6\n"                                                                 // 1-3
    "[[material]]\nname = \"glass\"\n"                                                                     // 4-5
    "[[material]]\nname = \"steel\"\nyoung = 2e11\npoisson = 0.29\nconductivity = 45\nemissivity = 0.3\n"  // 6-11
    "[[particles]]\nfile = \"p.csv\"\n";                                                                   // 12-13
const char* kParticles = "x,y,z,radius\n0,0,0.002,0.001\n";
const char* kWall = "x1,y1,z1,x2,y2,z2,x3,y3,z3\n-1,-1,0,1,-1,0,1,1,0\n";
const char* kStl = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1\nvertex 1 0 1\nvertex 0 1 1\nendloop\n"
                   "endfacet\nendsolid s\n";

void write_inputs(const TempDir& d) {
  d.write("p.csv", kParticles);
  d.write("w.csv", kWall);
  d.write("roof.stl", kStl);
}

}  // namespace

TEST(RigidBarrierKey, ReadAndAppliedToCsvAndStlSources) {
  TempDir d("mpdem_rigid");
  write_inputs(d);
  const fs::path scene = d.write("scene.toml",
                                 kHead + "[[barriers]]\nfile = \"w.csv\"\nmaterial = \"steel\"\nrigid = true\n"
                                         "[[barriers]]\nstl = \"roof.stl\"\nmaterial = \"steel\"\nrigid = true\n"
                                         "[[barriers]]\nfile = \"w.csv\"\ngroup = \"soft\"\nmaterial = \"steel\"\n");
  d.write("w.csv", std::string(kWall) + "-1,-1,0,1,1,0,-1,1,0\n");
  const Scene s = load_scene(scene);
  ASSERT_EQ(s.barrier_sources.size(), 3u);
  EXPECT_TRUE(s.barrier_sources[0].rigid);
  EXPECT_TRUE(s.barrier_sources[1].rigid);
  EXPECT_FALSE(s.barrier_sources[2].rigid);  // the default
  const Barriers& b = s.barriers;
  ASSERT_EQ(b.size(), 5u);  // 2 rigid CSV rows, 1 rigid STL facet, 2 soft CSV rows
  const int steel = s.model.material_index("steel");
  for (std::size_t e = 0; e < b.size(); ++e) {
    const Material& m = s.model.materials[static_cast<std::size_t>(b.material[e])];
    if (e < 3) {
      EXPECT_TRUE(std::isinf(b.young[e]) && b.young[e] > 0.0) << e;
      EXPECT_TRUE(is_rigid(m)) << e;
      EXPECT_EQ(m.variant_of, steel);
      EXPECT_EQ(m.conductivity, 45.0);  // the material's other constants stay
      EXPECT_EQ(m.emissivity, 0.3);
      EXPECT_EQ(b.material[e], b.material[0]);  // one rigid variant for both sources
    } else {
      EXPECT_EQ(b.young[e], 2e11) << e;
      EXPECT_EQ(b.material[e], steel);
    }
  }
}

TEST(RigidBarrierKey, BadValuesNameFileLineAndKey) {
  TempDir d("mpdem_rigid");
  write_inputs(d);
  const fs::path scene = d.write("scene.toml", kHead + "[[barriers]]\nfile = \"w.csv\"\nrigid = \"yes\"\n");
  expect_contains(error_of([&] { parse_scene_file(scene); }),
                  {scene.string() + ":16: 'barriers.rigid': ", "expected a boolean (true or false), got a string"});
  // A rigid element has no E or nu of its own: a per-row value would be ignored.
  d.write("scene.toml", kHead + "[[barriers]]\nfile = \"w.csv\"\nrigid = true\n");
  const fs::path wall = d.write("w.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3,poisson\n-1,-1,0,1,-1,0,1,1,0,0.2\n");
  expect_contains(error_of([&] { load_scene(scene); }),
                  {wall.string() + ":2: 'poisson': ", "a rigid barrier ([[barriers]] rigid = true) takes no young"});
}

// `mpdem check`: the rigid variant is listed as rigid, the particle-barrier contact time is that
// of E* = E/(1 - nu^2) (finite), nothing prints as NaN; a bad value exits with status 2.
TEST(RigidBarrierKey, CheckCommandPrintsRigid) {
  TempDir d("mpdem_rigid");
  write_inputs(d);
  d.write("scene.toml", kHead + "[[barriers]]\nfile = \"w.csv\"\nmaterial = \"steel\"\nrigid = true\n");
  const test::CommandResult ok = test::run_mpdem("check scene.toml", d.path);
  EXPECT_EQ(ok.status, 0) << ok.err;
  expect_contains(ok.out, {"E rigid", " 1 triangles (rigid)", "particle-barrier"});
  EXPECT_EQ(ok.out.find("nan"), std::string::npos) << ok.out;
  EXPECT_EQ(ok.out.find("inf"), std::string::npos) << ok.out;
  d.write("scene.toml", kHead + "[[barriers]]\nfile = \"w.csv\"\nrigid = \"yes\"\n");
  const test::CommandResult bad = test::run_mpdem("check scene.toml", d.path);
  EXPECT_EQ(bad.status, 2);
  expect_contains(bad.err, {"scene.toml:16: 'barriers.rigid': "});
}
