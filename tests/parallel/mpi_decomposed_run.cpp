// Runs over 1 to N ranks against the same runs on one rank (ctest runs this under mpirun -np 1,
// 2, 3, 4; docs/parallel.md). Every rank also runs the one-rank reference itself and compares
// its own particles with it, by id.
//  - a frictional, rolling, thermal cluster in a box of barriers, cut into bricks (contacts and
//    heat flows across the ranks, barrier loads summed over them), 10^4 steps, both integrators;
//  - a falling column cut across its height, whose spheres fall through the cuts (migration
//    with their contact and barrier history), 10^4 steps, both integrators;
//  - the cluster with charges: the near field (Coulomb's law) across the ranks;
//  - the cluster without rolling resistance, mu_s > mu_d: stick/slip decisions that jump the force;
//  - a sliding (then sticking) pair that crosses a cut: its spring, bit for bit, at every step;
//  - a floor switched on within a step: the lists rebuilt in that evaluation on every rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "neighbor/neighbor_search.hpp"
#include "parallel/communicator.hpp"
#include "sim/simulation.hpp"
#include "support/decomposed_scenes.hpp"
#include "support/timed_barrier_scenes.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

struct State {
  Vec3 x, v, w;
  double T;
};

std::map<std::int64_t, State> by_id(const Particles& p) {
  std::map<std::int64_t, State> m;
  for (std::size_t i = 0; i < p.size(); ++i) m[p.id[i]] = {p.x[i], p.v[i], p.w[i], p.T[i]};
  return m;
}

struct Outcome {
  double x = 0, v = 0, w = 0, T = 0;  // worst relative deviation over all ranks
  double loads = 0;                   // worst element load deviation / sum of |load|
  double T_change = 0;                // K, the reference's largest temperature change
  std::uint64_t held = 0, matched = 0, migrated = 0, ghosts = 0;
  bool everyone_holds = false;
  InteractionStats serial, decomposed;
};

// Runs the scene `steps` steps on one rank and on all, and compares (collective).
template <class Make>
Outcome compare(Make make, Integrator integ, double dt, int steps, const char* what) {
  const Communicator& world = Communicator::world();
  Simulation one(make(integ, dt), RunOptions{{}, false, false, &Communicator::single()});
  Simulation many(make(integ, dt), RunOptions{{}, false, false, &world});
  const auto start = by_id(one.particles());
  for (int k = 0; k < steps; ++k) {
    one.advance(dt);
    many.advance(dt);
  }
  Outcome o;
  const auto ref = by_id(one.particles());
  double vmax = 0, wmax = 0;
  for (const auto& [id, s] : ref) {
    vmax = std::max(vmax, norm(s.v));
    wmax = std::max(wmax, norm(s.w));
    o.T_change = std::max(o.T_change, std::abs(s.T - start.at(id).T));
  }
  std::uint64_t matched = 0;
  for (const auto& [id, s] : by_id(many.particles())) {
    const auto it = ref.find(id);
    if (it == ref.end()) continue;
    ++matched;
    o.x = std::max(o.x, norm(s.x - it->second.x) / 1e-3);  // to the radius
    o.v = std::max(o.v, norm(s.v - it->second.v) / vmax);
    o.w = std::max(o.w, norm(s.w - it->second.w) / wmax);
    o.T = std::max(o.T, std::abs(s.T - it->second.T) / 20.0);  // to the initial spread
  }
  const Barriers& a = one.barriers();
  const Barriers& b = many.barriers();
  double scale = 0;
  for (std::size_t e = 0; e < a.size(); ++e) scale += norm(a.force[e]);
  for (std::size_t e = 0; e < a.size(); ++e) o.loads = std::max(o.loads, norm(a.force[e] - b.force[e]) / scale);
  double worst[] = {o.x, o.v, o.w, o.T, o.loads};
  world.max(worst);
  o.x = worst[0], o.v = worst[1], o.w = worst[2], o.T = worst[3], o.loads = worst[4];
  o.matched = world.sum(matched);
  o.held = world.sum(static_cast<std::uint64_t>(many.particles().size()));
  o.everyone_holds = world.min(static_cast<double>(many.particles().size())) > 0;
  const HaloExchange* halo = many.interactions().search().halo();
  o.migrated = world.sum(halo ? halo->migrated() : std::uint64_t{0});
  o.ghosts = world.sum(static_cast<std::uint64_t>(halo ? halo->size() : 0));
  o.serial = one.interactions().stats();
  o.decomposed = many.interactions().global_stats();
  if (world.rank() == 0)
    std::printf("[%d ranks, %s, %s] %d steps: max rel diff x %.2e v %.2e w %.2e T %.2e (largest T change %.3g K); "
                "element loads %.2e; contacts pp %zu vs %zu, pb %zu vs %zu; %llu migrations, %llu ghosts; evaluations "
                "per step %.3f vs %.3f\n",
                world.size(), what, integ == Integrator::Verlet ? "verlet" : "trapezoidal", steps, o.x, o.v, o.w, o.T,
                o.T_change, o.loads, o.serial.contacts_pp, o.decomposed.contacts_pp, o.serial.contacts_pb,
                o.decomposed.contacts_pb, static_cast<unsigned long long>(o.migrated),
                static_cast<unsigned long long>(o.ghosts), static_cast<double>(one.evaluations()) / steps,
                static_cast<double>(many.evaluations()) / steps);
  EXPECT_EQ(o.held, one.particles().size());  // nobody lost or duplicated
  EXPECT_EQ(o.matched, one.particles().size());
  EXPECT_EQ(o.decomposed.contacts_pp, o.serial.contacts_pp);
  EXPECT_EQ(o.decomposed.contacts_pb, o.serial.contacts_pb);
  return o;
}

std::string integrator_name(const ::testing::TestParamInfo<Integrator>& p) {
  return p.param == Integrator::Verlet ? "Verlet" : "Trapezoidal";
}

}  // namespace

class DecomposedRun : public ::testing::TestWithParam<Integrator> {};

TEST_P(DecomposedRun, RollingThermalClusterFollowsTheOneRankRun) {
  const Outcome o = compare(cluster, GetParam(), 2e-6, 10000, "cluster");
  for (double d : {o.x, o.v, o.w, o.T}) EXPECT_LT(d, 1e-10);
  EXPECT_LT(o.loads, 1e-10);
  EXPECT_GT(o.T_change, 1e-4);            // heat flowed (the T deviation is that of T's last bit)
  EXPECT_GT(o.serial.contacts_pp, 100u);  // a cluster, not a gas
  EXPECT_GT(o.serial.contacts_pb, 20u);
  if (Communicator::world().size() > 1) {
    EXPECT_TRUE(o.everyone_holds);
    EXPECT_GT(o.ghosts, 20u);  // contacts across the ranks
  }
}

// Without rolling resistance and with mu_s > mu_d the tangential force jumps at every stick/slip
// decision: the trapezoidal rule keeps the first iteration's, made at the predictor (the step
// start's state and rates only, the same on any rank count), so the runs still agree.
TEST_P(DecomposedRun, ClusterWithoutRollingResistanceFollowsTheOneRankRun) {
  const Outcome o = compare(sliding_cluster, GetParam(), 2e-6, 10000, "cluster without rolling resistance");
  for (double d : {o.x, o.v, o.w, o.T}) EXPECT_LT(d, 1e-10);
  EXPECT_LT(o.loads, 1e-10);
  EXPECT_GT(o.serial.contacts_pp, 100u);
  if (Communicator::world().size() > 1) {
    EXPECT_GT(o.ghosts, 20u);
  }
}

// The near field (Coulomb's law between charged spheres) on ghosts: its forces across the cuts,
// its potential summed over the ranks.
TEST_P(DecomposedRun, ChargedClusterFollowsTheOneRankRun) {
  const Outcome o = compare(charged_cluster, GetParam(), 2e-6, 10000, "charged cluster");
  for (double d : {o.x, o.v, o.w, o.T}) EXPECT_LT(d, 1e-10);
  EXPECT_LT(o.loads, 1e-10);
  EXPECT_GT(std::abs(o.serial.near_field_energy), 1e-9);  // J: the pairs within the cutoff count
  EXPECT_NEAR(o.decomposed.near_field_energy, o.serial.near_field_energy, 1e-10 * std::abs(o.serial.near_field_energy));
  if (Communicator::world().size() > 1) {
    EXPECT_GT(o.ghosts, 20u);
  }
}

// 10^4 steps (20 ms: the column has landed and collapsed onto the floor), 16-48 migrations with
// their pair and barrier history.
TEST_P(DecomposedRun, FallingColumnMigratesAndFollowsTheOneRankRun) {
  const Outcome o = compare(column, GetParam(), 2e-6, 10000, "column");
  for (double d : {o.x, o.v, o.w, o.T}) EXPECT_LT(d, 1e-10);
  EXPECT_LT(o.loads, 1e-10);
  EXPECT_GT(o.serial.contacts_pb, 10u);  // landed
  if (Communicator::world().size() > 1) {
    EXPECT_TRUE(o.everyone_holds);
    EXPECT_GT(o.migrated, 10u);  // spheres changed rank, with their history
  }
}

// Adaptive steps (the trapezoidal rule, physics.md section 10): every rank takes the step
// factor from the convergence norms summed over all ranks, so the ranks agree bit for bit on
// every step size and every redone step. Against the one-rank run: the norms differ in their
// last bits, so an iteration count or a redo decided at its threshold can differ, and with it
// the step sequence; both runs are the same trapezoidal rule to its fixed-point tolerance, so
// the states agree to about that (docs/parallel.md: 2e-7 to 4e-7 over these 4 ms, 8e-4 over 10 ms).
TEST(DecomposedRun, AdaptiveStepsFollowTheOneRankRun) {
  const Communicator& world = Communicator::world();
  auto scene = [] {
    Scene s = cluster(Integrator::Trapezoidal, 4e-6);
    s.model.params.time.adaptive = true;
    s.model.params.time.dt_min = 1e-8;
    s.model.params.time.dt_max = 2e-5;
    s.model.params.time.desired_iterations = 4;
    return s;
  };
  Simulation one(scene(), RunOptions{{}, false, false, &Communicator::single()});
  Simulation many(scene(), RunOptions{{}, false, false, &world});
  const double end = 0.004;           // s
  double dt_min = 1.0, dt_max = 0.0;  // s, of the one-rank run
  int steps = 0;
  while (one.time() < end) {
    one.advance_adaptive(end - one.time());
    ++steps;
    dt_min = std::min(dt_min, one.current_dt());
    dt_max = std::max(dt_max, one.current_dt());
  }
  std::uint64_t differing = 0;  // steps whose size some rank saw otherwise
  while (many.time() < end) {   // (collective: every rank takes this loop as often)
    many.advance_adaptive(end - many.time());
    differing += world.min(many.current_dt()) != world.max(many.current_dt()) ? 1 : 0;
  }
  double worst = 0.0;
  std::uint64_t matched = 0;
  double vmax = 0.0;
  for (std::size_t i = 0; i < one.particles().size(); ++i) vmax = std::max(vmax, norm(one.particles().v[i]));
  for (std::size_t i = 0; i < many.particles().size(); ++i)
    for (std::size_t j = 0; j < one.particles().size(); ++j)
      if (one.particles().id[j] == many.particles().id[i]) {
        ++matched;
        worst = std::max({worst, norm(many.particles().x[i] - one.particles().x[j]) / 1e-3,
                          norm(many.particles().v[i] - one.particles().v[j]) / vmax});
      }
  worst = world.max(worst);
  matched = world.sum(matched);
  const auto rank_steps = static_cast<double>(many.steps());
  if (world.rank() == 0)
    std::printf("[%d ranks, adaptive] one rank: %d steps (dt %.3g..%.3g s), %llu redone; all: %llu steps, %llu "
                "redone; max rel diff x/v %.2e\n",
                world.size(), steps, dt_min, dt_max, static_cast<unsigned long long>(one.redone_steps()),
                static_cast<unsigned long long>(many.steps()), static_cast<unsigned long long>(many.redone_steps()),
                worst);
  const auto redone = static_cast<double>(many.redone_steps());
  EXPECT_EQ(differing, 0u);
  EXPECT_EQ(world.min(rank_steps), world.max(rank_steps));  // every rank took the same steps
  EXPECT_EQ(world.min(redone), world.max(redone));
  EXPECT_NEAR(many.time(), end, 1e-15);
  EXPECT_GT(dt_max, 2.0 * dt_min);  // the step did adapt
  EXPECT_GT(one.redone_steps(), 10u);
  EXPECT_LT(worst, 5e-3);
  EXPECT_EQ(matched, one.particles().size());
}

INSTANTIATE_TEST_SUITE_P(Integrators, DecomposedRun, ::testing::Values(Integrator::Verlet, Integrator::Trapezoidal),
                         integrator_name);

// A floor switched on within a Verlet step (gate_scene): every rank, those without a particle
// too, rebuilds its lists in that step's evaluation, each deciding so from the barriers alone
// (the same on every rank, with no collective), and the sphere bounces off the floor as on one rank.
TEST(DecomposedRun, FloorSwitchedOnWithinAStepRebuildsOnEveryRank) {
  const Communicator& world = Communicator::world();
  const auto make = [] {
    Scene s = gate_scene(Integrator::Verlet);
    DomainParams& d = s.model.params.domain;  // bounded, so that it can be cut into bricks
    d.bounded = true;
    d.min = {-0.05, -0.05, -0.02};
    d.max = {0.05, 0.05, 0.1};
    return s;
  };
  Simulation one(make(), RunOptions{{}, false, false, &Communicator::single()});
  Simulation many(make(), RunOptions{{}, false, false, &world});
  while (one.time() < 0.4) {
    one.advance(kTimedDt);
    many.advance(kTimedDt);
  }
  EXPECT_EQ(one.interactions().mid_step_rebuilds(), 1u);
  const auto rebuilds = static_cast<double>(many.interactions().mid_step_rebuilds());
  EXPECT_EQ(world.min(rebuilds), 1.0);
  EXPECT_EQ(world.max(rebuilds), 1.0);
  const Particles& p = one.particles();
  ASSERT_EQ(p.size(), 1u);
  EXPECT_GT(p.v[0].z, 0.0);  // bounced
  const Particles& q = many.particles();
  EXPECT_EQ(world.sum(static_cast<std::uint64_t>(q.size())), 1u);
  double dx = 0.0, dv = 0.0;
  if (q.size() == 1) {
    dx = norm(q.x[0] - p.x[0]) / kR;
    dv = norm(q.v[0] - p.v[0]) / norm(p.v[0]);
  }
  EXPECT_LT(world.max(dx), 1e-10);
  EXPECT_LT(world.max(dv), 1e-10);
}

// A sphere sliding, then sticking, on a fixed sphere that moves at a constant velocity (with and
// without rolling resistance): the pair crosses the cut between two bricks, both particles change
// rank, and at every step the pair's spring (summed over the ranks: one holds it) and at the end
// every state equal the one-rank run's bit for bit.
class DecomposedPair : public ::testing::TestWithParam<double> {};

TEST_P(DecomposedPair, SlidingContactKeepsItsSpringBitwiseAcrossRanks) {
  const Communicator& world = Communicator::world();
  const double dt = 2e-6, r = 1e-3, mu_r = GetParam();
  auto scene = [&] {
    Scene s = make_scene(dt, 1.0);
    s.model.params.time.integrator = Integrator::Verlet;
    s.model.params.fields.gravity = {0.0, 0.0, -9.81};
    set_contact_law(s, 0.3);
    for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier})
      c->mu_rolling = mu_r;
    s.model.params.domain.bounded = true;
    s.model.params.domain.min = {0.0, -0.005, -0.005};
    s.model.params.domain.max = {0.02, 0.005, 0.005};
    s.model.params.domain.on_exit = ExitPolicy::Stop;
    const std::size_t base = add_particle(s, 7, r, {0.006, 0.0, 0.0}, {1.0, 0.0, 0.0});
    s.particles.fixed[base] = 1;
    add_particle(s, 3, r, {0.006, 0.0, 2.0 * r}, {1.002, 0.001, 0.0}, {0.0, 0.0, 5.0});
    return s;
  };
  Simulation one(scene(), RunOptions{{}, false, false, &Communicator::single()});
  Simulation many(scene(), RunOptions{{}, false, false, &world});
  const int steps = 6000;
  std::uint64_t differing = 0, touching = 0;
  for (int k = 0; k < steps; ++k) {
    one.advance(dt);
    many.advance(dt);
    const auto h1 = one.interactions().particle_contacts().export_history(one.particles(), one.interactions().search());
    const auto hn = many.interactions().particle_contacts().export_history(many.particles(),
                                                                           many.interactions().search());
    Vec3 s1{}, sn{};  // the pair's spring, oriented from the lower id
    for (const auto& h : h1) s1 = h.id_first < h.id_second ? h.spring : -h.spring;
    for (const auto& h : hn) sn = h.id_first < h.id_second ? h.spring : -h.spring;
    double held[] = {hn.empty() ? 0.0 : 1.0, sn.x, sn.y, sn.z};
    world.sum(held);  // one rank holds it: the sums are its values
    if (held[0] != static_cast<double>(h1.size()) || held[1] != s1.x || held[2] != s1.y || held[3] != s1.z) ++differing;
    touching += h1.size();
  }
  const auto ref = by_id(one.particles());
  double same = 1.0;
  for (const auto& [id, st] : by_id(many.particles()))
    if (!(st.x == ref.at(id).x && st.v == ref.at(id).v && st.w == ref.at(id).w)) same = 0.0;
  same = world.min(same);
  const HaloExchange* halo = many.interactions().search().halo();
  const std::uint64_t migrated = world.sum(halo ? halo->migrated() : std::uint64_t{0});
  if (world.rank() == 0)
    std::printf("[%d ranks] sliding pair (mu_r %.2f): %llu of %d steps in contact, %llu differing, %llu migrations, "
                "x %.4f m\n",
                world.size(), mu_r, static_cast<unsigned long long>(touching), steps,
                static_cast<unsigned long long>(differing), static_cast<unsigned long long>(migrated), ref.at(3).x.x);
  EXPECT_EQ(differing, 0u);
  EXPECT_EQ(same, 1.0);
  EXPECT_EQ(touching, static_cast<std::uint64_t>(steps));  // the spring lives through the crossing
  EXPECT_GT(ref.at(3).x.x, 0.0105);                        // the pair crossed the cut at x = 0.01 m
  if (world.size() > 1) {
    EXPECT_GE(migrated, 2u);
  }
}

INSTANTIATE_TEST_SUITE_P(RollingResistance, DecomposedPair, ::testing::Values(0.0, 0.05),
                         [](const auto& p) { return p.param > 0.0 ? "Rolling" : "NoRolling"; });
