// DMT adhesion (contact/laws/dmt.hpp): the evaluator against F = 4/3 E* sqrt(r*) delta^(3/2) -
// 2 pi w r* and its potential, the clamp at the pull-off, Coulomb's limit on the compressive load,
// Newton's third law in a run, and the pull-off through the engine: two equal spheres (E = 1e7
// Pa, nu = 0.3, R = 1 mm, w = 0.05 J/m^2) pulled apart by a slowly rising force part at 2 pi w r*
// = 157.1 uN, a sphere on a barrier (r* = R) at 314.2 uN, both within 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/contact_law.hpp"
#include "core/input_error.hpp"
#include "sim/simulation.hpp"
#include "support/action_reaction.hpp"
#include "support/contact_scenes.hpp"
#include "support/run_command.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = 1e7, kNu = 0.3, kR = 1e-3, kW = 0.05, kRho = 2500.0;
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

PairLaw dmt_law(double E_star, double w, double mu = 0.5) {
  ContactLawParams p;
  p.cohesion = "dmt";
  p.law_keys["surface_energy"] = w;
  p.damping_ratio = 0.3;
  p.mu_static = p.mu_dynamic = mu;
  return resolve_pair_law(p, E_star, 0.4 * E_star);
}

// The force, stiffness and potential of the law at rest (no dashpot), relative 1e-13, and the
// potential's derivative equal to the force (central difference, relative 1e-6).
TEST(DmtLaw, ForceAndPotentialAreHertzLessThePullOff) {
  const double E_star = 5e6, r = 5e-4;
  const PairLaw law = dmt_law(E_star, kW);
  const double pull = 2.0 * kPi * kW * r;
  for (const double d : {1e-9, 1e-7, 1e-6, 1e-5}) {
    const Stiffness s = DmtLaw::stiffness(law, r, d);
    EXPECT_LT(rel(s.f_el, 4.0 / 3.0 * E_star * std::sqrt(r) * std::pow(d, 1.5) - pull), 1e-13) << d;
    EXPECT_LT(rel(s.k_n, 2.0 * E_star * std::sqrt(r * d)), 1e-13) << d;
    EXPECT_LT(rel(s.energy, 8.0 / 15.0 * E_star * std::sqrt(r) * std::pow(d, 2.5) - pull * d), 1e-13) << d;
    const double h = 1e-4 * d;
    const double slope = (DmtLaw::stiffness(law, r, d + h).energy - DmtLaw::stiffness(law, r, d - h).energy) /
                         (2.0 * h);
    EXPECT_LT(rel(slope, s.f_el), 1e-6) << d;
    ContactState c;
    c.overlap = d, c.r_star = r, c.m_star = 1e-5, c.normal = {0, 0, 1};
    const ContactResult at_rest = evaluate_contact<DmtLaw>(law, c);
    EXPECT_LT(rel(at_rest.fn, s.f_el), 1e-13);
    EXPECT_EQ(at_rest.energy, s.energy);
  }
  // Touching: finite, the whole pull, no stiffness.
  const Stiffness s0 = DmtLaw::stiffness(law, r, 0.0);
  EXPECT_EQ(s0.k_n, 0.0);
  EXPECT_EQ(s0.f_el, -pull);
  EXPECT_EQ(s0.energy, 0.0);
  // w = 0 is the Hertz law, bit for bit.
  const PairLaw hertz = resolve_pair_law(ContactLawParams{}, E_star, 0.4 * E_star);
  const Stiffness a = DmtLaw::stiffness(dmt_law(E_star, 0.0), r, 1e-6), b = HertzLaw::stiffness(hertz, r, 1e-6);
  EXPECT_EQ(a.f_el, b.f_el);
  EXPECT_EQ(a.energy, b.energy);
}

// Receding fast, the dashpot would pull harder than the pull-off: the force stops at -2 pi w r*,
// and the load Coulomb's limit scales with is f_n + 2 pi w r* >= 0. A sliding contact's
// tangential force is mu_d times that load.
TEST(DmtLaw, DashpotClampsAtThePullOffAndFrictionTakesTheLoad) {
  const double E_star = 5e6, r = 5e-4, pull = 2.0 * kPi * kW * r;
  const PairLaw law = dmt_law(E_star, kW, 0.3);
  ContactState c;
  c.overlap = 1e-7, c.r_star = r, c.m_star = 1e-5, c.normal = {0, 0, 1};
  c.normal_rate = 10.0;  // m/s, receding
  const ContactResult fast = evaluate_contact<DmtLaw>(law, c);
  EXPECT_EQ(fast.fn, -pull);
  EXPECT_EQ(fast.fn_limit, 0.0);
  c.normal_rate = 0.0;
  c.increment = {1e-3, 0.0, 0.0};  // far beyond the stick limit
  const ContactResult slide = evaluate_contact<DmtLaw>(law, c);
  EXPECT_TRUE(slide.slipped);
  EXPECT_LT(rel(slide.fn_limit, slide.fn + pull), 1e-12);
  EXPECT_LT(rel(-slide.ft.x, 0.3 * slide.fn_limit), 1e-12);
  EXPECT_GT(slide.fn_limit, 0.0);
  EXPECT_LT(slide.fn, 0.0);  // attractive, yet the surfaces are pressed together and rub
}

Scene dmt_scene(double dt) {
  Scene s = test::make_scene(dt, 10.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  s.model.params.checks.max_overlap = 0.0;
  s.model.params.checks.energy_jump = 0.0;
  test::set_material(s, kRho, kE, kNu);
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->cohesion = "dmt";
    c->law_keys["surface_energy"] = kW;
    c->restitution = 0.3;
  }
  return s;
}

// Pulls particle 2 (and, for a pair, particle 1 the other way) along +x with a force rising at
// `rate` (N/s) from the adhesive rest until the contact opens; returns the force then (N).
double pull_off_force(bool barrier, double rate, double dt) {
  Scene s = dmt_scene(dt);
  if (barrier) {
    // A plate in the plane x = 0, the sphere pressed 1 um into it, pulled along +x.
    test::add_grid(s.barriers, "plate", {0.0, -0.01, -0.01}, {0.0, 0.02, 0.0}, {0.0, 0.0, 0.02}, 2, 2, kE, kNu);
    test::add_particle(s, 2, kR, {kR - 1e-6, 0.0, 0.0});
  } else {
    test::add_particle(s, 1, kR, {-kR + 0.5e-6, 0.0, 0.0});
    test::add_particle(s, 2, kR, {kR - 0.5e-6, 0.0, 0.0});
  }
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  const auto overlap = [&] {
    const Vec3 x2 = p.x[test::index_of(p, 2)];
    return barrier ? kR - x2.x : 2.0 * kR - norm(x2 - p.x[test::index_of(p, 1)]);
  };
  // Let the adhesion pull the spheres into their rest overlap first (the dashpot settles it).
  for (int k = 0; k < 20000; ++k) sim.advance(dt);
  EXPECT_GT(overlap(), 0.0);
  for (int k = 0; k < 2000000; ++k) {
    const double f = rate * k * dt;  // N
    if (barrier) sim.interactions().external_loads().set({2}, {{f, 0.0, 0.0}}, {Vec3{}});
    else sim.interactions().external_loads().set({1, 2}, {{-f, 0.0, 0.0}, {f, 0.0, 0.0}}, {Vec3{}, Vec3{}});
    sim.advance(dt);
    if (overlap() <= 0.0) return f;
  }
  ADD_FAILURE() << "the contact never opened";
  return 0.0;
}

// Equal spheres, r* = R/2: the pull-off 2 pi w R/2 = 157.1 uN; on a barrier r* = R: 314.2 uN.
// The force rises slowly against the contact's dynamics (a period of about 1 ms at rest, longer
// as the overlap vanishes), to 157 uN in 0.6 s: the contact opens about 0.1 % late (0.3 % at
// four times the rate), within the 1 % asked.
TEST(DmtLaw, SpheresPulledApartPartAtThePullOff) {
  const double pair = pull_off_force(false, 2.5e-4, 2e-6);
  std::printf("pair pull-off %.6g uN (2 pi w r* = %.6g uN)\n", 1e6 * pair, 1e6 * kPi * kW * kR);
  EXPECT_NEAR(pair / (kPi * kW * kR), 1.0, 0.01);
  EXPECT_NEAR(1e6 * pair, 157.1, 1.571);
  const double wall = pull_off_force(true, 5e-4, 2e-6);
  std::printf("barrier pull-off %.6g uN (2 pi w R = %.6g uN)\n", 1e6 * wall, 1e6 * 2.0 * kPi * kW * kR);
  EXPECT_NEAR(wall / (2.0 * kPi * kW * kR), 1.0, 0.01);
  EXPECT_NEAR(1e6 * wall, 314.2, 3.142);
}

// An adhesive contact at rest stores negative energy (8/15 E* sqrt(r*) delta^(5/2) - 2 pi w r*
// delta < 0 at the rest overlap): the energy-jump check (checks.energy_jump, default 0.5) scales
// with the magnitude of the kinetic and elastic energy, so the balance's round-off at rest is no
// "jump" (it was, against a negative threshold).
TEST(DmtLaw, AdhesiveRestIsNoEnergyJump) {
  Scene s = dmt_scene(2e-6);
  s.model.params.checks.energy_jump = 0.5;
  test::add_particle(s, 1, kR, {-kR + 0.5e-6, 0.0, 0.0});
  test::add_particle(s, 2, kR, {kR - 0.5e-6, 0.0, 0.0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  EXPECT_NO_THROW(for (int k = 0; k < 20000; ++k) sim.advance(2e-6));
  EXPECT_LT(sim.interactions().stats().elastic_energy, 0.0);
}

// Newton's third law pair by pair in an oblique, spinning, adhesive contact: f_2 = -f_1, and the
// torques are the contact-point arms (62) times the tangential force.
TEST(DmtLaw, NewtonThirdLaw) {
  Scene s = dmt_scene(1e-6);
  test::add_particle(s, 1, kR, {0.0, 0.0, 0.0}, {0.03, 0.005, 0.0}, {10.0, -40.0, 25.0});
  test::add_particle(s, 2, 0.7 * kR, {1.69 * kR, 0.4 * kR, 0.2 * kR}, {-0.02, 0.0, 0.003}, {-5.0, 0.0, 60.0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  int touching = 0, attractive = 0;
  for (int k = 0; k < 4000; ++k) {
    sim.advance(1e-6);
    const std::optional<double> fn = test::expect_action_reaction(p, test::index_of(p, 1), test::index_of(p, 2), kR,
                                                                  0.7 * kR);
    touching += fn.has_value();
    attractive += fn.has_value() && *fn < 0.0;
  }
  EXPECT_GT(touching, 10);
  EXPECT_GT(attractive, 0);
}

// The scene keys: cohesion = "dmt" and surface_energy under [contact.*] and [[contact.pair]];
// DMT is a Hertz law (law = "linear" with it is refused), w >= 0.
TEST(DmtLaw, SceneKeys) {
  const std::string head = "[time]\nduration = 1.0\ndt = 1e-5\n"
                           "[[material]]\nname = \"glass\"\n[[material]]\nname = \"steel\"\n";  // lines 1-7
  test::TempDir d("mpdem_dmt");
  const auto scene = d.write("scene.toml", head + "[contact.particle_particle]\ncohesion = \"dmt\"\n"
                                                  "surface_energy = 0.05\n"
                                                  "[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\n"
                                                  "cohesion = \"dmt\"\nsurface_energy = 0.2\n");
  const Scene s = parse_scene_file(scene);
  EXPECT_EQ(s.model.params.contact.particle_particle.cohesion, "dmt");
  EXPECT_EQ(s.model.params.contact.particle_particle.law_keys.at("surface_energy"), 0.05);
  ContactTable t;
  t.build(s.model);
  EXPECT_EQ(t.particle_pair(0, 0).law, law_id<DmtLaw>());
  EXPECT_EQ(t.particle_pair(0, 0).c[DmtLaw::kTwoPiW], 2.0 * kPi * 0.05);
  EXPECT_EQ(t.particle_pair(0, 1).c[DmtLaw::kTwoPiW], 2.0 * kPi * 0.2);
  EXPECT_EQ(t.barrier_pair(0, 0).law, law_id<HertzLaw>());  // the barrier default is plain Hertz
  EXPECT_EQ(t.barrier_pair(0, 1).law, law_id<DmtLaw>());    // the pair entry applies to both kinds
  struct Case {
    std::string toml;
    int line;
    std::string key, expect;
  };
  for (const Case& c : std::vector<Case>{
           {"[contact.particle_particle]\nlaw = \"linear\"\nstiffness_normal = 1.0\ncohesion = \"dmt\"\n", 9,
            "contact.particle_particle.law", "cohesion = \"dmt\" needs law = \"hertz\", got law = \"linear\""},
           {"[contact.particle_particle]\ncohesion = \"vdw\"\n", 9, "contact.particle_particle.cohesion",
            "expected \"none\", \"dmt\", \"jkr\" or \"sjkr\", got \"vdw\""},
           {"[contact.particle_barrier]\ncohesion = \"dmt\"\nsurface_energy = -1\n", 10,
            "contact.particle_barrier.surface_energy", "expected a number >= 0"},
           {"[contact.particle_particle]\nlaw = \"linear\"\nstiffness_normal = 1.0\n"
            "[[contact.pair]]\nmaterials = [\"glass\", \"glass\"]\ncohesion = \"dmt\"\n",
            13, "contact.pair.cohesion", "cohesion = \"dmt\" needs law = \"hertz\""},
       }) {
    SCOPED_TRACE(c.toml);
    const auto bad = d.write("bad.toml", head + c.toml);
    const std::string msg = test::error_of([&] { parse_scene_file(bad); });
    test::expect_contains(msg, {bad.string() + ":" + std::to_string(c.line) + ": '" + c.key + "': ", c.expect});
  }
}

}  // namespace
