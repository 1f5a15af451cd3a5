// Clump outputs in the file formats (docs/output.md "Body CSV snapshots", "Particle VTU"): the body
// CSV writer's rows are the bodies as a scene gives them (the orientation of the template as
// written), read back by the body CSV reader into the same bodies and members to round-off (a
// template's name, a field of those rows, cannot hold a comma, a quote or a line break); the
// particle column `body` names each member's body in the particle CSV and VTU, and a particle
// snapshot with it still reads as input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "io/body_csv_writer.hpp"
#include "io/particle_csv_reader.hpp"
#include "io/particle_csv_writer.hpp"
#include "io/vtu_writer.hpp"
#include "scene/scene_reader.hpp"
#include "support/clump_scenes.hpp"
#include "support/output_folder.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test::output;
namespace fs = std::filesystem;

namespace {

// An L of three separate spheres (m): its principal frame is turned against the frame as written
// (to_input is no identity), so the written orientation differs from the engine's.
const std::vector<ClumpMember> kEll = {{{0.0, 0.0, 0.0}, 1e-3}, {{2e-3, 0.0, 0.0}, 1e-3}, {{0.0, 1.8e-3, 0.0}, 7e-4}};

// Round-off of a product of two unit quaternions and a normalisation: a few units of 1e-16.
constexpr double kQuatRoundOff = 1e-15;
// m: round-off of a member position x + R d (|x| ~ 1e-2 m, |d| ~ 1e-3 m).
constexpr double kPositionRoundOff = 1e-17;

struct Given {
  std::int64_t id;
  Vec3 x, v, w;
  Quat q;  // the template's frame as written -> world
};

// Ids out of order: the rows come in ascending id whatever the storage order.
const std::vector<Given> kBodies = {
    {9, {0.01, 0.02, 0.03}, {0.1, -0.2, 0.3}, {5.0, -6.0, 7.0}, quat_normalized({0.8, 0.0, 0.6, 0.0})},
    {2, {-0.01, 0.005, 0.0}, {0.0, 0.0, -1.5}, {0.0, 40.0, 0.0}, quat_normalized({0.5, 0.5, 0.5, 0.5})},
    {5, {0.0, -0.013, 0.007}, {}, {}, quat_normalized({0.3, -0.4, 0.2, 0.8})},
};

Scene clump_scene() {
  Scene s = test::make_scene(1e-6, 1.0);
  const int ell = test::add_template(s, "ell", kEll);
  test::add_particle(s, 100, 1e-3, {0.05, 0.0, 0.0});  // a free sphere
  for (const Given& g : kBodies) test::add_clump(s, g.id, ell, g.x, g.v, g.w, g.q);
  test::finish_clumps(s);
  return s;
}

const Given& given(std::int64_t id) {
  for (const Given& g : kBodies)
    if (g.id == id) return g;
  throw std::logic_error("no such body");
}

void expect_quat_near(const Quat& a, const Quat& b, const std::string& what) {
  EXPECT_NEAR(a.w, b.w, kQuatRoundOff) << what;
  EXPECT_NEAR(a.x, b.x, kQuatRoundOff) << what;
  EXPECT_NEAR(a.y, b.y, kQuatRoundOff) << what;
  EXPECT_NEAR(a.z, b.z, kQuatRoundOff) << what;
}

}  // namespace

// The header, one row per body in ascending id, the template's name, the state as given (x, v,
// w exact: round-trip digits), the orientation as given in the scene (not the principal frame's),
// the body's mass and principal moments exact.
TEST_F(OutputTest, BodyCsvRowsAreTheBodiesAsGiven) {
  const Scene s = clump_scene();
  const Bodies& B = s.particles.bodies;
  ASSERT_GT(std::abs(s.model.clumps[0].shape.to_input.w), 0.0);
  ASSERT_LT(std::abs(s.model.clumps[0].shape.to_input.w), 1.0 - 1e-6);  // the frames differ
  write_bodies_csv(dir / "b.csv", B, s.model.clumps, 0.25);
  const std::vector<std::string> lines = lines_of(slurp(dir / "b.csv"));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "time,id,clump,x,y,z,q0,q1,q2,q3,vx,vy,vz,wx,wy,wz,mass,I1,I2,I3");
  const std::int64_t ascending[] = {2, 5, 9};
  for (std::size_t r = 0; r < 3; ++r) {
    const std::vector<std::string> f = split(lines[r + 1], ',');
    ASSERT_EQ(f.size(), 20u) << lines[r + 1];
    EXPECT_EQ(f[0], "0.25");
    EXPECT_EQ(std::stoll(f[1]), ascending[r]);
    EXPECT_EQ(f[2], "ell");
    const Given& g = given(ascending[r]);
    const std::size_t b = static_cast<std::size_t>(B.find(g.id));
    const auto num = [&f](std::size_t c) { return std::stod(f[c]); };
    EXPECT_EQ((Vec3{num(3), num(4), num(5)}), g.x);
    expect_quat_near({num(6), num(7), num(8), num(9)}, g.q, "body " + f[1]);
    EXPECT_EQ((Vec3{num(10), num(11), num(12)}), g.v);
    EXPECT_EQ((Vec3{num(13), num(14), num(15)}), g.w);
    EXPECT_EQ(num(16), B.mass[b]);
    EXPECT_EQ((Vec3{num(17), num(18), num(19)}), B.inertia[b]);
  }
}

// Written and read back as a body CSV (read_clump_bodies, the same template and material) into a
// fresh scene: the same bodies (x, v, w, mass and moments exact; the principal frame's orientation
// to round-off) and members at the same places (to round-off, 1e-17 m) with the same velocities.
TEST_F(OutputTest, BodyCsvReadsBackIntoTheSameBodies) {
  Scene s = clump_scene();
  Particles& p = s.particles;
  write_bodies_csv(dir / "b.csv", p.bodies, s.model.clumps, 0.25);
  Particles in;
  read_clump_bodies(dir / "b.csv", s.model, 0, 0, in);
  assign_member_ids(in, "test");
  Bodies &A = p.bodies, &B = in.bodies;
  ASSERT_EQ(B.size(), A.size());
  A.index_members(p);
  B.index_members(in);
  for (std::size_t b = 0; b < B.size(); ++b) {
    const std::size_t a = static_cast<std::size_t>(A.find(B.id[b]));
    EXPECT_EQ(B.x[b], A.x[a]);
    EXPECT_EQ(B.v[b], A.v[a]);
    EXPECT_EQ(B.w[b], A.w[a]);
    EXPECT_EQ(B.mass[b], A.mass[a]);
    EXPECT_EQ(B.inertia[b], A.inertia[a]);
    EXPECT_EQ(B.clump[b], A.clump[a]);
    expect_quat_near(B.q[b], A.q[a], "body " + std::to_string(B.id[b]));
    ASSERT_EQ(B.first[b + 1] - B.first[b], A.first[a + 1] - A.first[a]);
    for (std::uint32_t k = 0; k < B.first[b + 1] - B.first[b]; ++k) {
      const std::size_t i = B.index[B.first[b] + k], j = A.index[A.first[a] + k];
      EXPECT_LE(norm(in.x[i] - p.x[j]), kPositionRoundOff) << "body " << B.id[b] << " member " << k;
      EXPECT_LE(norm(in.v[i] - p.v[j]), 1e-15) << "body " << B.id[b] << " member " << k;  // m/s, |v| ~ 0.3
      EXPECT_EQ(in.radius[i], p.radius[j]);
      EXPECT_EQ(in.body[i], B.id[b]);
    }
  }
}

// The particle column `body` (int64, output only): the member's body id, -1 for a free sphere, in
// the particle CSV (after the torque) and the particle VTU (Int64 PointData "body"); a snapshot
// with the column still seeds a scene (the column skipped: the particles read are free spheres).
TEST_F(OutputTest, ParticleBodyColumnIsInTheCsvAndTheVtu) {
  const Scene s = clump_scene();
  const Particles& p = s.particles;
  write_particles_csv(dir / "p.csv", p, 0.25);
  const std::vector<std::string> lines = lines_of(slurp(dir / "p.csv"));
  const std::vector<std::string> header = split(lines.at(0), ',');
  ASSERT_EQ(header.back(), "body");
  EXPECT_EQ(header[header.size() - 2], "tz");
  ASSERT_EQ(lines.size(), p.size() + 1);
  std::size_t members = 0;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const std::vector<std::string> f = split(lines[r], ',');
    const std::int64_t id = std::stoll(f[1]), body = std::stoll(f.back());
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.id[i] == id) {
        EXPECT_EQ(body, p.body[i]) << "particle " << id;
      }
    if (id == 100) {
      EXPECT_EQ(body, -1);
    }
    members += body != -1 ? 1 : 0;
  }
  EXPECT_EQ(members, 3 * kBodies.size());

  Particles in;
  Model m = s.model;
  read_particle_csv(dir / "p.csv", m, 0, in);
  ASSERT_EQ(in.size(), p.size());
  for (std::size_t i = 0; i < in.size(); ++i) EXPECT_EQ(in.body[i], kNoBody) << i;

  write_particles_vtu(dir / "p.vtu", p, 0.25, {VtkFormat::Ascii, {}});
  const std::string text = slurp(dir / "p.vtu");
  const std::size_t open = text.find(R"(<DataArray type="Int64" Name="body")");
  ASSERT_NE(open, std::string::npos);
  const std::size_t begin = text.find('>', open) + 1;
  std::istringstream values(text.substr(begin, text.find("</DataArray>", begin) - begin));
  std::vector<std::int64_t> got;
  for (std::int64_t v; values >> v;) got.push_back(v);
  EXPECT_EQ(got, p.body);  // the owned particles in storage order
}

// The template's name is a field of the body CSV: one that would break its rows (a comma, a quote,
// a line break) or is empty is refused naming file, line and key.
TEST(BodyCsv, TemplateNamesAreCsvFields) {
  test::TempDir d("body_csv_names");
  const std::string scene = "[time]\nduration = 0.01\ndt = 1e-5\n[[material]]\nname = \"glass\"\n[[clump]]\nname = "
                            "NAME\nmembers = [[0.0, 0.0, 0.0, 0.001]]\n";
  // (An empty name has a message of its own: ClumpReader.BadTemplatesNameLineAndKey.)
  for (const char* bad : {R"("a,b")", R"("say \"hi\"")", R"("two\nlines")"}) {
    std::string text = scene;
    text.replace(text.find("NAME"), 4, bad);
    const fs::path f = d.write("bad.toml", text);
    test::expect_contains(test::error_of([&] { parse_scene_file(f); }),
                          {f.string() + ":", "'clump.name'", "without ',', '\"' or line breaks"});
  }
  std::string good = scene;
  good.replace(good.find("NAME"), 4, "\"ell 2 (pellets)\"");
  EXPECT_EQ(parse_scene_file(d.write("good.toml", good)).model.clumps.at(0).name, "ell 2 (pellets)");
}
