// The tangential spring's two forms (physics.md section 6: the thesis's total spring and
// Mindlin's incremental one), the default tangential damping (xi_t = xi_n) and the sliding loss
// booked per step, all on the one evaluator the kernels run (contact/contact_law.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/contact_law.hpp"
#include "contact/contact_table.hpp"
#include "physics/restitution.hpp"
#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

PairLaw hertz_law(TangentialSpring form, double mu) {
  ContactLawParams p;
  p.restitution = 0.5;
  p.mu_static = p.mu_dynamic = mu;
  p.tangential_spring = form;
  return resolve_pair_law(p, 1e8, 4e7);
}

ContactState state(double overlap, const Vec3& spring, const Vec3& increment) {
  ContactState c;
  c.overlap = overlap, c.r_star = 0.005, c.m_star = 1e-3, c.normal = {0.0, 0.0, 1.0};
  c.spring = spring, c.increment = increment;
  return c;
}

}  // namespace

// Left out, xi_t is the normal ratio: calibrated from the restitution, or damping_ratio as
// given; given, it is used as written (0 included).
TEST(TangentialDamping, DefaultsToTheNormalRatio) {
  ContactLawParams p;
  p.restitution = 0.5;
  const PairLaw calibrated = resolve_pair_law(p, 1e8, 4e7);
  EXPECT_EQ(calibrated.xi_t(), damping_ratio_for_restitution(0.5));
  EXPECT_EQ(calibrated.xi_t(), calibrated.xi_n());
  p.restitution.reset();
  p.damping_ratio = 0.3;
  EXPECT_EQ(resolve_pair_law(p, 1e8, 4e7).xi_t(), 0.3);
  p.tangential_damping = 0.0;
  EXPECT_EQ(resolve_pair_law(p, 1e8, 4e7).xi_t(), 0.0);
  p.tangential_damping = 0.7;
  EXPECT_EQ(resolve_pair_law(p, 1e8, 4e7).xi_t(), 0.7);
  EXPECT_EQ(resolve_pair_law(ContactLawParams{}, 1e8, 4e7).xi_t(), 0.0);  // undamped: e = 1
}

// A [[contact.pair]] entry sets the form (and xi_t) for its pair of materials only.
TEST(TangentialSpring, PairEntryChoosesTheForm) {
  Model model;
  for (const char* name : {"glass", "steel"}) {
    Material m;
    m.name = name;
    model.materials.push_back(m);
  }
  model.params.contact.particle_particle.restitution = 0.5;
  ContactPairParams e;
  e.material_a = "glass", e.material_b = "steel";
  e.tangential_spring = TangentialSpring::Incremental;
  e.tangential_damping = 0.1;
  model.params.contact.pairs.push_back(e);
  ContactTable t;
  t.build(model);
  EXPECT_EQ(t.particle_pair(0, 1).spring, TangentialSpring::Incremental);
  EXPECT_EQ(t.particle_pair(1, 0).spring, TangentialSpring::Incremental);
  EXPECT_EQ(t.barrier_pair(0, 1).spring, TangentialSpring::Incremental);
  EXPECT_EQ(t.particle_pair(0, 0).spring, TangentialSpring::Total);
  EXPECT_EQ(t.particle_pair(0, 1).xi_t(), 0.1);
  EXPECT_EQ(t.particle_pair(1, 1).xi_t(), t.particle_pair(1, 1).xi_n());
}

// Sticking, the total spring gives f_t = -k_t(delta') (s + ds); the incremental one, which
// stores k_t(delta) s (N), gives f_t = -(k_t(delta) s + k_t(delta') ds): the new stiffness scales
// only the increment. Each to 1e-14, and the stored value is what the next step needs.
TEST(TangentialSpring, TotalAndIncrementalForms) {
  const double d0 = 1e-5, d1 = 2e-5;  // m, overlap of the last step and of this one
  const Vec3 s{1e-7, 0.0, 0.0}, ds{2e-8, 1e-8, 0.0};
  const PairLaw total = hertz_law(TangentialSpring::Total, 1e6), inc = hertz_law(TangentialSpring::Incremental, 1e6);
  const double kt0 = HertzLaw::stiffness(total, 0.005, d0).k_t, kt1 = HertzLaw::stiffness(total, 0.005, d1).k_t;
  const ContactResult t = evaluate_contact<HertzLaw>(total, state(d1, s, ds));
  EXPECT_LT(rel(t.ft.x, -kt1 * (s.x + ds.x)), 1e-14);
  EXPECT_LT(rel(t.ft.y, -kt1 * ds.y), 1e-14);
  EXPECT_LT(rel(t.spring.x, s.x + ds.x), 1e-14);
  const ContactResult i = evaluate_contact<HertzLaw>(inc, state(d1, kt0 * s, ds));
  EXPECT_LT(rel(i.ft.x, -(kt0 * s.x + kt1 * ds.x)), 1e-14);
  EXPECT_LT(rel(i.ft.y, -kt1 * ds.y), 1e-14);
  EXPECT_LT(rel(i.spring.x, -i.ft.x), 1e-14);  // stored: the elastic force's magnitude, k_t s
  // Stored energy 1/2 k_t |s|^2 with s the displacement either form holds now.
  const double en_total = HertzLaw::stiffness(total, 0.005, d1).energy;
  EXPECT_LT(rel(t.energy - en_total, 0.5 * kt1 * norm2(t.spring)), 1e-12);
  EXPECT_LT(rel(i.energy - en_total, 0.5 * norm2(i.spring) / kt1), 1e-12);
  // At constant overlap the two forms agree.
  const ContactResult t0 = evaluate_contact<HertzLaw>(total, state(d0, s, ds));
  const ContactResult i0 = evaluate_contact<HertzLaw>(inc, state(d0, kt0 * s, ds));
  EXPECT_LT(norm(t0.ft - i0.ft) / norm(t0.ft), 1e-14);
}

// Sliding, both forms apply mu_d |f_n| and store the slip length (incremental: as k_t s); the
// step's tangential loss is the work the force took, mu_d |f_n| |ds| here, less what the spring
// gained at this step's stiffness, 1/2 k_t (|s_slip|^2 - |s|^2).
TEST(TangentialSpring, SlidingForceAndLoss) {
  const double d = 1e-5, mu = 0.3;
  const Vec3 s{1e-6, 0.0, 0.0}, ds{4e-7, 0.0, 0.0};
  for (const TangentialSpring form : {TangentialSpring::Total, TangentialSpring::Incremental}) {
    const PairLaw law = hertz_law(form, mu);
    const Stiffness k = HertzLaw::stiffness(law, 0.005, d);
    const bool inc = form == TangentialSpring::Incremental;
    const ContactResult r = evaluate_contact<HertzLaw>(law, state(d, inc ? k.k_t * s : s, ds));
    ASSERT_TRUE(r.slipped);
    EXPECT_LT(rel(r.ft.x, -mu * r.fn), 1e-14);
    const double slip = mu * r.fn / k.k_t;  // m
    EXPECT_LT(rel(r.spring.x, inc ? k.k_t * slip : slip), 1e-14);
    EXPECT_LT(rel(r.spring_energy, 0.5 * k.k_t * slip * slip), 1e-14);
    EXPECT_LT(rel(r.spring_energy_before, 0.5 * k.k_t * norm2(s)), 1e-14);
    EXPECT_LT(rel(r.tangential_loss, mu * r.fn * ds.x - 0.5 * k.k_t * (slip * slip - norm2(s))), 1e-12);
    EXPECT_EQ(r.damping, evaluate_contact<HertzLaw>(law, state(d, {}, {})).damping);  // no dashpot while sliding
  }
}

namespace {

// Oblique sphere-plane impact at 30 degrees, e = 0.5, mu = 0.4: the contact-point slip after
// the rebound over the one before (physics.md section 6, rigid-body closed form 1 - chi in
// gross sliding, chi = 3.5 mu (1 + e) v_n / V_s).
double slip_ratio(TangentialSpring form, double tan_angle) {
  using namespace mpdem::test;
  const double vn = 0.5, vt = vn * tan_angle, dt = 2e-6;
  Scene s = base_scene(Integrator::Verlet, dt, {});
  s.model.params.analysis.rotation = true;
  ContactLawParams& c = s.model.params.contact.particle_barrier;
  c.restitution = 0.5;
  c.mu_static = c.mu_dynamic = 0.4;
  c.tangential_spring = form;
  add_flat_square(s.barriers, "floor", {0.0, 0.0, 0.0}, 40.0 * kR, 2, kE, kNu);
  const std::size_t i = add_particle(s, 1, kR, {0.0, 0.0, 1.001 * kR}, {vt, 0.0, -vn});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 3000; ++k) sim.advance(dt);
  const Particles& p = sim.particles();
  return (p.v[i].x - kR * p.w[i].y) / vt;  // contact point velocity v + w x (-R z)
}

}  // namespace

// Through the engine: in gross sliding (chi = 0.42, 0.93) both forms give the closed form
// 1 - chi within 1% (the spring sits at the slip length throughout, which both store alike);
// past the threshold (chi = 1.5, 3), where the contact sticks before it ends and k_t changes
// while it sticks, they differ measurably, by a few percent of V_s at most (the issue's
// estimate: about 2%; measured 1.7% and 2.0%).
TEST(TangentialSpring, ObliqueImpactBothForms) {
  const double e = 0.5, mu = 0.4;
  for (const double chi : {0.42, 0.93, 1.5, 3.0}) {
    const double tan_angle = 3.5 * mu * (1.0 + e) / chi;  // V_s / v_n
    const double total = slip_ratio(TangentialSpring::Total, tan_angle);
    const double inc = slip_ratio(TangentialSpring::Incremental, tan_angle);
    std::printf("oblique impact chi %.2f: slip ratio total %.4f, incremental %.4f, closed form (sliding) %.4f\n", chi,
                total, inc, 1.0 - chi);
    if (chi < 1.0) {
      EXPECT_NEAR(total, 1.0 - chi, 0.01 * (1.0 - chi));
      EXPECT_NEAR(inc, 1.0 - chi, 0.01 * (1.0 - chi));
    } else {
      EXPECT_GT(std::abs(total - inc), 1e-3);
      EXPECT_LT(std::abs(total - inc), 0.05);
    }
  }
}
