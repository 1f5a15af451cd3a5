// Cohesion at barriers and on clumps' members (contact/cohesive_contact.hpp, physics.md 21):
// - a JKR sphere on a plate pulled off by a slowly rising force parts at F_c = 3/2 pi w R
//   (r* = R: 235.6 uN for R = 1 mm, w = 0.05 J/m^2), 1 %;
// - a sphere held moving away from a plate at 1 mm/s across a Willett bridge feels
//   4 pi R gamma / (1 + 1.05 S^ + 2.5 S^^2), S^ = S sqrt(2R/V) (the harmonic radius of a sphere and a
//   plane is 2R), to 1e-3, until the gap passes V^(1/3);
// - a clump's member bridged to a sphere feels the equal-sphere Willett force, and the body
//   takes it (the member's force is the sphere's, opposite).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "sim/simulation.hpp"
#include "support/clump_scenes.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = 1e7, kNu = 0.3, kR = 1e-3, kW = 0.05, kRho = 2500.0;
constexpr double kGamma = 0.0206, kVolume = 74.2e-12 / 8.0;  // N/m; m^3, a bridge for 1 mm spheres
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

Scene base(double dt) {
  Scene s = test::make_scene(dt, 10.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  s.model.params.checks.max_overlap = 0.0;
  test::set_material(s, kRho, kE, kNu);
  return s;
}

void bridges_everywhere(Scene& s) {
  LiquidBridgeKeys k;
  k.surface_tension = kGamma;
  k.volume = kVolume;
  s.model.params.contact.liquid_bridge.defaults = k;
}

// N, Willett's force of the harmonic mean radius Rh (m) across the gap S (m), theta = 0.
double willett_force(double Rh, double S) {
  const double sh = S * std::sqrt(Rh / kVolume);
  return 2.0 * kPi * Rh * kGamma / (1.0 + 1.05 * sh + 2.5 * sh * sh);
}

// A plate in the plane x = 0 (normal +x).
void add_plate(Scene& s) {
  test::add_grid(s.barriers, "plate", {0.0, -0.01, -0.01}, {0.0, 0.02, 0.0}, {0.0, 0.0, 0.02}, 2, 2, kE, kNu);
}

}  // namespace

TEST(JkrAtABarrier, PullOffUnderARisingForce) {
  const double dt = 1e-6, rate = 4e-4;  // N/s
  Scene s = base(dt);
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->cohesion = "jkr";
    c->law_keys["surface_energy"] = kW;
    c->restitution = 0.3;
  }
  add_plate(s);
  test::add_particle(s, 2, kR, {kR - 0.5e-6, 0.0, 0.0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 20000; ++k) sim.advance(dt);
  ASSERT_EQ(sim.interactions().stats().contacts_pb, 1u);
  const double fc = 1.5 * kPi * kW * kR;
  double parted = 0.0;
  for (int k = 0; k < 1000000 && parted == 0.0; ++k) {
    const double f = rate * k * dt;  // N
    sim.interactions().external_loads().set({2}, {{f, 0.0, 0.0}}, {Vec3{}});
    sim.advance(dt);
    if (sim.interactions().stats().contacts_pb == 0) parted = f;
  }
  std::printf("parted from the plate at %.6e N, F_c = 3/2 pi w R = %.6e N, relative %.2e\n", parted, fc,
              rel(parted, fc));
  EXPECT_LT(rel(parted, fc), 1e-2);
  EXPECT_EQ(sim.interactions().stats().cohesion_breaks, 1u);
}

TEST(LiquidBridgeAtABarrier, WillettForceOfASphereOnAPlane) {
  const double dt = 2e-6, v = 1e-3;
  Scene s = base(dt);
  bridges_everywhere(s);
  add_plate(s);
  const std::size_t i = test::add_particle(s, 2, kR, {kR - 1e-9, 0.0, 0.0}, {v, 0.0, 0.0});
  s.particles.fixed[i] = 1;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Particles& p = sim.particles();
  const double rupture = std::cbrt(kVolume);
  int checked = 0;
  bool ruptured = false;
  for (int k = 0; k < 400000 && !ruptured; ++k) {
    sim.advance(dt);
    const double S = p.x[0].x - kR, f = p.force[0].x;
    if (S < rupture) {
      ASSERT_EQ(sim.interactions().stats().bridges, 1u) << S;
      if (k % 20000 == 0) {
        EXPECT_LT(rel(-f, willett_force(2.0 * kR, std::max(S, 0.0))), 1e-3) << "gap " << S;
        ++checked;
      }
    } else if (S > rupture + 2.0 * v * dt) {
      EXPECT_EQ(f, 0.0);
      ruptured = sim.interactions().stats().ruptures == 1;
    }
  }
  std::printf("checked %d gaps up to the rupture at %.4e m\n", checked, rupture);
  EXPECT_GT(checked, 4);
  EXPECT_TRUE(ruptured);
}

TEST(LiquidBridgeOnAClump, MemberBridgedToASphere) {
  const double dt = 2e-6, v = 1e-3;
  Scene s = base(dt);
  bridges_everywhere(s);
  // A dumbbell along x, centre at -2R, at rest and held (fixed); member 1 at x = -R.
  const int dumbbell = test::add_template(s, "dumbbell", {{{kR, 0.0, 0.0}, kR}, {{-kR, 0.0, 0.0}, kR}});
  test::add_clump(s, 100, dumbbell, {-2.0 * kR, 0.0, 0.0});
  s.particles.bodies.fixed[0] = 1;
  const std::size_t i = test::add_particle(s, 1, kR, {kR - 1e-9, 0.0, 0.0}, {v, 0.0, 0.0});
  s.particles.fixed[i] = 1;
  test::finish_clumps(s);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Particles& p = sim.particles();
  const std::size_t sphere = test::index_of(p, 1);
  int checked = 0;
  for (int k = 1; k <= 100000; ++k) {
    sim.advance(dt);
    if (k % 25000 != 0) continue;
    // The member nearer the sphere (at x = -R).
    const std::size_t m0 = test::member_of(p, 100, 0), m1 = test::member_of(p, 100, 1);
    const std::size_t m = p.x[m0].x > p.x[m1].x ? m0 : m1;
    const double S = p.x[sphere].x - p.x[m].x - 2.0 * kR;
    const double f = p.force[sphere].x;
    EXPECT_LT(rel(-f, willett_force(kR, S)), 1e-3) << "gap " << S;  // equal spheres: the harmonic radius is R
    EXPECT_EQ(p.force[m].x, -f);
    ++checked;
  }
  EXPECT_EQ(checked, 4);
  EXPECT_EQ(sim.interactions().stats().bridges, 1u);
}
