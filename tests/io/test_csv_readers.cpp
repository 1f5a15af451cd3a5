// Tests of the CSV table helper and the particle and barrier CSV readers: column order does not
// matter, missing columns take the material's/source's defaults, derived mass and inertia are
// the closed forms, and every bad row is an InputError naming file, line and column.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "io/barrier_csv.hpp"
#include "io/csv_table.hpp"
#include "core/input_error.hpp"
#include "io/particle_csv_reader.hpp"
#include "support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::error_of;
using mpdem::test::expect_contains;

namespace {


// The material of particle i (the constants are looked up through it).
const Material& material_of(const Model& model, const Particles& p, std::size_t i) {
  return model.materials[static_cast<std::size_t>(p.material[i])];
}

Model two_materials() {
  Model m;
  Material glass;
  glass.name = "glass";
  glass.density = 2600.0;
  glass.young = 6e10;
  glass.poisson = 0.22;
  glass.conductivity = 1.1;
  glass.heat_capacity = 840.0;
  glass.emissivity = 0.85;
  glass.charge = 2e-12;
  glass.temperature = 300.0;
  Material steel;
  steel.name = "steel";
  steel.density = 7800.0;
  steel.young = 2e11;
  steel.poisson = 0.29;
  steel.conductivity = 45.0;
  steel.heat_capacity = 490.0;
  steel.emissivity = 0.3;
  steel.charge = 0.0;
  steel.temperature = 350.0;
  m.materials = {glass, steel};
  return m;
}

}  // namespace

// ---------------------------------------------------------------- CsvTable

TEST(CsvTable, TrimsSkipsCommentsAndTracksLines) {
  TempDir d("mpdem_csv");
  const fs::path f = d.write("t.csv", "# comment\n\n  a , b\t,c \r\n# another\n 1,2 , 3\n\n4,,6\n");
  const CsvTable t = CsvTable::read(f);
  EXPECT_EQ(t.header_line(), 3u);
  ASSERT_EQ(t.columns(), (std::vector<std::string>{"a", "b", "c"}));
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.rows()[0].line, 5u);
  EXPECT_EQ(t.rows()[1].line, 7u);
  EXPECT_EQ(t.number(t.rows()[0], t.column("b")), 2.0);
  EXPECT_TRUE(t.missing(t.rows()[1], t.column("b")));
  EXPECT_TRUE(t.missing(t.rows()[1], t.column("zz")));  // absent column
  EXPECT_EQ(t.integer(t.rows()[1], t.column("c")), 6);
}

TEST(CsvTable, NumberParsingIsStrict) {
  TempDir d("mpdem_csv");
  const CsvTable t = CsvTable::read(d.write("t.csv", "v\n+1.5e3\n1.5x\ninf\n1e999\n"));
  EXPECT_EQ(t.number(t.rows()[0], 0), 1500.0);
  expect_contains(error_of([&] { (void)t.number(t.rows()[1], 0); }), {"t.csv:3: 'v': expected a number, got '1.5x'"});
  expect_contains(error_of([&] { (void)t.number(t.rows()[2], 0); }), {"t.csv:4: 'v': expected a finite number"});
  expect_contains(error_of([&] { (void)t.number(t.rows()[3], 0); }), {"t.csv:5: 'v': ", "out of range"});
  expect_contains(error_of([&] { (void)t.integer(t.rows()[0], 0); }), {"t.csv:2: 'v': expected an integer"});
}

// ---------------------------------------------------------------- Particle CSV

TEST(ParticleCsv, ShuffledColumnsGiveTheSameParticles) {
  TempDir d("mpdem_csv");
  Model model = two_materials();  // particle rows may add material variants
  const fs::path a = d.write("a.csv",
                             "id,x,y,z,vx,vy,vz,wx,wy,wz,radius,material,density,young,poisson,charge,temperature,"
                             "heat_capacity,conductivity,emissivity\n"
                             "3,0.1,0.2,0.3,1,2,3,4,5,6,0.01,steel,7000,1e9,0.25,1e-9,320,500,10,0.5\n"
                             "9,-1,-2,-3,0,0,-1,0,0,0,0.02,glass,2000,2e9,0.2,0,280,600,2,0.9\n");
  const fs::path b = d.write("b.csv",
                             "emissivity,conductivity,heat_capacity,temperature,charge,poisson,young,density,material,"
                             "radius,wz,wy,wx,vz,vy,vx,z,y,x,id\n"
                             "0.5,10,500,320,1e-9,0.25,1e9,7000,steel,0.01,6,5,4,3,2,1,0.3,0.2,0.1,3\n"
                             "0.9,2,600,280,0,0.2,2e9,2000,glass,0.02,0,0,0,-1,0,0,-3,-2,-1,9\n");
  Particles pa, pb;
  read_particle_csv(a, model, 0, pa);
  read_particle_csv(b, model, 0, pb);
  ASSERT_EQ(pa.size(), 2u);
  ASSERT_EQ(pb.size(), 2u);
  EXPECT_EQ(pa.id, pb.id);
  EXPECT_EQ(pa.material, pb.material);
  EXPECT_EQ(pa.radius, pb.radius);
  EXPECT_EQ(pa.mass, pb.mass);
  EXPECT_EQ(pa.charge, pb.charge);
  EXPECT_EQ(pa.T, pb.T);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(pa.x[i], pb.x[i]);
    EXPECT_EQ(pa.v[i], pb.v[i]);
    EXPECT_EQ(pa.w[i], pb.w[i]);
  }
  // And the values are the ones written.
  EXPECT_EQ(pa.id[0], 3);
  // Its own constants: a variant of steel (glass for the second row, whose values differ too).
  EXPECT_EQ(model.materials[pa.material[0]].variant_of, 1);
  EXPECT_EQ(pa.x[0], (Vec3{0.1, 0.2, 0.3}));
  EXPECT_EQ(pa.v[0], (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(pa.w[0], (Vec3{4.0, 5.0, 6.0}));
  EXPECT_EQ(material_of(model, pa, 0).density, 7000.0);
  EXPECT_EQ(material_of(model, pa, 0).young, 1e9);
  EXPECT_EQ(material_of(model, pa, 0).poisson, 0.25);
  EXPECT_EQ(pa.charge[0], 1e-9);
  EXPECT_EQ(pa.T[0], 320.0);
  EXPECT_EQ(material_of(model, pa, 0).heat_capacity, 500.0);
  EXPECT_EQ(material_of(model, pa, 0).conductivity, 10.0);
  EXPECT_EQ(material_of(model, pa, 0).emissivity, 0.5);
  EXPECT_EQ(model.materials[pa.material[1]].variant_of, 0);
}

TEST(ParticleCsv, MissingColumnsTakeTheMaterialDefaults) {
  TempDir d("mpdem_csv");
  Model model = two_materials();  // particle rows may add material variants
  const fs::path f = d.write("p.csv", "x,y,z,radius,material\n0,0,0,0.01,\n1,0,0,0.01,glass\n2,0,0,0.01,1\n");
  Particles p;
  read_particle_csv(f, model, 1, p);  // default material: steel
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.material, (std::vector<int>{1, 0, 1}));  // empty field, name, integer index
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Material& m = model.materials[p.material[i]];
    EXPECT_EQ(material_of(model, p, i).density, m.density);
    EXPECT_EQ(material_of(model, p, i).young, m.young);
    EXPECT_EQ(material_of(model, p, i).poisson, m.poisson);
    EXPECT_EQ(p.charge[i], m.charge);
    EXPECT_EQ(p.T[i], m.temperature);
    EXPECT_EQ(material_of(model, p, i).heat_capacity, m.heat_capacity);
    EXPECT_EQ(material_of(model, p, i).conductivity, m.conductivity);
    EXPECT_EQ(material_of(model, p, i).emissivity, m.emissivity);
    EXPECT_EQ(p.v[i], Vec3{});
    EXPECT_EQ(p.w[i], Vec3{});
  }
}

TEST(ParticleCsv, MassInertiaAndClearedState) {
  TempDir d("mpdem_csv");
  Model model = two_materials();  // particle rows may add material variants
  const fs::path f = d.write("p.csv", "x,y,z,radius,density\n0,0,0,0.0035,1234.5\n0,0,1,2.5,3000\n");
  Particles p;
  read_particle_csv(f, model, 0, p);
  ASSERT_EQ(p.size(), 2u);
  const double r[2] = {0.0035, 2.5}, rho[2] = {1234.5, 3000.0};
  for (std::size_t i = 0; i < 2; ++i) {
    const double m = 4.0 / 3.0 * std::numbers::pi * r[i] * r[i] * r[i] * rho[i];
    EXPECT_DOUBLE_EQ(p.mass[i], m);                         // to 4 ulp
    EXPECT_DOUBLE_EQ(p.inertia[i], 0.4 * m * r[i] * r[i]);  // (32), to 4 ulp
    EXPECT_EQ(p.q[i].w, 1.0);
    EXPECT_EQ(p.q[i].x, 0.0);
    EXPECT_EQ(p.q[i].y, 0.0);
    EXPECT_EQ(p.q[i].z, 0.0);
    EXPECT_EQ(p.force[i], Vec3{});
    EXPECT_EQ(p.torque[i], Vec3{});
    EXPECT_EQ(p.heat[i], 0.0);
  }
}

TEST(ParticleCsv, IdsContinueAfterTheLargestSeen) {
  TempDir d("mpdem_csv");
  Model model = two_materials();  // particle rows may add material variants
  Particles p;
  read_particle_csv(d.write("a.csv", "x,y,z,radius\n0,0,0,1\n0,0,0,1\n"), model, 0, p);  // 0, 1
  read_particle_csv(d.write("b.csv", "id,x,y,z,radius\n,0,0,0,1\n10,0,0,0,1\n,0,0,0,1\n"), model, 0, p);
  EXPECT_EQ(p.id, (std::vector<std::int64_t>{0, 1, 2, 10, 11}));
  const std::string msg = error_of(
      [&] { read_particle_csv(d.write("c.csv", "id,x,y,z,radius\n10,0,0,0,1\n"), model, 0, p); });
  expect_contains(msg, {"c.csv:2: 'id': duplicate particle id 10", "earlier particle file"});
}

TEST(ParticleCsv, ErrorsNameFileLineAndColumn) {
  struct Case {
    const char* what;
    std::string csv;
    std::string where;  // "file:line: 'column': " or "file:line: "
    std::vector<std::string> expect;
  };
  const std::vector<Case> cases = {
      {"unknown column", "x,y,z,radius,radious\n", ":1: 'radious': ", {"unknown column"}},
      {"unknown column, suggestion", "x,y,z,radius,densty\n", ":1: 'densty': ", {"did you mean 'density'"}},
      {"duplicate column", "x,y,z,radius,x\n", ":1: 'x': ", {"duplicate column"}},
      {"missing column", "# particles\nx,y,radius\n", ":2: 'z': ", {"missing required column"}},
      {"duplicate id",
       "id,x,y,z,radius\n1,0,0,0,1\n# c\n1,0,0,0,1\n",
       ":4: 'id': ",
       {"duplicate particle id 1", "first on line 2"}},
      {"field count", "x,y,z,radius\n0,0,0,1\n0,0,0\n", ":3: ", {"expected 4 fields", "got 3"}},
      {"non-numeric", "x,y,z,radius\n0,abc,0,1\n", ":2: 'y': ", {"expected a number, got 'abc'"}},
      {"empty required", "x,y,z,radius\n0,0,0,\n", ":2: 'radius': ", {"expected a number, got an empty field"}},
      {"zero radius", "x,y,z,radius\n0,0,0,0\n", ":2: 'radius': ", {"expected a radius > 0, got 0"}},
      {"negative radius", "x,y,z,radius\n\n0,0,0,-1e-3\n", ":3: 'radius': ", {"expected a radius > 0, got -1e-3"}},
      {"zero density", "x,y,z,radius,density\n0,0,0,1,0\n", ":2: 'density': ", {"expected a density > 0, got 0"}},
      {"poisson 0.5",
       "x,y,z,radius,poisson\n0,0,0,1,0.5\n",
       ":2: 'poisson': ",
       {"expected a Poisson ratio in [0, 0.5), got 0.5"}},
      {"negative poisson", "x,y,z,radius,poisson\n0,0,0,1,-0.1\n", ":2: 'poisson': ", {"in [0, 0.5), got -0.1"}},
      {"emissivity", "x,y,z,radius,emissivity\n0,0,0,1,1.5\n", ":2: 'emissivity': ", {"in [0, 1], got 1.5"}},
      {"unknown material",
       "x,y,z,radius,material\n0,0,0,1,wood\n",
       ":2: 'material': ",
       {"unknown material 'wood'", "glass, steel"}},
      {"material index out of range",
       "x,y,z,radius,material\n0,0,0,1,2\n",
       ":2: 'material': ",
       {"unknown material '2'"}},
      {"non-integer id", "id,x,y,z,radius\n1.5,0,0,0,1\n", ":2: 'id': ", {"expected an integer, got '1.5'"}},
      {"empty file", "# nothing\n\n", ": ", {"empty file: expected a header row"}},
  };
  Model model = two_materials();  // particle rows may add material variants
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_csv");
    const fs::path f = d.write("p.csv", c.csv);
    Particles p;
    const std::string msg = error_of([&] { read_particle_csv(f, model, 0, p); });
    EXPECT_EQ(msg.rfind(f.string() + c.where, 0), 0u) << "expected prefix '" << f.string() + c.where << "' in: " << msg;
    expect_contains(msg, c.expect);
  }
}

TEST(ParticleCsv, MissingFile) {
  TempDir d("mpdem_csv");
  Model model = two_materials();
  Particles p;
  const std::string msg = error_of([&] { read_particle_csv(d.path / "none.csv", model, 0, p); });
  expect_contains(msg, {"none.csv", "does not exist"});
}

// ---------------------------------------------------------------- Barrier CSV

TEST(BarrierCsv, GeometryDefaultsAndMotionOverrides) {
  TempDir d("mpdem_csv");
  const Model model = two_materials();
  BarrierSource src;
  src.material = "steel";
  src.thickness = 0.004;
  src.motion.a = {1.0, 2.0, 3.0};
  src.motion.w1 = 5.0;
  const fs::path f = d.write("ramp.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3,ay,w1,Bz,group,young\n"
                                         "0,0,0,2,0,0,0,3,0,,,,,\n"
                                         "0,0,1,0,1,1,1,0,1,-7,9,0.5,lid,1e8\n");
  Barriers b;
  read_barrier_csv(f, src, model, b);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b.id, (std::vector<std::int64_t>{0, 1}));
  // Triangle 0: right triangle with legs 2 and 3 in the z = 0 plane, counter-clockwise about +z.
  EXPECT_EQ(b.area[0], 3.0);
  EXPECT_EQ(b.normal[0], (Vec3{0.0, 0.0, 1.0}));
  // Triangle 1 is clockwise seen from +z: its normal points down.
  EXPECT_EQ(b.normal[1], (Vec3{0.0, 0.0, -1.0}));
  EXPECT_EQ(b.group_names[b.group[0]], "ramp");  // no group anywhere: the file stem
  EXPECT_EQ(b.group_names[b.group[1]], "lid");
  EXPECT_EQ(b.young[0], 2e11);  // source material steel
  EXPECT_EQ(b.young[1], 1e8);
  EXPECT_EQ(b.poisson[1], 0.29);
  EXPECT_EQ(b.thickness[1], 0.004);
  EXPECT_TRUE(std::isnan(b.temperature[0]));  // insulated
  EXPECT_EQ(b.motion[0].a, (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(b.motion[0].w1, 5.0);
  EXPECT_EQ(b.motion[1].a, (Vec3{1.0, -7.0, 3.0}));  // only ay overridden
  EXPECT_EQ(b.motion[1].w1, 9.0);
  EXPECT_EQ(b.motion[1].B, (Vec3{0.0, 0.0, 0.5}));
  // Literal law: B cos(w2 t) with w2 = 0 is a constant shift by B, present at t = 0.
  EXPECT_EQ(b.offset[1], (Vec3{0.0, 0.0, 0.5}));
}

TEST(BarrierCsv, SourceGroupTemperatureAndFirstMaterial) {
  TempDir d("mpdem_csv");
  const Model model = two_materials();
  BarrierSource src;
  src.group = "walls";
  src.temperature = 400.0;
  const fs::path f = d.write(
      "w.csv", "z3,y3,x3,z2,y2,x2,z1,y1,x1,id,temperature\n0,1,0,0,0,1,0,0,0,5,\n0,1,0,0,0,1,0,0,0,,250\n");
  Barriers b;
  read_barrier_csv(f, src, model, b);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b.id, (std::vector<std::int64_t>{5, 6}));
  EXPECT_EQ(b.group_names, (std::vector<std::string>{"walls"}));
  EXPECT_EQ(b.young[0], 6e10);  // no source material: the first material (glass)
  EXPECT_EQ(b.poisson[0], 0.22);
  EXPECT_EQ(b.temperature[0], 400.0);
  EXPECT_EQ(b.temperature[1], 250.0);
  EXPECT_EQ(b.p0[0], (Vec3{0.0, 0.0, 0.0}));
  EXPECT_EQ(b.p1[0], (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(b.p2[0], (Vec3{0.0, 1.0, 0.0}));
  EXPECT_EQ(b.area[0], 0.5);
}

TEST(BarrierCsv, ErrorsNameFileLineAndColumn) {
  struct Case {
    const char* what;
    std::string csv;
    std::string where;
    std::vector<std::string> expect;
  };
  const std::string head = "x1,y1,z1,x2,y2,z2,x3,y3,z3";
  const std::vector<Case> cases = {
      {"degenerate", head + "\n0,0,0,1,0,0,0,1,0\n# next\n0,0,0,1,1,1,2,2,2\n", ":4: ", {"degenerate triangle"}},
      {"unknown column", head + ",w_1\n", ":1: 'w_1': ", {"unknown column", "did you mean 'w1'"}},
      {"missing vertex column", "x1,y1,z1,x2,y2,z2,x3,y3\n", ":1: 'z3': ", {"missing required column"}},
      {"non-numeric", head + "\n0,0,0,1,0,0,0,one,0\n", ":2: 'y3': ", {"expected a number, got 'one'"}},
      {"field count", head + "\n0,0,0,1,0,0,0,1,0,7\n", ":2: ", {"expected 9 fields", "got 10"}},
      {"poisson", head + ",poisson\n0,0,0,1,0,0,0,1,0,0.7\n", ":2: 'poisson': ", {"in [0, 0.5), got 0.7"}},
      {"young", head + ",young\n0,0,0,1,0,0,0,1,0,-5\n", ":2: 'young': ", {"expected a Young's modulus > 0, got -5"}},
      {"duplicate id",
       head + ",id\n0,0,0,1,0,0,0,1,0,4\n0,0,0,1,0,0,0,1,0,4\n",
       ":3: 'id': ",
       {"duplicate barrier id 4"}},
  };
  const Model model = two_materials();
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d("mpdem_csv");
    const fs::path f = d.write("w.csv", c.csv);
    Barriers b;
    const std::string msg = error_of([&] { read_barrier_csv(f, BarrierSource{}, model, b); });
    EXPECT_EQ(msg.rfind(f.string() + c.where, 0), 0u) << "expected prefix '" << f.string() + c.where << "' in: " << msg;
    expect_contains(msg, c.expect);
  }
}
