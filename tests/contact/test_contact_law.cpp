// The contact-law evaluators (contact/contact_law.hpp) against the single-law oracle
// (tests/support/hertz_oracle.hpp) and, for the linear spring-dashpot, against the closed forms
// of the damped linear oscillator (physics.md section 13): contact time pi / sqrt(k_n/m* (1 -
// zeta^2)) and restitution exp(-zeta pi / sqrt(1 - zeta^2)), sphere-sphere and sphere-barrier.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact/contact_law.hpp"
#include "sim/simulation.hpp"
#include "support/action_reaction.hpp"
#include "support/contact_scenes.hpp"
#include "support/hertz_oracle.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {

const double kPi = std::acos(-1.0);
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// The evaluator's Hertz law equals the oracle: normal force with damping (49)-(50), the
// tangential stiffness (65) and damping (67) seen through a sticking spring, the stored energy.
// Relative 1e-14 (the shared square roots change only the rounding).
TEST(HertzLaw, EvaluatorEqualsTheSingleLawOracle) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> lg(-1.0, 1.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const double E = 1e7 * std::pow(10.0, 3 * lg(rng)), G = 0.4 * E, r = 1e-3 * std::pow(10.0, lg(rng));
    const double m = 1e-5 * std::pow(10.0, 2 * lg(rng)), d = 1e-3 * r * std::pow(10.0, lg(rng));
    ContactLawParams params;
    params.damping_ratio = 0.2 + 0.1 * lg(rng);
    params.tangential_damping = trial % 2 ? 0.0 : 0.3;
    params.mu_static = params.mu_dynamic = 1e6;  // sticks
    const PairLaw law = resolve_pair_law(params, E, G);
    ContactState c;
    c.overlap = d, c.r_star = r, c.m_star = m, c.normal = {0, 0, 1};
    // Approaching or receding, slowly enough that the damped force stays positive.
    c.normal_rate = 0.05 * lg(rng) * d * std::sqrt(hertz_stiffness(E, r, d) / m);
    c.increment = {1e-3 * d, 0.0, 0.0};
    const ContactResult spring_only = evaluate_contact<HertzLaw>(law, c);
    const NormalForce fn = normal_contact_force(E, r, m, *params.damping_ratio, d, c.normal_rate);
    EXPECT_LT(rel(spring_only.fn, fn.magnitude), 1e-14);
    EXPECT_LT(rel(-spring_only.ft.x / c.increment.x, tangential_stiffness(G, r, d)), 1e-14);
    EXPECT_LT(rel(spring_only.energy - 0.5 * tangential_stiffness(G, r, d) * c.increment.x * c.increment.x,
                  hertz_elastic_energy(E, r, d)),
              1e-12);
    c.increment = {};
    c.vt = {0.0, 1e-2, 0.0};
    const ContactResult dashpot = evaluate_contact<HertzLaw>(law, c);
    const double d_t = params.tangential_damping > 0.0 ? tangential_damping_coefficient(*params.tangential_damping, m,
                                                                                        tangential_stiffness(G, r, d))
                                                       : 0.0;
    if (d_t > 0.0) EXPECT_LT(rel(-dashpot.ft.y / c.vt.y, d_t), 1e-14);
    else EXPECT_EQ(dashpot.ft.y, 0.0);
  }
}

// Coulomb cap of the linear law: a spring beyond mu_s k_t... slides at mu_d |f_n| (Cundall-Strack).
TEST(LinearLaw, TangentialSpringIsCappedAtCoulomb) {
  ContactLawParams params;
  params.law = "linear";
  params.law_keys["stiffness_normal"] = 1e4;
  params.law_keys["stiffness_tangential"] = 3e3;
  params.damping_ratio = 0.0;
  params.mu_static = 0.5;
  params.mu_dynamic = 0.4;
  const PairLaw law = resolve_pair_law(params, 0.0, 0.0);
  ContactState c;
  c.overlap = 1e-4, c.r_star = 1e-3, c.m_star = 1e-3, c.normal = {0, 0, 1};
  c.increment = {1e-6, 0.0, 0.0};
  const ContactResult stick = evaluate_contact<LinearLaw>(law, c);
  EXPECT_FALSE(stick.slipped);
  EXPECT_DOUBLE_EQ(stick.fn, 1.0);      // k_n delta
  EXPECT_DOUBLE_EQ(stick.ft.x, -3e-3);  // -k_t ds
  EXPECT_DOUBLE_EQ(stick.energy, 0.5 * 1e4 * 1e-8 + 0.5 * 3e3 * 1e-12);
  c.increment = {1e-3, 0.0, 0.0};  // k_t ds = 3 N > mu_s f_n
  const ContactResult slip = evaluate_contact<LinearLaw>(law, c);
  EXPECT_TRUE(slip.slipped);
  EXPECT_DOUBLE_EQ(slip.ft.x, -0.4);
  EXPECT_DOUBLE_EQ(slip.spring.x, 0.4 / 3e3);  // stored at the dynamic limit
}

// --- the linear law in a run ---

constexpr double kR = 0.005, kRho = 2500.0;  // m, kg/m^3
constexpr double kK = 2000.0;                // N/m

struct Collision {
  double t_c = 0.0;  // s, from the interpolated zero crossings of the overlap
  double e = 0.0;    // -, separation / approach speed
};

double sphere_mass() { return 4.0 / 3.0 * kPi * kR * kR * kR * kRho; }

Scene linear_scene(double dt, double e) {
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  s.model.params.checks.max_overlap = 0.0;
  test::set_material(s, kRho, 1e7, 0.3);
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->law = "linear";
    c->law_keys["stiffness_normal"] = kK;
    c->restitution = e;
  }
  return s;
}

// Head-on pair (barrier = false) or a sphere dropped flat onto a plate, closing speed v.
Collision collide(bool barrier, double v, double e, double dt) {
  Scene s = linear_scene(dt, e);
  const double gap = 3.3 * v * dt;
  if (barrier) {
    test::add_flat_square(s.barriers, "plate", {0.0, 0.0, 0.0}, 0.05, 2, 1e7, 0.3);
    test::add_particle(s, 1, kR, {0.0, 0.0, kR + gap}, {0.0, 0.0, -v});
  } else {
    test::add_particle(s, 1, kR, {-kR - 0.5 * gap, 0.0, 0.0}, {0.5 * v, 0.0, 0.0});
    test::add_particle(s, 2, kR, {kR + 0.5 * gap, 0.0, 0.0}, {-0.5 * v, 0.0, 0.0});
  }
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  const auto overlap = [&] {
    if (barrier) return kR - p.x[0].z;
    return 2.0 * kR - norm(p.x[test::index_of(p, 1)] - p.x[test::index_of(p, 2)]);
  };
  Collision c;
  double prev = overlap(), start = -1.0;
  for (int k = 0; k < 100000; ++k) {
    sim.advance(dt);
    const double ov = overlap(), t = sim.time();
    if (prev <= 0.0 && ov > 0.0 && start < 0.0) start = t - dt * ov / (ov - prev);
    if (prev > 0.0 && ov <= 0.0) {
      c.t_c = t - dt * (-ov) / (prev - ov) - start;
      c.e = barrier ? p.v[0].z / v : (p.v[test::index_of(p, 2)].x - p.v[test::index_of(p, 1)].x) / v;
      break;
    }
    prev = ov;
  }
  return c;
}

// Contact time within 0.5% of pi / sqrt(k_n/m* (1 - zeta^2)) and restitution within 0.002 of e,
// at three speeds (the linear law's are speed-independent), pair and barrier.
TEST(LinearLaw, ContactTimeAndRestitutionMatchTheDampedOscillator) {
  for (bool barrier : {false, true})
    for (double e : {0.5, 0.9}) {
      const double m_star = barrier ? sphere_mass() : 0.5 * sphere_mass();
      const double zeta = -std::log(e) / std::sqrt(kPi * kPi + std::log(e) * std::log(e));
      const double t_c = kPi / std::sqrt(kK / m_star * (1.0 - zeta * zeta));
      for (double v : {0.01, 0.1, 1.0}) {
        const Collision c = collide(barrier, v, e, t_c / 400.0);
        EXPECT_NEAR(c.t_c / t_c, 1.0, 0.005) << (barrier ? "barrier" : "pair") << " e " << e << " v " << v;
        EXPECT_NEAR(c.e, e, 0.002) << (barrier ? "barrier" : "pair") << " e " << e << " v " << v;
      }
    }
}

// Newton's third law pair by pair for the linear law: f_2 = -f_1, and the torques are the
// contact-point arms (62) times the tangential force, in an oblique, spinning, damped contact.
TEST(LinearLaw, NewtonThirdLaw) {
  Scene s = linear_scene(1e-5, 0.5);
  ContactLawParams& c = s.model.params.contact.particle_particle;
  c.mu_static = 0.5, c.mu_dynamic = 0.4, c.tangential_damping = 0.2;
  test::add_particle(s, 1, kR, {0.0, 0.0, 0.0}, {0.3, 0.05, 0.0}, {10.0, -40.0, 25.0});
  test::add_particle(s, 2, 0.7 * kR, {1.69 * kR, 0.4 * kR, 0.2 * kR}, {-0.2, 0.0, 0.03}, {-5.0, 0.0, 60.0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  int touching = 0;
  for (int k = 0; k < 400; ++k) {
    sim.advance(1e-5);
    touching += test::expect_action_reaction(p, test::index_of(p, 1), test::index_of(p, 2), kR, 0.7 * kR).has_value();
  }
  EXPECT_GT(touching, 10);
}

}  // namespace
