// VTU particle and barrier snapshots and the PVD index, read back by an independent reader (meshio and
// xml.etree: tests/read_vtu.py run with /usr/bin/python3); 17 significant digits: every double exact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/pvd_index.hpp"
#include "io/vtu_writer.hpp"
#include "state/barriers.hpp"
#include "state/particles.hpp"
#include "support/output_folder.hpp"
#include "support/sample_particles.hpp"

#ifndef MPDEM_SOURCE_DIR
#error "MPDEM_SOURCE_DIR must name the repository root (tests/read_vtu.py lives there)"
#endif

namespace fs = std::filesystem;
using namespace mpdem;
using namespace mpdem::test::output;  // OutputTest, slurp, split, lines_of, files_in
using mpdem::test::make_particles;

namespace {

// Runs the independent reader; fails the test if it exits non-zero.
std::string run_reader(const fs::path& file, const std::string& option = "") {
  const std::string cmd = std::string("/usr/bin/python3 '") + MPDEM_SOURCE_DIR + "/tests/read_vtu.py' " + option +
                          " '" + file.string() + "' 2>&1";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("popen failed");
  std::string out;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  const int status = ::pclose(pipe);
  EXPECT_EQ(status, 0) << "reader failed on " << file << ":\n" << out;
  return out;
}

// One array printed by read_vtu.py: tuples x components tokens.
struct Array {
  std::size_t tuples = 0, components = 0;
  std::vector<std::string> tokens;
  double d(std::size_t t, std::size_t c) const { return std::stod(tokens.at(t * components + c)); }
  long long i(std::size_t t, std::size_t c) const { return std::stoll(tokens.at(t * components + c)); }
};

// Key "kind/name", e.g. "point_data/velocity", "cells/vertex", "field_data/TimeValue".
std::map<std::string, Array> read_vtu(const fs::path& file) {
  std::istringstream in(run_reader(file));
  std::map<std::string, Array> out;
  std::string kind, name;
  while (in >> kind >> name) {
    Array a;
    in >> a.tuples >> a.components;
    a.tokens.resize(a.tuples * a.components);
    for (auto& t : a.tokens) in >> t;
    out[kind + "/" + name] = std::move(a);
  }
  return out;
}

struct Listed {
  double time;
  std::string file;
};
std::vector<Listed> read_pvd(const fs::path& file) {
  std::vector<Listed> out;
  for (const std::string& line : lines_of(run_reader(file))) {
    if (line.empty()) continue;
    std::istringstream in(line);
    std::string tag, t;
    in >> tag >> t;
    EXPECT_EQ(tag, "dataset") << line;
    std::string rest;
    std::getline(in, rest);
    out.push_back({std::stod(t), rest.substr(1)});  // rest starts with the separating space
  }
  return out;
}

// read_vtu.py's meshio dump without its "cells ..." blocks: what the VTK reader's dump must equal.
std::string without_cells(const std::string& dump) {
  std::istringstream in(dump);
  std::string out, line;
  bool skip = false;
  while (std::getline(in, line)) {
    const bool header = line.rfind("points ", 0) == 0 || line.rfind("cells ", 0) == 0 ||
                        line.rfind("point_data ", 0) == 0 || line.rfind("cell_data ", 0) == 0 ||
                        line.rfind("field_data ", 0) == 0;
    if (header) skip = line.rfind("cells ", 0) == 0;
    if (!skip) out += line + "\n";
  }
  return out;
}

// Every format reads back, with meshio and with VTK, exactly as the ASCII file does: the ASCII
// file is checked value by value against the state, the others against it.
void expect_formats_agree(const std::function<void(const fs::path&, VtkFormat)>& write, const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path ascii = dir / "ascii.vtu";
  write(ascii, VtkFormat::Ascii);
  const std::string meshio_ascii = run_reader(ascii);
  // compared with == (gtest's diff of large texts is quadratic); the files stay for a look
  EXPECT_TRUE(run_reader(ascii, "--vtk") == without_cells(meshio_ascii)) << "VTK's reading of " << ascii;
  for (const VtkFormat f : {VtkFormat::Binary, VtkFormat::Compressed}) {
    SCOPED_TRACE(vtk_format_name(f));
    const fs::path file = dir / (std::string(vtk_format_name(f)) + ".vtu");
    write(file, f);
    EXPECT_TRUE(run_reader(file) == meshio_ascii) << "meshio's reading of " << file;
    EXPECT_TRUE(run_reader(file, "--vtk") == without_cells(meshio_ascii)) << "VTK's reading of " << file;
    const std::string head = slurp(file).substr(0, 400);
    EXPECT_NE(head.find("format=\"appended\""), std::string::npos);
    EXPECT_EQ(head.find("compressor=") != std::string::npos, f == VtkFormat::Compressed);
  }
}

void expect_vec(const Array& a, std::size_t t, const Vec3& v) {
  ASSERT_EQ(a.components, 3u);
  EXPECT_EQ(a.d(t, 0), v.x);
  EXPECT_EQ(a.d(t, 1), v.y);
  EXPECT_EQ(a.d(t, 2), v.z);
}

}  // namespace

TEST_F(OutputTest, ParticleVtuRoundTripsThroughMeshio) {
  const Particles p = make_particles(5);
  const double time = 0.1 + 1.0 / 3.0 * 1e-3;
  const fs::path file = dir / "particles.vtu";
  const VtuOptions ascii{VtkFormat::Ascii, {"glass", "steel"}};
  write_particles_vtu(file, p, time, ascii);
  EXPECT_EQ(files_in(dir), std::vector<fs::path>{"particles.vtu"});
  const auto r = read_vtu(file);

  std::vector<std::string> keys;
  for (const auto& [k, a] : r) keys.push_back(k);
  const std::vector<std::string> expected_keys = {"cells/vertex",
                                                  "field_data/TimeValue",
                                                  "field_data/material:glass",
                                                  "field_data/material:steel",
                                                  "point_data/angular_velocity",
                                                  "point_data/body",
                                                  "point_data/charge",
                                                  "point_data/fixed",
                                                  "point_data/force",
                                                  "point_data/id",
                                                  "point_data/material",
                                                  "point_data/orientation",
                                                  "point_data/radius",
                                                  "point_data/temperature",
                                                  "point_data/torque",
                                                  "point_data/velocity",
                                                  "points/Points"};
  ASSERT_EQ(keys, expected_keys);  // std::map keeps them sorted
  EXPECT_EQ(r.at("field_data/material:glass").i(0, 0), 0);
  EXPECT_EQ(r.at("field_data/material:steel").i(0, 0), 1);

  ASSERT_EQ(r.at("field_data/TimeValue").tokens.size(), 1u);
  EXPECT_EQ(r.at("field_data/TimeValue").d(0, 0), time);
  const Array& cells = r.at("cells/vertex");
  ASSERT_EQ(cells.tuples, p.size());
  ASSERT_EQ(cells.components, 1u);
  for (const auto& [k, a] : r)
    if (k.rfind("field_data/", 0) != 0) {
      EXPECT_EQ(a.tuples, p.size()) << k;
    }

  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(cells.i(i, 0), static_cast<long long>(i));
    expect_vec(r.at("points/Points"), i, p.x[i]);
    EXPECT_EQ(r.at("point_data/id").i(i, 0), p.id[i]);
    EXPECT_EQ(r.at("point_data/material").i(i, 0), p.material[i]);
    EXPECT_EQ(r.at("point_data/fixed").i(i, 0), p.fixed[i]);
    EXPECT_EQ(r.at("point_data/radius").d(i, 0), p.radius[i]);
    expect_vec(r.at("point_data/velocity"), i, p.v[i]);
    expect_vec(r.at("point_data/angular_velocity"), i, p.w[i]);
    expect_vec(r.at("point_data/force"), i, p.force[i]);
    EXPECT_EQ(r.at("point_data/temperature").d(i, 0), p.T[i]);
    EXPECT_EQ(r.at("point_data/charge").d(i, 0), p.charge[i]);
    const Array& q = r.at("point_data/orientation");
    ASSERT_EQ(q.components, 4u);
    EXPECT_EQ(q.d(i, 0), p.q[i].w);
    EXPECT_EQ(q.d(i, 1), p.q[i].x);
    EXPECT_EQ(q.d(i, 2), p.q[i].y);
    EXPECT_EQ(q.d(i, 3), p.q[i].z);
  }
  expect_formats_agree(
      [&](const fs::path& f, VtkFormat format) {
        write_particles_vtu(f, p, time, {format, ascii.material_names});
      },
      dir / "formats");
}

// Enough particles for several compressed blocks (32 KiB each), with a partial last block.
TEST_F(OutputTest, LargeParticleVtuAgreesInEveryFormat) {
  const Particles p = make_particles(3001);
  expect_formats_agree(
      [&](const fs::path& f, VtkFormat format) {
        write_particles_vtu(f, p, 0.25, {format, {"a"}});
      },
      dir);
}

// meshio 5 cannot read a grid without cells, so the empty case is checked with xml.etree:
// well-formed, zero points and cells, every array empty except the time.
TEST_F(OutputTest, EmptyParticleVtuIsWellFormed) {
  const fs::path file = dir / "empty.vtu";
  write_particles_vtu(file, Particles{}, 2.5, {VtkFormat::Ascii, {}});
  const auto lines = lines_of(run_reader(file, "--xml"));
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "piece 0 0");
  int arrays = 0;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    std::istringstream in(lines[k]);
    std::string tag, name;
    std::size_t count = 99;
    in >> tag >> name >> count;
    EXPECT_EQ(tag, "array");
    EXPECT_EQ(count, name == "TimeValue" ? 1u : 0u) << lines[k];
    ++arrays;
  }
  EXPECT_EQ(arrays, 1 + 12 + 1 + 3);  // time, 12 point arrays, points, 3 cell arrays
}

TEST_F(OutputTest, BarrierVtuHasMovedTrianglesAndLoads) {
  Barriers b;
  const MotionLaw law0{{0.5, 0.0, -0.25}, {0.01, 0.02, 0.0}, 3.0, {0.0, 0.0, 0.003}, 7.0, {}};
  const MotionLaw law1{};  // static
  const MotionLaw law2{{0.0, -1.0 / 3.0, 0.0}, {}, 0.0, {}, 0.0, {}};
  ASSERT_TRUE(b.add(11, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1e9, 0.3, law0, 1e-3, 300.0));
  ASSERT_TRUE(b.add(12, {0.1, 0.2, 0.3}, {1.1, 0.2, 0.3}, {0.1, 0.2, 1.3}, 1, 1e9, 0.3, law1, 1e-3, 300.0));
  ASSERT_TRUE(b.add(13, {-1, -1, 2}, {1.0 / 3.0, -1, 2}, {-1, std::sqrt(2.0), 2.5}, 1, 1e9, 0.3, law2, 1e-3, 300.0));
  const double time = 0.37;
  b.move_to(time);
  for (std::size_t e = 0; e < b.size(); ++e) {
    const double s = static_cast<double>(e) + 1.0;
    b.force[e] = {s / 3.0, -s * 1e5 / 7.0, std::exp(s)};
    b.moment[e] = {1e-9 / s, s / 13.0, -std::sqrt(s)};
    b.pressure[e] = 1e6 / (3.0 * s);
  }
  b.group_names = {"floor", "walls"};
  const fs::path file = dir / "barriers.vtu";
  write_barriers_vtu(file, b, time, VtkFormat::Ascii);
  const auto r = read_vtu(file);

  std::vector<std::string> keys;
  for (const auto& [k, a] : r) keys.push_back(k);
  const std::vector<std::string> expected_keys = {
      "cell_data/force",      "cell_data/group",        "cell_data/id",           "cell_data/moment",
      "cell_data/normal",     "cell_data/pressure",     "cell_data/velocity",     "cells/triangle",
      "field_data/TimeValue", "field_data/group:floor", "field_data/group:walls", "points/Points"};
  ASSERT_EQ(keys, expected_keys);
  EXPECT_EQ(r.at("field_data/group:walls").i(0, 0), 1);
  expect_formats_agree([&](const fs::path& f, VtkFormat format) { write_barriers_vtu(f, b, time, format); },
                       dir / "formats");
  EXPECT_EQ(r.at("field_data/TimeValue").d(0, 0), time);

  const Array& pts = r.at("points/Points");
  const Array& tri = r.at("cells/triangle");
  ASSERT_EQ(pts.tuples, 3 * b.size());
  ASSERT_EQ(tri.tuples, b.size());
  ASSERT_EQ(tri.components, 3u);
  const MotionLaw* laws[] = {&law0, &law1, &law2};
  for (std::size_t e = 0; e < b.size(); ++e) {
    const Vec3 rest[3] = {b.p0[e], b.p1[e], b.p2[e]};
    const Vec3 u = laws[e]->a * time + laws[e]->A * std::sin(laws[e]->w1 * time) +
                   laws[e]->B * std::cos(laws[e]->w2 * time);  // u(t), physics.md (97)
    for (int k = 0; k < 3; ++k) {
      const long long vtx = tri.i(e, static_cast<std::size_t>(k));
      ASSERT_GE(vtx, 0);
      ASSERT_LT(vtx, static_cast<long long>(pts.tuples));
      // Written positions are the moved vertices, exactly rest + u(t).
      expect_vec(pts, static_cast<std::size_t>(vtx), rest[k] + u);
    }
    EXPECT_EQ(r.at("cell_data/id").i(e, 0), b.id[e]);
    EXPECT_EQ(r.at("cell_data/group").i(e, 0), b.group[e]);
    expect_vec(r.at("cell_data/force"), e, b.force[e]);
    expect_vec(r.at("cell_data/moment"), e, b.moment[e]);
    EXPECT_EQ(r.at("cell_data/pressure").d(e, 0), b.pressure[e]);
    // Normal read back against the test's own cross product; tolerance 1e-15 for the rounding
    // of a normalised vector computed along a different path.
    const Vec3 n = cross(rest[1] - rest[0], rest[2] - rest[0]);
    const Vec3 nn = n / norm(n);
    const Array& rn = r.at("cell_data/normal");
    EXPECT_NEAR(rn.d(e, 0), nn.x, 1e-15);
    EXPECT_NEAR(rn.d(e, 1), nn.y, 1e-15);
    EXPECT_NEAR(rn.d(e, 2), nn.z, 1e-15);
    expect_vec(r.at("cell_data/velocity"), e, b.velocity[e]);
  }
  // The first element really moved, so the check above distinguishes moved from rest positions.
  EXPECT_GT(std::abs(pts.d(0, 0) - b.p0[0].x), 0.1);
}

TEST_F(OutputTest, PvdListsEverySnapshotWithItsTime) {
  const fs::path pvd = dir / "particles.pvd";
  PvdIndex index(pvd);
  EXPECT_TRUE(read_pvd(pvd).empty());  // valid, empty collection before the first snapshot

  Particles p = make_particles(3);
  std::vector<double> times;
  for (int k = 0; k < 4; ++k) {
    const double t = 0.1 * k + 1e-3 / 3.0;
    char name[32];
    std::snprintf(name, sizeof name, "particles_%06d.vtu", k);
    p.x[0].x += 0.01;  // each snapshot differs
    write_particles_vtu(dir / name, p, t);
    index.add(t, name);
    times.push_back(t);

    const auto listed = read_pvd(pvd);  // the .pvd is complete after every add
    ASSERT_EQ(listed.size(), times.size());
    for (std::size_t j = 0; j < listed.size(); ++j) {
      char expected_name[32];
      std::snprintf(expected_name, sizeof expected_name, "particles_%06d.vtu", static_cast<int>(j));
      EXPECT_EQ(listed[j].time, times[j]);
      EXPECT_EQ(listed[j].file, expected_name);
    }
  }
  // Every listed file exists beside the .pvd and carries the same time.
  for (const auto& l : read_pvd(pvd)) EXPECT_EQ(read_vtu(dir / l.file).at("field_data/TimeValue").d(0, 0), l.time);

  // Resume at the second snapshot's time: later entries go, new ones follow; XML escaping holds.
  PvdIndex resumed(pvd, times[1]);
  ASSERT_EQ(resumed.entries().size(), 2u);
  resumed.add(0.25, "a & <b>.vtu");
  const auto listed = read_pvd(pvd);
  ASSERT_EQ(listed.size(), 3u);
  EXPECT_EQ(listed[0].time, times[0]);
  EXPECT_EQ(listed[1].time, times[1]);
  EXPECT_EQ(listed[2].time, 0.25);
  EXPECT_EQ(listed[2].file, "a & <b>.vtu");
  for (const auto& f : files_in(dir)) EXPECT_EQ(f.string().find(".tmp-"), std::string::npos) << f;
}
