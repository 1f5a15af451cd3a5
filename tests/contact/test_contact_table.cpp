// Per-material-pair contact tables (contact/contact_table.hpp, [[contact.pair]]): each pair of
// materials gets its own friction, restitution and law, particle-particle and particle-barrier;
// the tables follow the model when a material changes between steps.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_table.hpp"
#include "model/particle_defaults.hpp"
#include "sim/simulation.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {

const double kPi = std::acos(-1.0);
constexpr double kR = 0.005;  // m

int add_material(Scene& s, const std::string& name, double density, double young, double poisson) {
  Material m;
  m.name = name, m.density = density, m.young = young, m.poisson = poisson;
  s.model.materials.push_back(m);
  return static_cast<int>(s.model.materials.size()) - 1;
}

std::size_t add_sphere(Scene& s, int mat, std::int64_t id, const Vec3& x, const Vec3& v, const Vec3& w = {}) {
  const Material& m = s.model.materials[static_cast<std::size_t>(mat)];
  Particles& p = s.particles;
  p.add(id, mat, kR, m.density, x, v);
  const std::size_t i = p.size() - 1;
  p.w[i] = w;
  take_material_properties(p, i, m);
  return i;
}

ContactPairParams pair_entry(const std::string& a, const std::string& b) {
  ContactPairParams e;
  e.material_a = a, e.material_b = b;
  return e;
}

// Two floors of different barrier materials, with mu_dynamic 0.3 and 0.1 against the sphere's
// material: a sphere sliding without rolling decelerates at mu_d g on each (1e-9 relative),
// until friction has spun it up to rolling (after 2 v0 / (7 mu_d g)).
TEST(ContactTable, SlidingDecelerationFollowsEachFloorsFriction) {
  const double g = 9.81, E = 1e8, nu = 0.3, rho = 2500.0, v0 = 0.5, dt = 2e-6;
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {0.0, 0.0, -g};
  test::set_material(s, rho, E, nu);
  s.model.materials[0].name = "ball";
  const int rough = add_material(s, "rough", rho, E, nu), smooth = add_material(s, "smooth", rho, E, nu);
  s.model.params.contact.particle_barrier.restitution = 0.5;
  ContactPairParams a = pair_entry("ball", "rough"), b = pair_entry("ball", "smooth");
  a.mu_static = 0.3, a.mu_dynamic = 0.3;
  b.mu_static = 0.1, b.mu_dynamic = 0.1;
  s.model.params.contact.pairs = {a, b};
  const double side = 0.1;
  test::add_flat_square(s.barriers, "rough", {0.0, 0.0, 0.0}, side, 2, E, nu);
  const std::size_t rough_end = s.barriers.size();
  test::add_flat_square(s.barriers, "smooth", {0.0, 0.2, 0.0}, side, 2, E, nu);
  for (std::size_t e = 0; e < s.barriers.size(); ++e) s.barriers.material[e] = e < rough_end ? rough : smooth;
  // Resting on each floor at the Hertz rest overlap (no vertical motion), sliding along +x.
  const double m = 4.0 / 3.0 * kPi * kR * kR * kR * rho;
  const double delta = test::hertz_rest_overlap(m * g, E / (2.0 * (1.0 - nu * nu)), kR);  // E* (51), r* = R
  add_sphere(s, 0, 1, {-0.03, 0.0, kR - delta}, {v0, 0.0, 0.0});
  add_sphere(s, 0, 2, {-0.03, 0.2, kR - delta}, {v0, 0.0, 0.0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  for (int k = 0; k < 500; ++k) sim.advance(dt);  // past the stick of the first steps
  const double t1 = sim.time();
  const double v1a = p.v[test::index_of(p, 1)].x, v1b = p.v[test::index_of(p, 2)].x;
  for (int k = 0; k < 2000; ++k) sim.advance(dt);  // 4 ms: well within both sliding phases
  const double t2 = sim.time();
  const double aa = (p.v[test::index_of(p, 1)].x - v1a) / (t2 - t1);
  const double ab = (p.v[test::index_of(p, 2)].x - v1b) / (t2 - t1);
  EXPECT_NEAR(-aa / (0.3 * g), 1.0, 1e-9);
  EXPECT_NEAR(-ab / (0.1 * g), 1.0, 1e-9);
}

// Glass and steel spheres in one scene, a restitution per pair of materials: head-on collisions
// glass-glass, glass-steel and steel-steel each rebound with their own e (within 0.005).
TEST(ContactTable, RestitutionPerPairOfParticleMaterials) {
  const double v = 0.2;
  Scene s = test::make_scene(1e-6, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  s.model.params.checks.max_overlap = 0.0;
  test::set_material(s, 2500.0, 6.3e8, 0.22);
  s.model.materials[0].name = "glass";
  const int steel = add_material(s, "steel", 7850.0, 2.1e9, 0.29);
  s.model.params.contact.particle_particle.restitution = 0.8;  // glass-glass: the default
  ContactPairParams gs = pair_entry("glass", "steel"), ss = pair_entry("steel", "steel");
  gs.restitution = 0.6;
  ss.restitution = 0.4;
  s.model.params.contact.pairs = {gs, ss};
  const int mats[3][2] = {{0, 0}, {0, steel}, {steel, steel}};
  for (int c = 0; c < 3; ++c) {
    const double y = 0.05 * c;
    add_sphere(s, mats[c][0], 10 * c + 1, {-kR - 1e-5, y, 0.0}, {v, 0.0, 0.0});
    add_sphere(s, mats[c][1], 10 * c + 2, {kR + 1e-5, y, 0.0}, {-v, 0.0, 0.0});
  }
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  for (int k = 0; k < 3000; ++k) sim.advance(1e-6);
  const double expected[3] = {0.8, 0.6, 0.4};
  for (int c = 0; c < 3; ++c) {
    const std::size_t a = test::index_of(p, 10 * c + 1), b = test::index_of(p, 10 * c + 2);
    ASSERT_GT(norm(p.x[a] - p.x[b]), 2.0 * kR) << "collision " << c << " not over";
    const double e = (p.v[b].x - p.v[a].x) / (2.0 * v);
    EXPECT_NEAR(e, expected[c], 0.005) << "collision " << c;
  }
}

// A material's Young's modulus changed in the model between two steps acts at the next step:
// a resting Hertz contact's force scales with E* (here E, both spheres of one material).
TEST(ContactTable, YoungsModulusEditedBetweenStepsTakesEffect) {
  Scene s = test::make_scene(1e-7, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  s.model.params.contact.particle_particle.damping_ratio = 0.0;
  // Doubling E doubles the stored energy in one step, which the energy-jump check rightly flags.
  s.model.params.checks.energy_jump = 0.0;
  test::set_material(s, 2500.0, 1e7, 0.3);
  const double delta = 1e-5;
  test::add_particle(s, 1, kR, {-kR + 0.5 * delta, 0.0, 0.0});
  test::add_particle(s, 2, kR, {kR - 0.5 * delta, 0.0, 0.0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  sim.advance(1e-7);
  const double f1 = norm(p.force[0]), x1 = norm(p.x[0] - p.x[1]);
  sim.model().materials[0].young = 2e7;
  sim.advance(1e-7);
  const double f2 = norm(p.force[0]), x2 = norm(p.x[0] - p.x[1]);
  // Hertz: F = 4/3 E* sqrt(r*) d^(3/2); the overlap changed slightly over the step.
  const double expected = 2.0 * std::pow((2.0 * kR - x2) / (2.0 * kR - x1), 1.5);
  EXPECT_NEAR(f2 / f1 / expected, 1.0, 1e-9);
}

// One scene mixing the laws: linear for glass-steel contacts, Hertz elsewhere. The glass-steel
// collision lasts the linear law's pi / sqrt(k/m*) (undamped, 0.5%); the glass-glass one the
// Hertz closed form 2.943 delta_max / v (1%).
TEST(ContactTable, LinearForOnePairHertzElsewhere) {
  const double v = 0.2, k = 5000.0, dt = 2e-6;
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  s.model.params.checks.max_overlap = 0.0;
  s.model.params.contact.particle_particle.damping_ratio = 0.0;
  const double E = 1e8, nu = 0.3, rho = 2500.0;
  test::set_material(s, rho, E, nu);
  s.model.materials[0].name = "glass";
  const int steel = add_material(s, "steel", rho, E, nu);
  ContactPairParams gs = pair_entry("glass", "steel");
  gs.law = "linear";
  gs.law_keys["stiffness_normal"] = k;
  s.model.params.contact.pairs = {gs};
  add_sphere(s, 0, 1, {-kR - 1e-6, 0.0, 0.0}, {0.5 * v, 0.0, 0.0});
  add_sphere(s, steel, 2, {kR + 1e-6, 0.0, 0.0}, {-0.5 * v, 0.0, 0.0});
  add_sphere(s, 0, 3, {-kR - 1e-6, 0.05, 0.0}, {0.5 * v, 0.0, 0.0});
  add_sphere(s, 0, 4, {kR + 1e-6, 0.05, 0.0}, {-0.5 * v, 0.0, 0.0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  double start[2] = {-1.0, -1.0}, duration[2] = {-1.0, -1.0}, prev[2] = {-1.0, -1.0}, dmax = 0.0;
  for (int step = 0; step < 20000 && (duration[0] < 0.0 || duration[1] < 0.0); ++step) {
    sim.advance(dt);
    for (int c = 0; c < 2; ++c) {
      const double ov = 2.0 * kR - norm(p.x[test::index_of(p, 2 * c + 1)] - p.x[test::index_of(p, 2 * c + 2)]);
      if (c == 1) dmax = std::max(dmax, ov);
      const double t = sim.time();
      if (prev[c] <= 0.0 && ov > 0.0 && start[c] < 0.0) start[c] = t - dt * ov / (ov - prev[c]);
      if (prev[c] > 0.0 && ov <= 0.0 && duration[c] < 0.0) duration[c] = t - dt * (-ov) / (prev[c] - ov) - start[c];
      prev[c] = ov;
    }
  }
  const double m_star = 0.5 * 4.0 / 3.0 * kPi * kR * kR * kR * rho;
  EXPECT_NEAR(duration[0] / (kPi / std::sqrt(k / m_star)), 1.0, 0.005);
  EXPECT_NEAR(duration[1] / (2.943275 * dmax / v), 1.0, 0.01);
}

}  // namespace
