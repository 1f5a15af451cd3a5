// Fixed particles (Particles::fixed): their velocity and angular velocity stay as given, their
// centre advances by exactly dt v a step, contacts and fields do not accelerate them, they still
// carry the free particles (and feel their weight), the work of what holds them to their motion
// is booked so that the energy balance stays closed, and a checkpoint carries the flag.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <vector>

#include "integrate/energy_balance.hpp"
#include "sim/simulation.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

constexpr double kR = 1e-3;   // m
constexpr double kDt = 4e-6;  // s, about the Rayleigh time / 20 for the default material
constexpr Vec3 kGravity{0.0, 0.0, -9.81};

const char* name(Integrator integ) { return integ == Integrator::Verlet ? "verlet" : "trapezoidal"; }

Scene base_scene(Integrator integ) {
  Scene s = make_scene(kDt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = kGravity;
  set_contact_law(s, 0.5);
  return s;
}

std::size_t add_fixed(Scene& s, std::int64_t id, const Vec3& x, const Vec3& v = {}, const Vec3& w = {}) {
  const std::size_t i = add_particle(s, id, kR, x, v, w);
  s.particles.fixed[i] = 1;
  return i;
}

// An 8 x 8 layer of fixed spheres (ids 1000 + k, centres 2.02 R apart at z = 0) loaded by 4 x 4
// free spheres (ids 1-16) in its middle hollows and 3 x 3 more (ids 17-25) in theirs, each placed
// 0.01 R above its nest, so that the bed settles within the test's steps.
Scene loaded_bed(Integrator integ) {
  Scene s = base_scene(integ);
  const double a = 2.02 * kR;                                  // m
  const double nest = std::sqrt(4.0 * kR * kR - 0.5 * a * a);  // m, height of a nest above its four
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) add_fixed(s, 1000 + 8 * j + i, {a * i, a * j, 0.0});
  std::int64_t id = 1;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) add_particle(s, id++, kR, {a * (i + 2.5), a * (j + 2.5), nest + 0.01 * kR});
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) add_particle(s, id++, kR, {a * (i + 3), a * (j + 3), 2.0 * nest + 0.02 * kR});
  return s;
}

struct Kinematics {
  Vec3 x, v, w;
};

// Each fixed particle's state by id.
std::vector<std::pair<std::int64_t, Kinematics>> fixed_states(const Particles& p) {
  std::vector<std::pair<std::int64_t, Kinematics>> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.fixed[i]) out.push_back({p.id[i], {p.x[i], p.v[i], p.w[i]}});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

std::size_t index_of(const Particles& p, std::int64_t id) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == id) return i;
  ADD_FAILURE() << "no particle id " << id;
  return 0;
}

// J, kinetic + rotational + potential + elastic + dissipated - barrier and fixed-particle work.
double balance(Simulation& sim) {
  const ParticleEnergy e = particle_energy(sim.particles(), sim.model().params.fields.gravity);
  const InteractionStats& st = sim.interactions().stats();
  return e.kinetic + e.rotational + e.potential + st.elastic_energy + st.damping_dissipated + st.friction_dissipated -
         st.barrier_work - st.fixed_work;
}

}  // namespace

// The fixed layer carries 25 spheres that settle onto it during 10^4 steps: every fixed centre,
// velocity and spin stays bitwise what it was (memcmp), for both integrators, while the free
// spheres rest on the layer (none below its top, 4 contacts each) and it carries their weight
// (within 1%: the bed has nearly come to rest).
TEST(FixedParticles, BaseStaysBitwiseUnderALoadedBed) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    Simulation sim(loaded_bed(integ), RunOptions{{}, false, false});
    const auto before = fixed_states(sim.particles());
    ASSERT_EQ(before.size(), 64u);
    for (int k = 0; k < 10000; ++k) sim.advance(kDt);
    const auto after = fixed_states(sim.particles());
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t k = 0; k < before.size(); ++k) {
      EXPECT_EQ(before[k].first, after[k].first);
      EXPECT_EQ(std::memcmp(&before[k].second, &after[k].second, sizeof(Kinematics)), 0) << "id " << before[k].first;
    }
    const Particles& p = sim.particles();
    double lowest = 1.0, base_load = 0.0;  // m, N
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.fixed[i]) base_load += p.mass[i] * kGravity.z - p.force[i].z;  // the contact forces pressing down
      else lowest = std::min(lowest, p.x[i].z);
    }
    const double weight = 25.0 * sphere_mass(kR, sim.model().materials[0].density) * 9.81;  // N
    std::printf("[%s] lowest free centre %.4f R, contacts %zu, load on the base %.4f of the free weight\n", name(integ),
                lowest / kR, sim.interactions().stats().contacts_pp, base_load / weight);
    EXPECT_GT(lowest, kR);  // on top of the layer (whose top is at z = R)
    EXPECT_EQ(sim.interactions().stats().contacts_pp, 100u);
    EXPECT_NEAR(base_load / weight, 1.0, 0.01);
  }
}

// A fixed sphere with v = (0.2, 0.01, 0) m/s and w = 30 rad/s about z pushes two resting spheres
// out of its way: its centre is x0 + v t to 1e-12 relative after 3000 steps, v and w are bitwise
// unchanged, its orientation has turned by |w| t about z (1e-10), and the spheres it hit move.
TEST(FixedParticles, PrescribedVelocityIsExactWhileHit) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    Scene s = base_scene(integ);
    s.model.params.fields.gravity = {};
    const Vec3 x0{1.234e-3, -0.5e-3, 0.3e-3}, v{0.2, 0.01, 0.0}, w{0.0, 0.0, 30.0};
    add_fixed(s, 7, x0, v, w);
    add_particle(s, 1, kR, x0 + Vec3{2.5 * kR, 0.0, 0.0});
    add_particle(s, 2, kR, x0 + Vec3{4.6 * kR, 0.4 * kR, 0.0});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    std::size_t touched = 0;
    for (int k = 0; k < 3000; ++k) {
      sim.advance(kDt);
      touched = std::max(touched, sim.interactions().stats().contacts_pp);
    }
    const Particles& p = sim.particles();
    const std::size_t f = index_of(p, 7);
    const double t = sim.time();
    const Vec3 exact = x0 + t * v;
    const double err = norm(p.x[f] - exact) / norm(exact);
    const double angle = 2.0 * std::atan2(p.q[f].z, p.q[f].w);  // rad, about z
    std::printf("[%s] t = %.6g s: |x - (x0 + v t)| / |x| = %.2e, angle %.12f (|w| t %.12f), speeds hit %.4f %.4f m/s\n",
                name(integ), t, err, angle, norm(w) * t, norm(p.v[index_of(p, 1)]), norm(p.v[index_of(p, 2)]));
    EXPECT_LT(err, 1e-12);
    EXPECT_EQ(std::memcmp(&p.v[f], &v, sizeof v), 0);
    EXPECT_EQ(std::memcmp(&p.w[f], &w, sizeof w), 0);
    EXPECT_NEAR(angle, norm(w) * t, 1e-10);
    EXPECT_NEAR(p.q[f].x, 0.0, 1e-12);
    EXPECT_NEAR(p.q[f].y, 0.0, 1e-12);
    EXPECT_GE(touched, 1u);
    EXPECT_GT(norm(p.v[index_of(p, 1)]), 0.1);  // pushed along at about v
    EXPECT_GT(norm(p.v[index_of(p, 2)]), 0.01);
  }
}

// One sphere nested on four fixed spheres (a square of side 2.2 R) under gravity comes to rest:
// the contact forces then carry its weight (total force on it below 1e-6 m g), and the fixed
// spheres feel that weight, their contact forces summing to -m g within 1e-6 relative.
TEST(FixedParticles, RestingOnAFixedBaseBalancesTheWeight) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    Scene s = base_scene(integ);
    const double h = 1.1 * kR;  // m, half the square's side
    add_fixed(s, 10, {-h, -h, 0.0});
    add_fixed(s, 11, {h, -h, 0.0});
    add_fixed(s, 12, {h, h, 0.0});
    add_fixed(s, 13, {-h, h, 0.0});
    // Touching at zero overlap, slightly off centre so that the tangential springs work too.
    const double z = std::sqrt(4.0 * kR * kR - 2.0 * h * h);
    add_particle(s, 1, kR, {0.01 * kR, 0.0, z + 0.001 * kR});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    for (int k = 0; k < 15000; ++k) sim.advance(kDt);
    const Particles& p = sim.particles();
    const std::size_t b = index_of(p, 1);
    const double mg = p.mass[b] * 9.81;  // N
    Vec3 on_base{};                      // N, contact forces on the fixed spheres
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.fixed[i]) on_base += p.force[i] - p.mass[i] * kGravity;
    std::printf("[%s] |F| on the sphere %.2e m g, |v| %.2e m/s; base load z %.9f m g, horizontal %.2e m g\n",
                name(integ), norm(p.force[b]) / mg, norm(p.v[b]), -on_base.z / mg,
                std::hypot(on_base.x, on_base.y) / mg);
    EXPECT_LT(norm(p.force[b]), 1e-6 * mg);
    EXPECT_NEAR(-on_base.z / mg, 1.0, 1e-6);
    EXPECT_LT(std::hypot(on_base.x, on_base.y), 1e-6 * mg);
    EXPECT_EQ(sim.interactions().stats().contacts_pp, 4u);
  }
}

// Four fixed spheres moving together at (0.05, 0, 0.1) m/s lift a sphere resting on them and
// push a second one aside under gravity, with friction and the energy_jump check on, for 0.02 s.
// The work of what holds them to their motion (fixed_work) exceeds their own lift m g v_z t, and
// the energy balance with it taken off drifts by less than 1e-3 of that work at dt = 2e-6 s; the
// drift is the integrators' first-order error (halving dt halves it, ratio 2 +- 0.4), not a
// booking error, which would not shrink with dt.
TEST(FixedParticles, EnergyBalanceClosedWithAMovingFixedParticle) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const Vec3 u{0.05, 0.0, 0.1};  // m/s
    const auto drift_at = [&](double dt) {
      Scene s = base_scene(integ);
      s.model.params.checks.energy_jump = 0.01;
      const double h = 1.1 * kR;  // m
      for (int k = 0; k < 4; ++k) add_fixed(s, 10 + k, {k % 3 ? h : -h, k < 2 ? -h : h, 0.0}, u);
      add_particle(s, 1, kR, {0.0, 0.0, std::sqrt(4.0 * kR * kR - 2.0 * h * h)});
      add_particle(s, 2, kR, {2.9 * kR, 0.0, 0.9 * kR});
      Simulation sim(std::move(s), RunOptions{{}, false, false});
      sim.advance(dt);
      const double b0 = balance(sim);
      while (sim.time() < 0.02 - 0.5 * dt) sim.advance(dt);
      const InteractionStats& st = sim.interactions().stats();
      const Particles& p = sim.particles();
      double lift = 0.0;  // J, m g u_z t of the fixed spheres themselves
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.fixed[i]) lift += p.mass[i] * 9.81 * u.z * sim.time();
      const double drift = (balance(sim) - b0) / st.fixed_work;
      std::printf("[%s] dt %.0e s: fixed work %.6e J (their own lift %.6e J), dissipated %.3e J, balance drift "
                  "%.2e of the work\n",
                  name(integ), dt, st.fixed_work, lift, st.damping_dissipated + st.friction_dissipated, drift);
      EXPECT_GT(st.fixed_work, lift);          // their own lift and what they carry and push
      EXPECT_GT(p.v[index_of(p, 2)].x, 0.01);  // the second sphere was pushed aside
      return drift;
    };
    const double coarse = drift_at(kDt), fine = drift_at(0.5 * kDt);
    EXPECT_LT(std::abs(fine), 1e-3);
    EXPECT_NEAR(coarse / fine, 2.0, 0.4);
  }
}

// A run with a fixed sphere ploughing into the loaded bed, checkpointed after 300 steps and resumed,
// continues bitwise as the uninterrupted run for 300 more (states, flags, the booked work).
TEST(FixedParticles, CheckpointResumeKeepsTheFlag) {
  const fs::path dir = fs::temp_directory_path() / ("mpdem_fixed_ck_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const auto scene = [integ] {
      Scene s = loaded_bed(integ);
      add_fixed(s, 77, {5.0 * kR, 6.06 * kR, 4.6 * kR}, {0.1, 0.03, -0.01}, {0.0, 20.0, 0.0});  // into the top
      return s;
    };
    Simulation full(scene(), RunOptions{{}, false, false});
    for (int k = 0; k < 300; ++k) full.advance(kDt);
    full.write_checkpoint(dir / "ck.bin");
    for (int k = 0; k < 300; ++k) full.advance(kDt);
    Simulation resumed(scene(), RunOptions{{}, false, false});
    resumed.resume_from(dir / "ck.bin");
    for (int k = 0; k < 300; ++k) resumed.advance(kDt);
    const Particles& a = full.particles();
    const Particles& b = resumed.particles();
    ASSERT_EQ(a.size(), b.size());
    std::size_t fixed = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a.id[i], b.id[i]);
      EXPECT_EQ(a.fixed[i], b.fixed[i]) << "id " << a.id[i];
      EXPECT_EQ(std::memcmp(&a.x[i], &b.x[i], sizeof(Vec3)), 0) << "id " << a.id[i];
      EXPECT_EQ(std::memcmp(&a.v[i], &b.v[i], sizeof(Vec3)), 0) << "id " << a.id[i];
      EXPECT_EQ(std::memcmp(&a.w[i], &b.w[i], sizeof(Vec3)), 0) << "id " << a.id[i];
      fixed += b.fixed[i];
    }
    EXPECT_EQ(fixed, 65u);  // the layer and the moving one
    EXPECT_EQ(full.interactions().stats().fixed_work, resumed.interactions().stats().fixed_work);
    // More than the gravity on it alone (m g |v_z| t, 2.5e-9 J): it did push on the bed.
    EXPECT_GT(std::abs(full.interactions().stats().fixed_work), 5e-9);
    std::printf("[%s] resumed bitwise; fixed work %.6e J\n", name(integ), resumed.interactions().stats().fixed_work);
  }
  fs::remove_all(dir);
}
