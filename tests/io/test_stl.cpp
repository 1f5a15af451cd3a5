// STL barriers: ASCII and binary files of the same mesh load identically; malformed files give an
// InputError naming the file and the problem; scene [[barriers]] stl with transform, group,
// material and motion law; degenerate triangles dropped with a warning.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <limits>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/barrier_csv.hpp"
#include "core/input_error.hpp"
#include "io/stl_reader.hpp"
#include "io/stl_writer.hpp"
#include "model/scene.hpp"
#include "tools/mesh_builder.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::error_of;
using mpdem::test::expect_contains;

namespace {


std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The InputError of read_stl(file), or a test failure.
InputError stl_error(const fs::path& file) {
  try {
    read_stl(file);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for " << file;
  return InputError("", 0, "", "");
}

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in: " << text;
}

const char* kFacets = R"(solid test
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 1 0 0
      vertex 0 1 0
    endloop
  endfacet
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 1 1 0
      vertex 2 2 0
    endloop
  endfacet
  FACET NORMAL 0 0 0
    OUTER LOOP
      VERTEX 1 0 0
      VERTEX 1 1 0
      VERTEX 0 1 0
    ENDLOOP
  ENDFACET
endsolid test
)";

}  // namespace

TEST(Stl, AsciiAndBinaryLoadIdentically) {
  TempDir dir("mpdem_stl");
  // Dyadic sizes: every coordinate is exact in float and double, so both files must agree bitwise.
  const auto box = soup(make_box(1.0, 0.5, 0.25, true));
  write_stl(dir.path / "box_a.stl", box, StlFormat::Ascii);
  write_stl(dir.path / "box_b.stl", box, StlFormat::Binary);
  const StlMesh a = read_stl(dir.path / "box_a.stl"), b = read_stl(dir.path / "box_b.stl");
  EXPECT_FALSE(a.binary);
  EXPECT_TRUE(b.binary);
  ASSERT_EQ(a.triangles.size(), 12u);
  ASSERT_EQ(b.triangles.size(), 12u);
  for (std::size_t t = 0; t < 12; ++t)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a.triangles[t][k], box[t][k]);
      EXPECT_EQ(b.triangles[t][k], box[t][k]);
    }
  EXPECT_EQ(fs::file_size(dir.path / "box_b.stl"), 84u + 50u * 12u);

  // A cylinder: ASCII keeps doubles exactly; binary rounds to float (relative 2^-24).
  const auto cyl = soup(make_cylinder(0.05, 0.1, 16, true));
  write_stl(dir.path / "cyl_a.stl", cyl, StlFormat::Ascii);
  write_stl(dir.path / "cyl_b.stl", cyl, StlFormat::Binary);
  const StlMesh ca = read_stl(dir.path / "cyl_a.stl"), cb = read_stl(dir.path / "cyl_b.stl");
  ASSERT_EQ(ca.triangles.size(), cyl.size());
  ASSERT_EQ(cb.triangles.size(), cyl.size());
  for (std::size_t t = 0; t < cyl.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(ca.triangles[t][k], cyl[t][k]);
      EXPECT_LE(norm(cb.triangles[t][k] - cyl[t][k]), 0.1 * 6e-8);
    }
}

TEST(Stl, DegenerateTrianglesDroppedAndCounted) {
  TempDir dir("mpdem_stl");
  const StlMesh m = read_stl(dir.write("d.stl", kFacets));
  EXPECT_EQ(m.triangles.size(), 2u);  // upper-case keywords accepted
  EXPECT_EQ(m.degenerate, 1u);        // the collinear (0,0,0), (1,1,0), (2,2,0)
}

TEST(Stl, MalformedFilesNameFileAndProblem) {
  TempDir dir("mpdem_stl");
  // Truncated binary: 10 bytes short of what its header announces.
  write_stl(dir.path / "t.stl", soup(make_box(1, 1, 1, true)), StlFormat::Binary);
  std::string bin = slurp(dir.path / "t.stl");
  const fs::path trunc = dir.write("trunc.stl", bin.substr(0, bin.size() - 10));
  InputError e = stl_error(trunc);
  expect_contains(e.what(), trunc.string());
  expect_contains(
      e.what(),
      "truncated or malformed binary STL: the header announces 12 triangles (684 bytes) but the file has 674 bytes");
  e = stl_error(dir.write("short.stl", bin.substr(0, 50)));
  expect_contains(e.what(), "less than the 84-byte header");

  // NaN coordinate in a binary file.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bin.data() + 84 + 50 * 3 + 12 + 12 + 4, &nan, 4);  // triangle 4, vertex 2, y
  e = stl_error(dir.write("nan.stl", bin));
  expect_contains(e.what(), "binary STL triangle 4: vertex 2 has a non-finite coordinate");

  // Bad ASCII keyword on line 5.
  std::string text = kFacets;
  text.replace(text.find("vertex 1 0 0"), 6, "vertx");
  e = stl_error(dir.write("kw.stl", text));
  EXPECT_EQ(e.line(), 5u);
  expect_contains(e.what(), (dir.path / "kw.stl").string() + ":5: expected keyword 'vertex', got 'vertx'");
  // NaN and a non-number in ASCII, both with their line.
  text = kFacets;
  text.replace(text.find("vertex 0 1 0"), 12, "vertex 0 nan 0");
  e = stl_error(dir.write("nan_a.stl", text));
  expect_contains(e.what(), "nan_a.stl:6: non-finite vertex coordinate 'nan'");
  text = kFacets;
  text.replace(text.find("normal 0 0 1"), 12, "normal 0 x 1");
  e = stl_error(dir.write("num.stl", text));
  expect_contains(e.what(), "num.stl:2: expected a number (normal component), got 'x'");
  // Cut off in the middle of a facet.
  text = kFacets;
  e = stl_error(dir.write("cut.stl", text.substr(0, text.find("endloop"))));
  expect_contains(e.what(), "unexpected end of file, expected 'endloop'");
  // Empty.
  e = stl_error(dir.write("empty.stl", ""));
  expect_contains(e.what(), "empty STL file");
}

TEST(Stl, SceneBarriersWithTransformGroupMaterialMotion) {
  TempDir dir("mpdem_stl");
  write_stl(dir.path / "bin.stl", soup(make_box(1.0, 0.5, 0.25, true)), StlFormat::Binary);
  dir.write("deg.stl", kFacets);
  const fs::path scene = dir.write("scene.toml", R"(
[time]
duration = 1.0
dt = 1e-5

[[material]]
name = "glass"

[[material]]
name = "steel"
young = 2.1e11
poisson = 0.29

[[barriers]]
stl = "bin.stl"
scale = 2.0
rotate_deg = [0, 0, 90]
translate = [1, 0, 0]
group = "bin"
material = "steel"
thickness = 0.001
motion = { a = [0, 0, 0.5] }

[[barriers]]
stl = "deg.stl"
)");
  ::testing::internal::CaptureStderr();
  const Scene s = load_scene(scene);
  const std::string err = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(s.barriers.size(), 12u + 2u);
  expect_contains(err, "deg.stl: dropped 1 degenerate (zero-area) triangle(s) of 3");
  EXPECT_EQ(s.barriers.group_names[s.barriers.group[0]], "bin");
  EXPECT_EQ(s.barriers.group_names[s.barriers.group[12]], "deg");  // default: the file stem
  const auto box = soup(make_box(1.0, 0.5, 0.25, true));
  double area = 0.0;
  for (std::size_t e = 0; e < 12; ++e) {
    // Scale 2, quarter turn about z: (x, y, z) -> (-2y, 2x, 2z), then + (1, 0, 0).
    const Vec3 p = box[e][0];
    EXPECT_NEAR(norm(s.barriers.p0[e] - Vec3{1 - 2 * p.y, 2 * p.x, 2 * p.z}), 0.0, 1e-15);
    EXPECT_EQ(s.barriers.young[e], 2.1e11);
    EXPECT_EQ(s.barriers.poisson[e], 0.29);
    EXPECT_EQ(s.barriers.thickness[e], 0.001);
    EXPECT_EQ(s.barriers.motion[e].a, (Vec3{0, 0, 0.5}));
    area += s.barriers.area[e];
  }
  EXPECT_NEAR(area, 4 * 2 * (0.5 + 0.125 + 0.25), 1e-14);
  EXPECT_EQ(s.barriers.id[12], 12);  // ids continue across sources

  // A malformed STL in a scene: the STL file and the problem.
  dir.write("bad.stl", "solid x\n facet normal 0 0 1\n outer lop\n");
  const fs::path bad = dir.write("bad.toml", "[time]\nduration = 1.0\ndt = 1e-5\n[[barriers]]\nstl = \"bad.stl\"\n");
  try {
    load_scene(bad);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    expect_contains(e.what(), "bad.stl:3: expected keyword 'loop', got 'lop'");
  }
}

TEST(Stl, MeshCommandWritesCsvAndStl) {
  TempDir dir("mpdem_stl");
  const auto run = [&](const std::string& args) {
    const std::string cmd = std::string("\"") + MPDEM_BINARY + "\" mesh " + args + " > /dev/null 2>&1";
    const int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  };
  const std::string out = dir.path.string();
  ASSERT_EQ(run("cylinder --radius 0.05 --height 0.1 --segments 12 --closed -o \"" + out + "/c.stl\""), 0);
  ASSERT_EQ(run("cylinder --radius 0.05 --height 0.1 --segments 12 --closed --format stl-ascii -o \"" + out +
                "/c_ascii.stl\""),
            0);
  ASSERT_EQ(run("cylinder --radius 0.05 --height 0.1 --segments 12 --closed --group drum -o \"" + out + "/c.csv\""), 0);
  const StlMesh b = read_stl(dir.path / "c.stl"), a = read_stl(dir.path / "c_ascii.stl");
  EXPECT_TRUE(b.binary);
  EXPECT_FALSE(a.binary);
  EXPECT_EQ(a.triangles.size(), 48u);  // 12 x (2 side + 2 cap)
  EXPECT_EQ(b.triangles.size(), 48u);
  Barriers csv;
  read_barrier_csv(dir.path / "c.csv", BarrierSource{}, Model{}, csv);
  ASSERT_EQ(csv.size(), 48u);
  EXPECT_EQ(csv.group_names[csv.group[0]], "drum");
  for (std::size_t t = 0; t < 48; ++t)
    for (int k = 0; k < 3; ++k) {
      const Vec3 v = k == 0 ? csv.p0[t] : k == 1 ? csv.p1[t] : csv.p2[t];
      EXPECT_EQ(v, a.triangles[t][k]);  // CSV and ASCII STL both keep doubles exactly
    }
  ASSERT_EQ(run("chute --length 1 --angle 30 --transition-radius 0.2 --runout 0.5 --width 0.1 --wall-height 0.05 "
                "--rotate-deg 0 0 0 -o \"" +
                out + "/chute.csv\""),
            0);
  ASSERT_EQ(run("plate --size 0.2 0.2 --hole-radius 0.03 -o \"" + out + "/plate.stl\""), 0);
  ASSERT_EQ(run("funnel --top-radius 0.1 --outlet-radius 0.02 --height 0.1 -o \"" + out + "/f.stl\""), 0);
  // Bad input: exit status 2.
  EXPECT_EQ(run("plate --size 0.2 0.2 --hole-radius 0.2 -o \"" + out + "/p2.stl\""), 2);
  EXPECT_EQ(run("box --size 1 1 1 -o \"" + out + "/b.txt\""), 2);
}
