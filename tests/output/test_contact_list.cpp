// The contact list of the last evaluation (output/contact_list.hpp): each particle's listed contact
// forces (plus on `first`, minus on `second`: Newton's third law) sum to its contact force, the
// total force less gravity, for both integrators; the list does not depend on the thread count,
// and recording does not change the run. Cohesion, from hand-made records (no cohesive law on
// this branch's scenes yet): the touching and bridge flags, a gap's negative overlap and its
// middle as the contact point, and a bridge's share of the coarse-grained contact stress.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/coarse_grain.hpp"
#include "output/analysis_outputs.hpp"
#include "output/contact_list.hpp"
#include "sim/simulation.hpp"
#include "support/dense_granular_scene.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

// A settling bed of 4 x 4 x 3 spheres in an open box: pairs and barrier contacts from the start.
std::unique_ptr<Simulation> bed(Integrator integ, bool record, int threads) {
  omp_set_num_threads(threads);
  Scene s = dense_scene(4, 4, 3, 1e-3, 0.05, 2.09e-3, 0.15, 7, 1e-6);
  s.model.params.time.integrator = integ;
  auto sim = std::make_unique<Simulation>(std::move(s), RunOptions{{}, false, false});
  sim->interactions().particle_contacts().record_contacts(record);
  for (int k = 0; k < 300; ++k) sim->advance(1e-6);
  return sim;
}

}  // namespace

TEST(ContactList, ForcesSumToEachParticlesContactForce) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    auto sim = bed(integ, true, 1);
    const Particles& p = sim->particles();
    const std::vector<ContactEntry> list = contact_list(p, sim->barriers(), sim->interactions());
    const InteractionStats& st = sim->interactions().stats();
    std::size_t pairs = 0, walls = 0;
    std::map<std::int64_t, Vec3> sum;
    for (const ContactEntry& e : list) {
      (e.second >= 0 ? pairs : walls) += 1;
      EXPECT_TRUE((e.second >= 0) != (e.element >= 0));
      const Vec3 f = e.normal_force + e.tangential_force;
      sum[e.first] += f;
      if (e.second >= 0) sum[e.second] -= f;
      EXPECT_NEAR(norm(e.normal), 1.0, 1e-14);
      EXPECT_GT(e.overlap, 0.0);
      // The tangential force lies in the tangent plane up to the step's turn of that plane (the
      // trapezoidal increment (64) weighs in the step-start tangential velocity).
      EXPECT_LE(std::abs(dot(e.tangential_force, e.normal)), 1e-5 * norm(e.tangential_force) + 1e-300);
    }
    EXPECT_EQ(pairs, st.contacts_pp);
    EXPECT_EQ(walls, st.contacts_pb);
    ASSERT_GT(pairs, 10u);
    ASSERT_GT(walls, 10u);
    double scale = 0.0;  // N, the largest contact force component
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 c = p.force[i] - p.mass[i] * sim->model().params.fields.gravity;
      scale = std::max({scale, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 c = p.force[i] - p.mass[i] * sim->model().params.fields.gravity;
      const Vec3 d = sum[p.id[i]] - c;
      EXPECT_LE(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}), 1e-12 * scale) << "particle " << p.id[i];
    }
  }
}

TEST(ContactList, SameForAnyThreadCountAndRecordingChangesNothing) {
  auto one = bed(Integrator::Trapezoidal, true, 1);
  auto two = bed(Integrator::Trapezoidal, true, 2);
  auto off = bed(Integrator::Trapezoidal, false, 2);
  omp_set_num_threads(1);
  auto by_pair = [](std::vector<ContactEntry> l) {
    std::sort(l.begin(), l.end(), [](const ContactEntry& a, const ContactEntry& b) {
      return std::tie(a.first, a.second, a.element) < std::tie(b.first, b.second, b.element);
    });
    return l;
  };
  const auto a = by_pair(contact_list(one->particles(), one->barriers(), one->interactions()));
  const auto b = by_pair(contact_list(two->particles(), two->barriers(), two->interactions()));
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].first, b[k].first);
    EXPECT_EQ(a[k].second, b[k].second);
    EXPECT_EQ(a[k].element, b[k].element);
    EXPECT_EQ(a[k].overlap, b[k].overlap);
    EXPECT_EQ(a[k].normal_force.x, b[k].normal_force.x);
    EXPECT_EQ(a[k].tangential_force.y, b[k].tangential_force.y);
  }
  // Without recording: the same trajectory, bit for bit, and no pair contacts listed.
  for (std::size_t i = 0; i < off->particles().size(); ++i) {
    EXPECT_EQ(off->particles().x[i].x, two->particles().x[i].x);
    EXPECT_EQ(off->particles().v[i].z, two->particles().v[i].z);
  }
  const auto none = contact_list(off->particles(), off->barriers(), off->interactions());
  EXPECT_TRUE(std::all_of(none.begin(), none.end(), [](const ContactEntry& e) { return e.second < 0; }));
}

namespace {

// Two spheres on the x axis with a gap between them: i (id 10, R 1 mm) at the origin, j (id 20,
// R 2 mm) at d = 3.5 mm, so overlap = R_i + R_j - d = -0.5 mm; the surfaces at x = 1 and 1.5 mm.
Particles gap_pair() {
  Particles p;
  p.add(10, 0, 1e-3, 2500.0, {0.0, 0.0, 0.0}, {});
  p.add(20, 0, 2e-3, 2500.0, {3.5e-3, 0.0, 0.0}, {});
  return p;
}

// A pair record as the pair kernel writes it: the net normal force fn along the normal from j to
// i (on i; < 0 attracts) plus a tangential force.
PairRecord record(double overlap, double fn, Vec3 ft, std::uint32_t live) {
  const Vec3 n{-1.0, 0.0, 0.0};
  return PairRecord{n * fn + ft, n, overlap, fn, 0, live};
}

}  // namespace

TEST(ContactList, PairEntriesOfCohesiveRecords) {
  const Particles p = gap_pair();
  const double ov = -5e-4;                                                // m
  EXPECT_FALSE(pair_entry(p, 0, 1, record(ov, 0.0, {}, 0)).has_value());  // nothing acts: not listed

  // A bridge alone across the gap: attracts, is not a contact, its point is the gap's middle.
  const auto b = pair_entry(p, 0, 1, record(ov, -2e-3, {}, kBridgeFormed));
  ASSERT_TRUE(b.has_value());
  EXPECT_TRUE(b->bridge);
  EXPECT_FALSE(b->touching);
  EXPECT_EQ(b->first, 10);
  EXPECT_EQ(b->second, 20);
  EXPECT_EQ(b->overlap, ov);
  EXPECT_NEAR(b->point.x, 1.25e-3, 1e-18);  // (1 mm + 1.5 mm) / 2
  EXPECT_EQ(b->point.y, 0.0);
  EXPECT_EQ(b->point.z, 0.0);
  EXPECT_EQ(b->normal_force.x, 2e-3);  // on i, towards j
  EXPECT_EQ(norm(b->tangential_force), 0.0);
  EXPECT_EQ(b->branch.x, -3.5e-3);  // centre to centre, whatever the gap
  EXPECT_EQ(b->centre.x, 0.0);

  // A JKR neck held past touching with a bridge around it: both flags, its tangential force kept.
  const auto nb = pair_entry(p, 0, 1, record(ov, -1e-3, {0.0, 3e-4, 0.0}, kLawFormed | kBridgeFormed));
  ASSERT_TRUE(nb.has_value());
  EXPECT_TRUE(nb->touching);
  EXPECT_TRUE(nb->bridge);
  EXPECT_EQ(nb->tangential_force.y, 3e-4);
  EXPECT_EQ(nb->normal_force.x, 1e-3);

  // A plain contact (overlap > 0): touching only, the point in the middle of the overlap.
  Particles q = gap_pair();
  q.x[1].x = 2.9e-3;  // overlap 0.1 mm: i's surface at 1 mm, j's at 0.9 mm
  const auto c = pair_entry(q, 0, 1, record(1e-4, 5e-2, {}, kLawFormed));
  ASSERT_TRUE(c.has_value());
  EXPECT_TRUE(c->touching);
  EXPECT_FALSE(c->bridge);
  EXPECT_NEAR(c->point.x, 0.95e-3, 1e-18);
}

TEST(ContactList, BarrierEntriesOfCohesiveSlots) {
  // A plain scene's slots keep state 0, and every detected contact touches.
  EXPECT_EQ(barrier_live(0, 1e-6), kLawFormed);
  EXPECT_EQ(barrier_live(0, -1e-6), 0u);  // a cohesive scene's contact that broke at this evaluation
  EXPECT_EQ(barrier_live(kBridgeFormed, -1e-6), kBridgeFormed);
  EXPECT_EQ(barrier_live(kLawFormed | kBridgeFormed, 1e-6), kLawFormed | kBridgeFormed);

  const Particles p = gap_pair();
  BarrierSlot slot;
  slot.normal = {-1.0, 0.0, 0.0};  // a wall at x = 1.4 mm, facing i
  BarrierLoad load;
  load.point = {1.4e-3, 0.0, 0.0};
  load.overlap = -4e-4;
  load.force = {-1e-3, 0.0, 0.0};  // the element's: drawn towards i
  load.element = 0;
  EXPECT_FALSE(barrier_entry(p, 0, 7, slot, load).has_value());
  slot.state = kBridgeFormed;
  const auto e = barrier_entry(p, 0, 7, slot, load);
  ASSERT_TRUE(e.has_value());
  EXPECT_TRUE(e->bridge);
  EXPECT_FALSE(e->touching);
  EXPECT_EQ(e->element, 7);
  EXPECT_EQ(e->second, -1);
  EXPECT_EQ(e->overlap, -4e-4);
  EXPECT_EQ(e->point.x, 1.4e-3);
  EXPECT_EQ(e->branch.x, -1.4e-3);     // centre to the wall's point across the gap
  EXPECT_EQ(e->normal_force.x, 1e-3);  // the particle's: towards the wall
  EXPECT_EQ(norm(e->tangential_force), 0.0);
  // A plain scene's contact (state 0, touching).
  slot.state = 0;
  load.overlap = 1e-5;
  const auto t = barrier_entry(p, 0, 7, slot, load);
  ASSERT_TRUE(t.has_value());
  EXPECT_TRUE(t->touching);
  EXPECT_FALSE(t->bridge);
}

// A bridge's share of the coarse-grained stress is f (x) b with b the branch from centre to centre
// (averaged over a box of volume V: sigma = f (x) b / V, a tension), it is not a contact in the
// coordination, and a touching neighbour is; the box holds both particles.
TEST(ContactList, BridgeStressAlongTheBranchAndNoCoordination) {
  Particles p = gap_pair();
  p.add(30, 0, 1e-3, 2500.0, {-1.9e-3, 0.0, 0.0}, {});  // touches i (overlap 0.1 mm)
  const double f = 2e-3;                                // N, the bridge's attraction
  const auto bridge = pair_entry(p, 0, 1, record(-5e-4, -f, {}, kBridgeFormed));
  PairRecord touch{{3e-2, 0.0, 0.0}, {1.0, 0.0, 0.0}, 1e-4, 3e-2, 0, kLawFormed};  // on i, from 30 to i
  const auto contact = pair_entry(p, 0, 2, touch);
  ASSERT_TRUE(bridge && contact);
  const std::vector<ContactEntry> list{*bridge, *contact};
  std::vector<CgParticle> particles(3);
  for (std::size_t i = 0; i < 3; ++i) particles[i] = {p.x[i], {}, p.mass[i], 1.0, 0};
  std::vector<CgContact> contacts;
  cg_contacts(p.id, list, particles, contacts);
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_EQ(particles[0].contacts, 1);  // i: the touching neighbour only
  EXPECT_EQ(particles[1].contacts, 0);  // j: a bridge alone
  EXPECT_EQ(particles[2].contacts, 1);
  EXPECT_EQ(contacts[0].force.x, f);
  EXPECT_EQ(contacts[0].branch.x, -3.5e-3);
  EXPECT_FALSE(contacts[0].boundary);

  const double L = 2e-2, V = L * L * L;  // m, m^3: the box [-L/2, L/2]^3, every axis averaged
  const CgGrid g{{-0.5 * L, -0.5 * L, -0.5 * L}, {0.5 * L, 0.5 * L, 0.5 * L}, {1, 1, 1}, {false, false, false}};
  const CgFields only_bridge = coarse_grain(g, CgKernel::lucy, 1e-3, particles, std::span(contacts).first(1));
  const double expected = -f * 3.5e-3 / V;  // Pa, f_x b_x / V < 0: tension
  EXPECT_NEAR(only_bridge.contact_stress[0][0], expected, 1e-12 * std::abs(expected));
  for (std::size_t q = 1; q < 9; ++q) EXPECT_EQ(only_bridge.contact_stress[0][q], 0.0) << q;
  const CgFields both = coarse_grain(g, CgKernel::lucy, 1e-3, particles, contacts);
  const double with_contact = expected + 3e-2 * 1.9e-3 / V;  // the contact's compression adds
  EXPECT_NEAR(both.contact_stress[0][0], with_contact, 1e-12 * std::abs(with_contact));
  EXPECT_NEAR(both.coordination[0], 2.0 / 3.0, 1e-15);  // 2 contact ends over 3 particles
}
