// The contact list of the last evaluation (output/contact_list.hpp): each particle's listed contact
// forces (plus on `first`, minus on `second`: Newton's third law) sum to its contact force, the
// total force less gravity, for both integrators; the list does not depend on the thread count,
// and recording does not change the run.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>

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
