// Inputs each in range whose derived quantities overflow or underflow (issue 16): the mass and
// moment of inertia of a particle, and a material's contact moduli and time scales, are checked
// at load time, so that such a scene is refused with the file, line and key (or column) instead
// of failing at the first step.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/barrier_csv.hpp"
#include "core/input_error.hpp"
#include "io/particle_csv_reader.hpp"
#include "model/derived_limits.hpp"
#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;
using mpdem::test::expect_contains;

namespace {

Model glass() {
  Model m;
  Material g;
  g.name = "glass";
  g.density = 2500.0;
  g.young = 6e10;
  g.poisson = 0.22;
  m.materials = {g};
  return m;
}

// The InputError of reading `csv` as a particle file with `model`, or a test failure.
InputError particle_error(const TempDir& d, const std::string& csv, Model model) {
  const fs::path f = d.write("p.csv", csv);
  Particles out;
  try {
    read_particle_csv(f, model, 0, out);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), f.string());
    return e;
  }
  ADD_FAILURE() << "expected an InputError for:\n" << csv;
  return InputError("", 0, "", "");
}

InputError scene_error(const fs::path& scene) {
  try {
    load_scene(scene);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), scene.string());
    return e;
  }
  ADD_FAILURE() << "expected an InputError loading " << scene;
  return InputError("", 0, "", "");
}

const char* kTime = "[time]\nduration = 1.0\ndt = 1e-5\n";  // lines 1-3

}  // namespace

// The mass 4/3 pi r^3 rho overflowed to inf (radius 1e308) or underflowed to 0 (radius 1e-300,
// density 1e-320), and the run failed at step 1 naming a particle index.
TEST(DerivedLimits, ParticleMassOverflowAndUnderflowNameLineAndColumn) {
  TempDir d("mpdem_derived");
  InputError e = particle_error(d, "id,x,y,z,radius\n1,0,0,0,0.001\n7,0,0,0,1e308\n", glass());
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.key(), "radius");
  expect_contains(e.what(), {"particle id 7", "the mass 4/3 pi r^3 rho overflows (inf kg)"});

  e = particle_error(d, "id,x,y,z,radius\n3,0,0,0,1e-300\n", glass());
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.key(), "radius");
  expect_contains(e.what(), {"particle id 3", "the mass 4/3 pi r^3 rho underflows (0 kg)"});

  // A radius whose r^3 is still usable but whose r^5 is not: the moment of inertia underflows.
  e = particle_error(d, "id,x,y,z,radius\n4,0,0,0,1e-100\n", glass());
  EXPECT_EQ(e.key(), "radius");
  expect_contains(e.what(), {"the moment of inertia 2/5 m r^2 underflows"});

  e = particle_error(d, "id,x,y,z,radius,density\n5,0,0,0,0.001,1e-320\n", glass());
  EXPECT_EQ(e.key(), "density");
  expect_contains(e.what(), {"particle id 5", "underflows (0 kg)", "density 1e-320"});
}

// A density of the material (no column) is named as the material's.
TEST(DerivedLimits, MaterialDensityIsNamedAsTheMaterials) {
  TempDir d("mpdem_derived");
  Model m = glass();
  m.materials[0].density = 1e-320;
  const InputError e = particle_error(d, "x,y,z,radius\n0,0,0,0.001\n", m);
  EXPECT_EQ(e.key(), "density");
  expect_contains(e.what(), {"particle id 0", "(the density of material 'glass')"});
}

// young = 1e308 passed as > 0; E* = E^2 / (2 E (1 - nu^2)) is NaN, the contact time printed inf.
TEST(DerivedLimits, YoungOverflowingTheContactModuliIsRefused) {
  TempDir d("mpdem_derived");
  InputError e = particle_error(d, "id,x,y,z,radius,young\n2,0,0,0,0.001,1e308\n", glass());
  EXPECT_EQ(e.key(), "young");
  expect_contains(e.what(), {"particle id 2", "the contact modulus E*", "young = 1e+308 Pa"});

  // In a [[material]] table: the scene's key, at its line.
  const fs::path scene = d.write("scene.toml", std::string(kTime) + "[[material]]\nname = \"m\"\nyoung = 1e308\n");
  try {
    parse_scene_file(scene);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& ex) {
    EXPECT_EQ(ex.line(), 6u);
    EXPECT_EQ(ex.key(), "material.young");
    expect_contains(ex.what(), {"the contact modulus E* of two particles of this material (51)"});
  }

  // A barrier CSV young column.
  const fs::path b = d.write("b.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3,young\n0,0,0,1,0,0,0,1,0,1e300\n");
  Barriers out;
  try {
    read_barrier_csv(b, BarrierSource{}, Model{}, out);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& ex) {
    EXPECT_EQ(ex.line(), 2u);
    EXPECT_EQ(ex.key(), "young");
  }
}

// The thermal mass m c underflows with a tiny heat capacity; checked only when thermal is on.
TEST(DerivedLimits, ThermalMassIsCheckedWhenThermal) {
  TempDir d("mpdem_derived");
  Model m = glass();
  const std::string csv = "x,y,z,radius,heat_capacity\n0,0,0,0.001,1e-310\n";
  Particles out;
  EXPECT_NO_THROW(read_particle_csv(d.write("p.csv", csv), m, 0, out));
  m.params.analysis.thermal = true;
  const InputError e = particle_error(d, csv, m);
  EXPECT_EQ(e.key(), "heat_capacity");
  expect_contains(e.what(), {"the heat capacity m c of the particle underflows"});
}

// A generate table drawing radii of 1e-300 m: refused before generating, naming the table.
TEST(DerivedLimits, GeneratedRadiusNamesTheGenerateTable) {
  TempDir d("mpdem_derived");
  const fs::path scene = d.write("scene.toml", std::string(kTime) +
                                                   "[[material]]\nname = \"glass\"\n[[particles]]\n"
                                                   "generate = { region = \"box\", min = [0, 0, 0], max = [1, 1, 1], "
                                                   "count = 1, radius = 1e-300 }\n");
  const InputError e = scene_error(scene);
  EXPECT_EQ(e.line(), 7u);
  EXPECT_EQ(e.key(), "particles.generate.radius");
  expect_contains(e.what(), {"material 'glass'", "the mass 4/3 pi r^3 rho underflows"});
}

// Ordinary and extreme-but-usable values pass (the inert thermal examples use young = 1e-20).
TEST(DerivedLimits, UsableValuesPass) {
  EXPECT_EQ(contact_moduli_problem(1e-20, 0.3), "");
  EXPECT_EQ(contact_moduli_problem(2.1e11, 0.29), "");
  EXPECT_EQ(contact_moduli_problem(1e150, 0.49), "");
  EXPECT_NE(contact_moduli_problem(1e155, 0.0), "");
  EXPECT_NE(contact_moduli_problem(1e-170, 0.0), "");  // E^2 underflows to 0
  EXPECT_EQ(mass_problem(1e-6, 2500.0), "");
  EXPECT_EQ(mass_problem(10.0, 7800.0), "");
  EXPECT_EQ(time_scale_problem(1e-6, 2500.0, 1e-20, 0.3), "");
  EXPECT_EQ(time_scale_problem(0.001, 2500.0, 6e10, 0.22), "");
  EXPECT_FALSE(usable_positive(1e-320));  // subnormal: dividing by it overflows
  EXPECT_TRUE(usable_positive(1e-300));
}
