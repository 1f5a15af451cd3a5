// Fixed particles in the input and output: the particle CSV's `fixed` column (0 or 1, absent or
// empty 0; anything else an InputError naming file, line and column, exit 2 from the command),
// the generator's and a [[particles]] entry's `fixed = true`, and the `fixed` field and column of
// the particle VTU and CSV snapshots.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/particle_csv_writer.hpp"
#include "io/particle_csv_reader.hpp"
#include "io/vtu_writer.hpp"
#include "model/scene.hpp"
#include "support/run_command.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
using mpdem::test::error_of;
using mpdem::test::expect_contains;
using mpdem::test::TempDir;

namespace {

// A model with one material (the scene builder's).
Model one_material() { return test::make_scene(1e-6, 1.0).model; }

std::vector<int> flags(const Particles& p) { return {p.fixed.begin(), p.fixed.end()}; }

const char* kScene = R"([time]
duration = 0.001
dt = 1e-6
[[material]]
name = "glass"
)";

}  // namespace

TEST(FixedParticleInput, CsvColumnRead) {
  TempDir d("fixed_csv");
  Model m = one_material();
  Particles p;
  // 1, 0 and an empty field (0), in a column anywhere in the header.
  read_particle_csv(d.write("a.csv", "id,fixed,x,y,z,radius,vx\n1,1,0,0,0,0.001,0.5\n2,0,0.01,0,0,0.001,0\n"
                                     "3,,0.02,0,0,0.001,0\n"),
                    m, 0, p);
  EXPECT_EQ(flags(p), (std::vector<int>{1, 0, 0}));
  EXPECT_EQ(p.v[0].x, 0.5);  // a fixed particle keeps its given velocity
  // No column: every particle free.
  read_particle_csv(d.write("b.csv", "x,y,z,radius\n0,0.01,0,0.001\n"), m, 0, p);
  EXPECT_EQ(flags(p), (std::vector<int>{1, 0, 0, 0}));
}

TEST(FixedParticleInput, BadCsvValueNamesFileLineAndColumn) {
  TempDir d("fixed_bad");
  for (const std::string bad : {"2", "yes", "1.0", "-1", "true"}) {
    Model m = one_material();
    Particles p;
    const auto f = d.write("bad.csv", "x,y,z,radius,fixed\n0,0,0,0.001,1\n\n0.01,0,0,0.001," + bad + "\n");
    const std::string msg = error_of([&] { read_particle_csv(f, m, 0, p); });
    expect_contains(msg, {f.string() + ":4: 'fixed'", "expected 0 (free) or 1", "got '" + bad + "'"});
  }
}

// The command's exit status for that error is 2 (bad input), with the same message on stderr.
TEST(FixedParticleInput, BadCsvValueExitsWithStatus2) {
  TempDir d("fixed_exit");
  d.write("beads.csv", "x,y,z,radius,fixed\n0,0,0,0.001,yes\n");
  d.write("scene.toml", std::string(kScene) + "[[particles]]\nfile = \"beads.csv\"\n");
  const test::CommandResult r = test::run_mpdem("check scene.toml", d.path);
  EXPECT_EQ(r.status, 2) << r.err;
  expect_contains(r.err, {"beads.csv:2: 'fixed'", "got 'yes'"});
}

TEST(FixedParticleInput, GeneratedAndEntryFlags) {
  TempDir d("fixed_toml");
  d.write("beads.csv", "x,y,z,radius,fixed\n0,0,0,0.001,0\n0.01,0,0,0.001,1\n");
  const auto scene = d.write("scene.toml", std::string(kScene) + R"([[particles]]
generate = { region = "box", min = [0, 0, 0.1], max = [0.02, 0.02, 0.12], count = 5, radius = 0.001, fixed = true }
[[particles]]
generate = { region = "box", min = [0, 0, 0.2], max = [0.02, 0.02, 0.22], count = 3, radius = 0.001 }
[[particles]]
file = "beads.csv"
[[particles]]
file = "beads.csv"
fixed = true
)");
  const Scene s = load_scene(scene);
  EXPECT_EQ(flags(s.particles), (std::vector<int>{1, 1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1}));

  const auto bad = d.write("bad.toml", std::string(kScene) + R"([[particles]]
generate = { region = "box", min = [0, 0, 0], max = [0.02, 0.02, 0.02], count = 1, radius = 0.001, fixed = 1 }
)");
  expect_contains(error_of([&] { parse_scene_file(bad); }),
                  {"bad.toml:", "'particles.generate.fixed'", "expected a boolean"});
  const auto bad2 = d.write("bad2.toml",
                            std::string(kScene) + "[[particles]]\nfile = \"beads.csv\"\nfixed = \"yes\"\n");
  expect_contains(error_of([&] { parse_scene_file(bad2); }), {"bad2.toml:", "'particles.fixed'", "expected a boolean"});
}

TEST(FixedParticleInput, SnapshotsCarryTheFlag) {
  TempDir d("fixed_out");
  Particles p;
  p.add(4, 0, 0.001, 2500.0, {0, 0, 0}, {0.1, 0, 0});
  p.add(5, 0, 0.001, 2500.0, {0.01, 0, 0}, {});
  p.fixed[0] = 1;
  write_particles_csv(d.path / "p.csv", p, 0.5);
  const std::string csv = test::slurp(d.path / "p.csv");
  const auto first = csv.find('\n');
  EXPECT_EQ(csv.substr(0, first),
            "time,id,x,y,z,vx,vy,vz,wx,wy,wz,radius,material,temperature,charge,fx,fy,fz,fixed,tx,ty,tz,body");
  const auto second = csv.find('\n', first + 1);
  EXPECT_EQ(csv.substr(second - 11, 11), ",1,0,0,0,-1");  // fixed, then the torque (none), the body (none)
  EXPECT_EQ(csv.substr(csv.size() - 12), ",0,0,0,0,-1\n");
  write_particles_vtu(d.path / "p.vtu", p, 0.5, {VtkFormat::Ascii, {}});
  const std::string vtu = test::slurp(d.path / "p.vtu");
  const auto at = vtu.find("type=\"UInt8\" Name=\"fixed\"");
  ASSERT_NE(at, std::string::npos) << vtu;
  const auto from = vtu.find('>', at) + 1;
  std::string values;
  for (const char c : vtu.substr(from, vtu.find('<', from) - from))
    if (c != ' ' && c != '\n') values += c;
  EXPECT_EQ(values, "10");
}
