// Clumps through checkpoints and invariances (docs/physics.md "Clumps"): a run checkpointed half
// way and resumed continues bitwise as the uninterrupted one under both integrators (the bodies'
// state and the trapezoidal predictor's body history are in the checkpoint); relabelling the
// bodies and changing when the neighbour lists are rebuilt change the run by round-off only.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/simulation.hpp"
#include "support/clump_scenes.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kR = 1e-3;   // m
constexpr double kDt = 2e-6;  // s

// 27 bodies (tetrahedra and dumbbells, turned) dropped in a heap on a floor. `reverse` numbers the
// bodies the other way round and loads them in the opposite order; `skin` (m) sets how often the lists are rebuilt.
Scene heap(Integrator integ, bool reverse = false, double skin = 0.0) {
  Scene s = make_scene(kDt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  s.model.params.neighbor.skin = skin;
  s.model.params.checks.max_overlap = 0.2;
  set_contact_law(s, 0.5);
  const double a = 0.7 * kR;
  const int tet = add_template(s, "tetra", {{{a, a, a}, kR}, {{a, -a, -a}, kR}, {{-a, a, -a}, kR}, {{-a, -a, a}, kR}});
  const int db = add_template(s, "dumbbell", {{{0, 0, -kR}, kR}, {{0, 0, kR}, 0.8 * kR}});
  const double h = 4.3 * kR;
  for (int m = 0; m < 27; ++m) {
    const int k = reverse ? 26 - m : m;  // relabelled: loaded in the opposite order too
    const int i = k % 3, j = (k / 3) % 3, l = k / 9;
    const Quat q = quat_normalized({1.0, 0.3 * i, 0.2 * j - 0.1, 0.25 * l});
    add_clump(s, reverse ? 100 - k : 1 + k, k % 2 ? db : tet,
              {h * (i - 1) + 0.2 * kR * l, h * (j - 1), 2.0 * kR + 0.92 * h * l}, {0.02 * (j - 1), 0.0, -0.3},
              {0.0, 0.0, 2.0 * (i - 1)}, q);
  }
  add_floor(s, 0.0, 0.05);
  finish_clumps(s);
  return s;
}

}  // namespace

TEST(ClumpResume, CheckpointResumeIsBitwise) {
  TempDir d("mpdem_clump_resume");
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(integ == Integrator::Verlet ? "verlet" : "trapezoidal");
    Simulation full(heap(integ), RunOptions{{}, false, false});
    for (int k = 0; k < 1500; ++k) full.advance(kDt);
    full.write_checkpoint(d.path / "ck.bin");
    for (int k = 0; k < 1500; ++k) full.advance(kDt);
    Simulation resumed(heap(integ), RunOptions{{}, false, false});
    resumed.resume_from(d.path / "ck.bin");
    for (int k = 0; k < 1500; ++k) resumed.advance(kDt);
    const Bodies &a = full.particles().bodies, &b = resumed.particles().bodies;
    ASSERT_EQ(a.size(), b.size());
    bool touched = false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a.x[k], b.x[k]);
      EXPECT_EQ(a.v[k], b.v[k]);
      EXPECT_EQ(a.w[k], b.w[k]);
      EXPECT_EQ(a.q[k].w, b.q[k].w);
      EXPECT_EQ(a.q[k].z, b.q[k].z);
      touched = touched || norm(a.torque[k]) > 0.0;
    }
    EXPECT_TRUE(touched);  // the heap is in contact: the check is not of free flight
    EXPECT_EQ(full.interactions().stats().contacts_pp, resumed.interactions().stats().contacts_pp);
  }
}

TEST(ClumpResume, RelabellingAndRebuildTimingChangeOnlyRoundOff) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(integ == Integrator::Verlet ? "verlet" : "trapezoidal");
    Simulation base(heap(integ), RunOptions{{}, false, false});
    Simulation relabelled(heap(integ, true), RunOptions{{}, false, false});
    Simulation rebuilt(heap(integ, false, 0.05 * kR), RunOptions{{}, false, false});
    for (int k = 0; k < 6000; ++k) {
      base.advance(kDt);
      relabelled.advance(kDt);
      rebuilt.advance(kDt);
    }
    EXPECT_GT(rebuilt.interactions().search().rebuilds(), base.interactions().search().rebuilds());
    const Bodies &a = base.particles().bodies, &r = relabelled.particles().bodies, &t = rebuilt.particles().bodies;
    double worst = 0.0;  // m and m/s relative to R and 0.1 m/s
    for (std::size_t k = 0; k < a.size(); ++k) {
      // Body k (id 1 + k) is body 26 - k (id 100 - k) of the relabelled run.
      const std::size_t j = a.size() - 1 - k;
      ASSERT_EQ(r.id[j], 101 - a.id[k]);
      worst = std::max({worst, norm(a.x[k] - r.x[j]) / kR, norm(a.v[k] - r.v[j]) / 0.1, norm(a.x[k] - t.x[k]) / kR,
                        norm(a.v[k] - t.v[k]) / 0.1});
    }
    EXPECT_GT(base.interactions().stats().contacts_pp, 5u);  // bodies touch each other
    EXPECT_LT(worst, 1e-9);
    std::printf("largest relative difference (relabelled, rebuilt): %.3g\n", worst);
  }
}
