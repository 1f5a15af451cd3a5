// SJKR adhesion (contact/laws/sjkr.hpp), law level: the attraction is k times the cross-section
// of the two spheres' overlap lens, computed here independently from R_1, R_2 and the centre
// distance d (a^2 = R_1^2 - ((d^2 + R_1^2 - R_2^2) / (2 d))^2, a plane at distance R - delta for a
// barrier), to 1e-9 at three overlaps; the potential is the Hertz one less k times the lens
// volume (its derivative is the force); at touching everything is zero and finite.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "contact/contact_law.hpp"
#include "contact/contact_table.hpp"
#include "scene/scene_reader.hpp"
#include "sim/simulation.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kK = 2e5;  // J/m^3, cohesion energy density
const double kEStar = 1e7 / (2.0 * (1.0 - 0.3 * 0.3));
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

PairLaw sjkr_law(double k, double mu = 0.5) {
  ContactLawParams p;
  p.cohesion = "sjkr";
  p.law_keys["cohesion_energy_density"] = k;
  p.damping_ratio = 0.3;
  p.mu_static = p.mu_dynamic = mu;
  return resolve_pair_law(p, kEStar, 0.4 * kEStar);
}
PairLaw hertz_law() { return resolve_pair_law(ContactLawParams{}, kEStar, 0.4 * kEStar); }

// One contact's geometry: two spheres (r2 = 0: a sphere of radius r1 on a barrier).
struct Pair {
  double r1, r2;
  double r_star() const { return r2 > 0.0 ? r1 * r2 / (r1 + r2) : r1; }
  double inv_reach() const { return r2 > 0.0 ? 1.0 / (r1 + r2) : 0.0; }
  // m^2, the lens cross-section from the centre distance (long double: R^2 - h^2 cancels).
  double area(double delta) const {
    const long double R1 = r1, R2 = r2;
    long double h = R1 - delta;  // the plane's distance from centre 1
    if (r2 > 0.0) {
      const long double d = R1 + R2 - delta;
      h = (d * d + R1 * R1 - R2 * R2) / (2.0L * d);
    }
    return static_cast<double>(std::numbers::pi_v<long double> * (R1 - h) * (R1 + h));
  }
  // m^3, the lens volume (two caps; a barrier: one cap of height delta).
  double volume(double delta) const {
    if (r2 == 0.0) return kPi * delta * delta * (3.0 * r1 - delta) / 3.0;
    const double d = r1 + r2 - delta;
    return kPi * delta * delta * (d * d + 2.0 * d * (r1 + r2) - 3.0 * (r1 - r2) * (r1 - r2)) / (12.0 * d);
  }
};

// The attraction is k A to 1e-9 at three overlaps, for unequal and equal spheres and a sphere
// on a barrier; the force is the Hertz one less it; the potential is the Hertz one less k V.
TEST(SjkrLaw, AttractionIsTheLensCrossSection) {
  const PairLaw law = sjkr_law(kK), hertz = hertz_law();
  for (const Pair p : {Pair{1e-3, 0.6e-3}, Pair{1e-3, 1e-3}, Pair{1e-3, 0.0}}) {
    for (const double d : {1e-7, 1e-5, 2e-4}) {
      const Stiffness s = SjkrLaw::stiffness(law, p.r_star(), d, p.inv_reach());
      const Stiffness h = HertzLaw::stiffness(hertz, p.r_star(), d);
      const double attraction = kK * p.area(d);
      EXPECT_LT(rel(s.adhesion, attraction), 1e-9) << p.r1 << " " << p.r2 << " " << d;
      EXPECT_LT(rel(h.f_el - s.f_el, attraction), 1e-9) << p.r1 << " " << p.r2 << " " << d;
      EXPECT_EQ(s.load_offset, s.adhesion);
      EXPECT_LT(rel(h.energy - s.energy, kK * p.volume(d)), 1e-9) << p.r1 << " " << p.r2 << " " << d;
      EXPECT_EQ(s.k_n, h.k_n);
      EXPECT_EQ(s.k_t, h.k_t);
    }
  }
}

// The potential's central difference is the force, 1e-6 relative.
TEST(SjkrLaw, EnergyDerivativeIsTheForce) {
  const PairLaw law = sjkr_law(kK);
  for (const Pair p : {Pair{1e-3, 0.6e-3}, Pair{1e-3, 0.0}})
    for (const double d : {1e-8, 1e-6, 1e-5, 1e-4, 3e-4}) {
      const double h = 1e-4 * d;
      const double slope = (SjkrLaw::stiffness(law, p.r_star(), d + h, p.inv_reach()).energy -
                            SjkrLaw::stiffness(law, p.r_star(), d - h, p.inv_reach()).energy) /
                           (2.0 * h);
      const double f = SjkrLaw::stiffness(law, p.r_star(), d, p.inv_reach()).f_el;
      EXPECT_LT(rel(slope, f), 1e-6) << p.r2 << " " << d;
    }
}

// Touching (and a step past it): zero force, energy, stiffness and attraction, all finite.
// k = 0 is the Hertz law bit for bit.
TEST(SjkrLaw, TouchingIsZeroAndZeroDensityIsHertz) {
  const PairLaw law = sjkr_law(kK);
  for (const double d : {0.0, -1e-7}) {
    const Stiffness s = SjkrLaw::stiffness(law, 3.75e-4, d, 1.0 / 1.6e-3);
    EXPECT_EQ(s.f_el, 0.0);
    EXPECT_EQ(s.energy, 0.0);
    EXPECT_EQ(s.k_n, 0.0);
    EXPECT_EQ(s.adhesion, 0.0);
  }
  const PairLaw zero = sjkr_law(0.0), hertz = hertz_law();
  for (const double d : {1e-7, 1e-5}) {
    const Stiffness a = SjkrLaw::stiffness(zero, 3.75e-4, d, 1.0 / 1.6e-3), b = HertzLaw::stiffness(hertz, 3.75e-4, d);
    EXPECT_EQ(a.f_el, b.f_el);
    EXPECT_EQ(a.energy, b.energy);
  }
}

// The dashpot never pulls harder than k A; Coulomb's load is f_n + k A.
TEST(SjkrLaw, ClampAtTheAttractionAndFrictionTakesTheLoad) {
  const PairLaw law = sjkr_law(kK, 0.3);
  const Pair p{1e-3, 0.6e-3};
  ContactState c;
  c.overlap = 1e-6, c.r_star = p.r_star(), c.inv_reach = p.inv_reach(), c.m_star = 1e-5, c.normal = {0, 0, 1};
  c.normal_rate = 10.0;  // m/s, receding
  const double attraction = SjkrLaw::stiffness(law, c.r_star, c.overlap, c.inv_reach).adhesion;
  const ContactResult fast = evaluate_contact<SjkrLaw>(law, c);
  EXPECT_EQ(fast.fn, -attraction);
  EXPECT_EQ(fast.fn_limit, 0.0);
  c.normal_rate = 0.0;
  c.increment = {1e-3, 0.0, 0.0};
  const ContactResult slide = evaluate_contact<SjkrLaw>(law, c);
  EXPECT_TRUE(slide.slipped);
  EXPECT_LT(rel(slide.fn_limit, slide.fn + attraction), 1e-12);
  EXPECT_LT(rel(-slide.ft.x, 0.3 * slide.fn_limit), 1e-12);
}

// The scene keys: cohesion = "sjkr" with cohesion_energy_density; a negative k is refused.
TEST(SjkrLaw, SceneKeys) {
  const std::string head = "[time]\nduration = 1.0\ndt = 1e-5\n[[material]]\nname = \"glass\"\n";  // lines 1-5
  test::TempDir d("mpdem_sjkr");
  const auto scene = d.write("scene.toml", head + "[contact.particle_barrier]\ncohesion = \"sjkr\"\n"
                                                  "cohesion_energy_density = 3e4\n");
  const Scene s = parse_scene_file(scene);
  ContactTable t;
  t.build(s.model);
  EXPECT_EQ(t.particle_pair(0, 0).law, law_id<HertzLaw>());
  EXPECT_EQ(t.barrier_pair(0, 0).law, law_id<SjkrLaw>());
  EXPECT_EQ(t.barrier_pair(0, 0).c[SjkrLaw::kPiK], kPi * 3e4);
  const auto bad = d.write("bad.toml", head + "[contact.particle_particle]\ncohesion = \"sjkr\"\n"
                                              "cohesion_energy_density = -1\n");
  const std::string msg = test::error_of([&] { parse_scene_file(bad); });
  test::expect_contains(
      msg, {bad.string() + ":8: 'contact.particle_particle.cohesion_energy_density': ", "expected a number >= 0"});
}

}  // namespace

// Through the engine (the pair kernel and the barrier kernel): two fixed spheres of 1 mm and
// 0.6 mm at rest at three overlaps, and a fixed sphere pressed into a plate: the force on each is
// the Hertz force less k times the lens area, 1e-9 (the kernels hand the laws 1 / (R_i + R_j)).
TEST(SjkrLaw, ThroughThePairAndBarrierKernels) {
  for (const double delta : {1e-7, 2e-6, 3e-5}) {
    Scene s = test::make_scene(1e-7, 1.0);
    s.model.params.fields.gravity = {};
    s.model.params.checks.max_overlap = 0.0;
    test::set_material(s, 2500.0, 1e7, 0.3);
    for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
      c->cohesion = "sjkr";
      c->law_keys["cohesion_energy_density"] = kK;
    }
    const Pair pair{1e-3, 0.6e-3}, wall{1e-3, 0.0};
    test::add_particle(s, 1, pair.r1, {0.0, 0.0, 0.0});
    test::add_particle(s, 2, pair.r2, {pair.r1 + pair.r2 - delta, 0.0, 0.0});
    // a plate in the plane z = -0.01 (normal +z) and a third sphere pressed into it
    test::add_grid(s.barriers, "plate", {-0.02, -0.02, -0.01}, {0.04, 0.0, 0.0}, {0.0, 0.04, 0.0}, 2, 2, 1e7, 0.3);
    test::add_particle(s, 3, wall.r1, {0.005, 0.005, -0.01 + wall.r1 - delta});
    for (std::size_t i = 0; i < 3; ++i) s.particles.fixed[i] = 1;
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    sim.advance(1e-7);
    const Particles& p = sim.particles();
    const double hertz_pair = 4.0 / 3.0 * kEStar * std::sqrt(pair.r_star()) * std::pow(delta, 1.5);
    // A barrier's E* of two equal materials (physics.md section 7): the particle and the plate alike.
    const double hertz_wall = 4.0 / 3.0 * kEStar * std::sqrt(wall.r_star()) * std::pow(delta, 1.5);
    const double f_pair = p.force[test::index_of(p, 2)].x, f_wall = p.force[test::index_of(p, 3)].z;
    EXPECT_LT(rel(hertz_pair - f_pair, kK * pair.area(delta)), 1e-9) << delta;
    EXPECT_EQ(p.force[test::index_of(p, 1)].x, -f_pair);
    EXPECT_LT(rel(hertz_wall - f_wall, kK * wall.area(delta)), 1e-9) << delta;
  }
}
