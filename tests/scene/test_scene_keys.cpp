// Tests of the TOML scene reader (src/scene/scene_reader.cpp) on valid scenes: every key lands in the
// right field and the documented defaults apply. Inputs are written to a fresh temporary folder per test.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;

namespace {

const char* kTime = "\n[time]\nduration = 1.0\ndt = 1e-5\n";

}  // namespace

TEST(SceneReader, FullSceneMapsEveryKey) {
  TempDir d("mpdem_scene");
  d.write("data/beads.csv", "x,y,z,radius\n0,0,0,0.001\n");
  d.write("walls.csv", "x1,y1,z1,x2,y2,z2,x3,y3,z3\n0,0,0,1,0,0,0,1,0\n");
  const fs::path scene = d.write("scene.toml", R"(
[time]
duration = 2          # an integer where a float is expected
integrator = "trapezoidal"  # the keys below are the trapezoidal rule's
phi = 0.75
dt = 1e-4
dt_min = 1e-6
dt_max = 2e-4
adaptive = true
desired_iterations = 8
p = 3.0
max_iterations = 40

[tolerance]
position = 1e-6
velocity = 2e-6
rotation = 3e-6
angular_velocity = 4e-6
temperature = 5e-6

[analysis]
rotation = false
thermal = true

[gravity]
vector = [0.5, -1, -9.0]

[fields]
electric = [1.0, 2.0, 3.0]
magnetic = [0.0, 0.0, 0.5]

[near_field]
a1 = 1e-9
b1 = 2.0
a2 = 3e-9
b2 = 4.0
coulomb = true
permittivity = 2.5
cutoff = 0.01

[[near_field.pair]]
material_a = "glass"
material_b = "steel"
a1 = 7e-9

[contact.particle_particle]
restitution = 0.8
mu_static = 0.6
mu_dynamic = 0.5
mu_rolling = 0.02
tangential_damping = 0.1

[contact.particle_barrier]
damping_ratio = 0.3
mu_static = 0.4
mu_dynamic = 0.3
mu_rolling = 0.01
tangential_damping = 0.2

[thermal]
air_temperature = 300.0
air_velocity = [1.0, 0.0, 0.0]
environment_temperature = 310.0
conduction = false
convection = true
radiation = true

[[material]]
name = "glass"
density = 2600.0
young = 6e10
poisson = 0.22
conductivity = 1.1
heat_capacity = 840.0
emissivity = 0.85
charge = 1e-12
temperature = 350.0

[[material]]
name = "steel"
density = 7800

[[particles]]
file = "data/beads.csv"
material = "steel"

[[barriers]]
file = "walls.csv"
group = "floor"
material = "steel"
thickness = 0.002
temperature = 400.0
motion = { a = [0.1, 0, 0], A = [0, 0.2, 0], w1 = 3.0, B = [0, 0, 0.3], w2 = 4.0 }

[domain]
min = [-1, -2, -3]
max = [1, 2, 3]
on_exit = "remove"

[neighbor]
skin = 0.0005

[output]
dir = "out"
particles_every = 0.01
barriers_every = 0.02
particle_csv_every = 0.03
barrier_log_every = 0.04
log_every = 50
checkpoint_every = 1000
progress_every = 5.0
)");
  const Scene s = parse_scene_file(scene);
  const Params& p = s.model.params;
  EXPECT_EQ(s.dir, d.path.lexically_normal());
  EXPECT_EQ(p.time.duration, 2.0);
  EXPECT_EQ(p.time.integrator, Integrator::Trapezoidal);
  EXPECT_EQ(p.time.phi, 0.75);
  EXPECT_EQ(p.time.dt, 1e-4);
  EXPECT_EQ(p.time.dt_min, 1e-6);
  EXPECT_EQ(p.time.dt_max, 2e-4);
  EXPECT_TRUE(p.time.adaptive);
  EXPECT_EQ(p.time.desired_iterations, 8);
  EXPECT_EQ(p.time.p, 3.0);
  EXPECT_EQ(p.time.max_iterations, 40);

  EXPECT_EQ(p.tolerance.position, 1e-6);
  EXPECT_EQ(p.tolerance.velocity, 2e-6);
  EXPECT_EQ(p.tolerance.rotation, 3e-6);
  EXPECT_EQ(p.tolerance.angular_velocity, 4e-6);
  EXPECT_EQ(p.tolerance.temperature, 5e-6);
  EXPECT_FALSE(p.analysis.rotation);
  EXPECT_TRUE(p.analysis.thermal);
  EXPECT_EQ(p.fields.gravity, (Vec3{0.5, -1.0, -9.0}));
  EXPECT_EQ(p.fields.electric, (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(p.fields.magnetic, (Vec3{0.0, 0.0, 0.5}));

  const NearFieldParams& nf = p.near_field;
  EXPECT_TRUE(nf.empirical);  // switched on by giving coefficients
  EXPECT_EQ(nf.a1, 1e-9);
  EXPECT_EQ(nf.b1, 2.0);
  EXPECT_EQ(nf.a2, 3e-9);
  EXPECT_EQ(nf.b2, 4.0);
  EXPECT_TRUE(nf.coulomb);
  EXPECT_EQ(nf.permittivity, 2.5);
  EXPECT_EQ(nf.cutoff, 0.01);
  ASSERT_EQ(nf.pairs.size(), 1u);
  EXPECT_EQ(nf.pairs[0].material_a, "glass");
  EXPECT_EQ(nf.pairs[0].material_b, "steel");
  EXPECT_EQ(nf.pairs[0].a1, 7e-9);
  EXPECT_EQ(nf.pairs[0].b1, 2.0);  // not given: the global value
  EXPECT_EQ(nf.pairs[0].a2, 3e-9);
  EXPECT_EQ(nf.pairs[0].b2, 4.0);

  const ContactLawParams& pp = p.contact.particle_particle;
  ASSERT_TRUE(pp.restitution.has_value());
  EXPECT_EQ(*pp.restitution, 0.8);
  EXPECT_FALSE(pp.damping_ratio.has_value());
  EXPECT_EQ(pp.mu_static, 0.6);
  EXPECT_EQ(pp.mu_dynamic, 0.5);
  EXPECT_EQ(pp.mu_rolling, 0.02);
  EXPECT_EQ(pp.tangential_damping, 0.1);
  const ContactLawParams& pb = p.contact.particle_barrier;
  EXPECT_FALSE(pb.restitution.has_value());
  ASSERT_TRUE(pb.damping_ratio.has_value());
  EXPECT_EQ(*pb.damping_ratio, 0.3);
  EXPECT_EQ(pb.mu_static, 0.4);
  EXPECT_EQ(pb.mu_dynamic, 0.3);
  EXPECT_EQ(pb.mu_rolling, 0.01);
  EXPECT_EQ(pb.tangential_damping, 0.2);

  EXPECT_EQ(p.thermal.air_temperature, 300.0);
  EXPECT_EQ(p.thermal.air_velocity, (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(p.thermal.environment_temperature, 310.0);
  EXPECT_FALSE(p.thermal.conduction);
  EXPECT_TRUE(p.thermal.convection);
  EXPECT_TRUE(p.thermal.radiation);

  ASSERT_EQ(s.model.materials.size(), 2u);
  const Material& g = s.model.materials[0];
  EXPECT_EQ(g.name, "glass");
  EXPECT_EQ(g.density, 2600.0);
  EXPECT_EQ(g.young, 6e10);
  EXPECT_EQ(g.poisson, 0.22);
  EXPECT_EQ(g.conductivity, 1.1);
  EXPECT_EQ(g.heat_capacity, 840.0);
  EXPECT_EQ(g.emissivity, 0.85);
  EXPECT_EQ(g.charge, 1e-12);
  EXPECT_EQ(g.temperature, 350.0);
  EXPECT_EQ(s.model.materials[1].density, 7800.0);
  EXPECT_EQ(s.model.materials[1].young, Material{}.young);  // not given: Material's default
  EXPECT_EQ(s.model.material_index("steel"), 1);
  EXPECT_EQ(s.model.material_index("wood"), -1);

  ASSERT_EQ(s.particle_sources.size(), 1u);
  EXPECT_EQ(s.particle_sources[0].file, (d.path / "data" / "beads.csv").lexically_normal());
  EXPECT_EQ(s.particle_sources[0].material, "steel");
  EXPECT_EQ(s.particle_sources[0].line, 83u);

  ASSERT_EQ(s.barrier_sources.size(), 1u);
  const BarrierSource& b = s.barrier_sources[0];
  EXPECT_EQ(b.file, (d.path / "walls.csv").lexically_normal());
  EXPECT_TRUE(b.stl.empty());
  EXPECT_EQ(b.group, "floor");
  EXPECT_EQ(b.material, "steel");
  EXPECT_EQ(b.thickness, 0.002);
  ASSERT_TRUE(b.temperature.has_value());
  EXPECT_EQ(*b.temperature, 400.0);
  EXPECT_EQ(b.motion.a, (Vec3{0.1, 0.0, 0.0}));
  EXPECT_EQ(b.motion.A, (Vec3{0.0, 0.2, 0.0}));
  EXPECT_EQ(b.motion.w1, 3.0);
  EXPECT_EQ(b.motion.B, (Vec3{0.0, 0.0, 0.3}));
  EXPECT_EQ(b.motion.w2, 4.0);

  EXPECT_TRUE(p.domain.bounded);
  EXPECT_EQ(p.domain.min, (Vec3{-1.0, -2.0, -3.0}));
  EXPECT_EQ(p.domain.max, (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(p.domain.on_exit, ExitPolicy::Remove);
  EXPECT_EQ(p.neighbor.skin, 0.0005);
  EXPECT_EQ(p.output.dir, "out");
  EXPECT_EQ(p.output.particles_every, 0.01);
  EXPECT_EQ(p.output.barriers_every, 0.02);
  EXPECT_EQ(p.output.particle_csv_every, 0.03);
  EXPECT_EQ(p.output.barrier_log_every, 0.04);
  EXPECT_EQ(p.output.log_every, 50);
  EXPECT_EQ(p.output.checkpoint_every, 1000);
  EXPECT_EQ(p.output.progress_every, 5.0);
}

// The defaults documented in docs/scene.md.
TEST(SceneReader, DocumentedDefaults) {
  TempDir d("mpdem_scene");
  const Scene s = parse_scene_file(d.write("scene.toml", "[time]\nduration = 0.5\ndt = 2e-5\n"));
  const Params& p = s.model.params;
  EXPECT_EQ(p.time.duration, 0.5);
  EXPECT_EQ(p.time.dt, 2e-5);
  EXPECT_EQ(p.time.dt_min, 2e-5 / 1000.0);
  EXPECT_EQ(p.time.dt_max, 2e-5);
  EXPECT_EQ(p.time.integrator, Integrator::Verlet);
  EXPECT_EQ(p.time.phi, 0.5);
  EXPECT_FALSE(p.time.adaptive);
  EXPECT_EQ(p.time.desired_iterations, 10);
  EXPECT_EQ(p.time.p, 2.0);
  EXPECT_EQ(p.time.max_iterations, 50);
  EXPECT_EQ(p.tolerance.position, 1e-8);
  EXPECT_EQ(p.tolerance.temperature, 1e-8);
  EXPECT_TRUE(p.analysis.rotation);
  EXPECT_FALSE(p.analysis.thermal);
  EXPECT_EQ(p.fields.gravity, (Vec3{0.0, 0.0, -9.81}));
  EXPECT_EQ(p.fields.electric, (Vec3{}));
  EXPECT_EQ(p.fields.magnetic, (Vec3{}));
  EXPECT_FALSE(p.near_field.empirical);
  EXPECT_FALSE(p.near_field.coulomb);
  EXPECT_EQ(p.near_field.cutoff, 0.0);
  EXPECT_FALSE(p.contact.particle_particle.restitution.has_value());
  EXPECT_FALSE(p.contact.particle_particle.damping_ratio.has_value());
  EXPECT_EQ(p.contact.particle_particle.mu_static, 0.5);
  EXPECT_EQ(p.contact.particle_particle.mu_dynamic, 0.4);
  EXPECT_EQ(p.contact.particle_barrier.mu_rolling, 0.0);
  EXPECT_EQ(p.thermal.air_temperature, 293.15);
  EXPECT_TRUE(p.thermal.conduction);
  EXPECT_FALSE(p.thermal.convection);
  EXPECT_FALSE(p.domain.bounded);
  EXPECT_EQ(p.neighbor.skin, 0.0);
  EXPECT_EQ(p.output.dir, "output");
  EXPECT_EQ(p.output.log_every, 100);
  EXPECT_EQ(p.output.checkpoint_every, 0);
  EXPECT_TRUE(s.model.materials.empty());
  EXPECT_TRUE(s.particle_sources.empty());
  EXPECT_TRUE(s.barrier_sources.empty());
}

TEST(SceneReader, DtBoundsDefaultAroundAGivenDt) {
  TempDir d("mpdem_scene");
  // Only dt_max given: dt_min still defaults to dt / 1000.
  const Scene s = parse_scene_file(
      d.write("scene.toml", "[time]\nduration = 1\ndt = 1e-3\nintegrator = \"trapezoidal\"\ndt_max = 1e-2\n"));
  EXPECT_EQ(s.model.params.time.dt_min, 1e-6);
  EXPECT_EQ(s.model.params.time.dt_max, 1e-2);
}

TEST(SceneReader, DomainTableMeansBounded) {
  TempDir d("mpdem_scene");
  const Scene s = parse_scene_file(
      d.write("scene.toml", std::string(kTime) + "[domain]\nmin = [0,0,0]\nmax = [1,1,1]\n"));
  EXPECT_TRUE(s.model.params.domain.bounded);
  EXPECT_EQ(s.model.params.domain.on_exit, ExitPolicy::Stop);
}

TEST(SceneReader, ExplicitEmpiricalFalseWins) {
  TempDir d("mpdem_scene");
  const Scene s = parse_scene_file(
      d.write("scene.toml", std::string(kTime) + "[near_field]\na1 = 1.0\nempirical = false\n"));
  EXPECT_FALSE(s.model.params.near_field.empirical);
  EXPECT_EQ(s.model.params.near_field.a1, 1.0);
}
