// STL barriers whose placement overflows or underflows (issue 16): a scale, translation or
// motion offset that makes a vertex, the area or the normal non-finite, or collapses a triangle
// to zero area, is an InputError naming the scene's key, the STL file and the triangle; so is a
// triangle whose area overflows in the file itself, and the same for barrier CSV rows. An ASCII
// STL may start with a UTF-8 byte order mark.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/barrier_csv.hpp"
#include "core/input_error.hpp"
#include "io/stl_reader.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::expect_contains;

namespace {

// One facet per call, `pos` its first vertex, unit legs along y and z.
std::string facet(const std::string& pos, const std::string& b, const std::string& c) {
  return "  facet normal 1 0 0\n    outer loop\n      vertex " + pos + "\n      vertex " + b + "\n      vertex " + c +
         "\n    endloop\n  endfacet\n";
}

const std::string kUnitTriangle = "solid t\n" + facet("0 0 0", "0 1 0", "0 0 1") + "endsolid t\n";

// A scene (material on lines 4-5, [[barriers]] on line 6) placing `stl` with `keys`.
fs::path scene_with(const TempDir& d, const std::string& stl, const std::string& keys) {
  return d.write("scene.toml",
                 "[time]\nduration = 1.0\ndt = 1e-5\n[[material]]\nname = \"steel\"\n[[barriers]]\nstl = \"" + stl +
                     "\"\n" + keys);
}

// The InputError load_scene throws, or a test failure.
InputError load_error(const fs::path& scene) {
  try {
    load_scene(scene);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError loading " << scene;
  return InputError("", 0, "", "");
}

}  // namespace

// scale = 1e160 made the area infinite and the normal NaN, and the scene loaded.
TEST(StlPlacement, ScaleOverflowingTheAreaNamesKeyFileAndTriangle) {
  TempDir d("mpdem_stlplace");
  d.write("tri.stl",
          "solid t\n" + facet("0 0 0", "0 1 0", "0 0 1") + facet("1 0 0", "1 1 0", "1 0 1") + "endsolid t\n");
  const fs::path scene = scene_with(d, "tri.stl", "scale = 1e160\n");
  const InputError e = load_error(scene);
  EXPECT_EQ(e.file(), scene.string());
  EXPECT_EQ(e.line(), 6u);
  EXPECT_EQ(e.key(), "barriers.scale");
  expect_contains(e.what(), {"tri.stl' triangle 1 (line 2)", "its area overflows", "after scale = 1e+160"});
}

// A scale of 1e-200 collapsed every triangle; they were dropped with a warning and the source
// held no barrier at all.
TEST(StlPlacement, ScaleCollapsingTrianglesIsAnError) {
  TempDir d("mpdem_stlplace");
  d.write("tri.stl", kUnitTriangle);
  const InputError e = load_error(scene_with(d, "tri.stl", "scale = 1e-200\n"));
  EXPECT_EQ(e.key(), "barriers.scale");
  expect_contains(e.what(), {"triangle 1 (line 2)", "collapses to zero area", "after scale = 1e-200"});
}

// A translation pushing a finite vertex past the largest double: the vertex is infinite.
TEST(StlPlacement, TranslateOverflowingAVertexNamesTheKey) {
  TempDir d("mpdem_stlplace");
  d.write("far.stl", "solid t\n" + facet("5e307 0 0", "5e307 1 0", "5e307 0 1") + "endsolid t\n");
  const InputError e = load_error(scene_with(d, "far.stl", "translate = [1.5e308, 0, 0]\n"));
  EXPECT_EQ(e.key(), "barriers.translate");
  expect_contains(e.what(), {"far.stl' triangle 1", "vertex 1 is (inf, 0, 0)", "after translate = (1.5e+308, 0, 0)"});
}

// The motion law's B shifts the element at t = 0: an overflowing shifted vertex is refused.
TEST(StlPlacement, MotionOffsetOverflowingAVertexNamesTheKey) {
  TempDir d("mpdem_stlplace");
  d.write("far.stl", "solid t\n" + facet("5e307 0 0", "5e307 1 0", "5e307 0 1") + "endsolid t\n");
  const InputError e = load_error(scene_with(d, "far.stl", "motion = { B = [1.5e308, 0, 0] }\n"));
  EXPECT_EQ(e.key(), "barriers.motion.B");
  expect_contains(e.what(), {"far.stl' triangle 1", "vertex 1 overflows"});
}

// Finite ASCII coordinates whose area overflows were counted as degenerate and dropped silently.
TEST(StlPlacement, AreaOverflowInTheFileNamesTheStlLine) {
  TempDir d("mpdem_stlplace");
  const fs::path stl = d.write("huge.stl", "solid t\n" + facet("0 0 0", "0 1 0", "0 0 1") +
                                               facet("0 0 0", "0 1e200 0", "0 0 1e200") + "endsolid t\n");
  const InputError e = load_error(scene_with(d, "huge.stl", ""));
  EXPECT_EQ(e.file(), stl.string());
  EXPECT_EQ(e.line(), 9u);
  expect_contains(e.what(), {"triangle 2: its area overflows"});
}

// A placement that keeps every triangle finite and non-degenerate still loads.
TEST(StlPlacement, UsualPlacementLoads) {
  TempDir d("mpdem_stlplace");
  d.write("tri.stl", kUnitTriangle);
  const Scene s = load_scene(
      scene_with(d, "tri.stl", "scale = 1e-3\nrotate_deg = [0, 90, 0]\ntranslate = [0, 0, 1]\n"));
  ASSERT_EQ(s.barriers.size(), 1u);
  EXPECT_NEAR(s.barriers.area[0], 0.5e-6, 1e-18);
  EXPECT_NEAR(std::abs(s.barriers.normal[0].z), 1.0, 1e-12);  // +x turned about y
}

// Barrier CSV: an overflowing area names the largest coordinate's column, an overflowing
// motion offset the B column (the message of either named no column before).
TEST(StlPlacement, BarrierCsvOverflowsNameTheColumn) {
  TempDir d("mpdem_stlplace");
  Barriers out;
  const fs::path f = d.write("b.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n0,0,0,1,0,0,0,1,0\n0,0,0,1e200,0,0,0,1e200,0\n");
  try {
    read_barrier_csv(f, BarrierSource{}, Model{}, out);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.key(), "x2");
    expect_contains(e.what(), {"triangle too large: its area overflows"});
  }
  const fs::path g = d.write("m.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3,Bx\n5e307,0,0,5e307,1,0,5e307,0,1,1.5e308\n");
  Barriers out2;
  try {
    read_barrier_csv(g, BarrierSource{}, Model{}, out2);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.key(), "Bx");
    expect_contains(e.what(), {"vertex 1 (5e+307, 0, 0) moved by B = (1.5e+308, 0, 0) at t = 0 overflows"});
  }
  EXPECT_EQ(out2.size(), 0u);
}

// An ASCII STL saved with a byte order mark was taken for a truncated binary file ("the header
// announces 774905976 triangles").
TEST(StlPlacement, AsciiWithByteOrderMarkIsRead) {
  TempDir d("mpdem_stlplace");
  const StlMesh m = read_stl(d.write("bom.stl", "\xEF\xBB\xBF" + kUnitTriangle));
  EXPECT_FALSE(m.binary);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.triangles[0][1], (Vec3{0, 1, 0}));
  // Lines count as without the mark.
  std::string bad = "\xEF\xBB\xBF" + kUnitTriangle;
  bad.replace(bad.find("vertex 0 1 0"), 6, "vertx");
  try {
    read_stl(d.write("bom_bad.stl", bad));
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 5u);
    expect_contains(e.what(), {"expected keyword 'vertex', got 'vertx'"});
  }
}
